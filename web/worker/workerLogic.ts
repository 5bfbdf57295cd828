// The worker's logic as plain functions over a SolverEngine, so the same code runs in the
// browser worker and under Node tests with the real wasm module.
//
// Scheduling (one job at a time, the newest request supersedes the running one):
//   preview job: a few iterations (one per slice), light growth, one non-final result (none
//                when a newer request came in meanwhile: the app no longer waits for it);
//   full job:    a first look after a few iterations (non-final, light growth), then iterate in slices,
//                yielding to the event loop between slices so a newer request can take over,
//                and grow the final hair when the field has converged (solver/solveRecipe.ts,
//                the recipe growSession.ts runs too: with "Avoid scalp" on, the converged field
//                gives the scalp-avoidance constraints (S4.7) and the field is solved again with
//                them, warm-started from that field). The converged field's hair is posted light first (its first strands, as
//                a first look is grown: what a slow GPU draws of the hair first), then in full.
// A 'scalpMask' message changes the scalp at once (no restart, nothing else rebuilt); a 'grid'
// message moves the engine to another grid in place (the head stays).
import { ResultLighting } from '../lighting/resultLighting';
import { structuredKey } from '../model/curveSet';
import type { GrowthParams } from '../model/growthParams';
import {
  type ConstraintArrays,
  ConstraintColour,
  type GridSpec,
  type ScalpMesh,
} from '../model/hairArrays';
import { engineSettings } from '../model/sessionSchema';
import { everyOtherPoint } from '../model/strandSubsample';
import {
  type IterateProgress,
  type MotionRun,
  type SolverEngine,
  SolverError,
} from '../solver/engine';
import type { FromWorker, SolverErrorKind, SolverName, ToWorker } from '../solver/protocol';
import { convergeField, solveFraction } from '../solver/solveRecipe';
import { lineAttributes } from '../viewer/strandAttributes';

export type Post = (msg: FromWorker) => void;
type SolveMsg = Extract<ToWorker, { type: 'solve' }>;
type Job = SolveMsg;
type MotionMsg = Extract<ToWorker, { type: 'motionStart' | 'motionStep' | 'motionStop' }>;

export interface SchedulerOptions {
  tolerance: number; // converged when the estimated relative field error is below this
  firstLookIterations: number;
  sliceIterations: number;
  previewIterations: number;
  /** Post the converged field's hair grown light (non-final, `converged`) before the full hair,
   *  when the light cap is below the session's strand count: it is on screen a full growth and
   *  lighting sooner. */
  convergedSample: boolean;
  /** Resolves after pending messages have had a chance to run. */
  yieldNow: () => Promise<void>;
  now: () => number;
}

export const DEFAULT_SCHEDULER: SchedulerOptions = {
  tolerance: 1e-6,
  firstLookIterations: 2,
  sliceIterations: 4,
  previewIterations: 2,
  convergedSample: true,
  yieldNow: () => new Promise((r) => setTimeout(r, 0)),
  now: () => (typeof performance !== 'undefined' ? performance.now() : Date.now()),
};

const errorMessage = (e: unknown): string => (e instanceof Error ? e.message : String(e));
const errorKind = (e: unknown): SolverErrorKind => (e instanceof SolverError ? e.kind : 'internal');

/** The growth of a light result (a preview, a first look): the job's growth capped at its
 *  lightMaxStrands (0 or less: no cap of its own; maxStrands 0 means no cap, as in GrowthParams). */
export function lightGrowth(job: SolveMsg): GrowthParams {
  const g = job.growth;
  const cap = job.lightMaxStrands > 0 ? Math.round(job.lightMaxStrands) : 0;
  if (cap === 0) return g;
  return { ...g, maxStrands: g.maxStrands > 0 ? Math.min(g.maxStrands, cap) : cap };
}

/** Whether a light growth of `job` grows fewer strands than its full growth may. */
function lightenedGrowth(job: SolveMsg): boolean {
  const light = lightGrowth(job).maxStrands;
  return light > 0 && (job.growth.maxStrands <= 0 || light < job.growth.maxStrands);
}

