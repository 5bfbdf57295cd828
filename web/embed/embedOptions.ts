// The embed page's query options: which still view to start from, the drawing quality, and
// `still` (a picture for `hairsketch render`: no link, no status text over the view).
import { isQualitySetting, type QualitySetting } from '../app/quality';
import { isViewName, type ViewName } from '../viewer/namedViews';

export interface EmbedOptions {
  /** null: the app's starting view. */
  view: ViewName | null;
  quality: QualitySetting;
  still: boolean;
}

/** Options from `location.search`; unknown values are ignored (the embed has nowhere to say so
 *  but its status line, and a bad option must not stop the picture). */
export function parseEmbedOptions(search: string): EmbedOptions {
  const q = new URLSearchParams(search);
  const view = q.get('view') ?? '';
  const quality = q.get('quality') ?? '';
  return {
    view: isViewName(view) ? view : null,
    quality: isQualitySetting(quality) ? quality : 'auto',
    still: q.has('still'),
  };
}

/** The editor's address for the session an embed at `href` shows (same origin, same fragment). */
export function editorUrlFor(href: string): string {
  const u = new URL(href);
  u.pathname = u.pathname.replace(/embed\.html$/, '');
  u.search = '';
  return u.toString();
}
