// The engine's primitive calls (engineCore.ts) over the wasm module (wasm-build/binding.cpp). Inputs are copied into wasm
// memory for the duration of a call and described to the binding by one C struct per call,
// written by writeStruct from its protocol.ts layout; results are copied out into fresh typed
// arrays of the protocol.ts layouts, so they can be transferred and outlive the next call.
// Every binding call returns a status; a failure throws SolverError with its kind.
// The module's loading is in wasmModule.ts, the boundary's data movement in wasmMemory.ts, the
// raw solver API in wasmRawSolver.ts.
import type { HairSolverModule } from '../generated/hairsolver.mjs';
import { DETAIL_GROUP_STRIDE } from '../model/detail';
import type { GrowthParams } from '../model/growthParams';
import type {
  ConstraintArrays,
  CurveSet,
  DetailArrays,
  FieldArrays,
  GridSpec,
  ScalpMesh,
  StrandArrays,
} from '../model/hairArrays';
import {
  type IterateProgress,
  type MotionOptions,
  type MotionRun,
  type SolverEngine,
  SolverError,
} from './engine';
import type { EngineCore } from './engineCore';
import type { SolverName, SolveStats } from './protocol';
import { engineOver } from './requestRunner';
import {
  callOut,
  callWith,
  check,
  copyInString,
  f32,
  f64,
  i32,
  num,
  u8,
  u32,
  withInputs,
  withScratch,
} from './wasmMemory';
import { instantiate, type LoadOptions, moduleLabel } from './wasmModule';
import { createMotion } from './wasmMotion';
import { toRawStats } from './wasmRawSolver';
import {
  AVOID_INPUT,
  CURVE_SET_HEADER,
  GRID_INPUT,
  GROWTH_INPUT,
  ITERATE_PROGRESS,
  SCALP_INPUT,
  STATS_OUTPUT,
} from './wasmStructs';

export {
  boundaryLayoutMismatches,
  chooseThreads,
  type LoadOptions,
  type ModuleFactory,
  moduleLabel,
  type ThreadedModule,
} from './wasmModule';
export {
  loadRawSolver,
  type MemoryEstimate,
  type RawSolveProgress,
  type RawSolver,
  type RawSolveStats,
} from './wasmRawSolver';

class WasmEngine implements EngineCore {
  private handle: number;

  constructor(private readonly mod: HairSolverModule) {
    this.handle = mod._hs_engine_create();
  }

  private h(): number {
    if (this.handle === 0) throw new SolverError('engine is disposed', 'not_ready');
    return this.handle;
  }

  setGrid(grid: GridSpec, omega: number, solver: SolverName): void {
    const h = this.h();
    const m = this.mod;
    const name = copyInString(m, solver);
    try {
      const [nx, ny, nz] = grid.dims;
      const [originX, originY, originZ] = grid.origin;
      callWith(
        m,
        GRID_INPUT,
        { originX, originY, originZ, step: grid.step, omega, nx, ny, nz, solver: name },
        (p) => m._hs_engine_set_grid(h, p),
      );
    } finally {
      m._free(name);
    }
  }

  setScalp(mesh: ScalpMesh): void {
    const h = this.h();
    const m = this.mod;
    const nt = Math.floor(mesh.indices.length / 3);
    if (mesh.scalp.length !== nt || mesh.indices.length !== 3 * nt || mesh.positions.length % 3)
      throw new SolverError(
        'scalp: array lengths do not match (3 per vertex, 3 per triangle)',
        'invalid_input',
      );
    withInputs(m, [mesh.positions, mesh.indices, mesh.scalp], ([positions, indices, scalp]) => {
      const [centerX, centerY, centerZ] = mesh.center;
      callWith(
        m,
        SCALP_INPUT,
        {
          centerX,
          centerY,
          centerZ,
          positions,
          vertexCount: mesh.positions.length / 3,
          indices,
          triangleCount: nt,
          scalp,
        },
        (p) => m._hs_engine_set_scalp(h, p),
      );
    });
  }

  /** A groom in motion over this engine's head (SolverEngine.startMotion). */
  startMotion(strands: StrandArrays, opts: MotionOptions): MotionRun {
    return createMotion(this.mod, this.h(), strands, opts);
  }

