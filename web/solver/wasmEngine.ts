// SolverEngine over the wasm module (wasm-build/binding.cpp). Inputs are copied into wasm
// memory for the duration of a call; results are copied out into fresh typed arrays of the
// protocol.ts layouts, so they can be transferred and outlive the next call.
import createHairSolver, { type HairSolverModule } from '../generated/hairsolver.mjs';
import { type IterateProgress, type SolverEngine, SolverError } from './engine';
import type {
  ConstraintArrays,
  CurveSet,
  FieldArrays,
  GridSpec,
  GrowthParams,
  ScalpMesh,
  SolverName,
  SolveStats,
  StrandArrays,
} from './protocol';

export interface LoadOptions {
  /** The .wasm bytes (Node: read from web/generated/hairsolver.wasm). */
  wasmBinary?: Uint8Array;
  /** Browser: where the .wasm lives, e.g. `() => wasmUrl` from `...hairsolver.wasm?url`. */
  locateFile?: (file: string) => string;
}

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

/** The raw solver: an explicit grid (indices only) + constraint list -> field. */
export interface RawSolver {
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

async function instantiate(opts: LoadOptions): Promise<HairSolverModule> {
  const locateFile = opts.locateFile;
  return createHairSolver({
    ...(opts.wasmBinary ? { wasmBinary: opts.wasmBinary } : {}),
    ...(locateFile ? { locateFile: (file: string) => locateFile(file) } : {}),
  });
}

/** Copies a typed array into fresh wasm memory; returns the pointer (free it). */
function copyIn(mod: HairSolverModule, arr: ArrayBufferView): number {
  const bytes = new Uint8Array(arr.buffer, arr.byteOffset, arr.byteLength);
  const ptr = mod._malloc(Math.max(8, bytes.byteLength));
  if (ptr === 0) throw new SolverError('out of wasm memory');
  mod.HEAPU8.set(bytes, ptr);
  return ptr;
}

function copyInString(mod: HairSolverModule, s: string): number {
  const bytes = new TextEncoder().encode(s);
  const z = new Uint8Array(bytes.length + 1);
  z.set(bytes);
  return copyIn(mod, z);
}

/** Runs fn with the given arrays copied into wasm memory, then frees them. */
function withInputs<T>(
  mod: HairSolverModule,
  inputs: ArrayBufferView[],
  fn: (ptrs: number[]) => T,
): T {
  const ptrs: number[] = [];
  try {
    for (const a of inputs) ptrs.push(copyIn(mod, a));
    return fn(ptrs);
  } finally {
    for (const p of ptrs) mod._free(p);
  }
}

function check(mod: HairSolverModule, status: number): void {
  if (status !== 0) throw new SolverError(mod.UTF8ToString(mod._hs_last_error()));
}

// Typed-array copies out of wasm memory (views are re-read: memory may have grown).
const f32 = (mod: HairSolverModule, ptr: number, n: number): Float32Array =>
  n === 0 ? new Float32Array(0) : mod.HEAPF32.slice(ptr >> 2, (ptr >> 2) + n);
const f64 = (mod: HairSolverModule, ptr: number, n: number): Float64Array =>
  n === 0 ? new Float64Array(0) : mod.HEAPF64.slice(ptr >> 3, (ptr >> 3) + n);
const u32 = (mod: HairSolverModule, ptr: number, n: number): Uint32Array =>
  n === 0 ? new Uint32Array(0) : mod.HEAPU32.slice(ptr >> 2, (ptr >> 2) + n);
const i32 = (mod: HairSolverModule, ptr: number, n: number): Int32Array =>
  n === 0 ? new Int32Array(0) : mod.HEAP32.slice(ptr >> 2, (ptr >> 2) + n);

function parseStats(json: string): RawSolveStats {
  const o = JSON.parse(json) as Record<string, unknown>;
  const num = (k: string): number => (typeof o[k] === 'number' ? (o[k] as number) : 0);
  return {
    method: typeof o.method === 'string' ? o.method : '',
    iterations: num('iterations'),
    residual: num('residual'),
    constraints: num('constraints'),
    added: num('added'),
    removed: num('removed'),
    changed: num('changed'),
    setupMs: num('setupMs'),
    solveMs: num('solveMs'),
  };
}

class WasmEngine implements SolverEngine {
  private handle: number;

  constructor(private readonly mod: HairSolverModule) {
    this.handle = mod._hs_engine_create();
  }

