// View state: how the user is looking at the work, not the work itself. Which overlays show, the
// drawing quality, mirror editing and which ponytail stroke comes next live here, in one small
// store; none of it is in the session, its undo history or its links (quality and mirror are
// kept in localStorage: quality.ts, localSettings.ts). The toolbar, the display toggles, the hint line and the
// overlays derive what they show from it. The camera is not here: the viewer's orbit controls
// move it every frame, and the editor hands the viewer a loaded session's saved view.
import { DEFAULT_CARD_COUNT } from '../export/cardCount';
import type { PonytailStage } from '../tools/ponytailTool';
import { DEFAULT_DISPLAY, type DisplayKey, type DisplayState } from '../ui/displayToggles';
import type { QualitySetting } from './quality';

export interface ViewState {
  readonly display: Readonly<DisplayState>;
  readonly quality: QualitySetting;
  /** Mirror editing: every new curve gets a twin across the head's mirror plane. */
  readonly mirror: boolean;
  /** The ponytail stroke the Ponytail tool expects next. */
  readonly ponytailStage: PonytailStage;
  /** How many hair cards the Cards view and the hair cards export cut the hair into. */
  readonly cardCount: number;
}

/** What changed, for subscribers that react to one part only. */
export type ViewChange = { readonly state: ViewState; readonly previous: ViewState };

export class ViewStore {
  private current: ViewState;
  private readonly listeners = new Set<(c: ViewChange) => void>();

  constructor(initial: Partial<ViewState> = {}) {
    this.current = {
      display: { ...DEFAULT_DISPLAY },
      quality: 'auto',
      mirror: false,
      ponytailStage: 'spine',
      cardCount: DEFAULT_CARD_COUNT,
      ...initial,
    };
  }

  get state(): ViewState {
    return this.current;
  }

  /** Changes part of the state; subscribers hear of it once, and only when something changed. */
  update(patch: Partial<ViewState>): void {
    const previous = this.current;
    const next = { ...previous, ...patch };
    const keys = Object.keys(patch) as (keyof ViewState)[];
    if (keys.every((k) => next[k] === previous[k])) return;
    this.current = next;
    for (const l of [...this.listeners]) l({ state: next, previous });
  }

  setDisplay(key: DisplayKey, on: boolean): void {
    if (this.current.display[key] === on) return;
    this.update({ display: { ...this.current.display, [key]: on } });
  }

  /** Subscribes to every change; returns the unsubscribe function. */
  listen(listener: (c: ViewChange) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }
}
