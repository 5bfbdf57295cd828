// One request, one groom: what the engine grows hair from, built from a session and a head in one
// place. The app's worker, the export worker, `hairsketch grow`, the embed and the tests all hand
// the engine a HairRequest (SolverEngine.run); nothing else sets up the engine.
import { packCurves, packHairOptions } from '../model/curveSet';
import { FIELD_OMEGA } from '../model/grid';
import type { GrowthParams } from '../model/growthParams';
import type { CurveSet, GridSpec, HairOptions, ScalpMesh } from '../model/hairArrays';
import type { SessionState, StyleCurve } from '../model/session';
import type { SolverName } from './protocol';

/** The session's part of a request: its curves (packed), its settings and detail, its growth. */
export interface HairJob {
  curves: CurveSet;
  options: HairOptions;
  growth: GrowthParams;
}

/** The head and grid a job runs over: the grid with its penalty weight and solver, the head's
 *  triangles, its scalp flags and its body (ScalpMesh.body). The engine sets up only what differs
 *  from the last request it ran (a new grid in place, a new scalp mask without rebuilding the
 *  head), so the incremental factorisation survives across requests. */
export interface HairSetup {
  grid: GridSpec;
  omega: number;
  solver: SolverName;
  head: ScalpMesh;
}

/** A whole request. Without a job it only sets up the head and grid (the worker's 'init'). */
export interface HairRequest extends HairSetup {
  job?: HairJob;
}

/** The job of a session's curves (the session's own unless given: a preview adds its draft),
 *  its settings and its growth (the session's unless given: a light growth). */
export function jobOf(
  session: SessionState,
  curves: readonly StyleCurve[] = session.curves,
  growth: GrowthParams = session.growth,
): HairJob {
  return {
    curves: packCurves(curves, null, !!session.fall),
    options: packHairOptions(session, curves),
    growth,
  };
}

/** The request that grows `session`'s full hair on `head` over `grid` with `solver` (the app's
 *  penalty weight, FIELD_OMEGA); `maxStrands` replaces the session's strand cap when given
 *  (0 = no cap). */
export function requestOf(
  session: SessionState,
  head: ScalpMesh,
  o: { grid: GridSpec; solver: SolverName; maxStrands?: number },
): HairRequest {
  const growth =
    o.maxStrands === undefined ? session.growth : { ...session.growth, maxStrands: o.maxStrands };
  return {
    grid: o.grid,
    omega: FIELD_OMEGA,
    solver: o.solver,
    head,
    job: jobOf(session, session.curves, growth),
  };
}
