// A session's full hair grown from scratch in one go: the browser's export worker, `hairsketch
// grow`, benchmarks and tests call it, so the same session, grid, solver and strand cap give the
// same strands (byte for byte) everywhere, and the same as the app's final hair: the session
// becomes a request (solver/hairRequest.ts requestOf) and the engine runs it
// (solver/requestRunner.ts growGroom: the solve recipe from a cold start, then growth).
import type { GridSpec, ScalpMesh, StrandArrays } from '../model/hairArrays';
import type { SessionState } from '../model/session';
import { type SolverEngine, SolverError } from '../solver/engine';
import { requestOf } from '../solver/hairRequest';
import type { SolverName } from '../solver/protocol';
import { GROW_TOLERANCE, type GrowOptions, growGroom } from '../solver/requestRunner';

export { GROW_TOLERANCE };

export interface GrowSessionOptions extends Pick<GrowOptions, 'onProgress' | 'tolerance'> {
  grid: GridSpec;
  solver: SolverName;
  /** Replaces session.growth.maxStrands when given; 0 = no cap. */
  maxStrands?: number;
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

/** Grows `session`'s full hair on `engine` (fresh, or used before: the run forgets the warm
 *  start of earlier requests, and grows from the field it holds when only growth or detail
 *  changed). The caller disposes of it. */
export function growSessionHair(
  engine: SolverEngine,
  session: SessionState,
  scalp: ScalpMesh,
  opts: GrowSessionOptions,
): GrownHair {
  const cap = opts.maxStrands;
  if (cap !== undefined && !(Number.isInteger(cap) && cap >= 0))
    throw new SolverError(`maxStrands must be an integer >= 0, got ${cap}`, 'invalid_input');
  const request = requestOf(session, scalp, {
    grid: opts.grid,
    solver: opts.solver,
    ...(cap !== undefined ? { maxStrands: cap } : {}),
  });
  const { strands, stats } = growGroom(engine, request, opts);
  return { strands, solveMs: stats.solveMs, growMs: stats.growMs, iterations: stats.iterations };
}
