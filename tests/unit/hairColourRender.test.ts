// The hair's colour as drawn (tests/support/hairColourMetrics.ts): Grey 100 % reads silver-white,
// not champagne, and the same look (lighter tips too) reads as the same hue and brightness in
// Fast and High. Drawn by `hairsketch render`'s renderer (the built app's embed in Chromium); the
// hair's pixels are those that differ from the same view without hair.
import { existsSync, readFileSync } from 'node:fs';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { openStillRenderer, type StillRenderer } from '../../web/cli/render';
import { Head } from '../../web/head/head';
import { DEFAULT_HAIR_LOOK, type HairLook } from '../../web/model/hairLook';
import type { SessionState } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';
import {
  blackShare,
  hairColour,
  highlightPeak,
  hueDistance,
  skinGrain,
  skinThroughHair,
  strandContrast,
} from '../support/hairColourMetrics';
import { readPng } from './pngPixels';

const DIST_BUILT = existsSync(new URL('../../dist/embed.html', import.meta.url));
const base = presetSession('bob', Head.builtin(), '25k', 1500);
const size = { width: 320, height: 280, views: ['back'] as const };
let renderer: StillRenderer;

beforeAll(async () => {
  if (DIST_BUILT) renderer = await openStillRenderer();
});
afterAll(async () => {
  await renderer?.close();
});

async function picture(look: Partial<HairLook> | null, quality: 'fast' | 'high') {
  const s: SessionState = look
    ? { ...base, hairLook: { ...DEFAULT_HAIR_LOOK, ...look } }
    : { ...base, curves: [] };
  return readPng((await renderer.render(s, { ...size, quality })).png[0]);
}
const baldPictures = new Map<string, ReturnType<typeof readPng>>();
/** The view without hair, drawn once per quality. */
async function bald(quality: 'fast' | 'high') {
  const known = baldPictures.get(quality);
  if (known) return known;
  const p = await picture(null, quality);
  baldPictures.set(quality, p);
  return p;
}