export class WorkerLogic {
  private initialised = false;
  /** The head from 'init': the hair's lighting is computed against it (resultLighting). */
  private head: ScalpMesh | null = null;
  /** The hair's lighting against that head, on a grid over it and the solver's grid. */
  private lighting: ResultLighting | null = null;
  private latest: SolveMsg | null = null;
  private running = false;
  /** The omega and solver of 'init' (a 'grid' message keeps them). */
  private setup: { omega: number; solver: SolverName } | null = null;
  /** Bumped by every grid change: a job started before it is dropped. */
  private gridEpoch = 0;
  private jobEpoch = 0;
  /** The field the engine holds is the converged full solve of the curves and settings of this
   *  key (fieldKey) on grid epoch `epoch`: a job asking for the same field (a change of growth or
   *  detail alone) grows from it without solving again. Null once anything else touched it. */
  private solved: { key: string; epoch: number; progress: IterateProgress } | null = null;

  constructor(
    readonly engine: SolverEngine,
    private readonly post: Post,
    private readonly opts: SchedulerOptions = DEFAULT_SCHEDULER,
  ) {}

  /** Handles one message; solve jobs run asynchronously. Returns when the job queue is empty. */
  handle(msg: ToWorker): Promise<void> {
    if (msg.type === 'init') {
      this.solved = null;
      try {
        this.engine.setGrid(msg.grid, msg.omega, msg.solver);
        this.setup = { omega: msg.omega, solver: msg.solver };
        this.engine.setScalp(msg.scalp);
        this.engine.setBody(msg.scalp.body ?? null);
        this.head = msg.scalp;
        this.lighting = new ResultLighting(msg.scalp, msg.grid);
        this.initialised = true;
        const n = msg.grid.dims[0] * msg.grid.dims[1] * msg.grid.dims[2];
        this.post({ type: 'ready', gridPoints: n, roots: 0 });
      } catch (e) {
        this.post({
          type: 'error',
          id: null,
          message: `Solver set-up failed: ${errorMessage(e)}`,
          kind: errorKind(e),
        });
      }
      return Promise.resolve();
    }
    if (msg.type === 'scalpMask') {
      this.setScalpMask(msg.scalp);
      return Promise.resolve();
    }
    if (msg.type === 'grid') {
      this.setGrid(msg.grid);
      return Promise.resolve();
    }
    if (msg.type === 'motionStart' || msg.type === 'motionStep' || msg.type === 'motionStop') {
      this.handleMotion(msg);
      return Promise.resolve();
    }
    if (!this.initialised) {
      this.post({
        type: 'error',
        id: msg.id,
        message: 'Solver is not initialised',
        kind: 'not_ready',
      });
      return Promise.resolve();
    }
    this.latest = msg;
    return this.running ? Promise.resolve() : this.run();
  }

  /** The motion playing (motionStart .. motionStop). */
  private motion: MotionRun | null = null;
  /** Frame arrays the page has drawn and given back (motionStep.recycle). */
  private motionSpare: Float32Array[] = [];

  private handleMotion(msg: MotionMsg): void {
    const fail = (message: string): void => {
      this.motion?.dispose();
      this.motion = null;
      this.post({ type: 'motionError', message });
    };
    try {
      if (msg.type === 'motionStop') {
        this.motion?.dispose();
        this.motion = null;
        this.motionSpare = [];
        return;
      }
      if (msg.type === 'motionStart') {
        this.motion?.dispose();
        this.motion = null;
        this.motionSpare = [];
        if (!this.initialised) fail('the solver is not initialised');
        else {
          this.motion = this.engine.startMotion(msg.strands, {
            motion: msg.motion,
            seed: msg.seed,
            body: msg.body,
            ...(msg.wind ? { wind: msg.wind } : {}),
          });
          this.post({ type: 'motionFrame', ...this.motion.step() });
        }
        return;
      }
      if (msg.recycle) this.motionSpare.push(...msg.recycle);
      if (!this.motion) return; // stopped meanwhile
      for (let k = 1; k < Math.max(1, Math.floor(msg.frames)); k++) this.motion.advance();
      // the points go into an array the page gave back (transferred both ways: no allocation
      // a frame once a few are in circulation)
      this.post({ type: 'motionFrame', ...this.motion.step(this.motionSpare.pop()) });
    } catch (e) {
      fail(errorMessage(e));
    }
  }

