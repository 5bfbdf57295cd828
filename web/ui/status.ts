// The status line: a visible sentence plus data-* attributes for automated tests. Details that
// only some users want (solver method, iterations, timings) go to its tooltip.
export type AppState = 'loading' | 'solving' | 'ready' | 'error';

export class StatusLine {
  state: AppState = 'loading';
  strands = 0;
  curves = 0;
  revision = 0;

  constructor(
    private readonly el: HTMLElement,
    private readonly hintEl: HTMLElement,
  ) {}

  set(state: AppState, text: string, details = ''): void {
    this.state = state;
    this.el.dataset.state = state;
    this.el.textContent = text;
    // the whole sentence when the line is clamped, then the details
    this.el.title = details ? `${text}\n${details}` : text;
  }

  counts(strands: number, curves: number): void {
    this.strands = strands;
    this.curves = curves;
    this.el.dataset.strands = String(strands);
    this.el.dataset.curves = String(curves);
  }

  /** Whether the hair on screen is every strand (`data-detail` full) or the sample a slow
   *  renderer draws while the view moves and until the full-detail frame is drawn (sample). */
  detail(full: boolean): void {
    const v = full ? 'full' : 'sample';
    if (this.el.dataset.detail !== v) this.el.dataset.detail = v;
  }

  bumpRevision(): void {
    this.revision++;
    this.el.dataset.revision = String(this.revision);
  }

  hint(text: string): void {
    this.hintEl.textContent = text;
    this.hintEl.title = text;
  }
}
