// The strands as every writer exports them: strands of fewer than 2 points dropped, strands of
// more than MAX_POINTS_PER_STRAND points resampled evenly by arc length (root and tip kept
// exactly), a diameter per point tapered ROOT_WIDTH → TIP_WIDTH by arc length, and a colour
// per strand. Pure and deterministic: no DOM, no three.js, no randomness beyond a seeded hash.
//
// Colours are LINEAR RGB floats (USD displayColor and glTF COLOR_0 are linear; the .hair
// colours use the same values): session.hairColor (#rrggbb, sRGB) varied per strand by
// ±STRAND_VALUE_VARIATION in value (the sRGB channels scaled by one factor, clamped to 1), then
// decoded with the sRGB transfer function. A session with a colour model (hairLook.ts) colours
// each strand from it instead (its grey pick and balayage section placed by its root as the
// view places them, colourPlacement.ts; its melanin spread seeded by the growth seed and the
// strand), and each point too (the lighter tips, by arc length from the tip), with the
// pigment per strand and point for Blender's Principled Hair BSDF (melanin, redness, tint).

import { colourPlacement, greyPick } from '../model/colourPlacement';
import type { StrandArrays } from '../model/hairArrays';
import { type HairLook, lookUniforms, strandLookColor, strandPigment } from '../model/hairLook';
import { DEFAULT_HAIR_COLOR, type SessionState } from '../model/session';
import { MAX_POINTS_PER_STRAND, ROOT_WIDTH, TIP_WIDTH } from './types';

/** Per-strand brightness variation: the value (HSV V) of each strand's colour is the session's
 *  colour × (1 + u · 0.04), u in [-1, 1) from a hash of (growth seed, strand index). */
export const STRAND_VALUE_VARIATION = 0.04;

/** Colour used when the session's colour is not #rrggbb (the session reader rejects that). */

export interface ExportStrands {
  /** Exported strand s owns points strandStart[s] .. strandStart[s + 1] - 1 (root first). */
  points: Float32Array; // points[3 * point + axis]
  strandStart: Uint32Array; // length = strands + 1
  /** Diameter per point, world units. */
  widths: Float32Array; // widths[point]
  /** Linear RGB per strand (a colour model's: at the root). */
  colors: Float32Array; // colors[3 * strand + channel]
  /** With a colour model: linear RGB per point (the lighter tips), else null. */
  pointColors: Float32Array | null; // pointColors[3 * point + channel]
  /** With a colour model: the pigment (Blender's Principled Hair, melanin parametrisation),
   *  else null. */
  pigment: {
    melanin: Float32Array; // melanin[point] (0..1, with the lighter tips)
    redness: Float32Array; // redness[strand]
    tint: Float32Array; // tint[3 * strand + channel], linear RGB (1, 1, 1: no dye)
  } | null;
  /** The input strand (StrandArrays index) each exported strand comes from. */
  source: Uint32Array; // source[strand]
  /** Bounds of points (exact float32 values), [0, 0, 0] for both when there are no points. */
  min: [number, number, number];
  max: [number, number, number];
}

/** sRGB transfer function, encoded 0..1 → linear 0..1 (IEC 61966-2-1). */
export function srgbToLinear(c: number): number {
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
}

/** #rrggbb → sRGB-encoded floats 0..1 (the fallback colour if it is not #rrggbb). */
export function parseHexColor(hex: string): [number, number, number] {
  const m = /^#([0-9a-fA-F]{6})$/.exec(hex) ?? /^#([0-9a-fA-F]{6})$/.exec(DEFAULT_HAIR_COLOR);
  const v = Number.parseInt((m as RegExpExecArray)[1], 16);
  return [((v >> 16) & 255) / 255, ((v >> 8) & 255) / 255, (v & 255) / 255];
}

/** A 32-bit integer hash of (seed, index) (murmur3's finaliser over a combined key). */
export function strandHash(seed: number, index: number): number {
  let h = (seed >>> 0) ^ Math.imul(index >>> 0, 0x9e3779b1);
  h = Math.imul(h ^ (h >>> 16), 0x85ebca6b);
  h = Math.imul(h ^ (h >>> 13), 0xc2b2ae35);
  h ^= h >>> 16;
  return h >>> 0;
}