  /** A new scalp on the init head: the next growth samples its roots over it (a job running now
   *  grows its remaining results from it too; the app asks again after a scalp edit). The
   *  lighting head keeps its triangles. A refused mask is reported and the old one stays. */
  private setScalpMask(scalp: Uint8Array): void {
    this.solved = null; // which curve points lie off the scalp (and so the constraints) may change
    const fail = (message: string, kind: SolverErrorKind): void => {
      this.post({ type: 'error', id: null, message: `Scalp mask: ${message}`, kind });
    };
    if (!this.initialised || !this.head) fail('the solver is not initialised', 'not_ready');
    else
      try {
        this.engine.setScalpMask(scalp);
        this.head = { ...this.head, scalp };
      } catch (e) {
        fail(errorMessage(e), errorKind(e));
      }
  }

  /** Another grid for the same head: the engine is set up on it in place and the job running
   *  is dropped (its field was on the old grid). The hair's lighting keeps its head caches when
   *  its grid still holds the new one (ResultLighting.forGrid). */
  private setGrid(grid: GridSpec): void {
    this.gridEpoch++;
    this.solved = null;
    if (!this.initialised || !this.setup) {
      this.post({
        type: 'error',
        id: null,
        message: 'Grid: the solver is not initialised',
        kind: 'not_ready',
      });
      return;
    }
    try {
      this.engine.setGrid(grid, this.setup.omega, this.setup.solver);
      this.lighting = this.lighting?.forGrid(grid) ?? null;
    } catch (e) {
      this.post({
        type: 'error',
        id: null,
        message: `Grid ${grid.dims.join('×')}: ${errorMessage(e)}`,
        kind: errorKind(e),
      });
    }
  }

  private async run(): Promise<void> {
    this.running = true;
    try {
      // Let messages already waiting arrive first: of a burst, only the newest is solved.
      await this.opts.yieldNow();
      while (this.latest) {
        const job: Job = this.latest;
        this.latest = null;
        this.jobEpoch = this.gridEpoch;
        try {
          await this.runJob(job);
        } catch (e) {
          this.post({ type: 'error', id: job.id, message: errorMessage(e), kind: errorKind(e) });
        }
      }
    } finally {
      this.running = false;
    }
  }

  private superseded(): boolean {
    return this.latest !== null || this.jobEpoch !== this.gridEpoch;
  }

