// The colour model on the exported strands' colours (strandsForExport with a session's
// hairLook): grey share, ombré, the seeded spread; each colour checked against the melanin
// mapping of melanin.ts taken directly (Unreal's GetHairColorFromMelanin of the pigment).
import { describe, expect, it } from 'vitest';
import { strandsForExport } from '../../web/export/strandsForExport';
import { DEFAULT_GROWTH } from '../../web/model/growthParams';
import {
  DEFAULT_HAIR_LOOK,
  GREY_MELANIN,
  GREY_REDNESS,
  type HairLook,
} from '../../web/model/hairLook';
import { hairColorFromMelanin } from '../../web/model/melanin';
import { quantizeHairLook, readHairLook } from '../../web/model/readHairLook';

/** `n` straight strands of 11 points each. */
function strands(n: number) {
  const points = new Float32Array(3 * 11 * n);
  const strandStart = new Uint32Array(n + 1);
  for (let s = 0; s < n; s++) {
    for (let i = 0; i < 11; i++) points.set([s * 0.01, -i * 0.1, 0], 3 * (11 * s + i));
    strandStart[s + 1] = 11 * (s + 1);
  }
  return { points, strandStart };
}

const exportWith = (look: HairLook, n = 2000, seed = DEFAULT_GROWTH.seed) =>
  strandsForExport(strands(n), {
    hairColor: '#5a3825',
    hairLook: look,
    growth: { ...DEFAULT_GROWTH, seed },
  });

const near = (a: ArrayLike<number>, i: number, b: readonly number[]) =>
  Math.max(...b.map((v, c) => Math.abs(a[i + c] - v))) < 1e-6;

describe('colour model on the strands', () => {
  it('a grey share of 30 % makes about 30 % of the strands unpigmented', () => {
    const look = { ...DEFAULT_HAIR_LOOK, grey: 30, variation: 0 };
    const out = exportWith(look);
    const grey = hairColorFromMelanin(GREY_MELANIN, GREY_REDNESS);
    const dark = hairColorFromMelanin(look.melanin, look.redness);
    let greys = 0;
    for (let s = 0; s < 2000; s++) {
      const isGrey = near(out.colors, 3 * s, grey);
      expect(isGrey || near(out.colors, 3 * s, dark)).toBe(true);
      if (isGrey) greys++;
    }
    // binomial: 600 ± 20.5 (one standard deviation)
    expect(greys).toBeGreaterThan(540);
    expect(greys).toBeLessThan(660);
    expect(out.pigment?.melanin[0]).toBeDefined();
  });

  it('the ombré keeps the root colour before its start and reaches the tip melanin at the tip', () => {
    const look = { ...DEFAULT_HAIR_LOOK, variation: 0, tipMelanin: 0.1, tipStart: 0.5 };
    const out = exportWith(look, 10);
    const root = hairColorFromMelanin(look.melanin, look.redness);
    const tip = hairColorFromMelanin(look.tipMelanin, look.redness);
    const pc = out.pointColors as Float32Array;
    for (let s = 0; s < 10; s++) {
      const a = out.strandStart[s];
      for (let i = 0; i <= 5; i++) expect(near(pc, 3 * (a + i), root)).toBe(true);
      expect(near(pc, 3 * (a + 10), tip)).toBe(true);
      // lighter towards the tip, point by point
      for (let i = 5; i < 10; i++) expect(pc[3 * (a + i + 1)]).toBeGreaterThan(pc[3 * (a + i)]);
      // Blender's melanin follows: root 0.4 … tip 0.1
      expect(out.pigment?.melanin[a]).toBeCloseTo(0.4, 6);
      expect(out.pigment?.melanin[a + 10]).toBeCloseTo(0.1, 6);
    }
  });

  it('the spread is seeded: the same seed gives the same colours, another seed others', () => {
    const look = { ...DEFAULT_HAIR_LOOK, grey: 10, variation: 0.3 };
    const a = exportWith(look, 200, 7);
    const b = exportWith(look, 200, 7);
    const c = exportWith(look, 200, 8);
    expect([...a.colors]).toEqual([...b.colors]);
    expect([...a.colors]).not.toEqual([...c.colors]);
    expect(new Set(a.colors).size).toBeGreaterThan(100);
  });

  it('a dye is the tint Blender reads; no colour model: no pigment, strand colours as before', () => {
    const out = exportWith({ ...DEFAULT_HAIR_LOOK, dye: '#ff0000' }, 3);
    expect([...(out.pigment?.tint.subarray(0, 3) ?? [])]).toEqual([1, 0, 0]);
    const plain = strandsForExport(strands(3), { hairColor: '#5a3825', growth: DEFAULT_GROWTH });
    expect(plain.pigment).toBeNull();
    expect(plain.pointColors).toBeNull();
  });
});

describe('session.hairLook in files and links', () => {
  it('reads what it is given, defaults what is left out, refuses what is wrong', () => {
    const look = { ...DEFAULT_HAIR_LOOK, melanin: 0.7, dye: '#A04020', grey: 12.5 };
    expect(readHairLook(JSON.parse(JSON.stringify(look)), 's.hairLook').hairLook).toEqual({
      ...look,
      dye: '#a04020',
    });
    expect(readHairLook({ redness: 0.9 }, 's.hairLook').hairLook).toEqual({
      ...DEFAULT_HAIR_LOOK,
      redness: 0.9,
    });
    expect(readHairLook(undefined, 's.hairLook')).toEqual({});
    expect(() => readHairLook({ melanin: 1.5 }, 's.hairLook')).toThrow(/melanin/);
    expect(() => readHairLook({ dye: 'red' }, 's.hairLook')).toThrow(/dye/);
    expect(() => readHairLook({ shine: 1 }, 's.hairLook')).toThrow(/shine/);
  });

  it('keeps numbers on their grid, and a look already on it as it is', () => {
    const q = quantizeHairLook({ ...DEFAULT_HAIR_LOOK, melanin: 0.12345, grey: 33.333 });
    expect(q.melanin).toBe(0.123);
    expect(q.grey).toBe(33.3);
    expect(quantizeHairLook(q)).toBe(q);
  });
});
