// The "Reference pictures" panel: shown while the session places pictures. It lists them (a
// click selects one), and for the selected one offers "Place for this view", "Hide" (a toggle),
// "Remove" and its opacity, size and offset. Every change is one undoable edit (the app runs it
// through the reference controller). Its data-* attributes say what the view shows (the tests
// wait on them): data-pictures (placed), data-shown (drawn), data-missing, data-busy.
import type { ReferenceImage } from '../model/referenceImage';
import { REFERENCE_RANGES as R } from '../model/referenceImage';
import type { Say } from './numberInput';
import { panelButton as button, numberRow } from './panelControls';

export interface ReferencePanelEvents {
  open(): void;
  select(hash: string): void;
  placeForView(): void;
  setHidden(hidden: boolean): void;
  remove(): void;
  patch(patch: Partial<ReferenceImage>, what: string): void;
  say: Say;
}

export interface ReferencePanelState {
  pictures: readonly ReferenceImage[];
  selected: string | null;
  missing: readonly string[];
  shown: number;
  busy: boolean;
}

export interface ReferencePanel {
  show(state: ReferencePanelState): void;
}

export function buildReferencePanel(
  root: HTMLElement,
  events: ReferencePanelEvents,
): ReferencePanel {
  const panel = document.createElement('section');
  panel.id = 'reference-panel';
  panel.setAttribute('aria-label', 'Reference pictures');
  panel.dataset.testid = 'references';
  panel.hidden = true;
  root.append(panel);
  let shownKey = '';

  function render(st: ReferencePanelState): void {
    panel.replaceChildren();
    const title = document.createElement('h2');
    title.textContent = 'Reference pictures';
    const list = document.createElement('div');
    list.className = 'head-buttons';
    for (const p of st.pictures) {
      const b = button(
        p.name,
        `Select this picture (${p.width} × ${p.height}, ${p.view} view)`,
        () => events.select(p.hash),
      );
      b.setAttribute('aria-pressed', String(p.hash === st.selected));
      list.append(b);
    }
    list.append(button('Add…', 'Open another picture (PNG, JPEG or WebP)', events.open));
    panel.append(title, list);
    const sel = st.pictures.find((p) => p.hash === st.selected);
    if (!sel) return;
    const about = document.createElement('p');
    about.textContent = st.missing.includes(sel.hash)
      ? `Needs “${sel.name}” (not stored here)`
      : `Faces the ${sel.view} view`;
    const acts = document.createElement('div');
    acts.className = 'head-buttons';
    const hide = button('Hide', 'Hide or show this picture', () => events.setHidden(!sel.hidden));
    hide.setAttribute('aria-pressed', String(!!sel.hidden));
    acts.append(
      button('Place for this view', 'Make this picture face the current view', events.placeForView),
      hide,
      button('Remove', 'Take this picture out of the session', events.remove),
    );
    const patch = (p: Partial<ReferenceImage>, what: string) => events.patch(p, what);
    panel.append(
      about,
      acts,
      numberRow(
        'Opacity',
        '%',
        1,
        { min: 0, max: 100, step: 5 },
        sel.opacity * 100,
        (v) => patch({ opacity: v / 100 }, 'Picture opacity'),
        events.say,
      ),
      numberRow(
        'Size',
        'cm',
        1,
        { min: R.scale.min * 10, max: R.scale.max * 10, step: 0.5 },
        sel.scale * 10,
        (v) => patch({ scale: v / 10 }, 'Picture size'),
        events.say,
      ),
      numberRow(
        'Right',
        'cm',
        1,
        { min: R.offset.min * 10, max: R.offset.max * 10, step: 0.5 },
        sel.offset[0] * 10,
        (v) => patch({ offset: [v / 10, sel.offset[1]] }, 'Picture moved'),
        events.say,
      ),
      numberRow(
        'Up',
        'cm',
        1,
        { min: R.offset.min * 10, max: R.offset.max * 10, step: 0.5 },
        sel.offset[1] * 10,
        (v) => patch({ offset: [sel.offset[0], v / 10] }, 'Picture moved'),
        events.say,
      ),
    );
  }

  return {
    show(st) {
      panel.dataset.pictures = String(st.pictures.length);
      panel.dataset.shown = String(st.shown);
      panel.dataset.missing = String(st.missing.length);
      panel.dataset.busy = String(st.busy);
      panel.hidden = st.pictures.length === 0;
      const key = JSON.stringify([st.pictures, st.selected, st.missing]);
      if (key === shownKey) return; // keep focus while the user types
      shownKey = key;
      render(st);
    },
  };
}
