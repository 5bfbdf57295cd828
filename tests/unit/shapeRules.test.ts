// The shape rules on stroke sets drawn by hand (tests/fixtures/shape: sessions shape.spec.ts drew
// with real pointer events on an empty head), grown by the real wasm engine as `hairsketch grow`
// grows them, measured from the strands against the head's exact signed distance and the
// strokes themselves: short spikes, tucked behind the ears, a short crop (slicked back), a long
// sweep. Each figure is also taken with the rules off (the session as saved before them), where
// the fault they fix shows.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { headForGrow } from '../../web/cli/head';
import { growSessionHair } from '../../web/export/growSession';
import { EYE_R, EYE_X, EYE_Y, EYE_Z, headSdf } from '../../web/head/headSdf';
import { gridForSession } from '../../web/model/grid';
import type { StrandArrays } from '../../web/model/hairArrays';
import { hangLength, type SessionState } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';
import { loadSolverEngine } from '../../web/solver/wasmEngine';
import {
  dist,
  eachStrand,
  earCoverShare,
  faceShare,
  fallOfUngoverned,
  lowerHairline,
  median,
  quantile,
  standOff,
  templeStrays,
  type V3,
  widthAtEars,
} from '../support/shapeMetrics';

function fixture(name: string): SessionState {
  const r = parseSession(
    JSON.parse(readFileSync(new URL(`../fixtures/shape/${name}.json`, import.meta.url), 'utf8')),
  );
  if (!r.ok) throw new Error(r.error);
  return { ...r.value, growth: { ...r.value.growth, maxStrands: 4000 } };
}

const wasmBinary = new Uint8Array(
  readFileSync(fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url))),
);

/** The hair of each session grown so far (the slicked crop is measured by two tests). */
const grown = new Map<string, Promise<StrandArrays>>();
function grow(s: SessionState): Promise<StrandArrays> {
  const key = JSON.stringify(s);
  let hair = grown.get(key);
  if (!hair) {
    hair = growFresh(s);
    grown.set(key, hair);
  }
  return hair;
}

async function growFresh(s: SessionState): Promise<StrandArrays> {
  const { scalp } = await headForGrow(s, undefined, null);
  const engine = await loadSolverEngine({ wasmBinary });
  try {
    return growSessionHair(engine, s, scalp, {
      grid: gridForSession(s.grid, s.curves, undefined, hangLength(s)),
      solver: 'fast',
    }).strands;
  } finally {
    engine.dispose();
  }
}

/** The lower hairline of the session's scalp (shapeMetrics lowerHairline). */
async function hairlineOf(s: SessionState) {
  const { scalp } = await headForGrow(s, undefined, null);
  return lowerHairline(scalp);
}
/** Whether p lies in the band round the lower hairline where short hair fades out (2.5 cm above
 *  it to 1 cm below, with 2 mm to spare for the bins). */
const inFade = (line: { at: (x: number, z: number) => number }, p: readonly number[]) => {
  const h = p[1] - line.at(p[0], p[2]);
  return h < 0.27 && h > -0.12;
};

const off = (s: SessionState): SessionState => {
  const { shape: _s, volume: _v, ...rest } = s;
  return rest;
};

/** Hair no stroke ends, rooted 4 cm or more from every stroke point: the median of its length
 *  over the Shepard blend of the stream curves' lengths (weights 1 / squared distance from the
 *  root to each curve's first point; a curve extended off the head counts as Max length, one that
 *  combs (ends on the scalp) only when every curve combs),
 *  capped by Max length, computed here from the strokes and the head's exact distance. */
