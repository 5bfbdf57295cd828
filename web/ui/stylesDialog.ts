// The "Styles" dialog: the style library (model/styleLibrary.ts) as buttons, each a picture and
// a name. A modal <dialog>: Tab moves through the styles, Enter or a click chooses one, Escape or
// Close shuts it without a change.
import type { LibraryStyle } from '../model/styleLibrary';

export interface StylesDialog {
  readonly open: boolean;
  show(): void;
  close(): void;
}

export function buildStylesDialog(
  parent: HTMLElement,
  styles: readonly LibraryStyle[],
  pictureUrl: (s: LibraryStyle) => string,
  choose: (s: LibraryStyle) => void,
): StylesDialog {
  const dialog = document.createElement('dialog');
  dialog.className = 'styles-dialog';
  dialog.id = 'styles-dialog';
  dialog.setAttribute('aria-label', 'Styles');
  const head = document.createElement('div');
  head.className = 'styles-head';
  const title = document.createElement('h2');
  title.textContent = 'Styles';
  const close = document.createElement('button');
  close.type = 'button';
  close.textContent = 'Close';
  close.addEventListener('click', () => dialog.close());
  head.append(title, close);
  const note = document.createElement('p');
  note.className = 'styles-note';
  note.textContent =
    'Start from a style: it replaces the session (Undo brings your work back). Each is drawn with the tools, so every stroke can be edited.';
  const grid = document.createElement('div');
  grid.className = 'styles-grid';
  for (const s of styles) {
    const b = document.createElement('button');
    b.type = 'button';
    b.className = 'style-button';
    b.dataset.style = s.id;
    const img = document.createElement('img');
    img.src = pictureUrl(s);
    img.alt = '';
    img.width = 128;
    img.height = 128;
    img.loading = 'lazy';
    const name = document.createElement('span');
    name.textContent = s.name;
    b.append(img, name);
    b.addEventListener('click', () => {
      dialog.close();
      choose(s);
    });
    grid.append(b);
  }
  dialog.append(head, note, grid);
  parent.append(dialog);
  return {
    get open() {
      return dialog.open;
    },
    show() {
      if (!dialog.open) dialog.showModal();
    },
    close() {
      dialog.close();
    },
  };
}
