// The app's side of the solver worker.
// - A full request goes to the worker at once and supersedes what runs there (the worker drops
//   a superseded solve between iteration slices).
// - Previews (the curve being drawn) are paced here, and only here: at most one is in flight;
//   while it runs, newer previews replace each other in a one-slot mailbox and the newest is sent
//   when the answer comes back. So a drag never queues stale solves, and the hair keeps up with
//   the pen. How light previews (and first looks) are is the caller's: lightMaxStrands.
// - A result is shown when it is newer than what is on screen and no full request newer than it
//   was made (a late answer never undoes an edit the user made since).
// Final results are cached by content (undo is instant and exact), and a worker that dies is
// restarted and sent the session again.
// The head and its scalp are part of that content: setHead restarts the worker on another head
// (the cache is dropped), setScalpMask sends the worker a new scalp without a restart (the
// mask's content is in the key, so undoing a scalp edit is answered from the cache). A result of
// a request made before either change is never cached (the worker may have grown it on either).
// The solved field is copied out of the worker only while `wantField` is set (the field display
// is on); a cached result without it does not answer a request that wants it.

import { contentKey, hairRequestKey } from '../model/curveSet';
import type { GrowthParams } from '../model/growthParams';
import type { CurveSet, HairOptions, ScalpMesh } from '../model/hairArrays';
import type { HairJob } from './hairRequest';
import type { FromWorker, SolverErrorKind, ToWorker } from './protocol';

export type InitMessage = Extract<ToWorker, { type: 'init' }>;
export type SolveResult = Extract<FromWorker, { type: 'result' }>;
export type SolveMode = 'preview' | 'full';

export interface SolverClientEvents {
  /** The worker is (re)starting or working; `phase` says what it does. */
  onBusy(phase: 'loading' | 'solving' | 'growing', fraction: number): void;
  /** A result of the newest request (`final` false: a preview or a first look). */
  onResult(result: SolveResult, final: boolean, fromCache: boolean): void;
  /** An error; `restarting` when the worker died and is being replaced; `kind` what went wrong
   *  (a worker that died: 'internal'). */
  onError(message: string, restarting: boolean, kind: SolverErrorKind): void;
  /** The newest request is answered in full and nothing else is pending. */
  onIdle(): void;
}

interface Request {
  id: number;
  key: string;
  mode: SolveMode;
  curves: CurveSet;
  growth: GrowthParams;
  options: HairOptions;
  wantField: boolean;
  lightMaxStrands: number;
  /** headRevision when it was made: its result is cached only if no head or scalp came since. */
  headRevision: number;
}

const CACHE_SIZE = 4;
const MAX_RESTARTS = 3;

export class SolverClient {
  private worker: Worker | null = null;
  private latest: Request | null = null;
  /** The newest request still waiting for its final answer. */
  private open: Request | null = null;
  /** The preview sent and not yet answered, and the newest one waiting to be sent. */
  private previewInFlight: Request | null = null;
  private previewWaiting: Request | null = null;
  /** Id of the newest full request; older results are never shown after it. */
  private lastFullId = 0;
  /** Id of the request whose result is on screen. */
  private shownId = 0;
  private nextId = 1;
  private readonly cache = new Map<string, SolveResult>();
  private restarts = 0;
  private ready = false;
  /** Bumped by every setHead and setScalpMask. */
  private headRevision = 0;
  /** Which head (bumped by setHead) and the content of its scalp mask: part of the cache key. */
  private headId = 0;
  private maskKey: string;
  /** Ask the worker for the solved field with each result (for the field display). */
  wantField = false;
  /** Called with the motion's binding, each frame and motion error from the worker
   *  (app/motionPlayer.ts). */
  onMotion:
    | ((msg: Extract<FromWorker, { type: 'motionBound' | 'motionFrame' | 'motionError' }>) => void)
    | null = null;
  constructor(
    private readonly makeWorker: () => Worker,
    private init: InitMessage,
    private readonly events: SolverClientEvents,
  ) {
    this.maskKey = contentKey(init.scalp.scalp);
    this.start();
  }

  get pending(): boolean {
    return this.open !== null || this.previewWaiting !== null || !this.ready;
  }

  /** The grid the worker solves on. */
  get grid(): InitMessage['grid'] {
    return this.init.grid;
  }

