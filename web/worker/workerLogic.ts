// The worker's logic over a SolverEngine, so the same code runs in the browser worker and under
// Node tests with the real wasm module. Each 'solve' message is a request (solver/hairRequest.ts:
// the head and grid of 'init', 'grid' and 'scalpMask', and the message's job) that the engine
// runs as a generator (solver/requestRunner.ts); this file only schedules it:
//   one request at a time, the newest superseding the running one: the run is stepped a slice
//   at a time, yielding to the event loop between slices, and dropped (not resumed) when a newer
//   request or another grid came in meanwhile;
//   'preview': a few iterations, light growth, one non-final result (none when superseded);
//   'full':    a first look (light), the field solved to convergence, the converged field's
//              hair light (what a slow GPU draws first), then in full.
// Its results get their lighting and, for the final hair, the view's vertex attributes here.
// 'scalpMask' and 'grid' set up the engine at once (no restart; a refusal is reported with id
// null and the old setup stays).
import { ResultLighting } from '../lighting/resultLighting';
import { followerAttributes } from '../model/guideFollowers';
import type { GridSpec } from '../model/hairArrays';
import { everyNthPoint, everyOtherPoint } from '../model/strandSubsample';
import {
  type Groom,
  type MotionRun,
  type RunPlan,
  type SolverEngine,
  SolverError,
} from '../solver/engine';
import type { HairSetup } from '../solver/hairRequest';
import type { FromWorker, SolverErrorKind, ToWorker } from '../solver/protocol';
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
  // One: previews came 21 a second instead of 19 at 25K (npm run bench:browser, the empty preset,
  // one run), each within 9 % of the converged field instead of 8 % (medians over a stroke drawn
  // point by point, warm-started from the last preview as while drawing).
  previewIterations: 1,
  convergedSample: true,
  yieldNow: () => new Promise((r) => setTimeout(r, 0)),
  now: () => (typeof performance !== 'undefined' ? performance.now() : Date.now()),
};

const errorMessage = (e: unknown): string => (e instanceof Error ? e.message : String(e));
const errorKind = (e: unknown): SolverErrorKind => (e instanceof SolverError ? e.kind : 'internal');

export class WorkerLogic {
  /** The head and grid requests run over (from 'init', 'grid' and 'scalpMask'); null before
   *  'init' succeeded. */
  private setup: HairSetup | null = null;
  /** The hair's lighting against the setup's head, on a grid over it and the solver's grid. */
  private lighting: ResultLighting | null = null;
  private latest: SolveMsg | null = null;
  private running = false;
  /** Bumped by every grid change: a job started before it is dropped. */
  private gridEpoch = 0;
  private jobEpoch = 0;

  constructor(
    readonly engine: SolverEngine,
    private readonly post: Post,
    private readonly opts: SchedulerOptions = DEFAULT_SCHEDULER,
  ) {}

  /** Sets up the engine on `setup` at once (a request without a job). */
  private setUp(setup: HairSetup): void {
    for (const _ of this.engine.run(setup, this.plan('once', 0, false))) {
      // a request without a job yields nothing
    }
  }

