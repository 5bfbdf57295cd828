// The engine's primitive calls, one per binding call of the wasm module (wasmEngine.ts implements
// them over wasm-build/binding.cpp, mirroring solver-cpp's HairEngine). They are stateful and
// their order matters; the only code that calls them in order is the request runner
// (requestRunner.ts), which turns a HairRequest into them. Binding tests and benchmarks that
// time one call use them directly.
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
import type { IterateProgress, MotionOptions, MotionRun } from './engine';
import type { SolverName, SolveStats } from './protocol';

export interface EngineCore {
  /** Analyse the grid and create the solver. Throws SolverError on bad input. */
  setGrid(grid: GridSpec, omega: number, solver: SolverName): void;
  /** Store the head: its triangles for root sampling and its distance grid. */
  setScalp(mesh: ScalpMesh): void;
  /** A new scalp mask for the head of setScalp (scalp[triangle] = 1 on the scalp, one flag per
   *  triangle): the next grow samples roots over it; nothing else is rebuilt. Throws SolverError
   *  (the old mask stays) on a wrong length. */
  setScalpMask(scalp: Uint8Array): void;
  /** The body under the head (a bust: neck, shoulders, chest, back), a closed triangle mesh
   *  apart from the head's (3 numbers per vertex, 3 indices per triangle, counter-clockwise =
   *  outward): with the session's bust setting on, hair slides over it and is kept out of it.
   *  null clears it. Takes effect at the next grow. Throws SolverError on non-finite positions,
   *  an index out of range or over the memory cap (the engine is then left without a body). */
  setBody(body: { positions: Float32Array; indices: Uint32Array } | null): void;
  /** Detail applied by grow (curl, clump, frizz, length jitter). */
  setDetail(detail: DetailArrays): void;
  /** The session's settings for the curves of the next setCurves, as
   *  sessionSchema.ts engineSettings packs them (solver-cpp/src/engine_settings.hpp reads them:
   *  natural fall, for one). */
  setSettings(values: Float64Array): void;
  /** Derive constraints from the curves and hand them to the solver (diffed in C++). */
  setCurves(curves: CurveSet): void;
  /** Solve the field for the current constraints. */
  solve(): void;
  /** Progressive solve: at most `maxIterations` more iterations, stopping once the estimated
   *  relative error is <= tolerance. Direct solvers solve fully and report converged. The
   *  field (and grow) then use the current iterate. */
  iterate(maxIterations: number, tolerance: number): IterateProgress;
  /** The next iterate() starts from zero instead of the previous field, so the converged field
   *  depends on the curves alone (the same session gives bit-identical hair whatever was drawn
   *  before: share links, exports). False when there is nothing to forget (a direct solver). */
  forgetWarmStart(): boolean;
  /** The next setCurves may leave the preconditioner's costliest update undone (the fast
   *  solver's coarsest factor), for a first look of a few iterations that forgetWarmStart
   *  follows: that reset would throw the update away (a direct solver: nothing to defer). */
  deferPreconditionerUpdate(): void;
  /** Sample roots (S5.1) and grow strands (S5.2) in the current field. Returns copies. */
  grow(params: GrowthParams): StrandArrays;
  /** The current constraints (sorted by grid index); their colours come from constraintColours. */
  constraints(): Omit<ConstraintArrays, 'colour'>;
  /** Display colour of each constraint of constraints(), same order (ConstraintColour values). */
  constraintColours(): Uint8Array;
  field(): FieldArrays;
  stats(): Omit<SolveStats, 'growMs' | 'errorEstimate' | 'heapBytes'>;
  /** Scalp-avoidance constraints (S4.7) from the current field. */
  scalpAvoidance(opts: {
    band?: number;
    magnitude?: number;
    wholeHead?: boolean;
    insideToo?: boolean;
    minField?: number;
  }): {
    index: Int32Array;
    target: Float64Array;
  };
  /** A groom in motion over this engine's head (and body): wasmMotion.ts. */
  startMotion(strands: StrandArrays, opts: MotionOptions): MotionRun;
  /** Bytes of the wasm heap (memory grows, never shrinks). */
  heapBytes(): number;
  dispose(): void;
}
