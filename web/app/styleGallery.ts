// The "Styles" toolbar action: the dialog of the style library, and loading a chosen style's
// session file as one undoable edit (the work before it is one Undo away; the link and Save
// carry it as any session), at the session's strand count. A file that cannot be fetched or
// read changes nothing and says why.
import type { Editor } from '../editor/editor';
import {
  type LibraryStyle,
  STYLE_LIBRARY,
  styleFileUrl,
  stylePictureUrl,
} from '../model/styleLibrary';
import { buildStylesDialog, type StylesDialog } from '../ui/stylesDialog';
import { loadSession } from './sessionIO';

export interface StyleGalleryDeps {
  editor: Editor;
  parent: HTMLElement;
  status: { error(m: string): void };
}

export function styleGallery(d: StyleGalleryDeps): StylesDialog {
  const load = async (s: LibraryStyle): Promise<void> => {
    let data: unknown;
    try {
      const r = await fetch(styleFileUrl(s));
      if (!r.ok) throw new Error(`the server answered ${r.status}`);
      data = await r.json();
    } catch (e) {
      d.status.error(
        `Could not load the style “${s.name}” (${e instanceof Error ? e.message : String(e)}): nothing changed. Reload the page and try again.`,
      );
      return;
    }
    // the strand count stays as it was, as with New (a count set low for speed is kept)
    const maxStrands = d.editor.session.growth.maxStrands;
    const withCount =
      data && typeof data === 'object' && 'growth' in data && typeof data.growth === 'object'
        ? { ...data, growth: { ...data.growth, maxStrands } }
        : data;
    const parsed = loadSession(d.editor, withCount, { kind: 'style', name: s.name });
    if (!parsed.ok)
      d.status.error(`The style “${s.name}” could not be read (${parsed.error}): nothing changed.`);
  };
  return buildStylesDialog(d.parent, STYLE_LIBRARY, stylePictureUrl, (s) => void load(s));
}
