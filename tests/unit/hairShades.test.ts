// The named shades (model/hairShades.ts) as the Hair panel's Shade sets them; how each reads when
// drawn is checked in hairColourRender.test.ts.
import { describe, expect, it } from 'vitest';
import { DEFAULT_HAIR_LOOK } from '../../web/model/hairLook';
import { HAIR_SHADES, shadeOf, withLighterTips, withShade } from '../../web/model/hairShades';
import { HAIR_LOOK_NUMBERS } from '../../web/model/readHairLook';

describe('hair shades', () => {
  it('each shade is found again in the look it sets, and a look of its own is none', () => {
    expect(new Set(HAIR_SHADES.map((s) => s.id)).size).toBe(HAIR_SHADES.length);
    for (const shade of HAIR_SHADES) expect(shadeOf(withShade(null, shade))).toBe(shade);
    expect(shadeOf(null)).toBeNull();
    expect(shadeOf({ ...DEFAULT_HAIR_LOOK, melanin: 0.123 })).toBeNull();
  });

  it('a shade sets the pigment and grey share within the panel ranges and keeps the rest', () => {
    const mine = { ...DEFAULT_HAIR_LOOK, variation: 0.7, roughness: 0.55 };
    for (const shade of HAIR_SHADES) {
      const look = withShade(mine, shade);
      expect(look).toEqual({
        ...mine,
        melanin: shade.melanin,
        redness: shade.redness,
        dye: shade.dye,
        grey: shade.grey,
        tipMelanin: shade.melanin,
        tipDye: null,
      });
      for (const key of ['melanin', 'redness', 'grey'] as const) {
        expect(look[key]).toBeGreaterThanOrEqual(HAIR_LOOK_NUMBERS[key].min);
        expect(look[key]).toBeLessThanOrEqual(HAIR_LOOK_NUMBERS[key].max);
      }
    }
  });

  it('with lighter tips on, the tips take an eighth of the melanin amount and the dye', () => {
    const auburn = HAIR_SHADES.find((s) => s.id === 'auburn');
    if (!auburn) throw new Error('no auburn');
    const look = withShade({ ...DEFAULT_HAIR_LOOK, tipLength: 2 }, auburn);
    // auburn 0.3: −ln(1 − 0.3) / 8 = 0.04458 → 1 − e^−0.04458 = 0.0436
    expect(look.tipMelanin).toBeCloseTo(0.044, 3);
    // the reds' tips copper-gold, not their own dye (auburn's #ff8070, hue 7°, read
    // salmon-pink): hue 60° (g − b) / (r − b) with red the largest, over 20°
    const hue = (hex: string) => {
      const [r, g, b] = [1, 3, 5].map((i) => Number.parseInt(hex.slice(i, i + 2), 16));
      return (60 * (g - b)) / (r - b);
    };
    expect(hue(auburn.dye ?? '')).toBeLessThan(10);
    expect(hue(look.tipDye ?? '')).toBeGreaterThan(20);
    expect(look.tipLength).toBe(2);
    // a shade without a dye of its own gives its tips a warm one; without tips, none
    const brown = HAIR_SHADES.find((s) => s.id === 'dark-brown');
    if (!brown || brown.dye !== null) throw new Error('dark brown has no dye');
    expect(withShade({ ...DEFAULT_HAIR_LOOK, tipLength: 2 }, brown).tipDye).toBe('#ffd8a0');
    expect(withShade({ ...DEFAULT_HAIR_LOOK, tipLength: 0 }, brown).tipDye).toBeNull();
    // Tips turned on after the shade: the same lighter tips; tips already lighter are kept
    const plain = withShade(DEFAULT_HAIR_LOOK, brown);
    expect(plain.tipMelanin).toBe(brown.melanin);
    const on = withLighterTips({ ...plain, tipLength: 2 });
    expect(on).toEqual(withShade({ ...DEFAULT_HAIR_LOOK, tipLength: 2 }, brown));
    const mine = { ...on, tipMelanin: 0.2, tipDye: null };
    expect(withLighterTips(mine)).toBe(mine);
  });
});