  /** Moves the solver to another grid (the session's bounding volume grew or shrank): the
   *  worker moves its engine there in place (a 'grid' message: no new worker, the head stays;
   *  a worker still loading gets it after its init) and drops the job it runs; the caller asks
   *  again (SolverBridge.sync). Cached results were grown on the old grid: dropped, and results
   *  of requests made before are not cached. */
  setGrid(grid: InitMessage['grid']): void {
    this.init = { ...this.init, grid };
    this.cache.clear();
    this.headRevision++;
    const msg: ToWorker = { type: 'grid', grid };
    this.worker?.postMessage(msg);
  }

  /** The head the worker grows on (protocol.ts ScalpMesh, its scalp mask included), and the grid
   *  when that changes with it (default: the same): the worker is replaced by one set up on
   *  them and the open request is sent to it when ready. Cached results were grown on the old
   *  head: dropped. */
  setHead(scalp: ScalpMesh, grid: InitMessage['grid'] = this.init.grid): void {
    this.init = { ...this.init, grid, scalp };
    this.headId++;
    this.headRevision++;
    this.maskKey = contentKey(scalp.scalp);
    this.restart('loading');
  }

  /** A new scalp on the same head (mask[triangle] = 1 on the scalp): the worker changes it in
   *  place (no restart) and a restart sends it with the head. Requests from now on are grown on
   *  it; the caller asks again for what is on screen (SolverBridge does). A mask whose length is
   *  not the head's triangle count changes nothing and is reported as an error. */
  setScalpMask(mask: Uint8Array): void {
    const triangles = this.init.scalp.scalp.length;
    if (mask.length !== triangles) {
      this.events.onError(
        `Scalp mask of ${mask.length} triangles for a head of ${triangles}: not changed`,
        false,
        'invalid_input',
      );
      return;
    }
    this.init = { ...this.init, scalp: { ...this.init.scalp, scalp: mask } };
    this.headRevision++;
    this.maskKey = contentKey(mask);
    const msg: ToWorker = { type: 'scalpMask', scalp: mask };
    // A worker still loading handles it after its init (messages keep their order).
    this.worker?.postMessage(msg);
  }

  /** Replaces the worker by a new one sent `init`; results cached for the old set-up are
   *  dropped. */
  private restart(phase: 'loading' | 'solving'): void {
    this.cache.clear();
    this.worker?.terminate();
    this.worker = null;
    this.ready = false;
    this.previewInFlight = null;
    this.previewWaiting = null;
    this.start(phase);
  }

  /** Runs a job (its curves solved, its growth grown) over the head and grid of the worker's set-up; previews and a full solve's first look are grown with
   *  at most `lightMaxStrands` strands (0: growth.maxStrands alone). The app's solver bridge
   *  (app/solverBridge.ts) decides the cap. */
  request(job: HairJob, mode: SolveMode = 'full', lightMaxStrands = 0): void {
    const { curves, growth, options } = job;
    const key = `${hairRequestKey(curves, growth, options)}|head ${this.headId}:${this.maskKey}`;
    const req: Request = {
      id: this.nextId++,
      key,
      mode,
      curves,
      growth,
      options,
      wantField: this.wantField,
      lightMaxStrands,
      headRevision: this.headRevision,
    };
    this.latest = req;
    if (mode === 'preview') {
      this.open = req;
      if (this.previewInFlight && this.worker && this.ready) this.previewWaiting = req;
      else this.sendPreview(req);
      return;
    }
    this.lastFullId = req.id;
    this.previewWaiting = null;
    this.previewInFlight = null; // its answer, if any, is older than this request: not shown
    const cached = this.cache.get(key);
    if (cached && (cached.field || !req.wantField)) {
      this.open = null;
      this.shownId = req.id;
      this.events.onResult(cached, true, true);
      if (!this.pending) this.events.onIdle();
      return;
    }
    this.open = req;
    this.send(req);
  }

  private sendPreview(req: Request): void {
    this.previewWaiting = null;
    this.previewInFlight = this.worker && this.ready ? req : null;
    this.send(req);
  }

  /** A preview was answered (or failed): send the newest waiting one. */
  private previewAnswered(id: number): void {
    if (this.previewInFlight?.id !== id) return;
    this.previewInFlight = null;
    if (this.previewWaiting) this.sendPreview(this.previewWaiting);
  }

