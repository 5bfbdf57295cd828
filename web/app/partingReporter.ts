// Says what a new parting did once the hair grown with it is on screen (model/partingReport.ts):
// the status line's "Added dividing curve c1" becomes "c1 splits the scalp: top 38 %, rest 62 %"
// or "c1 is open: no section…", so a user sees whether the section a tie needs exists.
import type { EditorChange } from '../editor/editor';
import type { StrandArrays } from '../model/hairArrays';
import { partingReport } from '../model/partingReport';
import type { Vec3 } from '../model/vec3';

export class PartingReporter {
  /** Partings added by the last edit, waiting for their hair. */
  private pending: { id: string; points: readonly Vec3[] }[] = [];

  constructor(private readonly say: (message: string) => void) {}

  editorChanged(c: EditorChange): void {
    if (!c.sessionChanged) return;
    const before = new Set(c.previous.curves.map((k) => k.id));
    const added = c.session.curves.filter((k) => k.type === 'dividing' && !before.has(k.id));
    if (c.cause === 'command' && added.length > 0)
      this.pending = added.map((k) => ({ id: k.id, points: k.points }));
    else if (c.cause !== 'stroke') this.pending = [];
  }

  /** The final hair of a solve is shown. */
  hairShown(hair: StrandArrays | null): void {
    if (this.pending.length === 0 || !hair) return;
    const lines = this.pending
      .map((p) => partingReport(p.id, p.points, hair))
      .filter((m): m is string => !!m);
    this.pending = [];
    if (lines.length > 0) this.say(lines.join('; '));
  }
}
