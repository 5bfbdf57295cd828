// Toolbar buttons with accessible names (the test contract relies on them).
export type ToolName = 'stream' | 'select' | 'dividing' | 'ponytail';

export interface ToolbarActions {
  tool(name: ToolName): void;
  undo(): void;
  redo(): void;
  deleteSelected(): void;
  hairColor(css: string): void;
  avoidScalp(): void;
  setViewpoint(): void;
  surfaceMode(): void;
  share(): void;
  saveFile(): void;
  openFile(file: File): void;
}

export interface Toolbar {
  setTool(name: string): void;
  setEnabled(state: {
    undo: boolean;
    redo: boolean;
    del: boolean;
    viewpoint: boolean;
    surfaceMode: boolean;
    avoid: boolean;
  }): void;
  setHairColor(css: string): void;
  openFileDialog(): void;
}

function button(label: string, title: string, onClick: () => void): HTMLButtonElement {
  const b = document.createElement('button');
  b.type = 'button';
  b.textContent = label;
  b.title = title;
  b.addEventListener('click', onClick);
  return b;
}

function separator(): HTMLElement {
  const s = document.createElement('span');
  s.className = 'sep';
  return s;
}

export function buildToolbar(root: HTMLElement, actions: ToolbarActions): Toolbar {
  const stream = button(
    'Stream curve',
    'Draw a stream curve starting on the scalp; on the selected curve’s supporting surface, a hint stroke edits it (S)',
    () => actions.tool('stream'),
  );
  const dividing = button(
    'Dividing curve',
    'Draw a parting on the scalp; a stroke beside the selected dividing curve tilts that side (D)',
    () => actions.tool('dividing'),
  );
  const ponytail = button(
    'Ponytail',
    'Four strokes: spine from the scalp, then cross-section and two profiles (P)',
    () => actions.tool('ponytail'),
  );
  const select = button('Select', 'Select a curve; drag to orbit (V)', () =>
    actions.tool('select'),
  );
  const viewpoint = button(
    'Set viewpoint',
    'Store the current camera as the selected curve’s viewpoint (its supporting surface is rebuilt)',
    actions.setViewpoint,
  );
  const surface = button(
    'Surface mode',
    'Switch the selected stream curve’s supporting surface: ruled (to the viewpoint) / strip (M)',
    actions.surfaceMode,
  );
  const avoid = button(
    'Avoid scalp',
    'Keep the hair out of the head: constrain the field near the scalp to point outward or along it',
    actions.avoidScalp,
  );
  const undo = button('Undo', 'Undo (Ctrl+Z)', actions.undo);
  const redo = button('Redo', 'Redo (Ctrl+Shift+Z)', actions.redo);
  const del = button('Delete', 'Delete the selected curve (Delete)', actions.deleteSelected);
  const share = button(
    'Share link',
    'Copy a link that opens this session (the address bar always holds it too)',
    actions.share,
  );
  const save = button('Save', 'Save the session as a JSON file (Ctrl+S)', actions.saveFile);
  const picker = document.createElement('input');
  picker.type = 'file';
  picker.accept = '.json,application/json';
  picker.hidden = true;
  picker.addEventListener('change', () => {
    const f = picker.files?.[0];
    picker.value = '';
    if (f) actions.openFile(f);
  });
  const open = button('Open', 'Open a session JSON file (Ctrl+O)', () => picker.click());
  const colorLabel = document.createElement('label');
  colorLabel.textContent = 'Hair colour';
  const color = document.createElement('input');
  color.type = 'color';
  color.addEventListener('input', () => actions.hairColor(color.value));
  colorLabel.append(color);
  root.append(
    stream,
    dividing,
    ponytail,
    select,
    separator(),
    viewpoint,
    surface,
    avoid,
    separator(),
    undo,
    redo,
    del,
    separator(),
    colorLabel,
    separator(),
    share,
    save,
    open,
    picker,
  );
  const tools: Record<string, HTMLButtonElement> = { stream, select, dividing, ponytail };
  return {
    setTool(name) {
      for (const [n, b] of Object.entries(tools))
        b.setAttribute('aria-pressed', String(n === name));
    },
    setEnabled(s) {
      undo.disabled = !s.undo;
      redo.disabled = !s.redo;
      del.disabled = !s.del;
      viewpoint.disabled = !s.viewpoint;
      surface.disabled = !s.surfaceMode;
      avoid.disabled = !s.avoid;
    },
    setHairColor(css) {
      color.value = css;
    },
    openFileDialog() {
      picker.click();
    },
  };
}