/** The value factor of strand `index` (its index among the input strands): 1 ± 0.04. */
export function strandValueFactor(seed: number, index: number): number {
  const u = (strandHash(seed, index) / 4294967296) * 2 - 1; // [-1, 1)
  return 1 + STRAND_VALUE_VARIATION * u;
}

/** The colour model's random values of input strand `index`: its own even value for the grey
 *  pick, its melanin spread, and the value that chooses between its own value and its rank
 *  (colourPlacement.ts greyPick). */
export function strandLookRandom(seed: number, index: number): [number, number, number] {
  const h = strandHash(seed ^ 0x6c8e9cf5, index);
  const piece = strandHash(seed ^ 0x2f1b8e43, index);
  return [(h >>> 16) / 65536, (h & 0xffff) / 65536, (piece >>> 16) / 65536];
}

/** Linear RGB of input strand `index` for a session colour and seed. */
export function strandColor(hex: string, seed: number, index: number): [number, number, number] {
  const f = strandValueFactor(seed, index);
  const [r, g, b] = parseHexColor(hex);
  return [
    srgbToLinear(Math.min(1, r * f)),
    srgbToLinear(Math.min(1, g * f)),
    srgbToLinear(Math.min(1, b * f)),
  ];
}

/** Width (diameter) at arc-length fraction t (0 at the root, 1 at the tip). */
export function widthAt(t: number): number {
  return ROOT_WIDTH + (TIP_WIDTH - ROOT_WIDTH) * t;
}