  /** The body under the head (SolverEngine.setBody); null clears it. */
  setBody(body: { positions: Float32Array; indices: Uint32Array } | null): void {
    const h = this.h();
    const m = this.mod;
    if (!body || body.indices.length === 0) {
      check(m, m._hs_engine_set_body(h, 0, 0, 0, 0));
      return;
    }
    if (body.indices.length % 3 || body.positions.length % 3)
      throw new SolverError(
        'body: array lengths do not match (3 per vertex, 3 per triangle)',
        'invalid_input',
      );
    withInputs(m, [body.positions, body.indices], ([positions, indices]) =>
      check(
        m,
        m._hs_engine_set_body(
          h,
          positions,
          body.positions.length / 3,
          indices,
          body.indices.length / 3,
        ),
      ),
    );
  }

  /** A new scalp mask (scalp[triangle] = 1) for the head of setScalp; the next grow samples
   *  roots over it. The binding refuses a length other than the head's triangle count. */
  setScalpMask(scalp: Uint8Array): void {
    const h = this.h();
    const m = this.mod;
    withInputs(m, [scalp], ([p]) => check(m, m._hs_engine_set_scalp_mask(h, p, scalp.length)));
  }

  /** Detail groups and each curve's group (protocol.ts DetailArrays), used by grow. */
  setDetail(d: DetailArrays): void {
    const h = this.h();
    const m = this.mod;
    if (d.groups.length % DETAIL_GROUP_STRIDE)
      throw new SolverError(
        `detail: groups must hold ${DETAIL_GROUP_STRIDE} numbers per group`,
        'invalid_input',
      );
    const nGroups = d.groups.length / DETAIL_GROUP_STRIDE;
    withInputs(m, [d.groups, d.curveGroup], ([groups, curveGroup]) =>
      check(m, m._hs_engine_set_detail(h, groups, nGroups, curveGroup, d.curveGroup.length)),
    );
  }

