// The ties' bands in the view: measured from the hair shown (model/tieBands.ts) each time new
// hair is shown, recoloured when the band colour changes, gone when the session's `ties` is
// turned off. The bands are measured against the session at the time the hair arrives (its
// tailCurves index that session's curves: the solver answers the newest request).
import type { Editor } from '../editor/editor';
import type { StrandArrays } from '../model/hairArrays';
import { DEFAULT_BAND_COLOR } from '../model/hairLook';
import { tieBands } from '../model/tieBands';
import type { TieBandView } from '../viewer/tieBandView';

export class TieBandPresenter {
  private measured: StrandArrays | null = null;

  constructor(
    private readonly view: TieBandView,
    private readonly editor: Editor,
  ) {
    editor.listen((c) => {
      if (!c.sessionChanged) return;
      if (!c.session.ties) this.view.show([], this.colour());
      else if (c.session.bandColor !== c.previous.bandColor)
        this.view.show(this.view.shown, this.colour());
    });
  }

  /** Call with the hair shown (null: none). A stroke's previews carry no tailCurves (thinned
   *  for drawing, model/strandSubsample.ts): the bands of the hair before them stay until the
   *  converged hair comes, rather than blinking out while the user draws. */
  hairShown(strands: StrandArrays | null): void {
    if (strands === this.measured || (strands && !strands.tailCurves)) return;
    this.measured = strands;
    this.view.show(strands ? tieBands(this.editor.session, strands) : [], this.colour());
  }

  private colour(): string {
    return this.editor.session.bandColor ?? DEFAULT_BAND_COLOR;
  }
}