/** Builds the exported strands (see the file comment). */
export function strandsForExport(
  strands: StrandArrays,
  session: Pick<SessionState, 'hairColor' | 'growth'> & { hairLook?: HairLook | null },
): ExportStrands {
  const src = strands.points;
  const start = strands.strandStart;
  const nIn = Math.max(0, start.length - 1);
  const cap = MAX_POINTS_PER_STRAND;

  // First pass: how many strands and points come out.
  let nOut = 0;
  let pOut = 0;
  for (let s = 0; s < nIn; s++) {
    const n = start[s + 1] - start[s];
    if (n < 2) continue;
    nOut++;
    pOut += Math.min(n, cap);
  }

  const points = new Float32Array(3 * pOut);
  const widths = new Float32Array(pOut);
  const colors = new Float32Array(3 * nOut);
  const strandStart = new Uint32Array(nOut + 1);
  const source = new Uint32Array(nOut);
  const seed = session.growth.seed;
  const base = parseHexColor(session.hairColor);
  const look = session.hairLook ?? null;
  const values = look ? lookUniforms(look, session.hairColor) : null;
  const pointColors = look ? new Float32Array(3 * pOut) : null;
  // where the grey strands and the balayage's sections go, as the view places them (the same
  // ranks and sections: colourPlacement.ts, seeded alike)
  const place = look ? colourPlacement(src, start, 0) : null;
  const pigment = look
    ? {
        melanin: new Float32Array(pOut),
        redness: new Float32Array(nOut),
        tint: new Float32Array(3 * nOut),
      }
    : null;
  const cum = new Float64Array(Math.max(2, maxStrandLength(start)));

  let so = 0;
  let po = 0;
  for (let s = 0; s < nIn; s++) {
    const a = start[s];
    const n = start[s + 1] - a;
    if (n < 2) continue;

    strandArc(src, start, s, cum); // float64
    const total = cum[n - 1];

    if (n <= cap) {
      points.set(src.subarray(3 * a, 3 * (a + n)), 3 * po);
      for (let i = 0; i < n; i++)
        widths[po + i] = widthAt(total > 0 ? cum[i] / total : i / (n - 1));
    } else {
      const m = cap;
      let seg = 0; // input segment holding the current target: cum[seg] <= target <= cum[seg + 1]
      for (let k = 0; k < m; k++) {
        const o = 3 * (po + k);
        let q: number; // index of the source point to copy, or -1 to interpolate
        let t = 0;
        if (k === 0) q = 0;
        else if (k === m - 1) q = n - 1;
        else if (total > 0) {
          const target = (total * k) / (m - 1);
          while (seg < n - 2 && cum[seg + 1] < target) seg++;
          const len = cum[seg + 1] - cum[seg];
          t = len > 0 ? (target - cum[seg]) / len : 0;
          q = -1;
        } else q = Math.round((k * (n - 1)) / (m - 1));
        if (q >= 0) {
          const p = 3 * (a + q);
          points[o] = src[p];
          points[o + 1] = src[p + 1];
          points[o + 2] = src[p + 2];
        } else {
          const p = 3 * (a + seg);
          points[o] = src[p] + (src[p + 3] - src[p]) * t;
          points[o + 1] = src[p + 1] + (src[p + 4] - src[p + 1]) * t;
          points[o + 2] = src[p + 2] + (src[p + 5] - src[p + 2]) * t;
        }
        widths[po + k] = widthAt(k / (m - 1));
      }
    }

    if (look && values && pointColors && pigment && place) {
      const r = strandLookRandom(seed, s);
      const u: [number, number, number] = [
        greyPick(place.greyRank[s], look.grey / 100, r[2], r[0]),
        r[1],
        (place.piece[s] + 0.5) / 256,
      ];
      const m = Math.min(n, cap);
      for (let k = 0; k < m; k++) {
        const along = m > 1 ? k / (m - 1) : 0;
        // the lighter tips by arc length from the tip: the kept points' own, or the evenly
        // resampled points' (k of m − 1 equal steps of the whole length)
        const tipDistance = n <= cap ? total - cum[k] : total * (1 - along);
        const c = strandLookColor(values, u, along, tipDistance);
        pointColors.set(c, 3 * (po + k));
        if (k === 0) colors.set(c, 3 * so);
        const p = strandPigment(look, u, along, tipDistance);
        pigment.melanin[po + k] = p.melanin;
        if (k === 0) {
          pigment.redness[so] = p.redness;
          pigment.tint.set(p.tint, 3 * so);
        }
      }
    } else {
      const f = strandValueFactor(seed, s);
      colors[3 * so] = srgbToLinear(Math.min(1, base[0] * f));
      colors[3 * so + 1] = srgbToLinear(Math.min(1, base[1] * f));
      colors[3 * so + 2] = srgbToLinear(Math.min(1, base[2] * f));
    }
    po += Math.min(n, cap);
    source[so] = s;
    so++;
    strandStart[so] = po;
  }

  const min: [number, number, number] = [0, 0, 0];
  const max: [number, number, number] = [0, 0, 0];
  if (pOut > 0) {
    for (let c = 0; c < 3; c++) {
      min[c] = points[c];
      max[c] = points[c];
    }
    for (let i = 3; i < points.length; i += 3)
      for (let c = 0; c < 3; c++) {
        const v = points[i + c];
        if (v < min[c]) min[c] = v;
        if (v > max[c]) max[c] = v;
      }
  }
  return { points, strandStart, widths, colors, pointColors, pigment, source, min, max };
}

function maxStrandLength(start: Uint32Array): number {
  let m = 0;
  for (let s = 0; s + 1 < start.length; s++) m = Math.max(m, start[s + 1] - start[s]);
  return m;
}

/** Strands and points as the writers export them (strandsForExport below): strands of fewer
 *  than 2 points dropped, longer ones resampled to MAX_POINTS_PER_STRAND. */
export function exportedCounts(s: StrandArrays): { strands: number; points: number } {
  let strands = 0;
  let points = 0;
  const st = s.strandStart;
  for (let i = 0; i + 1 < st.length; i++) {
    const n = st[i + 1] - st[i];
    if (n < 2) continue;
    strands++;
    points += Math.min(n, MAX_POINTS_PER_STRAND);
  }
  return { strands, points };
}

/** Cumulative arc lengths of strand s into cum[0 .. n − 1]; returns n. */
export function strandArc(
  points: Float32Array,
  strandStart: Uint32Array,
  s: number,
  cum: Float64Array,
): number {
  const a = strandStart[s];
  const n = strandStart[s + 1] - a;
  cum[0] = 0;
  for (let i = 1; i < n; i++) {
    const p = 3 * (a + i);
    const dx = points[p] - points[p - 3];
    const dy = points[p + 1] - points[p - 2];
    const dz = points[p + 2] - points[p - 1];
    cum[i] = cum[i - 1] + Math.sqrt(dx * dx + dy * dy + dz * dz);
  }
  return n;
}