  /** Test and fault hook: kills the worker as a crash would. */
  crash(): void {
    this.handleDeath('the solver worker was stopped');
  }

  dispose(): void {
    this.worker?.terminate();
    this.worker = null;
  }

  /** A new worker, sent `init`. `phase`: what the user is told meanwhile (a grid move is part of
   *  solving the edit that needed it, not a load). */
  /** Sends a motion message (protocol.ts motionStart / motionStep / motionStop); false when no
   *  worker is ready to take it. */
  motion(msg: Extract<ToWorker, { type: 'motionStart' | 'motionStep' | 'motionStop' }>): boolean {
    if (!this.worker || !this.ready) return false;
    if (msg.type === 'motionStep' && msg.recycle)
      this.worker.postMessage(
        msg,
        msg.recycle.map((a) => a.buffer as ArrayBuffer),
      );
    else this.worker.postMessage(msg);
    return true;
  }

  private start(phase: 'loading' | 'solving' = 'loading'): void {
    this.ready = false;
    this.events.onBusy(phase, 0);
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

  private send(req: Request): void {
    if (!this.worker || !this.ready) return; // sent on 'ready'
    this.events.onBusy('solving', 0);
    const msg: ToWorker = {
      type: 'solve',
      id: req.id,
      curves: req.curves,
      growth: req.growth,
      options: req.options,
      wantField: req.wantField,
      mode: req.mode,
      lightMaxStrands: req.lightMaxStrands,
    };
    this.worker.postMessage(msg);
  }

  private handleDeath(reason: string): void {
    this.worker?.terminate();
    this.worker = null;
    if (this.restarts >= MAX_RESTARTS) {
      this.events.onError(
        `The solver stopped (${reason}) ${MAX_RESTARTS} times in a row; reload the page. Your curves are kept in the session.`,
        false,
        'internal',
      );
      return;
    }
    this.restarts++;
    // The answer in flight is lost with the worker: the newest state is sent again (as a full
    // solve: a preview's stroke may have ended meanwhile).
    this.previewInFlight = null;
    this.previewWaiting = null;
    if (this.latest) {
      this.open = { ...this.latest, mode: 'full' };
      this.lastFullId = this.latest.id;
    }
    this.events.onError(
      `The solver stopped (${reason}); restarting it with your session.`,
      true,
      'internal',
    );
    this.start();
  }

  private onMessage(msg: FromWorker): void {
    switch (msg.type) {
      case 'ready':
        this.ready = true;
        if (this.open) {
          if (this.open.mode === 'preview') this.sendPreview(this.open);
          else this.send(this.open);
        }
        if (!this.pending) this.events.onIdle();
        return;
      case 'progress':
        if (this.open && msg.id === this.open.id)
          this.events.onBusy(msg.phase === 'grow' ? 'growing' : 'solving', msg.fraction);
        return;
      case 'result': {
        this.previewAnswered(msg.id);
        const isLatest = this.latest !== null && msg.id === this.latest.id;
        if (msg.final) {
          this.restarts = 0;
          const req = this.open && this.open.id === msg.id ? this.open : null;
          if (req && req.mode === 'full' && req.headRevision === this.headRevision) {
            this.cache.set(req.key, msg);
            while (this.cache.size > CACHE_SIZE) {
              const oldest = this.cache.keys().next().value as string;
              this.cache.delete(oldest);
            }
          }
        }
        if (msg.id < this.lastFullId || msg.id < this.shownId) return; // superseded
        this.shownId = msg.id;
        if (isLatest && (msg.final || this.latest?.mode === 'preview')) this.open = null;
        this.events.onResult(msg, msg.final && isLatest, false);
        if (!this.pending) this.events.onIdle();
        return;
      }
      case 'motionBound':
      case 'motionFrame':
      case 'motionError':
        this.onMotion?.(msg);
        return;
      case 'error':
        if (msg.id === null && !this.ready) {
          // Set-up failed: restarting would fail the same way.
          this.events.onError(msg.message, false, msg.kind);
          return;
        }
        if (msg.id !== null) this.previewAnswered(msg.id);
        if (this.open && msg.id === this.open.id) this.open = null;
        this.events.onError(msg.message, false, msg.kind);
        if (!this.pending) this.events.onIdle();
        return;
    }
  }
}
