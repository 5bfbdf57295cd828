// The raw solver API over the wasm module: an explicit grid (indices only) and constraint list
// in, the field out (`hairsketch solve`, research pipelines).
import type { HairSolverModule } from '../generated/hairsolver.mjs';
import { SolverError } from './engine';
import {
  callOut,
  callWith,
  check,
  copyInString,
  f64,
  num,
  withInputs,
  withScratch,
} from './wasmMemory';
import { instantiate, type LoadOptions } from './wasmModule';
import { CONSTRAINT_LIST, GRID_INPUT, STATS_OUTPUT } from './wasmStructs';

/** Stats of the raw solver API. */
export interface RawSolveStats {
  method: string;
  iterations: number;
  residual: number;
  constraints: number;
  added: number;
  removed: number;
  changed: number;
  setupMs: number;
  solveMs: number;
}

/** Progress of a long raw solve (iterative solvers). */
export interface RawSolveProgress {
  iterations: number;
  /** Estimated relative field error (Infinity while the solver has no estimate yet). */
  errorEstimate: number;
  relResidual: number;
}

/** The solver's memory estimate for a grid and the cap setGrid checks it against (bytes). */
export interface MemoryEstimate {
  needsBytes: number;
  capBytes: number;
}

/** Binding calls beyond wasm-build/hairsolver.d.mts (estimate and progress plumbing). */
type EstimateModule = HairSolverModule & {
  _hs_raw_estimate(h: number, nx: number, ny: number, nz: number, out: number): number;
  _hs_raw_set_progress(h: number, intervalMs: number): number;
  hsOnProgress?: (iterations: number, errorEstimate: number, relResidual: number) => boolean;
};

/** The raw solver: an explicit grid (indices only) + constraint list -> field. */
export interface RawSolver {
  /** Memory estimate for a grid of these dims (no allocation) and the current cap. */
  estimate(dims: [number, number, number]): MemoryEstimate;
  /** During solve(), fn is called at most every intervalMs with the progress; returning false
   *  stops the solve (solve() then throws). intervalMs <= 0 removes it. */
  onProgress(intervalMs: number, fn?: (p: RawSolveProgress) => boolean): void;
  /** Once per solver. Grid point (i, j, k) has index i + nx * (j + ny * k). */
  setGrid(dims: [number, number, number], omega: number): void;
  /** index[c] = grid point, target[3 * c + axis] = its target. Duplicates are averaged. */
  setConstraints(index: Int32Array, target: Float64Array): void;
  solve(): void;
  /** field[3 * p + axis], a copy. */
  field(): Float64Array;
  stats(): RawSolveStats;
  dispose(): void;
}

/** The stats struct (STATS_OUTPUT) as RawSolveStats. */
export function toRawStats(
  o: Record<(typeof STATS_OUTPUT.names)[number], number | string>,
): RawSolveStats {
  return {
    method: String(o.method),
    iterations: num(o.iterations),
    residual: num(o.residual),
    constraints: num(o.constraints),
    added: num(o.added),
    removed: num(o.removed),
    changed: num(o.changed),
    setupMs: num(o.setupMs),
    solveMs: num(o.solveMs),
  };
}

class WasmRawSolver implements RawSolver {
  constructor(
    private readonly mod: HairSolverModule,
    private handle: number,
  ) {}

  private h(): number {
    if (this.handle === 0) throw new SolverError('solver is disposed', 'not_ready');
    return this.handle;
  }

  setGrid(dims: [number, number, number], omega: number): void {
    const h = this.h();
    const m = this.mod;
    const [nx, ny, nz] = dims;
    const unit = { originX: 0, originY: 0, originZ: 0, step: 1, solver: 0 };
    callWith(m, GRID_INPUT, { ...unit, omega, nx, ny, nz }, (p) => m._hs_raw_set_grid(h, p));
  }

  estimate(dims: [number, number, number]): MemoryEstimate {
    const h = this.h();
    const m = this.mod as EstimateModule;
    return withScratch(m, 16, (out) => {
      check(m, m._hs_raw_estimate(h, dims[0], dims[1], dims[2], out));
      return { needsBytes: m.HEAPF64[out >> 3], capBytes: m.HEAPF64[(out >> 3) + 1] };
    });
  }

  onProgress(intervalMs: number, fn?: (p: RawSolveProgress) => boolean): void {
    const m = this.mod as EstimateModule;
    m.hsOnProgress = fn
      ? (iterations, errorEstimate, relResidual) => fn({ iterations, errorEstimate, relResidual })
      : undefined;
    check(m, m._hs_raw_set_progress(this.h(), fn ? intervalMs : 0));
  }

  setConstraints(index: Int32Array, target: Float64Array): void {
    if (target.length !== 3 * index.length)
      throw new SolverError('constraints: target must have 3 entries per index', 'invalid_input');
    const h = this.h();
    const m = this.mod;
    withInputs(m, [index, target], ([i, t]) => {
      callWith(m, CONSTRAINT_LIST, { index: i, target: t, count: index.length }, (p) =>
        m._hs_raw_set_constraints(h, p),
      );
    });
  }

  solve(): void {
    check(this.mod, this.mod._hs_raw_solve(this.h()));
  }

  field(): Float64Array {
    const h = this.h();
    return f64(this.mod, this.mod._hs_raw_field(h), 3 * this.mod._hs_raw_field_points(h));
  }

  stats(): RawSolveStats {
    const h = this.h();
    return toRawStats(callOut(this.mod, STATS_OUTPUT, (p) => this.mod._hs_raw_stats(h, p)));
  }

  dispose(): void {
    if (this.handle !== 0) this.mod._hs_raw_destroy(this.handle);
    this.handle = 0;
  }
}

/** Loads a fresh wasm module and creates the named solver ('cg', ...) over it. */
export async function loadRawSolver(solver: string, opts: LoadOptions = {}): Promise<RawSolver> {
  const mod = await instantiate(opts);
  const name = copyInString(mod, solver);
  try {
    const h = withScratch(mod, 4, (out) => {
      check(mod, mod._hs_raw_create(name, out));
      return mod.HEAPU32[out >> 2];
    });
    return new WasmRawSolver(mod, h);
  } finally {
    mod._free(name);
  }
}
