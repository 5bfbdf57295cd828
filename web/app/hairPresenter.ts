// Puts solver results on screen: the hair (a new revision only when the strands changed), the
// strand count and revision on the status line, the hair colour from the session, and when
// each revision reached the screen (for benchmarks). Holds the view at interactive detail while
// the hair is still settling.
import type { Editor } from '../editor/editor';
import type { StrandArrays } from '../model/hairArrays';
import { changesHair } from '../model/sessionSchema';
import type { SolveResult } from '../solver/solverClient';
import type { StatusLine } from '../ui/status';
import type { HairView } from '../viewer/hairView';
import type { Viewer } from '../viewer/viewer';

export interface HairRevision {
  revision: number;
  /** When a frame first drew it (performance.now()). */
  time: number;
  final: boolean;
  /** The converged field's hair: the final hair, or its light growth posted before it. */
  converged: boolean;
  strands: number;
  /** When its result reached this thread (performance.now()), and the worker's times for it:
   *  solve (set-up and iterations), growth, lighting precompute (ms). For benchmarks. */
  arrived: number;
  /** Main-thread time spent building its geometry (ms). */
  buildMs: number;
  solveMs: number;
  growMs: number;
  lightMs: number;
}

export class HairPresenter {
  private shown: StrandArrays | null = null;
  private shownFrom: SolveResult | null = null;
  /** Strands with at least one segment in the hair shown (visibleStrands). */
  private strandCount = 0;
  /** When each displayed hair revision reached the screen (performance.now()). */
  readonly log: HairRevision[] = [];
  private unstamped: Omit<HairRevision, 'time'> | null = null;
  heapBytes = 0;
  /** The converged hair was handed to the view and no frame has drawn it yet. */
  private finalPending = false;
  /** The bridge answered (a result or idle) in the task still running: an edit it hears of in the
   *  same dispatch was answered from its cache before this presenter hears of it. */
  private answered = false;
  /** Called when the converged hair is on screen (the moment to say "Ready"). */
  onFinalShown: (() => void) | null = null;

  constructor(
    private readonly viewer: Viewer,
    private readonly hair: HairView,
    private readonly status: StatusLine,
    editor: Editor,
  ) {
    hair.setLook(editor.session.hairLook ?? null, editor.session.hairColor);
    viewer.onRendered = () => this.stamp();
    editor.listen((c) => {
      // a no-op when it is the same colour (the editor replaces what it changes)
      this.hair.setLook(c.session.hairLook ?? null, c.session.hairColor);
      // until the final hair is shown; a change the hair does not depend on brings none, nor one
      // the bridge has already answered (it hears of each edit first: hair from its cache comes,
      // and is idle, before this runs; holding then drew that hair at interactive detail until
      // the next edit, as after Undo of a shaped ponytail)
      if (c.sessionChanged && changesHair(c.previous, c.session) && !this.answered)
        this.viewer.hold('settling', true);
    });
  }

  get strands(): StrandArrays | null {
    return this.shown;
  }

  /** The result whose hair is on screen (its lighting and attributes too). */
  get shownResult(): SolveResult | null {
    return this.shownFrom;
  }

  /** Strands in the hair on screen (those with at least one segment). */
  get shownStrands(): number {
    return this.strandCount;
  }

  /** Converged hair is waiting for its first frame. */
  get awaitingFrame(): boolean {
    return this.finalPending;
  }

  result(r: SolveResult, final: boolean): void {
    this.markAnswered();
    const arrived = performance.now();
    this.heapBytes = r.stats.heapBytes;
    if (this.shown !== r.strands) {
      this.shown = r.strands;
      this.shownFrom = r;
      this.finalPending = final;
      // previews and first looks keep the head's shadow as the converged hair cast it: the head
      // stays in the frame cache while a stroke is drawn (viewer/frameCache.ts)
      const b0 = performance.now();
      this.hair.show(
        r.strands,
        r.lighting,
        () => {
          if (!final || this.shown !== r.strands) return;
          this.finalPending = false;
          this.onFinalShown?.();
        },
        final,
        r.attributes ?? null,
      );
      const buildMs = performance.now() - b0;
      const n = visibleStrands(r.strands);
      this.strandCount = n;
      this.status.counts(n, this.status.curves);
      this.status.bumpRevision();
      this.unstamped = {
        revision: this.status.revision,
        final,
        converged: final || r.converged === true,
        strands: n,
        arrived,
        buildMs,
        solveMs: r.stats.solveMs,
        growMs: r.stats.growMs,
        lightMs: r.lighting?.ms ?? 0,
      };
    }
    // hair that is still settling is drawn at interactive detail, the final hair in full
    this.viewer.hold('settling', !final);
  }

  idle(): void {
    this.markAnswered();
    this.viewer.hold('settling', false);
  }

  private markAnswered(): void {
    if (this.answered) return;
    this.answered = true;
    queueMicrotask(() => {
      this.answered = false;
    });
  }

  private stamp(): void {
    if (!this.unstamped) return;
    this.log.push({ ...this.unstamped, time: performance.now() });
    if (this.log.length > 1000) this.log.shift();
    this.unstamped = null;
  }
}

/** Strands with at least one segment (a root in a zero field grows nothing: a bald head shows
 *  no strands). */
export function visibleStrands(s: StrandArrays): number {
  let n = 0;
  const start = s.strandStart;
  for (let i = 0; i + 1 < start.length; i++) if (start[i + 1] - start[i] >= 2) n++;
  return n;
}
