// npm run screenshots — draws each preset with `hairsketch render`'s renderer (web/cli/render.ts:
// the built app's embed in Debian's Chromium, captured as Export → PNG captures the view) and
// saves docs/screenshots/<preset>-front.png, -side.png and -back.png.
//   npx tsx scripts/screenshots.ts [preset ...]     (default: every preset but `empty`)
// SHOT_QUALITY=fast|high|auto picks the Quality setting (default: the app's Auto); SHOT_OUT=<dir>
// writes elsewhere; SHOT_SIZE=WxH another size; HAIRSKETCH_DIST=<dir> draws with another build (vite build --outDir <dir>).
import { mkdirSync, writeFileSync } from 'node:fs';
import { isQualitySetting } from '../web/app/quality';
import { presetSession } from '../web/cli/presetSession';
import { openStillRenderer } from '../web/cli/render';
import { Head } from '../web/head/head';
import { PRESET_NAMES, type PresetName } from '../web/model/presets';
import { VIEW_NAMES } from '../web/viewer/namedViews';

/** The pictures' size: the editor's view at 1280 x 800 (what the README has always shown). */
/** SHOT_SIZE=WxH draws another size (e.g. small pictures for a montage). */
const [WIDTH, HEIGHT] = (process.env.SHOT_SIZE ?? '1280x651').split('x').map(Number);

async function main(): Promise<void> {
  const asked = process.argv.slice(2);
  const unknown = asked.filter((p) => !(PRESET_NAMES as readonly string[]).includes(p));
  if (unknown.length) {
    console.error(`unknown preset(s): ${unknown.join(', ')}; known: ${PRESET_NAMES.join(', ')}`);
    process.exit(2);
  }
  const presets = (
    asked.length ? asked : PRESET_NAMES.filter((p) => p !== 'empty')
  ) as PresetName[];
  const q = process.env.SHOT_QUALITY ?? 'auto';
  const quality = isQualitySetting(q) ? q : 'auto';
  const out = process.env.SHOT_OUT ?? 'docs/screenshots';
  mkdirSync(out, { recursive: true });
  const head = Head.builtin();
  const renderer = await openStillRenderer();
  try {
    for (const preset of presets) {
      const session = presetSession(preset, head);
      const still = await renderer.render(session, {
        views: VIEW_NAMES,
        width: WIDTH,
        height: HEIGHT,
        quality,
        timeoutMs: 600_000,
      });
      for (const [i, view] of VIEW_NAMES.entries())
        writeFileSync(`${out}/${preset}-${view}.png`, still.png[i]);
      console.log(
        `${preset}: ${out}/${preset}-{${VIEW_NAMES.join(',')}}.png (${still.strands} strands, ${(still.ms / 1000).toFixed(1)} s)`,
      );
    }
  } finally {
    await renderer.close();
  }
}

await main();