  /** Handles one message; solve jobs run asynchronously. Returns when the job queue is empty. */
  handle(msg: ToWorker): Promise<void> {
    if (msg.type === 'init') {
      try {
        const setup = { grid: msg.grid, omega: msg.omega, solver: msg.solver, head: msg.scalp };
        this.setup = null;
        this.setUp(setup);
        this.setup = setup;
        this.lighting = new ResultLighting(msg.scalp, msg.grid);
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
    if (!this.setup) {
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

  /** The motion playing (motionStart .. motionStop), and its play id. */
  private motion: MotionRun | null = null;
  private play = 0;
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
        this.play = msg.play;
        if (!this.setup) fail('the solver is not initialised');
        else {
          this.motion = this.engine.startMotion(msg.strands, {
            motion: msg.motion,
            seed: msg.seed,
            body: msg.body,
            ...(msg.wind ? { wind: msg.wind } : {}),
          });
          const { binding } = this.motion;
          this.post({
            type: 'motionBound',
            play: this.play,
            binding,
            attributes: followerAttributes(
              msg.strands.points,
              msg.strands.strandStart,
              binding,
              msg.pointStride > 1
                ? everyNthPoint(msg.strands.strandStart, msg.pointStride).points
                : null,
            ),
          });
          this.post({ type: 'motionFrame', play: this.play, stepMs: 0, ...this.motion.step() });
        }
        return;
      }
      if (msg.recycle) this.motionSpare.push(...msg.recycle);
      if (!this.motion) return; // stopped meanwhile
      const t0 = performance.now();
      for (let k = 1; k < Math.max(1, Math.floor(msg.frames)); k++) this.motion.advance();
      // the guides go into an array the page gave back (transferred both ways: no allocation
      // a frame once a few are in circulation)
      const frame = this.motion.step(this.motionSpare.pop());
      this.post({ type: 'motionFrame', play: this.play, stepMs: performance.now() - t0, ...frame });
    } catch (e) {
      fail(errorMessage(e));
    }
  }

  /** A new scalp on the setup's head: the next growth samples its roots over it (a job running
   *  now grows its remaining results from it too; the app asks again after a scalp edit). The
   *  lighting head keeps its triangles. A refused mask is reported and the old one stays. */
  private setScalpMask(scalp: Uint8Array): void {
    const fail = (message: string, kind: SolverErrorKind): void => {
      this.post({ type: 'error', id: null, message: `Scalp mask: ${message}`, kind });
    };
    if (!this.setup) {
      fail('the solver is not initialised', 'not_ready');
      return;
    }
    const setup = { ...this.setup, head: { ...this.setup.head, scalp } };
    try {
      this.setUp(setup);
      this.setup = setup;
    } catch (e) {
      fail(errorMessage(e), errorKind(e));
    }
  }

  /** Another grid for the same head: the engine is set up on it in place and the job running
   *  is dropped (its field was on the old grid). The hair's lighting keeps its head caches when
   *  its grid still holds the new one (ResultLighting.forGrid). */
  private setGrid(grid: GridSpec): void {
    this.gridEpoch++;
    if (!this.setup) {
      this.post({
        type: 'error',
        id: null,
        message: 'Grid: the solver is not initialised',
        kind: 'not_ready',
      });
      return;
    }
    const setup = { ...this.setup, grid };
    try {
      this.setUp(setup);
      this.setup = setup;
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

  private plan(mode: RunPlan['mode'], lightMaxStrands: number, wantField: boolean): RunPlan {
    const o = this.opts;
    return {
      mode,
      tolerance: o.tolerance,
      slice: o.sliceIterations,
      firstLook: o.firstLookIterations,
      previewIterations: o.previewIterations,
      lightMaxStrands,
      convergedSample: o.convergedSample,
      wantField,
      now: o.now,
    };
  }

  /** Runs one request a slice at a time, posting its progress and results. */
  private async runJob(job: SolveMsg): Promise<void> {
    const setup = this.setup;
    if (!setup) return;
    const request = {
      ...setup,
      job: { curves: job.curves, options: job.options, growth: job.growth },
    };
    for (const step of this.engine.run(
      request,
      this.plan(job.mode, job.lightMaxStrands, job.wantField),
    )) {
      if (step.type === 'progress')
        this.post({ type: 'progress', id: job.id, phase: step.phase, fraction: step.fraction });
      else if (step.type === 'slice') {
        await this.opts.yieldNow();
        if (this.superseded()) return;
      } else this.postResult(job, step.groom, step.final, step.converged);
    }
  }

  /** Posts hair grown for `job`, lit against the head (a preview's with every other point: half
   *  the work on both sides), with the view's vertex attributes when final. */
  private postResult(job: SolveMsg, groom: Groom, final: boolean, converged: boolean): void {
    const strands = job.mode === 'preview' ? everyOtherPoint(groom.strands) : groom.strands;
    const lighting = this.lighting?.of(strands, this.opts.now, final) ?? null;
    this.post({
      type: 'result',
      id: job.id,
      strands,
      constraints: groom.constraints,
      field: groom.field,
      lighting,
      // the full hair's vertex attributes are built here, not on the page (it would stall there
      // for ~60 ms at 30K strands); lighter hair is quicker to build there than to send
      attributes: final
        ? lineAttributes(strands.points, strands.strandStart, 0, lighting?.strand ?? null)
        : null,
      stats: groom.stats,
      final,
      converged,
    });
  }
}
