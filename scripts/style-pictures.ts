// npm run pictures:styles: each library style's picture (model/styleLibrary.ts), drawn from its
// session file by `hairsketch render`'s renderer: public/styles/<id>.png, 256 × 256, from the
// style's view. STYLE_ONLY=a,b draws only those.
import { readFileSync, writeFileSync } from 'node:fs';
import { openStillRenderer } from '../web/cli/render';
import { parseSession } from '../web/model/sessionFile';
import { STYLE_LIBRARY } from '../web/model/styleLibrary';

const only = process.env.STYLE_ONLY?.split(',');
const renderer = await openStillRenderer();
try {
  for (const s of STYLE_LIBRARY) {
    if (only && !only.includes(s.id)) continue;
    const r = parseSession(JSON.parse(readFileSync(`public/styles/${s.id}.json`, 'utf8')));
    if (!r.ok) throw new Error(`${s.id}: ${r.error}`);
    const still = await renderer.render(r.value, {
      views: [s.view],
      width: 256,
      height: 256,
      quality: 'auto',
      timeoutMs: 600_000,
    });
    writeFileSync(`public/styles/${s.id}.png`, still.png[0]);
    console.log(`${s.id}: ${still.strands} strands, ${(still.ms / 1000).toFixed(1)} s`);
  }
} finally {
  await renderer.close();
}
