// The one place that turns a request into the engine's primitive calls, in their order: the
// head and grid where they changed, the job's detail, settings and curves, the iterations
// (solveRecipe.ts), growth. The worker, `hairsketch grow`, the exports and the tests all run
// requests through it, so they all grow the same hair from the same request.
import { structuredKey } from '../model/curveSet';
import { sameGrid } from '../model/grid';
import type { GrowthParams } from '../model/growthParams';
import { ConstraintColour } from '../model/hairArrays';
import { engineSettings } from '../model/sessionSchema';
import {
  type Groom,
  type IterateProgress,
  type RunPlan,
  type RunStep,
  type SolverEngine,
  SolverError,
} from './engine';
import type { EngineCore } from './engineCore';
import type { HairJob, HairRequest, HairSetup } from './hairRequest';
import { convergeField, solveFraction } from './solveRecipe';

/** The growth of a light result (a preview, a first look): the job's growth capped at
 *  `lightMaxStrands` (0 or less: no cap of its own; maxStrands 0 means no cap, as in
 *  GrowthParams). */
export function lightGrowth(growth: GrowthParams, lightMaxStrands: number): GrowthParams {
  const cap = lightMaxStrands > 0 ? Math.round(lightMaxStrands) : 0;
  if (cap === 0) return growth;
  return { ...growth, maxStrands: growth.maxStrands > 0 ? Math.min(growth.maxStrands, cap) : cap };
}

/** Whether a light growth grows fewer strands than the full growth may. */
function lightened(growth: GrowthParams, lightMaxStrands: number): boolean {
  const light = lightGrowth(growth, lightMaxStrands).maxStrands;
  return light > 0 && (growth.maxStrands <= 0 || light < growth.maxStrands);
}

/** What a job's field depends on: its curves (every field of the set) and its settings (natural
 *  fall's prior, scalp avoidance, sections); growth and detail are not part of it. */
function fieldKey(job: HairJob): string {
  return structuredKey({ curves: job.curves, settings: engineSettings(job.options) });
}

const sameBytes = (a: Uint8Array, b: Uint8Array): boolean =>
  a.length === b.length && a.every((v, i) => v === b[i]);

/** A SolverEngine over the primitive calls of `core` (which it disposes of). */
export function engineOver(core: EngineCore): SolverEngine {
  return new RequestRunner(core);
}

class RequestRunner implements SolverEngine {
  /** The setup the core holds (null until one is set up, and after a set-up failed). */
  private held: HairSetup | null = null;
  /** The core's field is the converged full solve of the job of this key on the setup held:
   *  a request asking for the same field (a change of growth or detail alone) grows from it
   *  without solving again. Null once anything else touched the field. */
  private solved: { key: string; progress: IterateProgress } | null = null;
  /** The core has had curves: a 'once' run forgets their warm start. */
  private used = false;

  constructor(private readonly core: EngineCore) {}

