// The app's side of the solver worker: one solve in flight at a time, the newest request
// supersedes any waiting one, results are cached by content (undo is instant and exact), and a
// worker that dies is restarted and sent the session again.

import { contentKey } from '../model/curveSet';
import type { CurveSet, FromWorker, GrowthParams, ToWorker } from './protocol';

export type InitMessage = Extract<ToWorker, { type: 'init' }>;
export type SolveResult = Extract<FromWorker, { type: 'result' }>;

export interface SolverClientEvents {
  /** The worker is (re)starting or solving; `phase` says what it does. */
  onBusy(phase: string): void;
  /** A result for `key`; `latest` is false when a newer request is already waiting. */
  onResult(result: SolveResult, latest: boolean, fromCache: boolean): void;
  /** An error; `restarting` when the worker died and is being replaced. */
  onError(message: string, restarting: boolean): void;
  /** Nothing is pending. */
  onIdle(): void;
}

interface Request {
  id: number;
  key: string;
  curves: CurveSet;
  growth: GrowthParams;
}

const CACHE_SIZE = 4;
const MAX_RESTARTS = 3;

export class SolverClient {
  private worker: Worker | null = null;
  private inFlight: Request | null = null;
  private waiting: Request | null = null;
  private latest: Request | null = null;
  private nextId = 1;
  private readonly cache = new Map<string, SolveResult>();
  private restarts = 0;
  private ready = false;

  constructor(
    private readonly makeWorker: () => Worker,
    private readonly init: InitMessage,
    private readonly events: SolverClientEvents,
  ) {
    this.start();
  }

  get pending(): boolean {
    return this.inFlight !== null || this.waiting !== null || !this.ready;
  }

  request(curves: CurveSet, growth: GrowthParams): void {
    const key = contentKey(
      curves.points,
      curves.curveStart,
      curves.kinds,
      curves.extend,
      curves.params,
      curves.paramStart,
      curves.extraIndex,
      curves.extraTarget,
      new Float64Array(Object.values(growth)),
    );
    const req: Request = { id: this.nextId++, key, curves, growth };
    this.latest = req;
    const cached = this.cache.get(key);
    if (cached) {
      this.waiting = null;
      this.events.onResult(cached, true, true);
      if (!this.inFlight && this.ready) this.events.onIdle();
      return;
    }
    this.waiting = req;
    this.pump();
  }

  /** Test and fault hook: kills the worker as a crash would. */
  crash(): void {
    this.handleDeath('the solver worker was stopped');
  }

  dispose(): void {
    this.worker?.terminate();
    this.worker = null;
  }

  private start(): void {
    this.ready = false;
    this.events.onBusy('loading');
    const w = this.makeWorker();
    this.worker = w;
    w.onmessage = (ev: MessageEvent<FromWorker>) => {
      if (this.worker === w) this.onMessage(ev.data);
    };
    w.onerror = (ev: ErrorEvent) => {
      ev.preventDefault();
      if (this.worker === w) this.handleDeath(ev.message || 'the solver worker crashed');
    };
    w.postMessage(this.init);
  }

  private handleDeath(reason: string): void {
    this.worker?.terminate();
    this.worker = null;
    // The in-flight request is lost with the worker: re-send the newest state.
    if (this.inFlight && !this.waiting) this.waiting = this.latest;
    this.inFlight = null;
    if (this.restarts >= MAX_RESTARTS) {
      this.events.onError(
        `The solver stopped (${reason}) ${MAX_RESTARTS} times in a row; reload the page. Your curves are kept in the session.`,
        false,
      );
      return;
    }
    this.restarts++;
    this.events.onError(`The solver stopped (${reason}); restarting it with your session.`, true);
    this.start();
  }

  private pump(): void {
    if (!this.worker || !this.ready || this.inFlight || !this.waiting) return;
    const req = this.waiting;
    this.waiting = null;
    this.inFlight = req;
    this.events.onBusy('solving');
    const msg: ToWorker = {
      type: 'solve',
      id: req.id,
      curves: req.curves,
      growth: req.growth,
      wantField: false,
    };
    this.worker.postMessage(msg);
  }

  private onMessage(msg: FromWorker): void {
    switch (msg.type) {
      case 'ready':
        this.ready = true;
        if (!this.waiting && !this.inFlight && this.latest) this.waiting = this.latest;
        this.pump();
        if (!this.pending) this.events.onIdle();
        return;
      case 'progress':
        this.events.onBusy(
          msg.phase === 'constraints' ? 'solving' : msg.phase === 'solve' ? 'solving' : 'growing',
        );
        return;
      case 'result': {
        const req = this.inFlight;
        this.inFlight = null;
        this.restarts = 0;
        if (req) {
          this.cache.set(req.key, msg);
          while (this.cache.size > CACHE_SIZE) {
            const oldest = this.cache.keys().next().value as string;
            this.cache.delete(oldest);
          }
        }
        const latest = req !== null && req === this.latest;
        if (!this.waiting) this.events.onResult(msg, latest, false);
        this.pump();
        if (!this.pending) this.events.onIdle();
        return;
      }
      case 'error':
        if (msg.id === null && !this.ready) {
          // Set-up failed: restarting would fail the same way.
          this.events.onError(msg.message, false);
          return;
        }
        this.inFlight = null;
        this.events.onError(msg.message, false);
        this.pump();
        if (!this.pending) this.events.onIdle();
        return;
    }
  }
}