function lengthRatio(
  s: StrandArrays,
  session: SessionState,
  skip: (tip: V3) => boolean = () => false,
): number {
  const maxLength = session.growth.maxLength;
  const strokes = session.curves
    .filter((c) => c.type === 'stream')
    .map((c) => {
      let L = 0;
      for (let i = 1; i < c.points.length; i++) L += dist(c.points[i], c.points[i - 1]);
      // a stroke that grows on counts as Max length, unless it ends on the scalp (within 5 mm:
      // it combs, and counts its own length)
      const end = c.points[c.points.length - 1];
      const combs = headSdf(end[0], end[1], end[2]) < 0.05;
      return {
        start: c.points[0],
        length: c.extend && !combs ? maxLength : Math.min(L, maxLength),
        combs: c.extend && combs,
      };
    })
    // a stroke that combs counts only when every stroke combs
    .filter((c, _, all) => !c.combs || all.every((o) => o.combs));
  const ratios: number[] = [];
  eachStrand(s, (pts) => {
    if (session.curves.some((c) => c.points.some((q) => dist(q, pts[0]) < 0.4))) return;
    if (skip(pts[pts.length - 1])) return;
    let sw = 0;
    let swl = 0;
    for (const c of strokes) {
      const w = 1 / (dist(c.start, pts[0]) ** 2 + 1e-4);
      sw += w;
      swl += w * c.length;
    }
    let len = 0;
    for (let i = 1; i < pts.length; i++) len += dist(pts[i], pts[i - 1]);
    ratios.push(len / Math.min(maxLength, swl / sw));
  });
  return median(ratios);
}

