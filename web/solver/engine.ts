// The solver engine as the worker sees it: one stateful object over the wasm module.
// Implemented by wasmEngine.ts; the same object runs in the browser worker and under Node.

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
import type { MotionFrame, MotionName, WindSettings } from '../model/motion';
import type { SolverErrorKind, SolverName, SolveStats } from './protocol';

/** A groom in motion over an engine's head (SolverEngine.startMotion; wasmMotion.ts). */
export interface MotionRun {
  /** Frame 0 (the groom as given) before the first step, then one frame per call; the points
   *  are written into `into` when it has their length (else a new array). */
  step(into?: Float32Array): MotionFrame;
  /** Advances like step without reading the frame (frames skipped when catching up). */
  advance(): void;
  readonly guides: number;
  dispose(): void;
}

export interface MotionOptions {
  motion: MotionName;
  seed: number;
  /** The Wind motion's wind (model/motion.ts DEFAULT_WIND when absent). */
  wind?: WindSettings;
  /** Collide with the engine's body (the session's bust is on). */
  body: boolean;
  maxGuides?: number;
}

export interface SolverEngine {
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

export interface IterateProgress {
  iterations: number; // since the last setCurves
  errorEstimate: number; // estimated relative error of the current iterate
  converged: boolean;
}

/** A failed solver call: `kind` says what went wrong (protocol.ts SolverErrorKind), the message
 *  says it in words. */
export class SolverError extends Error {
  constructor(
    message: string,
    readonly kind: SolverErrorKind = 'internal',
  ) {
    super(message);
    this.name = 'SolverError';
  }
}