  private async runJob(job: SolveMsg): Promise<void> {
    const o = this.opts;
    const t0 = o.now();
    this.post({ type: 'progress', id: job.id, phase: 'constraints', fraction: 0 });
    this.engine.setDetail(job.options.detail);
    this.engine.setSettings(engineSettings(job.options));
    const key = fieldKey(job);
    const kept = this.solved;
    if (job.mode !== 'preview' && kept && kept.key === key && kept.epoch === this.jobEpoch) {
      // the same field as the last full solve (only growth or detail changed): grow from it
      this.emit(job, job.growth, kept.progress, true, t0);
      return;
    }
    this.solved = null;
    // a full solve's first look runs a few warm iterations and forgetWarmStart then rebuilds the
    // preconditioner from the penalties alone: its incremental update would be thrown away
    if (job.mode !== 'preview') this.engine.deferPreconditionerUpdate();
    this.engine.setCurves(job.curves);
    if (job.mode === 'preview') {
      // one iteration at a time: when the pen lifts meanwhile, its full solve need not wait
      // for the rest of this preview, nor for its growth
      let p = this.engine.iterate(1, o.tolerance);
      for (let k = 1; ; k++) {
        await o.yieldNow();
        if (this.superseded()) return;
        if (k >= o.previewIterations || p.converged) break;
        p = this.engine.iterate(1, o.tolerance);
      }
      this.emit(job, lightGrowth(job), p, false, t0);
      return;
    }
    this.post({ type: 'progress', id: job.id, phase: 'solve', fraction: 0.05 });
    let p = this.engine.iterate(o.firstLookIterations, o.tolerance);
    // A first look from the warm start (the last preview of nearly the same curves), grown light
    // so it reaches the screen fast. The final field is then solved from zero: it depends on the
    // session alone, so a share link, an export or the command line grow bit-identical hair.
    if (!p.converged) this.emit(job, lightGrowth(job), p, false, t0);
    // then the recipe growSession.ts runs too (solver/solveRecipe.ts), a slice between messages
    let from: IterateProgress | undefined = p;
    if (this.engine.forgetWarmStart()) {
      await o.yieldNow();
      if (this.superseded()) return;
      from = undefined;
    }
    const steps = convergeField(this.engine, job.curves, {
      tolerance: o.tolerance,
      slice: o.sliceIterations,
      avoidFor: job.options.avoidScalp ? job.growth : null,
      from,
    });
    let step = steps.next();
    while (!step.done) {
      const { progress, stage } = step.value;
      const fraction =
        stage === 'avoidance' ? 0.95 : solveFraction(progress.errorEstimate, o.tolerance);
      this.post({
        type: 'progress',
        id: job.id,
        phase: 'solve',
        fraction: Math.min(0.95, Math.max(0.05, fraction)),
      });
      await o.yieldNow();
      if (this.superseded()) return;
      step = steps.next();
    }
    p = step.value;
    this.solved = { key, epoch: this.jobEpoch, progress: p };
    if (o.convergedSample && lightenedGrowth(job)) {
      this.emit(job, lightGrowth(job), p, false, t0, true);
      await o.yieldNow();
      if (this.superseded()) return;
    }
    this.emit(job, job.growth, p, true, t0);
  }

  /** The engine's constraints with their display colours (4, "extra", where a colour is missing,
   *  so the arrays always have the same length). */
  private constraintsWithColours(): ConstraintArrays {
    const c = this.engine.constraints();
    let colour = this.engine.constraintColours();
    if (colour.length !== c.index.length) {
      const fixed = new Uint8Array(c.index.length).fill(ConstraintColour.extra);
      fixed.set(colour.subarray(0, Math.min(colour.length, fixed.length)));
      colour = fixed;
    }
    return { ...c, colour };
  }

  private emit(
    job: SolveMsg,
    growth: GrowthParams,
    p: IterateProgress,
    final: boolean,
    t0: number,
    converged = final,
  ): void {
    this.post({ type: 'progress', id: job.id, phase: 'grow', fraction: 0.95 });
    const g0 = this.opts.now();
    const grown = this.engine.grow(growth);
    // a stroke's preview is drawn and lit with every other point: half the work on both sides
    const strands = job.mode === 'preview' ? everyOtherPoint(grown) : grown;
    const growMs = this.opts.now() - g0;
    const stats = {
      ...this.engine.stats(),
      iterations: p.iterations,
      errorEstimate: p.converged ? Math.min(p.errorEstimate, this.opts.tolerance) : p.errorEstimate,
      solveMs: g0 - t0,
      growMs,
      heapBytes: this.engine.heapBytes(),
    };
    const lighting = this.lighting?.of(strands, this.opts.now, final) ?? null;
    this.post({
      type: 'result',
      id: job.id,
      strands,
      constraints: this.constraintsWithColours(),
      field: job.wantField ? this.engine.field() : null,
      lighting,
      // the full hair's vertex attributes are built here, not on the page (it would stall there
      // for ~60 ms at 30K strands); lighter hair is quicker to build there than to send
      attributes: final
        ? lineAttributes(strands.points, strands.strandStart, 0, lighting?.strand ?? null)
        : null,
      stats,
      final,
      converged,
    });
  }
}

/** What a job's field depends on: its curves (every field of the set) and its settings (natural
 *  fall's prior, scalp avoidance, sections); growth and detail are not part of it. */
function fieldKey(job: SolveMsg): string {
  return structuredKey({ curves: job.curves, settings: engineSettings(job.options) });
}
