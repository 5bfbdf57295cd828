// The colour model on the exported strands' colours (strandsForExport with a session's
// hairLook): grey share, lighter tips (by length from the tip, and an older session's fraction),
// the seeded spread; each colour checked against the melanin mapping of melanin.ts taken directly
// (Unreal's GetHairColorFromMelanin of the pigment) at hand-computed melanin.
import { describe, expect, it } from 'vitest';
import { strandsForExport } from '../../web/export/strandsForExport';
import { colourPlacement } from '../../web/model/colourPlacement';
import { DEFAULT_GROWTH } from '../../web/model/growthParams';
import {
  DEFAULT_HAIR_LOOK,
  GREY_MELANIN,
  GREY_REDNESS,
  type HairLook,
} from '../../web/model/hairLook';
import { hairColorFromMelanin } from '../../web/model/melanin';
import { quantizeHairLook, readHairLook } from '../../web/model/readHairLook';
import { parseSession } from '../../web/model/sessionFile';
import { decodeSessionLink, encodeSessionLink } from '../../web/model/sessionLink';
import { pointAttributes } from '../../web/viewer/strandAttributes';

/** The melanin, by hand, `cm` from the tip of a strand whose balayage piece is `piece`, with
 *  lighter tips over `tipCm` (root melanin 0.4, tips 0.1): the strand's fade is tipCm · (0.6 +
 *  1.3 piece) long and its strength 0.4 + 0.6 piece, the tips' share t = strength · (1 − x²(3 −
 *  2x)), x = (cm − 0.35 fade) / (0.65 fade) (within 0 … 1: full strength over the last 35 % of
 *  the fade), and the melanin amounts a = −ln(1 − m) mix in log space:
 *  a = a_root^(1 − t) · a_tip^t. */
function tipMelaninByHand(cm: number, tipCm: number, piece: number): number {
  const fade = tipCm * (0.6 + 1.3 * piece);
  const x = Math.min(1, Math.max(0, (cm - 0.35 * fade) / (0.65 * fade)));
  const t = (0.4 + 0.6 * piece) * (1 - x * x * (3 - 2 * x));
  const amount = (-Math.log(0.6)) ** (1 - t) * (-Math.log(0.9)) ** t;
  return 1 - Math.exp(-amount);
}

/** Straight strands hanging down, points 0.1 apart (1 cm), `counts[s]` points in strand s. */
function hanging(counts: readonly number[]) {
  const total = counts.reduce((a, b) => a + b, 0);
  const points = new Float32Array(3 * total);
  const strandStart = new Uint32Array(counts.length + 1);
  counts.forEach((n, s) => {
    const a = strandStart[s];
    for (let i = 0; i < n; i++) points.set([s * 0.01, -i * 0.1, 0], 3 * (a + i));
    strandStart[s + 1] = a + n;
  });
  return { points, strandStart };
}

