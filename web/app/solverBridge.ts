// The bridge between the editor and the solver worker, with one input: the editor's state (the
// committed session and the stroke being drawn). It alone decides what the worker is asked: the
// session after every change that matters to the hair (a full solve), the session with the
// stroke while one is drawn (previews, at most one in flight: SolverClient paces them), and how
// many strands previews and first looks grow. Results and progress go to whoever subscribed
// (hair presenter, overlays, status line, the active tool).

import type { Editor, EditorChange, StrokeInProgress } from '../editor/editor';
import { FIELD_OMEGA, sameGrid } from '../model/grid';
import type { GridSpec, ScalpMesh } from '../model/hairArrays';
import { STROKE_KINDS } from '../model/kinds';
import {
  newCurveExtends,
  type SessionState,
  type StyleCurve,
  sessionGrid,
  streamExtends,
} from '../model/session';
import { needsSolve } from '../model/sessionSchema';
import type { Vec3 } from '../model/vec3';
import { jobOf } from '../solver/hairRequest';
import type { SolverErrorKind, SolverName } from '../solver/protocol';
import { type SolveResult, SolverClient } from '../solver/solverClient';

/** Strands grown for a preview or a first look: at most this many, fewer when the view draws a
 *  sample (a slow GPU), never fewer than the minimum. */
export const PREVIEW_STRANDS = 6000;
export const MIN_PREVIEW_STRANDS = 800;

export type BusyPhase = 'loading' | 'solving' | 'growing';

export interface SolverBridgeEvents {
  busy?(phase: BusyPhase, fraction: number, previewing: boolean): void;
  result?(r: SolveResult, final: boolean): void;
  error?(message: string, kind: SolverErrorKind | undefined, restarting: boolean): void;
  idle?(): void;
  /** The bounding volume changed (results from now on are on this grid). */
  gridChanged?(grid: GridSpec): void;
}

export interface SolverBridgeOptions {
  /** The grid of the session the page starts with (gridForSession). */
  grid: GridSpec;
  solver: SolverName;
  scalp: ScalpMesh;
  /** A loaded head's bounds, which the grid must hold too (gridForSession); absent or undefined
   *  for the built-in head. */
  headBounds?: () => { min: Vec3; max: Vec3 } | undefined;
  /** Fraction of the hair the view can draw while interacting (1 on a fast GPU). */
  interactiveDetail: () => number;
  /** Strands of the hair on screen now (previews grow no more than the view can draw). */
  shownStrands: () => number;
  makeWorker?: () => Worker;
}

export class SolverBridge {
  readonly client: SolverClient;
  /** What the worker was last asked for: a preview leaves a stroke's hair on screen, which the
   *  session's own hair must replace when the stroke ends without an edit. */
  private lastAsked: 'full' | 'preview' = 'full';
  private readonly listeners: SolverBridgeEvents[] = [];
  private idleWaiters: Array<() => void> = [];

  constructor(
    private readonly editor: Editor,
    private readonly opts: SolverBridgeOptions,
  ) {
    this.client = new SolverClient(
      opts.makeWorker ??
        (() => new Worker(new URL('../worker/worker.ts', import.meta.url), { type: 'module' })),
      { type: 'init', grid: opts.grid, omega: FIELD_OMEGA, solver: opts.solver, scalp: opts.scalp },
      {
        onBusy: (phase, fraction) => this.each((l) => l.busy?.(phase, fraction, this.previewing)),
        onResult: (r, final) => this.each((l) => l.result?.(r, final)),
        onError: (message, restarting, kind) =>
          this.each((l) => l.error?.(message, kind, restarting)),
        onIdle: () => {
          this.each((l) => l.idle?.());
          for (const w of this.idleWaiters.splice(0)) w();
        },
      },
    );
    editor.listen((c) => this.onEditorChange(c));
  }

  subscribe(events: SolverBridgeEvents): void {
    this.listeners.push(events);
  }

  private each(f: (l: SolverBridgeEvents) => void): void {
    for (const l of this.listeners) f(l);
  }

  get pending(): boolean {
    return this.client.pending;
  }
  /** A stroke is being drawn: the hair on screen is (or will be) its preview. */
  get previewing(): boolean {
    return this.editor.stroke !== null;
  }

