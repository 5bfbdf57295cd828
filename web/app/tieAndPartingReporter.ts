// Says what a new parting or tie did once the hair grown with it is on screen: a parting
// (model/partingReport.ts) "c1 splits the scalp: top 38 %, rest 62 %" or "c1 parts the hair: a parting…", so a user
// sees whether the section a tie needs exists; a tie "c2 gathers 62 % of the hair", so a tie
// that took another section than meant shows at once.
import type { EditorChange } from '../editor/editor';
import type { StrandArrays } from '../model/hairArrays';
import { defOf } from '../model/kinds';
import { partingReport } from '../model/partingReport';
import type { Vec3 } from '../model/vec3';

export class TieAndPartingReporter {
  /** Partings added by the last edit, waiting for their hair. */
  private pending: { id: string; points: readonly Vec3[] }[] = [];
  /** Ties added by the last edit, with their index in the session's curves. */
  private ties: { id: string; index: number }[] = [];
  /** What the edit that added them said ("Added ponytail c1 and its mirror c2."). */
  private tieMessage = '';

  constructor(private readonly say: (message: string) => void) {}

  editorChanged(c: EditorChange): void {
    if (!c.sessionChanged) return;
    const before = new Set(c.previous.curves.map((k) => k.id));
    const added = c.session.curves.filter((k) => defOf(k).role === 'parting' && !before.has(k.id));
    if (c.cause === 'command' && added.length > 0)
      this.pending = added.map((k) => ({ id: k.id, points: k.points }));
    else if (c.cause !== 'stroke') this.pending = [];
    const ties = c.session.curves
      .map((k, index) => ({ id: k.id, index, tie: defOf(k).role === 'tie' && !before.has(k.id) }))
      .filter((k) => k.tie);
    if (c.cause === 'command' && ties.length > 0) {
      this.ties = ties;
      this.tieMessage = c.message;
    } else if (c.cause !== 'stroke') this.ties = [];
  }

  /** The final hair of a solve is shown. */
  hairShown(hair: StrandArrays | null): void {
    if ((this.pending.length === 0 && this.ties.length === 0) || !hair) return;
    const lines = this.pending
      .map((p) => partingReport(p.id, p.points, hair))
      .filter((m): m is string => !!m);
    const tails = hair.tailCurves;
    const n = hair.strandStart.length - 1;
    const shares: string[] = [];
    if (tails && n > 0)
      for (const t of this.ties) {
        let held = 0;
        for (let s = 0; s < n; s++) if (tails[s] === t.index) held++;
        shares.push(`${t.id} gathers ${Math.round((100 * held) / n)} % of the hair`);
      }
    if (shares.length > 0)
      lines.push(`${this.tieMessage.replace(/\.$/, '')}: ${shares.join(', ')}.`);
    this.pending = [];
    this.ties = [];
    if (lines.length > 0) this.say(lines.join('; '));
  }
}
