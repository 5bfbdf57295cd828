// npm run bench:colour: the hair's colour as drawn, in Fast and High (tests/support/
// hairColourMetrics.ts): for named looks on the bob preset (3,000 strands), each view drawn by
// `hairsketch render`'s renderer in both qualities and without hair; the hair pixels' mean hue,
// luma and saturation, and Fast against High. Writes bench-results/colour.{json,md}.

import { hairColour, hueDistance } from '../tests/support/hairColourMetrics';
import { readPng } from '../tests/unit/pngPixels';
import { presetSession } from '../web/cli/presetSession';
import { openStillRenderer } from '../web/cli/render';
import { Head } from '../web/head/head';
import { DEFAULT_HAIR_LOOK, type HairLook } from '../web/model/hairLook';
import type { SessionState } from '../web/model/session';
import { writeBenchResults } from './benchResults.mjs';

export const NAMED_LOOKS: Record<string, Partial<HairLook>> = {
  'mid brown (default)': {},
  'auburn (melanin 0.32, redness 0.8)': { melanin: 0.32, redness: 0.8 },
  'grey 100 % (melanin 0.5)': { melanin: 0.5, grey: 100 },
  'black (melanin 0.9)': { melanin: 0.9, redness: 0.1 },
  'blonde (melanin 0.15)': { melanin: 0.15, redness: 0.35 },
};

const head = Head.builtin();
const base = presetSession('bob', head, '25k', 3000);
const bald: SessionState = { ...base, curves: [] };
const renderer = await openStillRenderer();
const size = { width: 480, height: 400 };
const views = ['back', 'side'] as const;
const rows: Record<string, unknown>[] = [];
try {
  const baldFast = await renderer.render(bald, { views, ...size, quality: 'fast' });
  const baldHigh = await renderer.render(bald, { views, ...size, quality: 'high' });
  for (const [name, look] of Object.entries(NAMED_LOOKS)) {
    const s = { ...base, hairLook: { ...DEFAULT_HAIR_LOOK, ...look } } as SessionState;
    const fast = await renderer.render(s, { views, ...size, quality: 'fast' });
    const high = await renderer.render(s, { views, ...size, quality: 'high' });
    views.forEach((view, i) => {
      const f = hairColour(readPng(fast.png[i]), readPng(baldFast.png[i]));
      const h = hairColour(readPng(high.png[i]), readPng(baldHigh.png[i]));
      const row = {
        look: name,
        view,
        fastHue: +f.hue.toFixed(1),
        highHue: +h.hue.toFixed(1),
        hueApart: +hueDistance(f.hue, h.hue).toFixed(1),
        fastLuma: +f.luma.toFixed(4),
        highLuma: +h.luma.toFixed(4),
        lumaRatio: +(f.luma / h.luma).toFixed(3),
        fastSaturation: +f.saturation.toFixed(3),
        highSaturation: +h.saturation.toFixed(3),
      };
      rows.push(row);
      console.log(JSON.stringify(row));
    });
  }
} finally {
  await renderer.close();
}
const table = [
  '| look | view | hue Fast | hue High | apart (°) | luma Fast | luma High | Fast / High | saturation Fast | saturation High |',
  '| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |',
  ...rows.map(
    (r) =>
      `| ${r.look} | ${r.view} | ${r.fastHue} | ${r.highHue} | ${r.hueApart} | ${r.fastLuma} | ${r.highLuma} | ${r.lumaRatio} | ${r.fastSaturation} | ${r.highSaturation} |`,
  ),
].join('\n');
writeBenchResults('colour', {
  title: 'Hair colour as drawn, Fast against High',
  script: 'scripts/bench-colour.ts',
  command: 'npm run bench:colour',
  measures:
    'The bob preset (3,000 strands) with named looks, drawn by `hairsketch render` at 480×400 in Fast and High; the hair pixels (those differing from the same view without hair): circular mean hue (weighted by saturation × value), mean relative luminance, mean HSV saturation.',
  config: { preset: 'bob', strands: 3000, size, views },
  results: rows,
  table,
});
