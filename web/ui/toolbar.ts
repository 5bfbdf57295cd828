// The toolbar, built from the actions table: a main row (tools, undo, redo, delete) that is
// always shown, and the rest (curve, file, view actions, hair colour, display toggles) inline on
// wide screens and in a "More" menu on narrow ones (phones). Buttons keep their accessible
// names (the test contract relies on them).
import { type Action, displayShortcut } from './action';

export interface ToolbarExtras {
  hairColor(css: string): void;
  openFile(file: File): void;
  /** A head mesh file chosen with "Open head". */
  /** The files picked in "Open head" (a head file, or a .gltf with its .bin and textures). */
  openHeadFiles(files: File[]): void;
  /** A picture file chosen with "Reference image". */
  openReferenceFile(file: File): void;
}

export interface Toolbar {
  /** Reflects enabled / pressed / state labels of every action. */
  refresh(): void;
  setHairColor(css: string): void;
  openFileDialog(): void;
  openHeadDialog(): void;
  openReferenceDialog(): void;
  /** Where the display toggles go. */
  readonly moreElement: HTMLElement;
}

function actionButton(a: Action): HTMLButtonElement {
  const b = document.createElement('button');
  b.type = 'button';
  b.textContent = a.label;
  const keys = a.shortcuts?.map(displayShortcut).join(' or ');
  b.title = keys ? `${a.title} (${keys})` : a.title;
  b.dataset.action = a.id;
  if (a.pressed) b.setAttribute('aria-pressed', 'false');
  if (a.widestLabel) reserveWidth(b, a.widestLabel);
  b.addEventListener('click', () => a.run());
  return b;
}

export function buildToolbar(
  root: HTMLElement,
  actions: readonly Action[],
  extras: ToolbarExtras,
): Toolbar {
  const main = document.createElement('div');
  main.className = 'toolbar-main';
  const more = document.createElement('div');
  more.className = 'toolbar-more';
  more.id = 'toolbar-more';
  const moreButton = document.createElement('button');
  moreButton.type = 'button';
  moreButton.className = 'more-button';
  moreButton.textContent = 'More';
  moreButton.title = 'More actions and display options';
  moreButton.setAttribute('aria-expanded', 'false');
  moreButton.setAttribute('aria-controls', more.id);
  const setOpen = (open: boolean) => {
    root.classList.toggle('open', open);
    moreButton.setAttribute('aria-expanded', String(open));
  };
  moreButton.addEventListener('click', () => setOpen(!root.classList.contains('open')));

  const buttons = new Map<Action, HTMLButtonElement>();
  let lastGroup = '';
  for (const a of actions) {
    if (!a.toolbar) continue;
    const b = actionButton(a);
    buttons.set(a, b);
    const row = a.toolbar === 'main' ? main : more;
    if (row === more && lastGroup && lastGroup !== a.group) more.append(separator());
    if (row === more) lastGroup = a.group;
    row.append(b);
    // a menu item closes the menu (phones)
    if (row === more) b.addEventListener('click', () => setOpen(false));
  }
  main.append(moreButton);

  const picker = document.createElement('input');
  picker.type = 'file';
  picker.accept = '.json,.usda,.glb,application/json';
  picker.hidden = true;
  picker.setAttribute('aria-label', 'Session file');
  picker.addEventListener('change', () => {
    const f = picker.files?.[0];
    picker.value = '';
    if (f) extras.openFile(f);
  });
  const headPicker = document.createElement('input');
  headPicker.type = 'file';
  headPicker.accept = '.obj,.gltf,.glb,.ply,.stl,.bin,.png,.jpg,.jpeg,.webp,.ktx2';
  headPicker.multiple = true; // a .gltf with its .bin and textures
  headPicker.hidden = true;
  headPicker.setAttribute('aria-label', 'Head file');
  headPicker.addEventListener('change', () => {
    const files = [...(headPicker.files ?? [])];
    headPicker.value = '';
    if (files.length) extras.openHeadFiles(files);
  });
  const referencePicker = document.createElement('input');
  referencePicker.type = 'file';
  referencePicker.accept = '.png,.jpg,.jpeg,.webp,image/png,image/jpeg,image/webp';
  referencePicker.hidden = true;
  referencePicker.setAttribute('aria-label', 'Reference image file');
  referencePicker.addEventListener('change', () => {
    const f = referencePicker.files?.[0];
    referencePicker.value = '';
    if (f) extras.openReferenceFile(f);
  });
  const colorLabel = document.createElement('label');
  colorLabel.textContent = 'Hair colour';
  const color = document.createElement('input');
  color.type = 'color';
  color.addEventListener('input', () => extras.hairColor(color.value));
  colorLabel.append(color);
  more.append(separator(), colorLabel, picker, headPicker, referencePicker);
  root.append(main, more);

  // closes the menu on a press outside it
  document.addEventListener('pointerdown', (e) => {
    if (root.classList.contains('open') && !root.contains(e.target as Node)) setOpen(false);
  });

  return {
    moreElement: more,
    refresh() {
      for (const [a, b] of buttons) {
        b.disabled = a.enabled ? !a.enabled() : false;
        if (a.pressed) b.setAttribute('aria-pressed', String(a.pressed()));
        if (a.stateLabel) {
          const text = a.stateLabel();
          if (b.textContent !== text) b.textContent = text;
        }
      }
    },
    setHairColor(css) {
      color.value = css;
    },
    openFileDialog() {
      picker.click();
    },
    openHeadDialog() {
      headPicker.click();
    },
    openReferenceDialog() {
      referencePicker.click();
    },
  };
}

/** Keeps `b` as wide as it is with `label` (measured once it is laid out; the button's own
 *  font), so its state labels never change the toolbar's layout. */
function reserveWidth(b: HTMLButtonElement, label: string): void {
  requestAnimationFrame(() => {
    const shown = b.textContent;
    b.textContent = label;
    const w = b.getBoundingClientRect().width;
    b.textContent = shown;
    if (w > 0) b.style.minWidth = `${Math.ceil(w)}px`;
  });
}

function separator(): HTMLElement {
  const s = document.createElement('span');
  s.className = 'sep';
  return s;
}
