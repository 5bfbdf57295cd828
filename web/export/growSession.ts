// The one pipeline that grows a session's full hair from scratch: the browser's export worker and
// `hairsketch grow` both call it, so the same session, grid, solver and strand cap give the same
// strands (byte for byte) in both.
//
// It does what the app does for a full solve (app/solverBridge.ts, worker/workerLogic.ts): the
// grid with omega 100, the scalp, the session's curves, then the worker's own recipe from a cold
// start (solver/solveRecipe.ts convergeField: iterations until the estimated field error is below
// the tolerance, then with the avoidance constraints), then growth with the session's growth
// parameters (the strand cap replaced when the caller gives one).
import { packCurves, packHairOptions } from '../model/curveSet';
import { FIELD_OMEGA } from '../model/grid';
import type { GridSpec, ScalpMesh, StrandArrays } from '../model/hairArrays';
import type { SessionState } from '../model/session';
import { engineSettings } from '../model/sessionSchema';
import { type SolverEngine, SolverError } from '../solver/engine';
import type { SolverName } from '../solver/protocol';
import { convergeField, solveFraction } from '../solver/solveRecipe';

/** Estimated relative field error at which the field counts as converged (as the app). */
export const GROW_TOLERANCE = 1e-6;
/** Iterations per slice between progress reports. */
const SLICE_ITERATIONS = 4;
/** A solve that has not converged after this many iterations is reported as an error. */
const MAX_ITERATIONS = 20_000;

export interface GrowSessionOptions {
  grid: GridSpec;
  solver: SolverName;
  /** Replaces session.growth.maxStrands when given; 0 = no cap. */
  maxStrands?: number;
  /** Estimated relative field error to iterate to (default 1e-6, as the app). */
  tolerance?: number;
  /** Progress of each phase, 0..1, never falling (solve: digits of the error estimate gained). */
  onProgress?: (phase: 'solve' | 'grow', fraction: number) => void;
}

export interface GrownHair {
  /** Every strand grown (strands of fewer than 2 points included, as the engine returns them). */
  strands: StrandArrays;
  /** Milliseconds of grid set-up, constraints and iterations. */
  solveMs: number;
  /** Milliseconds of root sampling and growth. */
  growMs: number;
  /** Solver iterations from the cold start to convergence. */
  iterations: number;
}

const now = (): number => (typeof performance !== 'undefined' ? performance.now() : Date.now());

/** Grows `session`'s full hair on `engine`, which must be fresh (loadSolverEngine: no grid,
 *  scalp or curves yet, so nothing warm-starts the solve). The caller disposes of it. */
export function growSessionHair(
  engine: SolverEngine,
  session: SessionState,
  scalp: ScalpMesh,
  opts: GrowSessionOptions,
): GrownHair {
  const tolerance = opts.tolerance ?? GROW_TOLERANCE;
  if (!(tolerance > 0 && tolerance < 1))
    throw new SolverError(`tolerance must be in (0, 1), got ${tolerance}`, 'invalid_input');
  const cap = opts.maxStrands;
  if (cap !== undefined && !(Number.isInteger(cap) && cap >= 0))
    throw new SolverError(`maxStrands must be an integer >= 0, got ${cap}`, 'invalid_input');
  const report = opts.onProgress ?? (() => {});

  const t0 = now();
  report('solve', 0);
  engine.setGrid(opts.grid, FIELD_OMEGA, opts.solver);
  engine.setScalp(scalp);
  engine.setBody(scalp.body ?? null);
  const curves = packCurves(session.curves, null, !!session.fall);
  const options = packHairOptions(session, session.curves);
  engine.setDetail(options.detail);
  engine.setSettings(engineSettings(options));
  engine.setCurves(curves);
  // the worker's recipe (solver/solveRecipe.ts), driven in one go
  const steps = convergeField(engine, curves, {
    tolerance,
    slice: SLICE_ITERATIONS,
    avoidFor: options.avoidScalp ? session.growth : null,
  });
  let fraction = 0; // reported fractions never fall back (the error estimate is not monotonic)
  let step = steps.next();
  while (!step.done) {
    const p = step.value.progress;
    if (p.iterations >= MAX_ITERATIONS || !Number.isFinite(p.errorEstimate))
      throw new SolverError(
        `the field did not converge (${p.iterations} iterations, estimated error ${p.errorEstimate})`,
        'internal',
      );
    fraction = Math.max(fraction, Math.min(0.99, solveFraction(p.errorEstimate, tolerance)));
    report('solve', fraction);
    step = steps.next();
  }
  const p = step.value;
  report('solve', 1);
  const t1 = now();

  report('grow', 0);
  const growth = cap === undefined ? session.growth : { ...session.growth, maxStrands: cap };
  const strands = engine.grow(growth);
  const t2 = now();
  report('grow', 1);
  return { strands, solveMs: t1 - t0, growMs: t2 - t1, iterations: p.iterations };
}