  private h(): number {
    if (this.handle === 0) throw new SolverError('engine is disposed');
    return this.handle;
  }

  setGrid(grid: GridSpec, omega: number, solver: SolverName): void {
    const h = this.h();
    const name = copyInString(this.mod, solver);
    try {
      const [nx, ny, nz] = grid.dims;
      const [ox, oy, oz] = grid.origin;
      check(
        this.mod,
        this.mod._hs_engine_set_grid(h, nx, ny, nz, ox, oy, oz, grid.step, omega, name),
      );
    } finally {
      this.mod._free(name);
    }
  }

  setScalp(mesh: ScalpMesh): void {
    const h = this.h();
    const nt = Math.floor(mesh.indices.length / 3);
    if (mesh.scalp.length !== nt || mesh.indices.length !== 3 * nt || mesh.positions.length % 3)
      throw new SolverError('scalp: array lengths do not match (3 per vertex, 3 per triangle)');
    withInputs(this.mod, [mesh.positions, mesh.indices, mesh.scalp], ([p, i, s]) => {
      const [cx, cy, cz] = mesh.center;
      check(
        this.mod,
        this.mod._hs_engine_set_scalp(h, p, mesh.positions.length / 3, i, nt, s, cx, cy, cz),
      );
    });
  }

  setCurves(curves: CurveSet): void {
    const h = this.h();
    const nc = curves.curveStart.length - 1;
    if (nc < 0) throw new SolverError('curves: curveStart must have curves + 1 entries');
    if (curves.kinds.length !== nc || curves.extend.length !== nc || curves.points.length % 3)
      throw new SolverError('curves: array lengths do not match');
    if (curves.paramStart.length !== nc + 1)
      throw new SolverError('curves: paramStart must have curves + 1 entries');
    const ne = curves.extraIndex.length;
    if (curves.extraTarget.length !== 3 * ne)
      throw new SolverError('curves: extraTarget must have 3 entries per extraIndex');
    withInputs(
      this.mod,
      [
        curves.points,
        curves.curveStart,
        curves.kinds,
        curves.extend,
        curves.params,
        curves.paramStart,
        curves.extraIndex,
        curves.extraTarget,
      ],
      ([p, s, k, e, pr, ps, xi, xt]) => {
        check(
          this.mod,
          this.mod._hs_engine_set_curves(
            h,
            p,
            curves.points.length / 3,
            s,
            nc,
            k,
            e,
            pr,
            curves.params.length,
            ps,
            xi,
            xt,
            ne,
          ),
        );
      },
    );
  }

  /** Display colour of each constraint of constraints(), same order: 0 blue, 1 red, 2 purple,
   *  3 green, 4 explicit extra (solver-cpp/src/constraint_colour.hpp). */
  constraintColours(): Uint8Array {
    const h = this.h();
    const m = this.mod;
    const n = m._hs_engine_prepare_constraints(h);
    const ptr = m._hs_engine_constraint_colour(h);
    return n === 0 ? new Uint8Array(0) : m.HEAPU8.slice(ptr, ptr + n);
  }

  /** Scalp avoidance (SPEC S4.7) on the last solved field: constraints to store as the
   *  CurveSet's extraIndex / extraTarget (sorted by grid index, |target| = magnitude). */
  scalpAvoidance(opts: ScalpAvoidanceOptions = {}): ScalpAvoidanceResult {
    const h = this.h();
    const m = this.mod;
    check(
      m,
      m._hs_engine_scalp_avoidance(
        h,
        opts.band ?? 1.5,
        opts.magnitude ?? 0.3,
        (opts.wholeHead ? 1 : 0) | (opts.insideToo ? 2 : 0),
      ),
    );
    const n = m._hs_engine_avoid_count(h);
    return {
      index: i32(m, m._hs_engine_avoid_index(h), n),
      target: f64(m, m._hs_engine_avoid_target(h), 3 * n),
    };
  }

  solve(): void {
    check(this.mod, this.mod._hs_engine_solve(this.h()));
  }

  iterate(maxIterations: number, tolerance: number): IterateProgress {
    const h = this.h();
    return withInputs(this.mod, [new Float64Array(3)], ([out]) => {
      check(this.mod, this.mod._hs_engine_iterate(h, maxIterations, tolerance, out));
      const p = f64(this.mod, out, 3);
      return { iterations: p[0], errorEstimate: p[1], converged: p[2] === 1 };
    });
  }