  /** The grid the solver works on: the session's bounding volume (gridForSession). */
  get grid(): GridSpec {
    return this.client.grid;
  }

  /** The grid the current session needs: its curves and the head (sessionGrid). */
  private gridNeeded(): GridSpec {
    const s = this.editor.session;
    return sessionGrid(s, this.opts.headBounds?.());
  }

  /** Another head (a loaded mesh, a turn of it, the built-in one), with its scalp mask: the
   *  worker is restarted on it (on the grid the session needs with it, so at most one restart)
   *  and the session is solved again. */
  setHead(scalp: ScalpMesh): void {
    const grid = this.gridNeeded();
    const moved = !sameGrid(grid, this.client.grid);
    this.client.setHead(scalp, grid);
    if (moved) this.each((l) => l.gridChanged?.(grid));
    this.sync();
  }

  /** A new scalp on the same head (scalp[triangle] = 1): the worker changes it in place (no
   *  restart, the head's distance grid is kept) and the session is solved again, its roots
   *  spread over the new scalp. */
  setScalpMask(mask: Uint8Array): void {
    this.client.setScalpMask(mask);
    this.sync();
  }

  /** Sends the current session for a full solve (on the grid its curves and head need). */
  sync(): void {
    this.lastAsked = 'full';
    const s = this.editor.session;
    const grid = this.gridNeeded();
    if (!sameGrid(grid, this.client.grid)) {
      this.client.setGrid(grid);
      this.each((l) => l.gridChanged?.(grid));
    }
    this.client.request(jobOf(s), 'full', this.lightCap(s));
  }

  /** The session with the stroke being drawn, solved as a preview (a stroke of fewer than three
   *  points is not one yet). */
  private preview(stroke: StrokeInProgress): void {
    if (stroke.points.length < 3) return;
    this.lastAsked = 'preview';
    const s = this.editor.session;
    // solved as the curve it will make: a flow (stream) curve runs on into a tie or combs on when
    // it ends on the scalp; a tie's stroke extends as a new curve does
    const kind = STROKE_KINDS[stroke.kind ?? 'stream'];
    const extend =
      stroke.extend ??
      (kind.role === 'flow' ? streamExtends(s, stroke.points) : newCurveExtends(s));
    const draft = {
      id: '~draft',
      ...kind.fromStroke(stroke.points as Vec3[], stroke.viewpoint, extend),
    } as StyleCurve;
    const cap = this.lightCap(s);
    const curves = [...s.curves, draft];
    this.client.request(jobOf(s, curves, { ...s.growth, maxStrands: cap }), 'preview', cap);
  }

  /** Shows the solved field in results (the field display), re-solving when it is missing. */
  setWantField(on: boolean, haveField: boolean): void {
    this.client.wantField = on;
    if (on && !haveField && !this.previewing) this.sync();
  }

  /** Resolves once no solve is pending (at once when idle). */
  whenIdle(): Promise<void> {
    if (!this.client.pending) return Promise.resolve();
    return new Promise((resolve) => this.idleWaiters.push(resolve));
  }

  crash(): void {
    this.client.crash();
  }

  private lightCap(s: SessionState): number {
    const shown = this.opts.shownStrands() || PREVIEW_STRANDS;
    const cap = Math.round(
      Math.min(
        PREVIEW_STRANDS,
        Math.max(MIN_PREVIEW_STRANDS, shown * this.opts.interactiveDetail()),
      ),
    );
    return s.growth.maxStrands > 0 ? Math.min(s.growth.maxStrands, cap) : cap;
  }

  private onEditorChange(c: EditorChange): void {
    if (c.stroke) {
      if (c.strokeChanged) this.preview(c.stroke);
      return;
    }
    if (c.sessionChanged && needsSolve(c.previous, c.session)) {
      this.sync();
      return;
    }
    // A stroke that ends without an edit (cancelled, or read as a hint that changes nothing)
    // must not leave its preview on screen: the session's own hair comes back (from the
    // client's cache, no solve).
    if (c.strokeChanged && this.lastAsked === 'preview') this.sync();
  }
}
