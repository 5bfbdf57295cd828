// The hair's colour as drawn (tests/support/hairColourMetrics.ts): each named Shade reads as its
// name (Silver silver-white, not champagne; Auburn red-brown), and the same look (lighter tips
// too) reads as the same hue and brightness in Fast and High. Drawn by `hairsketch render`'s renderer (the built app's embed in Chromium); the
// hair's pixels are those that differ from the same view without hair.
import { existsSync, readFileSync } from 'node:fs';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { openStillRenderer, type StillRenderer } from '../../web/cli/render';
import { Head } from '../../web/head/head';
import { DEFAULT_HAIR_LOOK, type HairLook } from '../../web/model/hairLook';
import { HAIR_SHADES, withShade } from '../../web/model/hairShades';
import { parseSession } from '../../web/model/sessionFile';
import {
  blackShare,
  bodyColour,
  clippedShare,
  greyLineShare,
  hairColour,
  hairlineWidth,
  highlightPeak,
  hueBelowShare,
  hueDistance,
  lightRim,
  shadingBlotches,
  skinGrain,
  skinThroughHair,
  strandContrast,
} from '../support/hairColourMetrics';
import { drawnToday } from '../support/lookSessions';
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

/** The bob preset's colour before it took the Dark brown shade: the near-black hair the
 *  highlight and the fill's sheen checks were made on. */
const NEAR_BLACK: HairLook = { ...DEFAULT_HAIR_LOOK, melanin: 0.7, redness: 0.1, tipMelanin: 0.7 };
/** Both qualities are drawn on one growth of the hair, in one page (the still renderer's
 *  qualities): png is Fast's pictures, then High's. */
const BOTH = ['fast', 'high'] as const;
let baldPictures: Promise<Record<'fast' | 'high', ReturnType<typeof readPng>>> | null = null;
/** The view without hair, drawn once in each quality. */
async function bald(quality: 'fast' | 'high') {
  baldPictures ??= renderer
    .render({ ...base, curves: [] }, { ...size, qualities: BOTH })
    .then(({ png }) => ({ fast: readPng(png[0]), high: readPng(png[1]) }));
  return (await baldPictures)[quality];
}
/** The near-black bob at 8,000 strands from the front, the side and the back, in both
 *  qualities (the highlight and the fill's sheen checks), with its bald views: png is Fast's
 *  three views, then High's. */
let darkBobPictures: Promise<{ hair: Uint8Array[]; none: Uint8Array[] }> | null = null;
function darkBob() {
  darkBobPictures ??= (async () => {
    const bob = { ...presetSession('bob', Head.builtin(), '25k', 8000), hairLook: NEAR_BLACK };
    const o = { width: 320, height: 280, views: ['front', 'side', 'back'] as const };
    const hair = (await renderer.render(bob, { ...o, qualities: BOTH })).png;
    const none = (await renderer.render({ ...bob, curves: [] }, { ...o, qualities: BOTH })).png;
    return { hair, none };
  })();
  return darkBobPictures;
}

/** The library's bob with a fringe as a new session draws it (the look pictures' bob) at 30,000
 *  strands, in the shade `shade`. */
const bobDrawnToday = (shade: string) => ({
  ...drawnToday('bob-fringe', 30000),
  hairLook: withShade(null, HAIR_SHADES.find((s) => s.id === shade) as never),
});

