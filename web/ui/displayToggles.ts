// Display toggles (method S6.2): a compact row of checkboxes with accessible names "Curves",
// "Constraints", "Surface", "Field", "Box" and "Cards" (the hair as hair cards; keys 1–6: the
// actions table, app/actions.ts). The state is view
// state, not part of the session: it is neither in the undo history nor in share links.

export interface DisplayState {
  curves: boolean; // the style curves
  constraints: boolean; // their constraints, coloured as in the paper's Figs. 2, 4, 5
  surface: boolean; // the supporting surface of the selected stream curve
  field: boolean; // the solved vector field as glyphs
  box: boolean; // the bounding volume (the grid's box)
  cards: boolean; // the hair as the hair cards export cuts it, instead of the strands
}
export type DisplayKey = keyof DisplayState;

export const DEFAULT_DISPLAY: Readonly<DisplayState> = {
  curves: true,
  constraints: false,
  surface: false,
  field: false,
  box: false,
  cards: false,
};

/** Order of the checkboxes, their labels and their shortcut keys ("1" .. "6"). */
export const DISPLAY_TOGGLES: ReadonlyArray<{ key: DisplayKey; label: string; title: string }> = [
  { key: 'curves', label: 'Curves', title: 'Show the style curves' },
  { key: 'constraints', label: 'Constraints', title: 'Show the constraints the curves make' },
  { key: 'surface', label: 'Surface', title: "Show the selected curve's supporting surface" },
  { key: 'field', label: 'Field', title: 'Show the vector field as glyphs' },
  { key: 'box', label: 'Box', title: 'Show the bounding volume' },
  {
    key: 'cards',
    label: 'Cards',
    title: 'Show the hair as the hair cards a game draws (Export → Hair cards), not as strands',
  },
];

export interface DisplayToggles {
  readonly element: HTMLElement;
  /** Reflects a state in the checkboxes (no change event). */
  set(state: DisplayState): void;
}

/** Builds the row into `root`. `onToggle` gets each change a user makes (click or shortcut). */
export function buildDisplayToggles(
  root: HTMLElement,
  initial: DisplayState,
  onToggle: (key: DisplayKey, on: boolean) => void,
): DisplayToggles {
  const group = document.createElement('div');
  group.className = 'display-toggles';
  group.setAttribute('role', 'group');
  group.setAttribute('aria-label', 'Display');
  const boxes = new Map<DisplayKey, HTMLInputElement>();
  DISPLAY_TOGGLES.forEach(({ key, label, title }, i) => {
    const l = document.createElement('label');
    l.title = `${title} (${i + 1})`;
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.checked = initial[key];
    box.dataset.testid = `display-${key}`;
    // A click leaves no focus on the checkbox: the app's shortcuts (Delete, Escape, S, V, Ctrl+Z)
    // ignore keys typed into inputs. Toggled from the keyboard (Tab, Space), it keeps the focus.
    let byPointer = false;
    l.addEventListener('pointerdown', () => {
      byPointer = true;
    });
    box.addEventListener('change', () => {
      if (byPointer) box.blur();
      byPointer = false;
      onToggle(key, box.checked);
    });
    l.append(box, label);
    group.append(l);
    boxes.set(key, box);
  });
  root.append(group);
  return {
    element: group,
    set(state) {
      for (const [key, box] of boxes) box.checked = state[key];
    },
  };
}

/** Whether key presses on `target` type text (then they are not shortcuts). */
export function typesText(target: EventTarget | null): boolean {
  if (target instanceof HTMLTextAreaElement) return true;
  if (target instanceof HTMLElement && target.isContentEditable) return true;
  return (
    target instanceof HTMLInputElement &&
    !['checkbox', 'radio', 'button', 'color'].includes(target.type)
  );
}