  grow(g: GrowthParams): StrandArrays {
    const h = this.h();
    const m = this.mod;
    check(
      m,
      m._hs_engine_grow(
        h,
        g.thetaStepDeg,
        g.phiStepDeg,
        g.jitter,
        g.seed,
        g.stepFraction,
        g.minMagnitude,
        g.maxLength,
        g.maxSegments,
        g.maxStrands,
      ),
    );
    return {
      points: f32(m, m._hs_engine_strand_points(h), 3 * m._hs_engine_strand_point_count(h)),
      strandStart: u32(m, m._hs_engine_strand_start(h), m._hs_engine_strand_start_count(h)),
    };
  }

  constraints(): Omit<ConstraintArrays, 'colour'> {
    const h = this.h();
    const m = this.mod;
    const n = m._hs_engine_prepare_constraints(h);
    return {
      index: i32(m, m._hs_engine_constraint_index(h), n),
      target: f32(m, m._hs_engine_constraint_target(h), 3 * n),
    };
  }

  field(): FieldArrays {
    const h = this.h();
    const n = this.mod._hs_engine_prepare_field(h);
    return { vectors: f32(this.mod, this.mod._hs_engine_field(h), 3 * n) };
  }

  stats(): Omit<SolveStats, 'growMs' | 'errorEstimate' | 'heapBytes'> {
    const s = parseStats(this.mod.UTF8ToString(this.mod._hs_engine_stats_json(this.h())));
    return {
      method: s.method,
      iterations: s.iterations,
      constraints: s.constraints,
      added: s.added,
      removed: s.removed,
      changed: s.changed,
      setupMs: s.setupMs,
      solveMs: s.solveMs,
    };
  }

  /** Milliseconds of the last grow (roots + strands), measured in wasm. */
  growMs(): number {
    return this.mod._hs_engine_grow_ms(this.h());
  }

  heapBytes(): number {
    return this.mod.HEAPU8.length;
  }

  /** Number of roots of the last grow. */
  rootCount(): number {
    return this.mod._hs_engine_root_count(this.h());
  }

  dispose(): void {
    if (this.handle !== 0) this.mod._hs_engine_destroy(this.handle);
    this.handle = 0;
  }
}

/** Engine with extras beyond SolverEngine (timings, root count). */
export type WasmSolverEngine = SolverEngine & {
  growMs(): number;
  rootCount(): number;
  scalpAvoidance(opts?: ScalpAvoidanceOptions): ScalpAvoidanceResult;
  constraintColours(): Uint8Array;
};

/** Options of scalp avoidance (SPEC S4.7). */
export interface ScalpAvoidanceOptions {
  band?: number; // grid steps from the scalp (default 1.5)
  magnitude?: number; // target length (default 0.3)
  wholeHead?: boolean; // measure against every head triangle, not only the scalp (default false)
  insideToo?: boolean; // also grid points inside the head within the band (default false)
}

/** index[e] = grid point, target[3 * e + axis]: ready for CurveSet.extraIndex / extraTarget. */
export interface ScalpAvoidanceResult {
  index: Int32Array;
  target: Float64Array;
}

/** Loads a fresh wasm module and returns an engine over it. */
export async function loadSolverEngine(opts: LoadOptions = {}): Promise<WasmSolverEngine> {
  return new WasmEngine(await instantiate(opts));
}

class WasmRawSolver implements RawSolver {
  constructor(
    private readonly mod: HairSolverModule,
    private handle: number,
  ) {}

  private h(): number {
    if (this.handle === 0) throw new SolverError('solver is disposed');
    return this.handle;
  }

  setGrid(dims: [number, number, number], omega: number): void {
    check(this.mod, this.mod._hs_raw_set_grid(this.h(), dims[0], dims[1], dims[2], omega));
  }

  setConstraints(index: Int32Array, target: Float64Array): void {
    if (target.length !== 3 * index.length)
      throw new SolverError('constraints: target must have 3 entries per index');
    const h = this.h();
    withInputs(this.mod, [index, target], ([i, t]) => {
      check(this.mod, this.mod._hs_raw_set_constraints(h, i, t, index.length));
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
    return parseStats(this.mod.UTF8ToString(this.mod._hs_raw_stats_json(this.h())));
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
    const h = mod._hs_raw_create(name);
    if (h === 0) throw new SolverError(mod.UTF8ToString(mod._hs_last_error()));
    return new WasmRawSolver(mod, h);
  } finally {
    mod._free(name);
  }
}
