// The one pipeline that grows a session's full hair from scratch: the browser's export worker and
// `hairsketch grow` both call it, so the same session, grid, solver and strand cap give the same
// strands (byte for byte) in both.
//
// It does what the app does for a full solve (app/solverBridge.ts, worker/workerLogic.ts): the
// grid with omega 100, the scalp, the session's curves and avoidance constraints, iterations from
// a cold start until the estimated field error is below the tolerance, then growth with the
// session's growth parameters (the strand cap replaced when the caller gives one).
import { packCurves, packHairOptions } from '../model/curveSet';
import { FIELD_OMEGA } from '../model/grid';
import type { GridSpec, ScalpMesh, StrandArrays } from '../model/hairArrays';
import type { SessionState } from '../model/session';
import { engineSettings } from '../model/sessionSchema';
import { avoidanceOptions } from '../solver/avoidance';
import { type SolverEngine, SolverError } from '../solver/engine';
import type { SolverName } from '../solver/protocol';

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
  const curves = packCurves(session.curves, null, !!session.fall);
  const options = packHairOptions(session, session.curves);
  engine.setDetail?.(options.detail);
  engine.setSettings?.(engineSettings(options));
  engine.setCurves(curves);
  let p = engine.iterate(SLICE_ITERATIONS, tolerance);
  let fraction = 0; // reported fractions never fall back (the error estimate is not monotonic)
  // With "Avoid scalp", the converged field gives the avoidance constraints and the field is
  // solved again with them from that field, as the worker does (workerLogic.ts).
  let avoided = !(options.avoidScalp && engine.scalpAvoidance);
  for (;;) {
    if (p.converged && !avoided && engine.scalpAvoidance) {
      const r = engine.scalpAvoidance(avoidanceOptions(session.growth));
      engine.setCurves({ ...curves, extraIndex: r.index, extraTarget: r.target });
      avoided = true;
      p = engine.iterate(SLICE_ITERATIONS, tolerance);
    }
    if (p.converged) break;
    if (p.iterations >= MAX_ITERATIONS || !Number.isFinite(p.errorEstimate))
      throw new SolverError(
        `the field did not converge (${p.iterations} iterations, estimated error ${p.errorEstimate})`,
        'internal',
      );
    // fraction: digits of the error estimate gained out of the tolerance's
    const digits = -Math.log10(Math.max(p.errorEstimate, tolerance));
    fraction = Math.max(fraction, Math.min(0.99, Math.max(0, digits / -Math.log10(tolerance))));
    report('solve', fraction);
    p = engine.iterate(SLICE_ITERATIONS, tolerance);
  }
  report('solve', 1);
  const t1 = now();

  report('grow', 0);
  const growth = cap === undefined ? session.growth : { ...session.growth, maxStrands: cap };
  const strands = engine.grow(growth);
  const t2 = now();
  report('grow', 1);
  return { strands, solveMs: t1 - t0, growMs: t2 - t1, iterations: p.iterations };
}