describe.runIf(DIST_BUILT)('hair colour as drawn', () => {
  it('Grey 100 % is silver-white: the hair pixels are nearly unsaturated', async () => {
    const grey = hairColour(await picture({ melanin: 0.5, grey: 100 }, 'fast'), await bald('fast'));
    const brown = hairColour(await picture({}, 'fast'), await bald('fast'));
    console.log(
      `grey 100 %: saturation ${grey.saturation.toFixed(3)} over ${grey.pixels} pixels; mid brown ${brown.saturation.toFixed(3)}`,
    );
    expect(grey.pixels).toBeGreaterThan(2000);
    expect(grey.saturation).toBeLessThan(0.15);
    // the measure sees colour where there is some
    expect(brown.saturation).toBeGreaterThan(0.4);
  });

  it('auburn reads as the same hue and brightness in Fast and High', async () => {
    const auburn = { melanin: 0.32, redness: 0.8 };
    const fast = hairColour(await picture(auburn, 'fast'), await bald('fast'));
    const high = hairColour(await picture(auburn, 'high'), await bald('high'));
    console.log(
      `auburn: hue ${fast.hue.toFixed(1)} deg Fast, ${high.hue.toFixed(1)} High; luma ${fast.luma.toFixed(4)} Fast, ${high.luma.toFixed(4)} High`,
    );
    expect(fast.pixels).toBeGreaterThan(2000);
    expect(hueDistance(fast.hue, high.hue)).toBeLessThan(10);
    expect(Math.abs(fast.luma / high.luma - 1)).toBeLessThan(0.15);
  });

  it('lighter tips over 25 cm lighten the hair alike in Fast and High', async () => {
    // the bob's strands are 10 to 25 cm long: from near-black at 25 cm from the tip to light blonde
    // at it, the hair seen from the back is lighter (+35 % luma here: the white highlights do not
    // change), by as much in both shaders (the gain, luma with tips ÷ luma without − 1, within a
    // fifth: High drawing no tips would give 0)
    const plain = { melanin: 0.6, tipMelanin: 0.6 };
    const tips = { melanin: 0.6, tipMelanin: 0.08, tipLength: 2.5 };
    const gains = [];
    for (const quality of ['fast', 'high'] as const) {
      const without = hairColour(await picture(plain, quality), await bald(quality));
      const lighter = hairColour(await picture(tips, quality), await bald(quality));
      expect(without.pixels).toBeGreaterThan(2000);
      gains.push(lighter.luma / without.luma - 1);
    }
    console.log(
      `lighter tips over 25 cm: hair luma +${(100 * gains[0]).toFixed(0)} % in Fast, +${(100 * gains[1]).toFixed(0)} % in High`,
    );
    expect(gains[0]).toBeGreaterThan(0.25);
    expect(Math.abs(gains[1] / gains[0] - 1)).toBeLessThan(0.2);
  });

  it("the key light's highlight over the crown breaks into strands, not one band", async () => {
    // the bob (near-black, where a highlight shows most) at 8,000 strands, front and side: one
    // smooth band ringing the crown's whorl and an S on the side read as cowlicks to a stylist.
    // highlightPeak: the band-scale luma's 99th percentile over its median on the top of the
    // hair; it was 12.9 and 14.8 in Fast, 15.0 and 22.3 in High before the strands' shading
    // tangents were tilted strand by strand (7.1, 6.3 and 10.3, 9.8 after)
    const bob = presetSession('bob', Head.builtin(), '25k', 8000);
    const views = { width: 320, height: 280, views: ['front', 'side'] as const };
    const limits = { fast: 10, high: 13.5 };
    for (const quality of ['fast', 'high'] as const) {
      const hair = await renderer.render(bob, { ...views, quality });
      const none = await renderer.render({ ...bob, curves: [] }, { ...views, quality });
      const peaks = hair.png.map((png, i) => highlightPeak(readPng(png), readPng(none.png[i])));
      console.log(
        `highlight peak, ${quality}: front ${peaks[0].toFixed(2)}, side ${peaks[1].toFixed(2)}`,
      );
      for (const p of peaks) expect(p).toBeLessThan(limits[quality]);
    }
  });

  it("in High, the hair's shadow on the neck is soft, not hatched by single strands", async () => {
    // the bob from the front: High's deep opacity maps shade the neck and shoulders; with one
    // small filter for all, the shadow of the hair's ends a few centimetres off the neck was a
    // hatching of single strands' shadows (p99 grain 8.34 against Fast's 5.31, which has no hair
    // shadow on the bust); a penumbra growing with the distance behind the hair
    // (hairShadowReceiver.ts) gave 5.38
    const bob = presetSession('bob', Head.builtin(), '25k', 30000);
    const views = { width: 600, height: 600, views: ['front'] as const };
    const grain = async (quality: 'fast' | 'high') =>
      skinGrain(readPng((await renderer.render(bob, { ...views, quality })).png[0]));
    const fast = await grain('fast');
    const high = await grain('high');
    console.log(
      `skin grain: Fast ${fast.grain.toFixed(2)} (${fast.pixels} px), High ${high.grain.toFixed(2)} (${high.pixels} px)`,
    );
    expect(high.pixels).toBeGreaterThan(0.8 * fast.pixels);
    expect(high.grain).toBeLessThan(1.4 * fast.grain);
  });

  it("from behind, dark hair shows its strands in the fill's sheen, not a black shell", async () => {
    // the dark brown bob (melanin 0.7) from behind, lit by the fill alone: with the fill lighting
    // only the hair's base colour, 0.65 of its pixels in Fast and 0.59 in High were under 12 of
    // 255 in every channel; with the fill's sheen (its primary reflection), 0.39 and 0.38
    const dark = presetSession('bob', Head.builtin(), '25k', 8000);
    for (const quality of ['fast', 'high'] as const) {
      const hair = readPng((await renderer.render(dark, { ...size, quality })).png[0]);
      const share = blackShare(hair, await bald(quality));
      console.log(`dark bob from behind (${quality}): ${share.toFixed(3)} of its pixels black`);
      expect(share).toBeLessThan(0.5);
    }
  });

  it('from behind, a short crop shows its hair, not pink stripes of scalp between its clumps', async () => {
    // the library's short crop (drawn by a new user) from behind in Fast: with the scalp's colour
    // under hair only in a band along its edge, 0.073 of the top of the hair's box read as skin
    // (a judge: "stripes of scalp between the clumps, like cornrows"); with the scalp farther in
    // keeping 0.6 of it, 0.042
    const read = parseSession(
      JSON.parse(
        readFileSync(new URL('../../public/styles/short-crop.json', import.meta.url), 'utf8'),
      ),
    );
    if (!read.ok) throw new Error(read.error);
    const crop = { ...read.value, growth: { ...read.value.growth, maxStrands: 12000 } };
    const o = { ...size, quality: 'fast' as const };
    const hair = readPng((await renderer.render(crop, o)).png[0]);
    const none = readPng((await renderer.render({ ...crop, curves: [] }, o)).png[0]);
    const skin = skinThroughHair(hair, none);
    console.log(
      `short crop from behind: ${skin.toFixed(3)} of the top of the hair's box reads as skin`,
    );
    expect(skin).toBeLessThan(0.055);
  });

  it('from behind, the outer strands show, not a smooth shell', async () => {
    // the default style at full density from behind, in Fast: drawn as the weighted mean of all
    // its layers, the hair was a smooth shell, near-black down the middle (each fragment's weight
    // counted its depth from one point for the whole hair, so beyond 6 cm of it every layer
    // weighed the same); weighted from the nearest hair in each pixel, the outer strands show.
    // strandContrast 0.067 before, 0.124 after (500 × 500 pixels, 30,000 strands)
    // light brown hair whose strands vary widely in colour: a pixel that is the mean of many
    // layers is the mean of many strands' colours
    const style = {
      ...presetSession('default', Head.builtin(), '25k', 30000),
      hairLook: { ...DEFAULT_HAIR_LOOK, melanin: 0.3, tipMelanin: 0.3, variation: 1 },
    };
    const views = { width: 500, height: 500, views: ['back'] as const };
    const hair = await renderer.render(style, { ...views, quality: 'fast' });
    const none = await renderer.render({ ...style, curves: [] }, { ...views, quality: 'fast' });
    const c = strandContrast(readPng(hair.png[0]), readPng(none.png[0]));
    console.log(`from behind: strand contrast ${c.toFixed(3)}`);
    expect(c).toBeGreaterThan(0.095);
  });
});
