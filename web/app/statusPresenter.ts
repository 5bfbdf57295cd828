// The status line in plain words: what the app does now ("Solving… 60 %", "Ready — 30,000
// strands"), the last thing the user did, and solver internals (method, iterations, times) in
// the details tooltip only. Progress never goes backwards within one solve.
import type { EditorChange } from '../editor/editor';
import { gridPointCount } from '../model/grid';
import type { GridSpec } from '../model/hairArrays';
import type { SolverErrorKind } from '../solver/protocol';
import type { SolveResult } from '../solver/solverClient';
import type { StatusLine } from '../ui/status';
import type { BusyPhase } from './solverBridge';

const fmt = (n: number) => n.toLocaleString('en-US');

/** What to do when the solver refuses work over its memory cap: the exact solver's factor, the
 *  strands' points, or the bounding volume (which long hair grows). */
function memoryAdvice(message: string): string {
  if (/exact|factor/i.test(message))
    return ' — the exact solver does not fit this grid; use ?solver=fast or a smaller ?grid';
  if (/^growth|strand points/.test(message))
    return ' — the strands do not fit in memory; use fewer strands or a shorter Max length';
  return ' — the bounding volume does not fit in memory; use a shorter Max length or a smaller ?grid';
}

export class StatusPresenter {
  private lastMessage = '';
  private details = '';
  /** Highest progress shown for the current solve, and whether a first look is on screen. */
  private progress = 0;
  private firstLook = false;

  /** `solver.pending`: the solver has work queued; `solver.previewing`: a stroke is being drawn
   *  (the hair on screen is its preview, a sample of the strands); `solver.grid`: the bounding
   *  volume's grid the hair was solved on (the tooltip says its size). The solver bridge. */
  constructor(
    private readonly line: StatusLine,
    private readonly solver: {
      readonly pending: boolean;
      readonly previewing: boolean;
      readonly grid?: GridSpec;
    },
  ) {}

  /** A sentence about what the user just did (kept beside "Ready"). */
  note(message: string): void {
    if (!message) return;
    this.lastMessage = message;
    if (this.line.state === 'ready') this.ready();
    else if (this.line.state !== 'error') this.line.set(this.line.state, this.busyText());
  }

  /** A long task of the user's (an export): its progress replaces the status text while the
   *  hair is ready; the solver's own progress still wins while it solves. */
  task(text: string): void {
    this.taskText = text;
    if (this.line.state !== 'error') this.line.set('solving', text);
  }

  /** The task ended: its sentence stays beside "Ready" (an error: shown as an error). */
  taskDone(message: string, failed = false): void {
    this.taskText = '';
    if (failed) this.error(message);
    else {
      this.lastMessage = message;
      this.ready();
    }
  }

  private taskText = '';

  /** An error the user must see until the next change. */
  error(message: string): void {
    this.lastMessage = message;
    this.line.set('error', message);
  }

  editorChanged(c: EditorChange): void {
    if (c.sessionChanged) {
      this.line.counts(this.line.strands, c.session.curves.length);
      this.progress = 0;
      this.firstLook = false;
      // The solver bridge hears of the edit first: when it asked for a solve, the line says so
      // now, not at the worker's first progress message (until then it would still say Ready,
      // or Preview after a stroke, with the new curve already counted).
      if (this.solver.pending && !this.solver.previewing && this.line.state === 'ready')
        this.line.set('solving', this.busyText());
    }
    if (c.cause !== 'tool' && c.cause !== 'select') this.note(c.message);
  }

  busy(phase: BusyPhase, fraction: number, previewing: boolean): void {
    if (phase === 'loading') {
      this.progress = 0;
      this.firstLook = false;
      this.line.set('loading', 'Loading the solver…');
      return;
    }
    if (previewing) return; // the hair follows the pen; no progress for previews
    // a first look is grown (at 95 %) before the solve goes on: growth counts as progress only
    // once that first look is on screen
    if (phase === 'solving' || this.firstLook) this.progress = Math.max(this.progress, fraction);
    this.phase = phase === 'growing' && this.firstLook ? 'growing' : 'solving';
    this.line.set('solving', this.busyText());
  }

  private phase: 'solving' | 'growing' = 'solving';

  private busyText(): string {
    const what = this.phase === 'growing' ? 'Growing the hair' : 'Solving';
    const pct = Math.round(this.progress * 100);
    const base = `${what}… ${pct} %`;
    return this.lastMessage ? `${base} · ${this.lastMessage}` : base;
  }

  result(r: SolveResult, final: boolean): void {
    const st = r.stats;
    if (!final) {
      this.firstLook = true;
      return;
    }
    this.progress = 0;
    this.firstLook = false;
    const g = this.solver.grid;
    const volume = g
      ? ` · bounding volume ${fmt(gridPointCount(g))} grid points (${g.dims.join(' × ')}, step ${(g.step * 100).toFixed(1)} mm)`
      : '';
    this.details = `${st.constraints.toLocaleString('en-US')} constraints · ${st.method}, ${st.iterations} iterations, solve ${st.solveMs.toFixed(0)} ms, growth ${st.growMs.toFixed(0)} ms${volume}${st.module ? ` · ${st.module}` : ''}`;
  }

  solverError(message: string, kind: SolverErrorKind | undefined, restarting: boolean): void {
    if (restarting) {
      this.lastMessage = message;
      this.line.set('loading', message);
      return;
    }
    const advice = kind === 'over_memory_cap' ? memoryAdvice(message) : '';
    this.error(`Error: ${message}${advice}`);
  }

  /** The newest hair is on screen and nothing is pending. */
  ready(): void {
    if (this.solver.pending) return;
    if (this.taskText) {
      this.line.set('solving', this.taskText);
      return;
    }
    const l = this.line;
    if (this.solver.previewing && l.strands > 0) {
      // the worker is idle between a stroke's previews: what is shown is not the final hair
      l.set('ready', `Preview — ${fmt(l.strands)} strands; release to grow all`);
      return;
    }
    const hair =
      l.strands > 0
        ? `${fmt(l.strands)} strands`
        : l.curves > 0
          ? 'no strands grow from these curves'
          : 'no hair yet: draw a stroke from the scalp with the tool chosen';
    const extra = this.lastMessage ? ` · ${this.lastMessage}` : '';
    l.set('ready', `Ready — ${hair}${extra}`, this.details);
  }
}
