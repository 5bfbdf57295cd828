// The one recipe for solving a request's field to convergence, run by requestRunner.ts for every
// full solve: the worker drives it a slice at a time between other messages, `hairsketch grow`
// and the exports in one go (growGroom): the same iterations in the same slices, so all grow
// bit-identical hair.
import type { GrowthParams } from '../model/growthParams';
import type { CurveSet } from '../model/hairArrays';
import type { IterateProgress } from './engine';
import type { EngineCore } from './engineCore';

/** Scalp avoidance as the app applies it (S4.7): grid points within 1.5 grid steps of the scalp
 *  (inside it too: growth interpolates them just outside), turned along the surface where they
 *  point inwards; the target keeps the field's length up to 0.3 (never longer: avoidance turns
 *  hair, it does not make hair where the curves asked for none), and grid points where the
 *  field is weaker than the growth threshold get none. Only the scalp is measured against,
 *  so no hair is pulled down over the face. */
export function avoidanceOptions(growth: GrowthParams) {
  return {
    band: 1.5,
    magnitude: 0.3,
    wholeHead: false,
    insideToo: true,
    minField: growth.minMagnitude,
  };
}

export interface ConvergeOptions {
  /** Estimated relative field error at which the field counts as converged. */
  tolerance: number;
  /** Iterations per step. */
  slice: number;
  /** "Avoid scalp" on: the growth whose threshold the avoidance constraints use. */
  avoidFor: GrowthParams | null;
  /** The progress of iterations already run on these curves (the step is then not run first). */
  from?: IterateProgress;
}

/** One step of the recipe: where it stands after a slice of iterations. `stage`: solving the
 *  curves, or solving again with the scalp-avoidance constraints. */
export interface ConvergeStep {
  progress: IterateProgress;
  stage: 'curves' | 'avoidance';
}

/** Solves the field of the curves the engine holds (`curves`, set by the caller) to convergence,
 *  a slice of iterations per step; with "Avoid scalp", the converged field gives the avoidance
 *  constraints (S4.7) and the field is solved again with them, warm-started from it. Yields
 *  after every slice that did not converge, and once between the two solves; returns the
 *  converged progress. The driver may stop early by not resuming it. */
export function* convergeField(
  engine: EngineCore,
  curves: CurveSet,
  o: ConvergeOptions,
): Generator<ConvergeStep, IterateProgress> {
  let p = o.from ?? engine.iterate(o.slice, o.tolerance);
  while (!p.converged) {
    yield { progress: p, stage: 'curves' };
    p = engine.iterate(o.slice, o.tolerance);
  }
  if (o.avoidFor) {
    yield { progress: p, stage: 'avoidance' };
    const r = engine.scalpAvoidance(avoidanceOptions(o.avoidFor));
    // warm-started from the curves' converged field, which depends on the session alone (it was
    // solved from zero): the second solve stays history-free and needs few iterations
    engine.setCurves({ ...curves, extraIndex: r.index, extraTarget: r.target });
    p = engine.iterate(o.slice, o.tolerance);
    while (!p.converged) {
      yield { progress: p, stage: 'avoidance' };
      p = engine.iterate(o.slice, o.tolerance);
    }
  }
  return p;
}

/** How far a solve is, 0..1: the digits of the error estimate gained out of the tolerance's. */
export function solveFraction(errorEstimate: number, tolerance: number): number {
  const digits = Math.log10(Math.max(errorEstimate, tolerance)) / Math.log10(tolerance);
  return Number.isFinite(digits) ? Math.min(1, Math.max(0, digits)) : 0;
}