describe.runIf(DIST_BUILT)('hair colour as drawn', () => {
  it('each Shade reads as its name, in Fast and High alike', async () => {
    // The bob from behind at 1,500 strands, each shade as the Hair panel's Shade sets it; the
    // body colour (bodyColour: the middle half of the hair's pixels by luma) against how a
    // colourist names hair: the levels get lighter from Black to Platinum blonde; browns and
    // blondes are warm (hue 18-48 deg, saturated); the reds are red (hue under 25 deg, auburn
    // redder and darker than copper); Black is black, Silver nearly unsaturated (Grey 100 % read
    // as champagne blonde at saturation 0.24 before) and Platinum between it and Light blonde.
    // Before the shades, auburn's settings (melanin 0.32, redness 0.8) drew hue 24 deg, a dark
    // brown.
    // every shade on one growth of the hair (the still renderer's looks), in each quality
    // and, last, Grey 100 % typed on melanin 0.5 (no shade, no dye)
    const grey100 = { ...DEFAULT_HAIR_LOOK, melanin: 0.5, tipMelanin: 0.5, grey: 100 };
    const looks = [...HAIR_SHADES.map((shade) => withShade(null, shade)), grey100];
    const png = (await renderer.render(base, { ...size, looks, qualities: BOTH })).png.map(readPng);
    const [fast, high] = [png.slice(0, looks.length), png.slice(looks.length)];
    const body = new Map<string, ReturnType<typeof bodyColour>>();
    for (const [k, shade] of HAIR_SHADES.entries()) {
      const c = bodyColour(fast[k], await bald('fast'));
      body.set(shade.id, c);
      console.log(
        `${shade.name}: body ${c.rgb.join(',')}, hue ${c.hue.toFixed(0)}, saturation ${c.saturation.toFixed(2)}, value ${c.value.toFixed(2)}`,
      );
    }
    const at = (id: string) => body.get(id) as ReturnType<typeof bodyColour>;
    const levels = ['black', 'dark-brown', 'medium-brown', 'light-brown', 'dark-blonde'];
    levels.push('blonde', 'light-blonde', 'platinum');
    for (let k = 1; k < levels.length; k++)
      expect(at(levels[k]).luma, levels[k]).toBeGreaterThan(at(levels[k - 1]).luma);
    expect(at('black').value).toBeLessThan(0.12);
    for (const id of levels.slice(1, -1)) {
      expect(at(id).hue, id).toBeGreaterThan(18);
      expect(at(id).hue, id).toBeLessThan(48);
      expect(at(id).saturation, id).toBeGreaterThan(0.25);
    }
    for (const id of ['strawberry', 'copper', 'auburn']) expect(at(id).hue, id).toBeLessThan(25);
    for (const id of ['copper', 'auburn']) expect(at(id).saturation, id).toBeGreaterThan(0.45);
    // strawberry blonde: a blonde gone red, redder than Blonde by 10 deg at least
    expect(at('strawberry').hue).toBeLessThan(at('blonde').hue - 10);
    expect(at('strawberry').value).toBeGreaterThan(at('light-brown').value);
    // auburn a red-brown: redder and darker than copper
    expect(at('auburn').hue).toBeLessThan(at('copper').hue);
    expect(at('auburn').luma).toBeLessThan(at('copper').luma);
    // Silver nearly unsaturated, Platinum ivory: paler than Light blonde, warmer than Silver
    for (const id of ['platinum', 'silver']) expect(at(id).value, id).toBeGreaterThan(0.55);
    expect(at('silver').saturation).toBeLessThan(0.1);
    expect(at('platinum').saturation).toBeGreaterThan(at('silver').saturation + 0.05);
    expect(at('platinum').saturation).toBeLessThan(at('light-blonde').saturation);
    expect(at('salt-pepper').saturation).toBeLessThan(0.2);
    const grey = bodyColour(fast[HAIR_SHADES.length], await bald('fast'));
    console.log(`Grey 100 % at melanin 0.5: saturation ${grey.saturation.toFixed(3)}`);
    expect(grey.saturation).toBeLessThan(0.15);
    // the same settings read as the same hue and brightness in Fast and High (hair pixels' mean)
    for (const [k, shade] of HAIR_SHADES.entries()) {
      const f = hairColour(fast[k], await bald('fast'));
      const h = hairColour(high[k], await bald('high'));
      console.log(
        `${shade.name}: hue ${f.hue.toFixed(1)} deg Fast, ${h.hue.toFixed(1)} High; luma ${f.luma.toFixed(4)} Fast, ${h.luma.toFixed(4)} High`,
      );
      expect(f.pixels).toBeGreaterThan(2000);
      if (f.saturation > 0.2) expect(hueDistance(f.hue, h.hue), shade.id).toBeLessThan(10);
      expect(Math.abs(f.luma / h.luma - 1), shade.id).toBeLessThan(0.15);
    }
  });

  it('dark brown shows no red glow round the head from the side', async () => {
    // the bob in its Dark brown at 8,000 strands from the side, both qualities. With the head's
    // terminator taken as hairs the key light crosses, the light forward-scattered "through" the
    // head kept only its red and glowed on the back and the sides (a judge: "a reddish band
    // down the side" of the bob in Fast): of the hair's coloured pixels (dark brown's hues run
    // 21-28 deg), 3.4 to 4.4 % were under 18 deg in Fast and 3.6 % in High (from behind 3.2 % and
    // 3.6 %); with the head's terminator outside the hair's scattering 0.18 to 0.27 % and 0.20 to
    // 0.39 % (0.42 % and 0.40 % from behind). The side alone: the check costs half as much
    const bob = {
      ...presetSession('bob', Head.builtin(), '25k', 8000),
      hairLook: withShade(null, HAIR_SHADES.find((s) => s.id === 'dark-brown') as never),
    };
    const o = { width: 320, height: 280, views: ['side'] as const, qualities: BOTH };
    const hair = (await renderer.render(bob, o)).png.map(readPng);
    const none = (await renderer.render({ ...bob, curves: [] }, o)).png.map(readPng);
    for (const [k, quality] of BOTH.entries()) {
      const red = hueBelowShare(hair[k], none[k], 18);
      console.log(
        `dark brown bob, ${quality}: ${(100 * red).toFixed(2)} % of its pixels under 18 deg`,
      );
      expect(red, quality).toBeLessThan(0.015);
    }
  });

  it("in High, the hair's shadow on the face is soft, not a grain of single strands' shadows", async () => {
    // the library's bob with a fringe as a new session draws it (natural detail, locks, the face
    // kept clear), Dark brown, from the front in both qualities. High's shadow of the hair on the
    // skin, nine taps over a disc from one texel, was a speckle of single strands' shadows on the
    // forehead and the cheek (a judge: "grainy dotted shadow on the forehead"): of the face's
    // skin smooth in Fast (the picture's top 60 %), 7.2 % grainy in High; with 16 taps over a
    // disc from 5 texels, 4.1 % (what is left: fine hairs over the forehead, the features' edges)
    const bob = bobDrawnToday('dark-brown');
    const o = { width: 320, height: 320, views: ['front'] as const, qualities: BOTH };
    const [fast, high] = (await renderer.render(bob, o)).png.map(readPng);
    const grain = skinGrain(high, fast, 0.6);
    console.log(
      `bob with a fringe from the front: ${(100 * grain).toFixed(2)} % of the skin grainy in High`,
    );
    expect(grain).toBeLessThan(0.055);
  });

  it("from behind, a silver bob's crown keeps its strands, not a patch clipped to white", async () => {
    // the bob with a fringe in Silver from behind, both qualities: where the key light tops the
    // crown the hair's colour ran past white and clipped (a judge: "a blown-out white glow on the
    // crown"): of the hair's pixels, 3.4 % had a channel at 250 or more in Fast; with the
    // highlights' soft shoulder, 0.17 % (High 0.14 %)
    const bob = bobDrawnToday('silver');
    const o = { width: 320, height: 320, views: ['back'] as const, qualities: BOTH };
    const hair = (await renderer.render(bob, o)).png.map(readPng);
    const none = (await renderer.render({ ...bob, curves: [] }, o)).png.map(readPng);
    for (const [k, quality] of BOTH.entries()) {
      const clipped = clippedShare(hair[k], none[k], 250);
      console.log(
        `silver bob from behind, ${quality}: ${(100 * clipped).toFixed(2)} % of its pixels clipped`,
      );
      expect(clipped, quality).toBeLessThan(0.01);
    }
  });

  it('lighter tips over 25 cm lighten the hair alike in Fast and High', async () => {
    // the bob's strands are 10 to 25 cm long: from near-black at 25 cm from the tip to light blonde
    // at it, the hair seen from the back is lighter (+35 % luma here: the white highlights do not
    // change), by as much in both shaders (the gain, luma with tips ÷ luma without − 1, within a
    // fifth: High drawing no tips would give 0)
    const plain = { melanin: 0.6, tipMelanin: 0.6 };
    const tips = { melanin: 0.6, tipMelanin: 0.08, tipLength: 2.5 };
    const gains = [];
    // both looks on one growth of the hair, in each quality (the still renderer's looks and
    // qualities)
    const looks = [plain, tips].map((l) => ({ ...DEFAULT_HAIR_LOOK, ...l }));
    const png = (await renderer.render(base, { ...size, looks, qualities: BOTH })).png;
    for (const [k, quality] of BOTH.entries()) {
      const none = await bald(quality);
      const [without, lighter] = png
        .slice(2 * k, 2 * k + 2)
        .map((p) => hairColour(readPng(p), none));
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
    const { hair, none } = await darkBob();
    const limits = { fast: 10, high: 13.5 };
    for (const [k, quality] of BOTH.entries()) {
      // front and side (darkBob's first two views)
      const peaks = [0, 1].map((i) =>
        highlightPeak(readPng(hair[3 * k + i]), readPng(none[3 * k + i])),
      );
      console.log(
        `highlight peak, ${quality}: front ${peaks[0].toFixed(2)}, side ${peaks[1].toFixed(2)}`,
      );
      for (const p of peaks) expect(p).toBeLessThan(limits[quality]);
    }
  });

  it("from behind, dark hair shows its strands in the fill's sheen, not a black shell", async () => {
    // the dark brown bob (melanin 0.7) from behind, lit by the fill alone: with the fill lighting
    // only the hair's base colour, 0.65 of its pixels in Fast and 0.59 in High were under 12 of
    // 255 in every channel; with the fill's sheen (its primary reflection), 0.39 and 0.38
    const { hair } = await darkBob();
    for (const [k, quality] of BOTH.entries()) {
      // from the back (darkBob's third view), at the size of bald's pictures
      const share = blackShare(readPng(hair[3 * k + 2]), await bald(quality));
      console.log(`dark bob from behind (${quality}): ${share.toFixed(3)} of its pixels black`);
      expect(share).toBeLessThan(0.5);
    }
  });

  it('from behind, a short crop shows its hair, not pink stripes of scalp between its clumps', async () => {
    // the library's short crop (drawn by a new user) from behind in Fast: with the scalp's colour
    // under hair only in a band along its edge, 0.073 of the top of the hair's box read as skin
    // (a judge: "stripes of scalp between the clumps, like cornrows"); with the scalp farther in
    // keeping 0.6 of it, 0.042; 0.058 since roots fade in over their first 8 % (3 mm here) and the
    // scalp's tint gives way to skin under the hairline's last centimetre (the skin above the
    // ears and at the nape's edge, not between the clumps)
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
    expect(skin).toBeLessThan(0.065);
  });

  it('from the front, a pulled-back hairline thins into the skin, not a pencil line', async () => {
    // the library's high ponytail (every strand of the front combed back to the band) from the
    // front in Fast, 12,000 strands: from the hair to the forehead's skin over 6 pixels of 320
    // (the median column) when each strand was opaque from its root and the bald scalp's tint
    // ran along the edge as a pink line; 11 with roots fading in over their first 1.5 cm and the
    // tint giving way to skin under the hairline
    const read = parseSession(
      JSON.parse(
        readFileSync(new URL('../../public/styles/high-ponytail.json', import.meta.url), 'utf8'),
      ),
    );
    if (!read.ok) throw new Error(read.error);
    const tail = { ...read.value, growth: { ...read.value.growth, maxStrands: 12000 } };
    const o = { width: 320, height: 320, views: ['front'] as const, quality: 'fast' as const };
    const hair = readPng((await renderer.render(tail, o)).png[0]);
    const none = readPng((await renderer.render({ ...tail, curves: [] }, o)).png[0]);
    const width = hairlineWidth(hair, none);
    console.log(`high ponytail from the front: hair to skin over ${width} pixels`);
    expect(width).toBeGreaterThanOrEqual(9);
  });

  it('in High, the back of long hair is shaded as smoothly as in Fast: no blotches, no line, no lit cap', async () => {
    // the long preset from behind, 12,000 strands, 400 pixels: the head's shadow in the deep
    // opacity maps ended in a line across the back of the head, with blotches beside it, where
    // the hair lying on the head turns away from the key light (new users: "a sharp diagonal
    // light-to-dark line across the back of the head"); shadingBlotches 0.0282 in High against
    // 0.0215 in Fast (1.31 times); with the light falling off softly round the head, 0.0229
    // (1.07 times). Highlights and brightness by lock (ed74186, f65e80e) add shading at a lock's
    // scale to both, more sharply in High's per-pixel shading than in Fast's per-vertex: 0.0272
    // and 0.0238 (1.14 times; 1.12 to 1.16 over the lock settings tried), so the bound is 1.2
    const long = presetSession('long', Head.builtin(), '25k', 12000);
    const o = { width: 400, height: 400, views: ['back'] as const, qualities: BOTH };
    const hair = (await renderer.render(long, o)).png;
    const none = (await renderer.render({ ...long, curves: [] }, o)).png;
    const [fast, high] = [0, 1].map((q) => shadingBlotches(readPng(hair[q]), readPng(none[q])));
    console.log(`long from behind: blotches ${fast.toFixed(4)} Fast, ${high.toFixed(4)} High`);
    expect(high).toBeLessThan(1.2 * fast);
    // and as bright in both: with the soft terminator in High only, Fast's back was the lighter
    // (hair luma 1.09 times High's; a judge: 'Fast and High disagree, High darker at the back')
    const [f, h] = [0, 1].map((q) => hairColour(readPng(hair[q]), readPng(none[q])).luma);
    console.log(`long from behind: hair luma Fast / High ${(f / h).toFixed(3)}`);
    // (1.02 with the head's terminator on all of the hair; 1.058 with it fading out over the
    // lengths hanging free of the head, whose shadow the two qualities then take from the grid
    // and from the maps: the bound is 15 %)
    expect(Math.abs(f / h - 1)).toBeLessThan(0.07);
    // and no lit cap over the crown: with the key light wrapped only from N.L -0.2 to 0.5 round
    // the head, the light ended where the hair turns over the crown, a bright cap with a hard rim
    // (a judge: "a hard lit cap boundary"); lightRim (the 90th percentile of the shading's
    // gradient over the top 40 % of the hair) 0.320 Fast, 0.360 High before; wrapped from -0.7
    // to 0.7 (and Fast's lines with High's whole dual scattering), 0.185 and 0.269; with the
    // terminator outside the hair's scattering, 0.275 and 0.305 from -0.7, 0.239 and 0.281 from
    // -1.1 (the light wrapped further round)
    const [rimFast, rimHigh] = [0, 1].map((q) => lightRim(readPng(hair[q]), readPng(none[q])));
    console.log(
      `long from behind: light rim ${rimFast.toFixed(3)} Fast, ${rimHigh.toFixed(3)} High`,
    );
    expect(Math.max(rimFast, rimHigh)).toBeLessThan(0.3);
  });

  it('from the side, auburn hair has no grey-blue line across it where it turns', async () => {
    // the long preset in Auburn from the side, 12,000 strands, Fast: the fill light's sheen (white
    // on the hair, the fill bluish) lay where the strands turn through its mirror angle, as sharp
    // as the key's highlight: a thin grey-blue wavy line at the temple (a judge: "very visible on
    // red"); with a lobe three times as wide it is a soft sheen. greyLineShare (saturation 0.2
    // below the 7 x 7 median where that is over 0.6): 0.326 % before, 0.136 % after
    const shade = HAIR_SHADES.find((s) => s.id === 'auburn');
    if (!shade) throw new Error('no Auburn shade');
    // without the preset's natural detail (a shading fault, measured on the smooth hair it
    // showed on): with it, the edges of locks lying over others catch the light as thin lighter
    // lines along the strands, 0.88 % of the hair by this measure
    const { detail: _detail, ...smooth } = presetSession('long', Head.builtin(), '25k', 12000);
    const long = { ...smooth, hairLook: withShade(DEFAULT_HAIR_LOOK, shade) };
    const o = { width: 320, height: 320, views: ['side'] as const, quality: 'fast' as const };
    const share = greyLineShare(readPng((await renderer.render(long, o)).png[0]), 0.6, 0.2);
    console.log(
      `auburn long from the side: ${(100 * share).toFixed(3)} % of the hair crossed by a grey line`,
    );
    expect(share).toBeLessThan(0.002);
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
