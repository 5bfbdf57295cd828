// npm run pictures:styles: each library style's pictures (model/styleLibrary.ts), drawn from its
// session file by `hairsketch render`'s renderer: the gallery's public/styles/<id>.png, 256 × 256,
// from the style's view, and the user guide's docs/screenshots/styles/<id>.png, front, side and
// back side by side (STYLE_VIEW_SIZE=WxH each, default 360x360; STYLE_VIEW_DIR=<dir> writes them
// elsewhere). STYLE_ONLY=a,b draws only those; STYLE_GALLERY=0 skips the gallery's pictures.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { openStillRenderer } from '../web/cli/render';
import { parseSession } from '../web/model/sessionFile';
import { STYLE_LIBRARY } from '../web/model/styleLibrary';
import { VIEW_NAMES, type ViewName } from '../web/viewer/namedViews';
import { sideBySide } from './pictureStrip';

const only = process.env.STYLE_ONLY?.split(',');
const gallery = process.env.STYLE_GALLERY !== '0';
const [viewW, viewH] = (process.env.STYLE_VIEW_SIZE ?? '360x360').split('x').map(Number);
const viewDir = process.env.STYLE_VIEW_DIR ?? 'docs/screenshots/styles';
mkdirSync(viewDir, { recursive: true });

const renderer = await openStillRenderer();
try {
  for (const s of STYLE_LIBRARY) {
    if (only && !only.includes(s.id)) continue;
    const r = parseSession(JSON.parse(readFileSync(`public/styles/${s.id}.json`, 'utf8')));
    if (!r.ok) throw new Error(`${s.id}: ${r.error}`);
    const render = (views: readonly ViewName[], width: number, height: number) =>
      renderer.render(r.value, { views, width, height, quality: 'auto', timeoutMs: 600_000 });
    if (gallery) {
      const still = await render([s.view], 256, 256);
      writeFileSync(`public/styles/${s.id}.png`, still.png[0]);
    }
    const views = await render(VIEW_NAMES, viewW, viewH);
    writeFileSync(`${viewDir}/${s.id}.png`, sideBySide(views.png));
    console.log(`${s.id}: ${views.strands} strands, ${(views.ms / 1000).toFixed(1)} s`);
  }
} finally {
  await renderer.close();
}