  setCurves(curves: CurveSet): void {
    const h = this.h();
    const m = this.mod;
    const nc = curves.curveStart.length - 1;
    const bad = (msg: string) => new SolverError(`curves: ${msg}`, 'invalid_input');
    if (nc < 0) throw bad('curveStart must have curves + 1 entries');
    if (curves.kinds.length !== nc || curves.extend.length !== nc || curves.points.length % 3)
      throw bad('array lengths do not match');
    if (curves.paramStart.length !== nc + 1) throw bad('paramStart must have curves + 1 entries');
    const ne = curves.extraIndex.length;
    if (curves.extraTarget.length !== 3 * ne)
      throw bad('extraTarget must have 3 entries per extraIndex');
    const c = curves;
    const arrays = [
      c.points,
      c.curveStart,
      c.kinds,
      c.extend,
      c.params,
      c.paramStart,
      c.extraIndex,
      c.extraTarget,
    ];
    withInputs(m, arrays, ([points, curveStart, kinds, extend, params, paramStart, xi, xt]) => {
      callWith(
        m,
        CURVE_SET_HEADER,
        {
          points,
          pointCount: c.points.length / 3,
          curveStart,
          curveCount: nc,
          kinds,
          extend,
          params,
          paramCount: c.params.length,
          paramStart,
          extraIndex: xi,
          extraTarget: xt,
          extraCount: ne,
        },
        (p) => m._hs_engine_set_curves(h, p),
      );
    });
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

  /** Scalp avoidance (method S4.7) on the last solved field: constraints to store as the
   *  CurveSet's extraIndex / extraTarget (sorted by grid index, |target| = magnitude). */
  scalpAvoidance(opts: ScalpAvoidanceOptions = {}): ScalpAvoidanceResult {
    const h = this.h();
    const m = this.mod;
    callWith(
      m,
      AVOID_INPUT,
      {
        band: opts.band ?? 1.5,
        magnitude: opts.magnitude ?? 0.3,
        wholeHead: opts.wholeHead ? 1 : 0,
        insideToo: opts.insideToo ? 1 : 0,
        minField: opts.minField ?? 0,
      },
      (p) => m._hs_engine_scalp_avoidance(h, p),
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
    const m = this.mod;
    const p = callOut(m, ITERATE_PROGRESS, (out) =>
      m._hs_engine_iterate(h, maxIterations, tolerance, out),
    );
    return {
      iterations: num(p.iterations),
      errorEstimate: num(p.errorEstimate),
      converged: p.converged === 1,
    };
  }

  forgetWarmStart(): boolean {
    return this.mod._hs_engine_forget_warm_start(this.h()) === 1;
  }

  deferPreconditionerUpdate(): void {
    this.mod._hs_engine_defer_preconditioner_update(this.h());
  }

  setSettings(values: Float64Array): void {
    const h = this.h();
    const m = this.mod;
    withInputs(m, [values], ([v]) => check(m, m._hs_engine_set_settings(h, v, values.length)));
  }

  grow(g: GrowthParams): StrandArrays {
    const h = this.h();
    const m = this.mod;
    callWith(m, GROWTH_INPUT, g, (p) => m._hs_engine_grow(h, p));
    const strands: StrandArrays = {
      points: f32(m, m._hs_engine_strand_points(h), 3 * m._hs_engine_strand_point_count(h)),
      strandStart: u32(m, m._hs_engine_strand_start(h), m._hs_engine_strand_start_count(h)),
    };
    const n = strands.strandStart.length - 1;
    if (n > 0 && m._hs_engine_strand_root_id_count(h) === n)
      strands.rootIds = u32(m, m._hs_engine_strand_root_ids(h), n);
    if (n > 0 && m._hs_engine_strand_tail_curve_count(h) === n)
      strands.tailCurves = i32(m, m._hs_engine_strand_tail_curves(h), n);
    const ties = m._hs_engine_tie_frame_count(h);
    if (n > 0 && ties > 0) strands.tieFrames = f32(m, m._hs_engine_tie_frames(h), 8 * ties);
    if (n > 0 && m._hs_engine_strand_section_count(h) === n)
      strands.rootSections = u8(m, m._hs_engine_strand_sections(h), n);
    return strands;
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
    const h = this.h();
    const { residual: _, ...s } = toRawStats(
      callOut(this.mod, STATS_OUTPUT, (p) => this.mod._hs_engine_stats(h, p)),
    );
    return { ...s, module: moduleLabel(this.mod) };
  }

  /** Which module this engine runs on ("threads: 2", "single-threaded: …"). */
  moduleLabel(): string {
    return moduleLabel(this.mod);
  }

  /** Milliseconds of the last grow (roots + strands), measured in wasm. */
  growMs(): number {
    const h = this.h();
    return num(callOut(this.mod, STATS_OUTPUT, (p) => this.mod._hs_engine_stats(h, p)).growMs);
  }

  heapBytes(): number {
    return this.mod.HEAPU8.length;
  }

  /** What the last setScalp took, measured in wasm (benchmarks). */
  headStats(): HeadStats {
    const h = this.h();
    const m = this.mod;
    return withScratch(m, 40, (out) => {
      check(m, m._hs_engine_head_stats(h, out));
      const v = m.HEAPF64.slice(out >> 3, (out >> 3) + 5);
      return {
        samplerMs: v[0],
        distanceMs: v[1],
        headBytes: v[2],
        distanceCells: v[3],
        inUseBytes: v[4],
      };
    });
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

/** What the last setScalp took (HairEngine::HeadStats). */
export interface HeadStats {
  samplerMs: number; // building the root sampler (mesh copy, bins)
  distanceMs: number; // building the head's distance grid
  headBytes: number; // what the head keeps in wasm memory (sampler + distance grid)
  distanceCells: number;
  inUseBytes: number; // bytes malloc has handed out in the module (its whole state)
}

/** The wasm module's primitive calls with extras beyond EngineCore (timings, root count). */
export type WasmEngineCore = EngineCore & {
  setScalpMask(scalp: Uint8Array): void;
  headStats(): HeadStats;
  growMs(): number;
  rootCount(): number;
  scalpAvoidance(opts?: ScalpAvoidanceOptions): ScalpAvoidanceResult;
  constraintColours(): Uint8Array;
  moduleLabel(): string;
};

/** Options of scalp avoidance (method S4.7). */
export interface ScalpAvoidanceOptions {
  band?: number; // grid steps from the scalp (default 1.5)
  magnitude?: number; // target length (default 0.3)
  wholeHead?: boolean; // measure against every head triangle, not only the scalp (default false)
  insideToo?: boolean; // also grid points inside the head within the band (default false)
  minField?: number; // no constraint where the field is shorter than this (default 0)
}

/** index[e] = grid point, target[3 * e + axis]: ready for CurveSet.extraIndex / extraTarget. */
export interface ScalpAvoidanceResult {
  index: Int32Array;
  target: Float64Array;
}

/** Loads a fresh wasm module and returns its primitive calls (binding tests, benchmarks that
 *  time one call). */
export async function loadWasmEngine(opts: LoadOptions = {}): Promise<WasmEngineCore> {
  return new WasmEngine(await instantiate(opts));
}

/** Loads a fresh wasm module and returns an engine that runs requests on it. */
export async function loadSolverEngine(opts: LoadOptions = {}): Promise<SolverEngine> {
  return engineOver(await loadWasmEngine(opts));
}