  *run(request: HairRequest, plan: RunPlan): Generator<RunStep, void, void> {
    this.setUp(request);
    const job = request.job;
    if (!job) return;
    const core = this.core;
    const t0 = plan.now();
    yield { type: 'progress', phase: 'constraints', fraction: 0 };
    core.setDetail(job.options.detail);
    core.setSettings(engineSettings(job.options));
    const key = fieldKey(job);
    const kept = this.solved;
    if (plan.mode !== 'preview' && kept && kept.key === key) {
      // the same field as the last full solve (only growth or detail changed): grow from it
      yield* this.grow(job.growth, kept.progress, plan, true, true, t0);
      return;
    }
    this.solved = null;
    if (plan.mode === 'preview') {
      core.setCurves(job.curves);
      this.used = true;
      // one iteration a slice: when the pen lifts meanwhile, its full solve need not wait for
      // the rest of this preview, nor for its growth
      let p = core.iterate(1, plan.tolerance);
      for (let k = 1; ; k++) {
        yield { type: 'slice' };
        if (k >= plan.previewIterations || p.converged) break;
        p = core.iterate(1, plan.tolerance);
      }
      yield* this.grow(lightGrowth(job.growth, plan.lightMaxStrands), p, plan, false, false, t0);
      return;
    }
    let from: IterateProgress | undefined;
    if (plan.mode === 'full') {
      // the first look runs a few warm iterations and forgetWarmStart then rebuilds the
      // preconditioner from the penalties alone: its incremental update would be thrown away
      core.deferPreconditionerUpdate();
      core.setCurves(job.curves);
      this.used = true;
      yield { type: 'progress', phase: 'solve', fraction: 0.05 };
      const p = core.iterate(plan.firstLook, plan.tolerance);
      // A first look from the warm start (the last preview of nearly the same curves), grown
      // light so it reaches the screen fast. The final field is then solved from zero: it
      // depends on the request alone, so every mode grows bit-identical hair from it.
      if (!p.converged)
        yield* this.grow(lightGrowth(job.growth, plan.lightMaxStrands), p, plan, false, false, t0);
      from = p;
      if (core.forgetWarmStart()) {
        yield { type: 'slice' };
        from = undefined;
      }
    } else {
      const warm = this.used;
      core.setCurves(job.curves);
      this.used = true;
      if (warm) core.forgetWarmStart();
    }
    const steps = convergeField(core, job.curves, {
      tolerance: plan.tolerance,
      slice: plan.slice,
      avoidFor: job.options.avoidScalp ? job.growth : null,
      ...(from ? { from } : {}),
    });
    let step = steps.next();
    while (!step.done) {
      const { progress, stage } = step.value;
      const fraction =
        stage === 'avoidance' ? 0.95 : solveFraction(progress.errorEstimate, plan.tolerance);
      yield {
        type: 'progress',
        phase: 'solve',
        fraction: Math.min(0.95, Math.max(0.05, fraction)),
        solve: progress,
      };
      yield { type: 'slice' };
      step = steps.next();
    }
    const p = step.value;
    this.solved = { key, progress: p };
    if (
      plan.mode === 'full' &&
      plan.convergedSample &&
      lightened(job.growth, plan.lightMaxStrands)
    ) {
      yield* this.grow(lightGrowth(job.growth, plan.lightMaxStrands), p, plan, false, true, t0);
      yield { type: 'slice' };
    }
    yield* this.grow(job.growth, p, plan, true, true, t0);
  }

  /** Sets up the request's head and grid where they differ from what the core holds. */
  private setUp(r: HairSetup): void {
    const core = this.core;
    const held = this.held;
    const gridMoved =
      !held || held.omega !== r.omega || held.solver !== r.solver || !sameGrid(held.grid, r.grid);
    const headMoved =
      !held ||
      held.head.positions !== r.head.positions ||
      held.head.indices !== r.head.indices ||
      held.head.center.some((v, i) => v !== r.head.center[i]);
    const bodyMoved = !held || held.head.body !== r.head.body;
    const maskMoved = !held || !sameBytes(held.head.scalp, r.head.scalp);
    if (!gridMoved && !headMoved && !bodyMoved && !maskMoved) return;
    this.solved = null;
    this.held = null; // until every part is set up: a failure leaves nothing assumed
    try {
      if (gridMoved) core.setGrid(r.grid, r.omega, r.solver);
      if (headMoved) core.setScalp(r.head);
      else if (maskMoved) core.setScalpMask(r.head.scalp);
      if (headMoved || bodyMoved) core.setBody(r.head.body ?? null);
    } catch (e) {
      if (held && !gridMoved && !headMoved && !bodyMoved) {
        // a refused scalp mask: the engine keeps the old one (setScalpMask's contract)
        this.held = held;
      }
      throw e;
    }
    // the mask is kept as a copy: a caller may change its array in place for the next request
    this.held = {
      grid: r.grid,
      omega: r.omega,
      solver: r.solver,
      head: { ...r.head, scalp: r.head.scalp.slice() },
    };
  }

