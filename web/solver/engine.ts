// The solver engine as its consumers see it: a HairRequest in (hairRequest.ts), a groom out.
// requestRunner.ts implements it over the primitive calls of engineCore.ts, which wasmEngine.ts
// binds to the wasm module; the same object runs in the browser worker and under Node.

import type { GuideBinding } from '../model/guideFollowers';
import type { ConstraintArrays, FieldArrays, StrandArrays } from '../model/hairArrays';
import type { MotionFrame, MotionName, WindSettings } from '../model/motion';
import type { HairRequest } from './hairRequest';
import type { SolverErrorKind, SolveStats } from './protocol';

/** A groom in motion over an engine's head (SolverEngine.startMotion; wasmMotion.ts). */
export interface MotionRun {
  /** The guides and how the strands are bound to them (fixed for the run). */
  readonly binding: GuideBinding;
  /** Frame 0 (the guides at rest) before the first step, then one frame per call; the guides'
   *  points are written into `into` when it has their length (else a new array). */
  step(into?: Float32Array): MotionFrame;
  /** Advances like step without reading the frame (frames skipped when catching up). */
  advance(): void;
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

/** What consumers of the engine see: a request in, a groom out (requestRunner.ts implements it
 *  over the primitive calls of engineCore.ts). The worker steps run() a slice at a time between
 *  messages; `hairsketch grow`, the exports and the tests drive it in one go (growGroom). */
export interface SolverEngine {
  /** Runs a request: sets up its head and grid where they differ from the last request's, then
   *  solves its job's field and grows its hair as `plan` says, yielding progress, slice
   *  boundaries (where a driver may pause, or stop by not resuming) and hair (light results, then
   *  the final groom). Without a job it only sets up. Throws SolverError on bad input. */
  run(request: HairRequest, plan: RunPlan): Generator<RunStep, void, void>;
  /** A groom in motion over the head (and body) of the last request run (wasmMotion.ts). */
  startMotion(strands: StrandArrays, opts: MotionOptions): MotionRun;
  /** Bytes of the wasm heap (memory grows, never shrinks). */
  heapBytes(): number;
  dispose(): void;
}

/** How a request's job is run.
 *  'preview': a few iterations from the warm start and one light growth (live feedback while a
 *             stroke is drawn);
 *  'full':    a first look after a few warm iterations (light), then the field solved from zero
 *             to convergence (solveRecipe.ts), a light growth of the converged field when it
 *             saves strands, then the final hair (the app's worker);
 *  'once':    the field solved to convergence and the final hair only (a fresh engine: the
 *             command line, the exports, tests). Every mode grows bit-identical final hair. */
export interface RunPlan {
  mode: 'preview' | 'full' | 'once';
  /** Estimated relative field error at which the field counts as converged. */
  tolerance: number;
  /** Iterations per slice of the converging solve. */
  slice: number;
  /** Iterations of a full run's first look. */
  firstLook: number;
  /** Iterations of a preview (one per slice). */
  previewIterations: number;
  /** Strand cap of light growths (previews, first looks); 0 = none of its own. */
  lightMaxStrands: number;
  /** A full run posts the converged field's light growth before the full hair. */
  convergedSample: boolean;
  /** Results carry the solved field. */
  wantField: boolean;
  now: () => number;
}

/** A step of a run: progress to report; the end of a slice of work (a driver may pause here, or
 *  stop); hair grown (light: final false; the final groom: final true, the run's last step). */
export type RunStep =
  | {
      type: 'progress';
      phase: 'constraints' | 'solve' | 'grow';
      fraction: number;
      /** The solve's progress when phase is 'solve'. */
      solve?: IterateProgress;
    }
  | { type: 'slice' }
  | { type: 'hair'; groom: Groom; final: boolean; converged: boolean };

/** Hair grown by a run, with what the views and the status show of how it was solved. */
export interface Groom {
  strands: StrandArrays;
  constraints: ConstraintArrays;
  field: FieldArrays | null;
  stats: SolveStats;
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
