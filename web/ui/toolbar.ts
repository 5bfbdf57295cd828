// Toolbar buttons with accessible names (the test contract relies on them).
export interface ToolbarActions {
  tool(name: 'stream' | 'select'): void;
  undo(): void;
  redo(): void;
  deleteSelected(): void;
  hairColor(css: string): void;
}

export interface Toolbar {
  setTool(name: string): void;
  setEnabled(state: { undo: boolean; redo: boolean; del: boolean }): void;
  setHairColor(css: string): void;
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
  const stream = button('Stream curve', 'Draw a stream curve starting on the scalp (S)', () =>
    actions.tool('stream'),
  );
  const select = button('Select', 'Select a curve; drag to orbit (V)', () =>
    actions.tool('select'),
  );
  const undo = button('Undo', 'Undo (Ctrl+Z)', actions.undo);
  const redo = button('Redo', 'Redo (Ctrl+Shift+Z)', actions.redo);
  const del = button('Delete', 'Delete the selected curve (Delete)', actions.deleteSelected);
  const colorLabel = document.createElement('label');
  colorLabel.textContent = 'Hair colour';
  const color = document.createElement('input');
  color.type = 'color';
  color.addEventListener('input', () => actions.hairColor(color.value));
  colorLabel.append(color);
  root.append(stream, select, separator(), undo, redo, del, separator(), colorLabel);
  const tools: Record<string, HTMLButtonElement> = { stream, select };
  return {
    setTool(name) {
      for (const [n, b] of Object.entries(tools))
        b.setAttribute('aria-pressed', String(n === name));
    },
    setEnabled(s) {
      undo.disabled = !s.undo;
      redo.disabled = !s.redo;
      del.disabled = !s.del;
    },
    setHairColor(css) {
      color.value = css;
    },
  };
}