describe('the shape rules on hand-drawn stroke sets', () => {
  it('short spikes drawn up and away lift their own hair only; far hair lies on the head', async () => {
    const s = fixture('spikes');
    const [before, after] = [await grow(off(s)), await grow(s)];
    const fb = fallOfUngoverned(before, s.curves);
    const fa = fallOfUngoverned(after, s.curves);
    const lieB = standOff(before, s.curves, 0.3, 0.4);
    const lieA = standOff(after, s.curves, 0.3, 0.4);
    console.log(
      `spikes, rules off -> on: median angle from down ${fb.medianAngle.toFixed(1)} -> ${fa.medianAngle.toFixed(1)} deg, above the root ${(100 * fb.aboveShare).toFixed(1)} -> ${(100 * fa.aboveShare).toFixed(1)} %, off the head ${(10 * lieB).toFixed(2)} -> ${(10 * lieA).toFixed(2)} cm`,
    );
    expect(fb.medianAngle).toBeGreaterThan(35); // the fault
    expect(fa.medianAngle).toBeLessThanOrEqual(35);
    expect(fa.aboveShare).toBeLessThanOrEqual(0.1);
    expect(lieA).toBeLessThanOrEqual(0.1);
    expect(lieB).toBeGreaterThan(0.1);
  });

  // ours, and the strokes a new user drew from the user guide's recipe (eyes-tucked)
  it.each(['tucked', 'eyes-tucked'])(
    '%s behind the ears: the ears stay open, the hair lies on the head',
    async (name) => {
      const s = fixture(name);
      const [before, after] = [await grow(off(s)), await grow(s)];
      const [eb, ea] = [earCoverShare(before), earCoverShare(after)];
      const lie = standOff(after, s.curves, 0.3, 0.4);
      const strays = templeStrays(after, s.curves);
      console.log(
        `${name}, rules off -> on: ${(100 * eb).toFixed(2)} -> ${(100 * ea).toFixed(2)} % of strands hide an ear; off the head ${(10 * lie).toFixed(2)} cm; ${(100 * strays).toFixed(2)} % stray across the temples`,
      );
      expect(ea).toBeLessThan(eb);
      // front hair no stroke governs parts aside and back round the temples, not across the eyes
      expect(strays).toBeLessThanOrEqual(0.005);
      expect(ea).toBeLessThanOrEqual(0.02);
      expect(lie).toBeLessThanOrEqual(0.1);
    },
  );

  it('tucked behind the ears at Volume 1.2 cm: the front hair parts at the hairline, no fringe nobody drew', async () => {
    // fresh eyes drew tucked behind the ears with the guide's Volume 1.2 cm: the front hair,
    // lifted off the hairline, came down over the forehead and ended on its skin as a short
    // blunt fringe. Strands with a point over the forehead, standing off it (6 mm to 3 cm off the
    // head, between 2 cm above the centre and just below the front hairline, within 3.5 cm of
    // the middle): 0 % at Volume 0; at 1.2 cm 1.18 % before the face's column reached up by the
    // Volume, 0 % after
    const s = { ...fixture('tucked'), volume: 0.12 };
    const overForehead = (hair: StrandArrays) => {
      let n = 0;
      let over = 0;
      eachStrand(hair, (pts) => {
        n++;
        const off = ([x, y, z]: V3) => {
          if (!(Math.abs(x) < 0.35 && y > 0.2 && y < 0.47 && z > 0.5)) return false;
          const d = headSdf(x, y, z);
          return d > 0.06 && d < 0.3;
        };
        if (pts.some(off)) over++;
      });
      return n ? over / n : 0;
    };
    const [flat, lifted] = [
      overForehead(await grow(fixture('tucked'))),
      overForehead(await grow(s)),
    ];
    console.log(
      `tucked: ${(100 * flat).toFixed(2)} % of strands over the forehead at Volume 0, ${(100 * lifted).toFixed(2)} % at 1.2 cm`,
    );
    expect(lifted).toBeLessThanOrEqual(Math.max(0.002, 2 * flat));
  });

  it('a short crop: hair no stroke ends is as long as the strokes around (within 20 %)', async () => {
    const s = fixture('slicked');
    const [before, after] = [await grow(off(s)), await grow(s)];
    // hair that ends round the lower hairline ends by the fade there (the next test)
    const line = await hairlineOf(s);
    const [rb, ra] = [lengthRatio(before, s), lengthRatio(after, s, (tip) => inFade(line, tip))];
    console.log(
      `short crop, rules off -> on: length of hair no stroke ends over its strokes' ${rb.toFixed(2)} -> ${ra.toFixed(2)}`,
    );
    expect(rb).toBeGreaterThan(1.2);
    expect(ra).toBeGreaterThan(0.8);
    expect(ra).toBeLessThan(1.2);
    expect(standOff(after, s.curves, 0.3, 0.4)).toBeLessThanOrEqual(0.1);
  });

  it.each(['pixie', 'eyes-pixie', 'eyes17-pixie', 'slicked'])(
    '%s: short hair fades out round the lower hairline (nape and over the ears), not on one line',
    async (name) => {
      const s = fixture(name);
      const line = await hairlineOf(s);
      const after = await grow(s);
      // the short hair that comes down to within 3 cm of the line behind the ears: where it ends
      // against the line (cm, + above)
      const ends: number[] = [];
      eachStrand(after, (pts) => {
        const tip = pts[pts.length - 1];
        const h = tip[1] - line.at(tip[0], tip[2]);
        if (!Number.isFinite(h) || pts[0][1] - tip[1] < 0.05 || h > 0.3) return;
        ends.push(10 * h);
      });
      const below = ends.filter((h) => h < -1.2).length / ends.length;
      const [q25, q50, q75] = [0.25, 0.5, 0.75].map((q) => quantile(ends, q));
      console.log(
        `${name}: ${ends.length} strands end round the lower hairline, quartiles ${q25.toFixed(2)} / ${q50.toFixed(2)} / ${q75.toFixed(2)} cm from it; ${(100 * below).toFixed(1)} % more than 1.2 cm below it`,
      );
      expect(ends.length).toBeGreaterThan(100);
      // spread over the band (2.5 cm above to 1 cm below; hair from higher up ends as it comes
      // down into it, so more end in its upper part), so the nape thins out to the skin; no
      // hair hangs on down the neck (without the fade: median about 1 cm below, 10 % or more
      // past 2 cm below)
      expect(below).toBeLessThanOrEqual(0.05);
      expect(q50).toBeGreaterThan(0.2);
      expect(q75 - q25).toBeGreaterThan(0.6);
    },
  );

  it('Avoid scalp lays the short crop along the scalp without wings', async () => {
    const s = { ...fixture('slicked'), avoidScalp: true };
    const [before, after] = [widthAtEars(await grow(off(s))), widthAtEars(await grow(s))];
    console.log(
      `short crop with Avoid scalp, rules off -> on: ${(10 * before.hair).toFixed(1)} -> ${(10 * after.hair).toFixed(1)} cm wide at the ears (the head ${(10 * after.head).toFixed(1)} cm)`,
    );
    expect(before.hair).toBeGreaterThan(before.head + 0.4); // the wings
    expect(after.hair).toBeLessThanOrEqual(after.head + 0.2);
  });

  it('a long sweep: the hair lies on the head and takes the sweep’s length', async () => {
    const s = fixture('sweep');
    const after = await grow(s);
    const lie = standOff(after, s.curves, 0.3, 0.4);
    const ratio = lengthRatio(after, s);
    console.log(
      `long sweep: off the head ${(10 * lie).toFixed(2)} cm; length over its strokes' ${ratio.toFixed(2)}`,
    );
    expect(lie).toBeLessThanOrEqual(0.1);
    expect(ratio).toBeGreaterThan(0.8);
    expect(ratio).toBeLessThan(1.2);
  });

  it('one stroke down the middle of the back: the hair beside it ends at its end, a straight hem', async () => {
    // a new user's long hair (fresh eyes, round 11): Max length 60 cm, Mirror on, one stroke
    // drawn from the crown down the back in the back view. Hair rooted at the back of the head 4
    // cm or more from the stroke ends no lower than the stroke's last point (a band of 1.2 cm),
    // not as long as the stroke, which hung the sides lower than the middle (an upside-down U)
    const s = fixture('eyes-back-stroke');
    const stroke = s.curves[0].points;
    const endY = stroke[stroke.length - 1][1];
    const below = (h: StrandArrays) => {
      const drop: number[] = [];
      eachStrand(h, (pts) => {
        const root = pts[0];
        if (root[2] > -0.3 || stroke.some((q) => dist(q, root) < 0.4)) return;
        drop.push(endY - pts[pts.length - 1][1]);
      });
      return quantile(drop, 0.9);
    };
    const [before, after] = [below(await grow(off(s))), below(await grow(s))];
    console.log(
      `one stroke down the back, rules off -> on: p90 of the back hair's ends below the stroke's end ${(10 * before).toFixed(1)} -> ${(10 * after).toFixed(1)} cm`,
    );
    expect(before).toBeGreaterThan(0.3); // the fault
    expect(after).toBeLessThanOrEqual(0.1);
  });

  it('a stroke combed into a bun leaves the loose hair its length', async () => {
    // fresh eyes' half-up: a parting, a bun on the top section and a mirrored pair of short
    // strokes from the temples into the bun (extended: "on into bun c2"). The loose hair below
    // the parting is as long with the pair as without it (Max length, 32 cm): counted with their
    // own length, the pair cut it to the chin
    const s = fixture('half-up-into-bun');
    const without = { ...s, curves: s.curves.filter((c) => c.type !== 'stream') };
    const loose = (h: StrandArrays) => {
      const lengths: number[] = [];
      let k = 0;
      eachStrand(h, (pts) => {
        const tied = (h.tailCurves?.[k++] ?? -1) >= 0;
        if (tied) return;
        let l = 0;
        for (let i = 1; i < pts.length; i++) l += dist(pts[i], pts[i - 1]);
        lengths.push(l);
      });
      return median(lengths);
    };
    const [a, b] = [loose(await grow(without)), loose(await grow(s))];
    console.log(
      `half-up: loose hair's median length ${(10 * a).toFixed(1)} cm without the strokes into the bun, ${(10 * b).toFixed(1)} cm with them`,
    );
    expect(a).toBeGreaterThan(2);
    expect(b).toBeGreaterThan(0.85 * a);
  });

  it('Max length caps every strand the rules grow, however far their ends overshoot a line', async () => {
    // the strokes' length with slack and the overshoot that spreads ends round a line stay
    // within Max length (a fresh clone's longHair.spec found 61.3 cm at 60). Clumping, flyaways
    // and curl, which bend a grown strand's path, are off here (absent blocks)
    // Max length below the strokes' lengths, so it is what ends the long hair
    const cases: [string, number][] = [
      ['eyes-back-stroke', 3],
      ['bob', 1.5],
      ['sweep', 2.5],
      ['eyes-sidepart', 4],
    ];
    for (const [name, maxLength] of cases) {
      const f = fixture(name);
      const s = {
        ...f,
        growth: { ...f.growth, maxLength },
        detail: { lengthJitter: f.detail?.lengthJitter ?? 0 },
      };
      let longest = 0;
      eachStrand(await grow(s), (pts) => {
        let len = 0;
        for (let i = 1; i < pts.length; i++) len += dist(pts[i], pts[i - 1]);
        longest = Math.max(longest, len);
      });
      console.log(
        `${name}: longest strand ${(10 * longest).toFixed(2)} cm at Max length ${10 * s.growth.maxLength} cm`,
      );
      expect(longest).toBeGreaterThan(0.9 * maxLength);
      expect(longest).toBeLessThanOrEqual(maxLength + 1e-4);
    }
  });

  it("a bob's hem stays at its strokes' ends with length jitter: hair cut at a line keeps its length", async () => {
    // fresh eyes (rounds 12, 14): a chin bob's hem sat 2-3 cm above where its strokes ended; the
    // length jitter (up to a tenth of the length: 2.5 cm on bob hair) cut the hair that a hem or
    // its strokes' end had already cut. Strand by strand (the same roots, in the same order), how
    // much higher the hair that ends below the ears' middle ends with jitter 0.3 than without
    const s = fixture('bob');
    const tips = (h: StrandArrays) => {
      const y: number[] = [];
      eachStrand(h, (pts) => y.push(pts[pts.length - 1][1]));
      return y;
    };
    const [plain, jittered] = [
      tips(await grow(s)),
      tips(await grow({ ...s, detail: { lengthJitter: 0.3 } })),
    ];
    expect(jittered.length).toBe(plain.length);
    const rise = plain.flatMap((y, k) => (y < -0.3 ? [jittered[k] - y] : []));
    console.log(
      `bob: ${rise.length} strands end below the ears' middle; with length jitter 0.3 they end ${(10 * median(rise)).toFixed(2)} cm higher (median), ${(10 * quantile(rise, 0.9)).toFixed(2)} cm (p90)`,
    );
    expect(rise.length).toBeGreaterThan(500);
    expect(median(rise)).toBeLessThan(0.02);
  });

  it('long curls with curl volume widen towards their ends as the formula says, the face stays open', async () => {
    // fresh eyes round 19's long curls (3A, 50 cm): "crimped hair in a box". With curl volume the
    // path a strand curls round moves out by 0.4 k L g t^1.3 at arc t past the curl's start (k
    // the curl's shrinkage, L the strand's length before curl, g a lock's factor within 1 ± 0.35,
    // each lock leaning up to 0.5 rad from straight out, the back part of the move halved): at
    // the tip of hair at the sides, about 0.4 k L g sideways. Strand by strand (the same roots),
    // how much further the tip is from the head's vertical axis, over that value with g = 1, for
    // strands ending below the chin at the sides (|x| over twice |z|); L from the curled strand's
    // length without curl volume (a helix is sqrt(1 + (2 pi q r)^2) times the path it winds
    // round). Behind, the hair moves out by half as much (round 22: at the full amount long
    // curls leaned back off the body).
    const s = fixture('eyes19-curls');
    const curl = s.detail?.curl;
    if (!curl) throw new Error('eyes19-curls has no curl');
    const steep = 2 * Math.PI * curl.frequency * curl.radius;
    const k = 1 - 1 / Math.sqrt(1 + steep * steep);
    const tips = (h: StrandArrays) => {
      const out: { x: number; z: number; y: number; len: number }[] = [];
      eachStrand(h, (pts) => {
        let len = 0;
        for (let i = 1; i < pts.length; i++) len += dist(pts[i], pts[i - 1]);
        const t = pts[pts.length - 1];
        out.push({ x: t[0], z: t[2], y: t[1], len });
      });
      return out;
    };
    const [plainHair, volumeHair] = [await grow(s), await grow({ ...s, curlVolume: true })];
    const [plain, volume] = [tips(plainHair), tips(volumeHair)];
    expect(volume.length).toBe(plain.length);
    const want = (p: { len: number }) => 0.4 * k * (p.len / Math.sqrt(1 + steep * steep));
    const side = plain.flatMap((p, i) =>
      p.y < -1.5 && Math.abs(p.x) > 2 * Math.abs(p.z)
        ? [(Math.hypot(volume[i].x, volume[i].z) - Math.hypot(p.x, p.z)) / want(p)]
        : [],
    );
    const back = plain.flatMap((p, i) =>
      p.y < -1.5 && p.z < -2 * Math.abs(p.x) ? [(p.z - volume[i].z) / want(p)] : [],
    );
    const face = [faceShare(plainHair), faceShare(volumeHair)];
    console.log(
      `long curls: ${side.length} tips below the chin at the sides move out by ${quantile(side, 0.1).toFixed(2)} / ${median(side).toFixed(2)} / ${quantile(side, 0.9).toFixed(2)} (p10 / median / p90) of 0.4 k L, ${back.length} behind by ${median(back).toFixed(2)} (median); strands across the face ${(100 * face[0]).toFixed(2)} -> ${(100 * face[1]).toFixed(2)} %`,
    );
    expect(side.length).toBeGreaterThan(300);
    expect(median(side)).toBeGreaterThan(0.75);
    expect(median(side)).toBeLessThan(1.15);
    expect(quantile(side, 0.1)).toBeGreaterThan(0.45);
    expect(quantile(side, 0.9)).toBeLessThan(1.5);
    expect(back.length).toBeGreaterThan(300);
    expect(median(back)).toBeGreaterThan(0.3);
    expect(median(back)).toBeLessThan(0.65);
    expect(face[1]).toBeLessThanOrEqual(face[0]);
  });
  it('face clear: hair between two bang strokes parts round the face instead of hanging across the eyes', async () => {
    // the library's long hair with curtain bangs (a new user's strokes: a centre part, three
    // mirrored bang strokes each pressed beside its front, sweeping out over the forehead to the
    // cheekbones): hair rooted at the part, between the strokes, took their blend, forward and
    // down, and hung across the eyes 2-4 cm in front of the face (the judges: "wisps across the
    // eyes", "a veil over the face in profile"). Strands with a point in the air in front of an
    // eye (beside the middle, at the eyes' height, more than 1 cm in front of the face):
    const read = parseSession(
      JSON.parse(
        readFileSync(new URL('../../public/styles/curtain-bangs.json', import.meta.url), 'utf8'),
      ),
    );
    if (!read.ok) throw new Error(read.error);
    const s = { ...read.value, growth: { ...read.value.growth, maxStrands: 30000 } };
    const acrossTheEyes = (h: StrandArrays) => {
      let n = 0;
      eachStrand(h, (pts) => {
        const across = pts.some(
          ([x, y, z]) =>
            Math.abs(Math.abs(x) - EYE_X) < EYE_R + 0.02 &&
            Math.abs(y - EYE_Y) < EYE_R + 0.02 &&
            z > EYE_Z &&
            headSdf(x, y, z) > 0.1,
        );
        if (across) n++;
      });
      return n;
    };
    const [before, after] = [
      acrossTheEyes(await grow({ ...s, faceClear: false })),
      acrossTheEyes(await grow({ ...s, faceClear: true })),
    ];
    console.log(
      `curtain bangs: ${before} strands across the eyes without face clear, ${after} with`,
    );
    expect(before).toBeGreaterThan(10);
    expect(after).toBeLessThanOrEqual(before / 10);
  });
});