  /** Grows `growth` in the field as it stands and yields it as hair. */
  private *grow(
    growth: GrowthParams,
    p: IterateProgress,
    plan: RunPlan,
    final: boolean,
    converged: boolean,
    t0: number,
  ): Generator<RunStep, void, void> {
    yield { type: 'progress', phase: 'grow', fraction: 0.95 };
    const core = this.core;
    const g0 = plan.now();
    const strands = core.grow(growth);
    const growMs = plan.now() - g0;
    const groom: Groom = {
      strands,
      constraints: this.constraintsWithColours(),
      field: plan.wantField ? core.field() : null,
      stats: {
        ...core.stats(),
        iterations: p.iterations,
        errorEstimate: p.converged ? Math.min(p.errorEstimate, plan.tolerance) : p.errorEstimate,
        solveMs: g0 - t0,
        growMs,
        heapBytes: core.heapBytes(),
      },
    };
    yield { type: 'hair', groom, final, converged };
  }

  /** The core's constraints with their display colours (4, "extra", where a colour is missing,
   *  so the arrays always have the same length). */
  private constraintsWithColours(): Groom['constraints'] {
    const c = this.core.constraints();
    let colour = this.core.constraintColours();
    if (colour.length !== c.index.length) {
      const fixed = new Uint8Array(c.index.length).fill(ConstraintColour.extra);
      fixed.set(colour.subarray(0, Math.min(colour.length, fixed.length)));
      colour = fixed;
    }
    return { ...c, colour };
  }

  startMotion(...args: Parameters<EngineCore['startMotion']>) {
    if (!this.held) throw new SolverError('no head is set up for the motion', 'not_ready');
    return this.core.startMotion(...args);
  }

  heapBytes(): number {
    return this.core.heapBytes();
  }

  dispose(): void {
    this.held = null;
    this.solved = null;
    this.core.dispose();
  }
}

/** What growGroom reports of a request grown in one go. */
export interface GrowOptions {
  /** Progress of each phase, 0..1, never falling (solve: digits of the error estimate gained). */
  onProgress?: (phase: 'solve' | 'grow', fraction: number) => void;
  /** A solve that has not converged after this many iterations is reported as an error. */
  maxIterations?: number;
  tolerance?: number;
  slice?: number;
}

/** Estimated relative field error at which the field counts as converged (as the app). */
export const GROW_TOLERANCE = 1e-6;

/** The plan of a request run in one go (`hairsketch grow`, the exports, tests). */
export function oncePlan(tolerance = GROW_TOLERANCE, slice = 4): RunPlan {
  return {
    mode: 'once',
    tolerance,
    slice,
    firstLook: 0,
    previewIterations: 0,
    lightMaxStrands: 0,
    convergedSample: false,
    wantField: false,
    now: () => (typeof performance !== 'undefined' ? performance.now() : Date.now()),
  };
}

/** Runs `request` on `engine` in one go and returns its final groom. */
export function growGroom(engine: SolverEngine, request: HairRequest, o: GrowOptions = {}): Groom {
  const tolerance = o.tolerance ?? GROW_TOLERANCE;
  if (!(tolerance > 0 && tolerance < 1))
    throw new SolverError(`tolerance must be in (0, 1), got ${tolerance}`, 'invalid_input');
  const maxIterations = o.maxIterations ?? 20_000;
  const report = o.onProgress ?? (() => {});
  let fraction = 0; // reported fractions never fall back (the error estimate is not monotonic)
  let groom: Groom | null = null;
  report('solve', 0);
  for (const step of engine.run(request, oncePlan(tolerance, o.slice))) {
    if (step.type === 'progress' && step.solve) {
      const p = step.solve;
      if (p.iterations >= maxIterations || !Number.isFinite(p.errorEstimate))
        throw new SolverError(
          `the field did not converge (${p.iterations} iterations, estimated error ${p.errorEstimate})`,
          'internal',
        );
      fraction = Math.max(fraction, Math.min(0.99, solveFraction(p.errorEstimate, tolerance)));
      report('solve', fraction);
    } else if (step.type === 'progress' && step.phase === 'grow') {
      report('solve', 1);
      report('grow', 0);
    } else if (step.type === 'hair' && step.final) groom = step.groom;
  }
  if (!groom) throw new SolverError('the request has no job to grow', 'invalid_input');
  report('grow', 1);
  return groom;
}
