// npm run pictures:shape: before and after pictures of the shape rules (docs/natural-fall.md section 5). Each session
// of tests/fixtures/shape (drawn by shape.spec.ts with real pointer events on an empty head) is
// drawn with `hairsketch render`'s renderer twice, with the shape rules off (the session as saved
// before them) and on, front, side and back: docs/screenshots/shape/<style>-{off,on}-<view>.png,
// and with ImageMagick's montage on the machine one picture per style (off above on),
// docs/screenshots/shape/<style>.png. SHOT_SIZE=WxH (default 420x340); SHAPE_ONLY=a,b draws only
// those styles. "On" is the shape rules with curl volume (natural-fall.md "Curl volume"), "off"
// neither.
import { execFileSync } from 'node:child_process';
import { mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import { openStillRenderer } from '../web/cli/render';
import type { SessionState } from '../web/model/session';
import { parseSession } from '../web/model/sessionFile';
import { VIEW_NAMES } from '../web/viewer/namedViews';

const [WIDTH, HEIGHT] = (process.env.SHOT_SIZE ?? '420x340').split('x').map(Number);
const dir = 'tests/fixtures/shape';
const out = 'docs/screenshots/shape';
mkdirSync(out, { recursive: true });

const hasMontage = (() => {
  try {
    execFileSync('montage', ['-version'], { stdio: 'ignore' });
    return true;
  } catch {
    return false;
  }
})();

const renderer = await openStillRenderer();
try {
  const only = process.env.SHAPE_ONLY?.split(',');
  for (const f of readdirSync(dir).filter(
    (n) => n.endsWith('.json') && (!only || only.includes(basename(n, '.json'))),
  )) {
    const r = parseSession(JSON.parse(readFileSync(join(dir, f), 'utf8')));
    if (!r.ok) throw new Error(`${f}: ${r.error}`);
    const style = basename(f, '.json');
    const { shape: _s, volume: _v, curlVolume: _c, ...before } = r.value;
    const files: string[] = [];
    for (const [label, session] of [
      ['off', before],
      ['on', { ...r.value, shape: true, curlVolume: true }],
    ] as [string, SessionState][]) {
      const still = await renderer.render(session, {
        views: VIEW_NAMES,
        width: WIDTH,
        height: HEIGHT,
        quality: 'auto',
        timeoutMs: 600_000,
      });
      for (const [i, view] of VIEW_NAMES.entries()) {
        const path = `${out}/${style}-${label}-${view}.png`;
        writeFileSync(path, still.png[i]);
        files.push(path);
      }
      console.log(
        `${style} (${label}): ${still.strands} strands, ${(still.ms / 1000).toFixed(1)} s`,
      );
    }
    if (hasMontage)
      execFileSync('montage', [
        ...files,
        '-tile',
        '3x',
        '-geometry',
        '+2+2',
        `${out}/${style}.png`,
      ]);
  }
} finally {
  await renderer.close();
}