/** `n` straight strands of 11 points each. */
const strands = (n: number) => hanging(new Array(n).fill(11));

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

  it("exports the view's grey strands: the ones its attributes rank below the share", () => {
    // 3000 two-point strands rooted round a ring at the temples' height, 18 % grey (no scatter
    // below 40 %): exported grey exactly where the view's rank byte (along[4i + 2]) is below it
    const n = 3000;
    const points = new Float32Array(6 * n);
    for (let s = 0; s < n; s++) {
      const a = (2 * Math.PI * s) / n;
      points.set(
        [0.8 * Math.sin(a), 0.3, 0.8 * Math.cos(a), 0.8 * Math.sin(a), 0.2, 0.8 * Math.cos(a)],
        6 * s,
      );
    }
    const strandStart = Uint32Array.from({ length: n + 1 }, (_, i) => 2 * i);
    const look = { ...DEFAULT_HAIR_LOOK, grey: 18 };
    const out = strandsForExport(
      { points, strandStart },
      { hairColor: '#5a3825', hairLook: look, growth: DEFAULT_GROWTH },
    );
    const view = pointAttributes(points, strandStart, 0, null);
    let greys = 0;
    for (let s = 0; s < n; s++) {
      const exported = Math.abs((out.pigment?.melanin[2 * s] ?? 1) - GREY_MELANIN) < 1e-6;
      expect(exported, `strand ${s}`).toBe((view.along[4 * 2 * s + 2] + 0.5) / 256 < 0.18);
      if (exported) greys++;
    }
    expect(Math.abs(greys / n - 0.18)).toBeLessThan(0.01);
  });

  it('an older fraction keeps the root colour before its start and reaches the tip melanin at the tip', () => {
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

  it("lighter tips over 8 cm, painted in pieces: the colour depends on the distance from the tip and the strand's piece, not on its length", () => {
    const look = { ...DEFAULT_HAIR_LOOK, variation: 0, tipMelanin: 0.1, tipLength: 0.8 };
    // 11 and 31 points 1 cm apart: 10 and 30 cm long
    const out = strandsForExport(hanging([11, 31]), {
      hairColor: '#5a3825',
      hairLook: look,
      growth: DEFAULT_GROWTH,
    });
    const pc = out.pointColors as Float32Array;
    const mel = out.pigment?.melanin as Float32Array;
    const rows: string[] = [];
    // each strand's balayage section, as the view places it (a byte's middle)
    const sections = colourPlacement(hanging([11, 31]).points, hanging([11, 31]).strandStart, 0);
    for (const s of [0, 1]) {
      const piece = (sections.piece[s] + 0.5) / 256;
      for (const cm of [0, 1, 2, 4, 6, 8, 9]) {
        const m = tipMelaninByHand(cm, 8, piece);
        const p = out.strandStart[s + 1] - 1 - cm; // cm points (1 cm each) up from the tip
        expect(mel[p], `strand ${s}, ${cm} cm from the tip`).toBeCloseTo(m, 6);
        expect(
          near(pc, 3 * p, hairColorFromMelanin(m, look.redness)),
          `strand ${s}, ${cm} cm`,
        ).toBe(true);
      }
      rows.push(
        `strand ${s} (piece ${piece.toFixed(2)}): melanin ${[0, 2, 4, 6].map((cm) => mel[out.strandStart[s + 1] - 1 - cm].toFixed(3)).join(', ')} at 0, 2, 4, 6 cm`,
      );
    }
    console.log(`lighter tips over 8 cm: ${rows.join('; ')}`);
    // pieces differ: the strands' tips are not all one colour
    const forty = strands(40);
    const tips = [...colourPlacement(forty.points, forty.strandStart, 0).piece].map((b) => b / 256);
    expect(Math.max(...tips) - Math.min(...tips)).toBeGreaterThan(0.5);
    // the long strand's root, 30 cm from its tip (past any piece's fade, 12.8 cm at most), is the
    // root colour
    expect(mel[out.strandStart[1]]).toBeCloseTo(0.4, 6);

    // by arc length, not by point: points unevenly spaced, 20, 12, 9, 8, 6, 4, 2, 1, 0 cm from
    // the tip, have the colours of those distances
    const fromTip = [20, 12, 9, 8, 6, 4, 2, 1, 0];
    const uneven = strandsForExport(
      {
        points: new Float32Array(fromTip.flatMap((cm) => [0, -2 + cm / 10, 0])),
        strandStart: new Uint32Array([0, fromTip.length]),
      },
      { hairColor: '#5a3825', hairLook: look, growth: DEFAULT_GROWTH },
    );
    const melUneven = uneven.pigment?.melanin as Float32Array;
    const piece0 = 128.5 / 256; // one strand: the middle rank
    for (const [i, cm] of fromTip.entries())
      expect(melUneven[i], `${cm} cm from the tip`).toBeCloseTo(tipMelaninByHand(cm, 8, piece0), 6);
  });

  it('an older session with tipStart keeps its colours: a fraction of each strand, not a length', () => {
    // saved before lengths in cm: the long preset's look as it was (tips from 55 % of the strand)
    const old = {
      version: 4,
      curves: [],
      hairColor: '#5a3825',
      hairLook: {
        melanin: 0.35,
        redness: 0.35,
        dye: null,
        grey: 0,
        tipMelanin: 0.12,
        tipDye: null,
        tipStart: 0.55,
        variation: 0,
        roughness: 0.3,
      },
    };
    const read = parseSession(JSON.parse(JSON.stringify(old)));
    if (!read.ok) throw new Error(read.error);
    const look = read.value.hairLook as HairLook;
    expect(look.tipStart).toBe(0.55);
    expect(look.tipLength).toBe(0);
    const out = strandsForExport(hanging([11, 31]), {
      hairColor: '#5a3825',
      hairLook: look,
      growth: DEFAULT_GROWTH,
    });
    const mel = out.pigment?.melanin as Float32Array;
    // by hand, as before: t = s((along − 0.55) / 0.45) at along = i / (n − 1), so along 0.6, 0.7,
    // 0.8, 0.9 give x = 1/9, 1/3, 5/9, 7/9 and t = 25/729, 7/27, 425/729, 637/729; melanin
    // 1 − 0.65^(1 − t) 0.88^t
    const byHand: [number, number][] = [
      [0.5, 0.35],
      [0.6, 0.3432118],
      [0.7, 0.296889],
      [0.8, 0.2244371],
      [0.9, 0.1530094],
      [1, 0.12],
    ];
    for (const [along, m] of byHand)
      for (const s of [0, 1]) {
        const n = out.strandStart[s + 1] - out.strandStart[s];
        const p = out.strandStart[s] + Math.round(along * (n - 1));
        expect(mel[p], `strand ${s} at ${along}`).toBeCloseTo(m, 6);
      }
    // so the two strands differ at the same distance from the tip (3 cm: 0.7 of the short one)
    const at3cm = [0, 1].map((s) => mel[out.strandStart[s + 1] - 1 - 3]);
    console.log(
      `older tipStart 0.55: 3 cm from the tip melanin ${at3cm.map((v) => v.toFixed(4)).join(' (10 cm strand), ')} (30 cm strand)`,
    );
    expect(at3cm[0]).toBeCloseTo(0.296889, 6); // along 0.7
    expect(at3cm[1]).toBeCloseTo(0.1530094, 6); // along 0.9
  });

  it('resampled strands (over 255 points) take the distance from the tip by arc length', () => {
    // 601 points 1 cm apart (6 m) are exported as 255 evenly by arc length: point k of 254 is
    // 600 (1 − k / 254) cm from the tip; 8 cm from the tip is not a kept point, 600 · 3/254 cm
    // (7.087 cm) is, as are 600 · 6/254 cm (14.17 cm: past any piece's fade, 12.8 cm at most)
    const look = { ...DEFAULT_HAIR_LOOK, variation: 0, tipMelanin: 0.1, tipLength: 0.8 };
    const out = strandsForExport(hanging([601]), {
      hairColor: '#5a3825',
      hairLook: look,
      growth: DEFAULT_GROWTH,
    });
    const mel = out.pigment?.melanin as Float32Array;
    expect(out.strandStart[1]).toBe(255);
    const piece = 128.5 / 256; // one strand: the middle rank
    expect(mel[254]).toBeCloseTo(tipMelaninByHand(0, 8, piece), 6);
    expect(mel[251]).toBeCloseTo(tipMelaninByHand((600 * 3) / 254, 8, piece), 6);
    expect(mel[248]).toBeCloseTo(0.4, 6);
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
    const q = quantizeHairLook({
      ...DEFAULT_HAIR_LOOK,
      melanin: 0.12345,
      grey: 33.333,
      tipLength: 0.81234,
    });
    expect(q.melanin).toBe(0.123);
    expect(q.grey).toBe(33.3);
    expect(q.tipLength).toBe(0.812);
    expect(q.tipStart).toBeUndefined();
    expect(quantizeHairLook(q)).toBe(q);
    // an older fraction on its grid; one that rounds to 1 (no tips) is dropped
    expect(quantizeHairLook({ ...DEFAULT_HAIR_LOOK, tipStart: 0.55 }).tipStart).toBe(0.55);
    expect('tipStart' in quantizeHairLook({ ...DEFAULT_HAIR_LOOK, tipStart: 0.9996 })).toBe(false);
  });

  it('reads an older tipStart as it was (1: none), and never with tipLength', () => {
    const older = readHairLook({ tipStart: 0.55, tipMelanin: 0.12 }, 's.hairLook').hairLook;
    expect(older).toEqual({ ...DEFAULT_HAIR_LOOK, tipMelanin: 0.12, tipStart: 0.55 });
    // every session saved before wrote tipStart 1 for no tips: it reads as a new look's none
    expect(readHairLook({ tipStart: 1 }, 's.hairLook').hairLook).toEqual(DEFAULT_HAIR_LOOK);
    expect(readHairLook({ tipLength: 0.8 }, 's.hairLook').hairLook?.tipLength).toBe(0.8);
    expect(readHairLook({ tipStart: 1, tipLength: 0.8 }, 's.hairLook').hairLook).toEqual({
      ...DEFAULT_HAIR_LOOK,
      tipLength: 0.8,
    });
    expect(() => readHairLook({ tipStart: 0.5, tipLength: 0.8 }, 's.hairLook')).toThrow(
      /hairLook\.tipStart: cannot be set with tipLength/,
    );
    expect(() => readHairLook({ tipLength: 11 }, 's.hairLook')).toThrow(/tipLength/);
  });

  it('a link keeps lighter tips in cm, and an older fraction', async () => {
    const base = parseSession({ version: 4, curves: [] });
    if (!base.ok) throw new Error(base.error);
    for (const hairLook of [
      { ...DEFAULT_HAIR_LOOK, tipMelanin: 0.12, tipLength: 0.8 },
      { ...DEFAULT_HAIR_LOOK, tipMelanin: 0.12, tipStart: 0.55 },
    ]) {
      const back = await decodeSessionLink(await encodeSessionLink({ ...base.value, hairLook }));
      if (!back.ok) throw new Error(back.error);
      expect(back.value.hairLook).toEqual(hairLook);
    }
  });
});
