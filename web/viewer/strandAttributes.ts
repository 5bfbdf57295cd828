// The strands' vertex attributes, as typed arrays (no three.js: the solver worker builds them
// for the final hair, the page for previews; strandGeometry.ts wraps them in a geometry).
// Per point i of strand s (points strandStart[s] .. strandStart[s + 1] − 1):
//   tangent[3i .. 3i+2]  tangent (central differences, one-sided at the ends), Int8 ÷ 127: its
//                        direction the strand's, its length 1 − ½ of the strand's turn there
//                        (encodeTurn: the angle between its two segments, for the highlight)
//   along[4i]            0 at the root … 255 at the tip (by point)
//   along[4i + 1]        the distance from the strand's tip by arc length, encoded
//                        (encodeTipDistance: finest near the tip), for the lighter tips
//   along[4i + 2]        per strand: its grey rank (colourPlacement.ts: the order strands turn
//                        grey in, temples first)
//   along[4i + 3]        per strand: its balayage section (colourPlacement.ts)
//   random[4i .. 4i+3]   per strand: value, hue, length appearance (a hash of s and the colour
//                        seed), and the lock's highlight (lockNoise of the root: strands rooted
//                        together share it), Uint8 ÷ 255
//   light[2i .. 2i+1]    transmittance, ambient occlusion (protocol.ts HairLightingArrays.strand),
//                        Uint8 ÷ 255; 255, 255 without lighting
// Level of detail: the index lists strands interleaved (stride LOD_GROUPS, groups in bit-reversed
// order), so any prefix of the groups is an even sample of the whole head of hair.

import { colourPlacement } from '../model/colourPlacement';
import type { StrandVertexArrays } from '../model/hairArrays';
import { hash32, lockNoise } from '../model/lockNoise';

/** Strands are drawn in this many interleaved groups (see buildStrandGeometry). */
export const LOD_GROUPS = 64;
const LOD_ORDER = Array.from({ length: LOD_GROUPS }, (_, g) => {
  let r = 0;
  for (let b = 1, x = g; b < LOD_GROUPS; b <<= 1, x >>= 1) r = (r << 1) | (x & 1);
  return r;
});

/** The farthest from a strand's tip `along`'s second byte tells apart, world units: 100 cm,
 *  the longest hair a session grows (SESSION_LIMITS); farther reads as this far. */
export const TIP_DISTANCE_RANGE = 10;

const TIP_BYTE = 255 / Math.sqrt(TIP_DISTANCE_RANGE);

/** The byte for a distance `d` from the tip (world units): 255 √(d / TIP_DISTANCE_RANGE), so its
 *  steps are finest near the tip, where a short fade needs them: 0.8 mm at 1 cm from the tip,
 *  2.5 mm at 10 cm, 5.5 mm at 50 cm (a point is off by at most half a step). One byte, in the
 *  attribute `along` already has (no attribute more to fetch per vertex and frame). */
export function encodeTipDistance(d: number): number {
  return Math.floor(TIP_BYTE * Math.sqrt(Math.min(TIP_DISTANCE_RANGE, Math.max(0, d))) + 0.5);
}

/** The distance (world units) a byte of encodeTipDistance stands for; the strand shader decodes
 *  the same way (strandShaders.ts tipDistanceOf, from the byte ÷ 255). */
export function decodeTipDistance(byte: number): number {
  return TIP_DISTANCE_RANGE * (byte / 255) ** 2;
}

/** Per-point vertex attributes (protocol.ts StrandVertexArrays states the layouts). */
export type PointAttributes = Omit<StrandVertexArrays, 'index' | 'lodCounts'>;

/** Point attributes and the lines' level-of-detail index: everything a line geometry needs
 *  besides the points (the worker builds them for the final hair, off the page's thread). */
export type LineAttributes = StrandVertexArrays;

/** The line geometry's attributes for the strands (buildStrandGeometry draws them). */
export function lineAttributes(
  points: Float32Array,
  strandStart: Uint32Array,
  colorSeed = 0,
  lighting: Float32Array | null = null,
): LineAttributes {
  return {
    ...pointAttributes(points, strandStart, colorSeed, lighting),
    ...lodIndex(strandStart, [0, 1]),
  };
}

/** Per-point attributes shared by lines and strips (see buildStrandGeometry). */
export function pointAttributes(
  points: Float32Array,
  strandStart: Uint32Array,
  colorSeed: number,
  lighting: Float32Array | null,
): PointAttributes {
  const strands = Math.max(0, strandStart.length - 1);
  const pointCount = strands > 0 ? strandStart[strands] : 0;
  if (3 * pointCount > points.length) throw new Error('strandStart exceeds the points array');
  const useLight = lighting !== null && lighting.length >= 2 * pointCount;
  // compact, normalised attributes: tangent as signed bytes (÷127), the rest as unsigned bytes
  // (÷255); the shader reads floats either way
  const tangent = new Int8Array(3 * pointCount);
  const along = new Uint8Array(4 * pointCount);
  const random = new Uint8Array(4 * pointCount);
  const light = new Uint8Array(2 * pointCount);
  const seedMix = Math.imul(colorSeed >>> 0, 0x9e3779b1);
  const bounds = writeTangents(points, strandStart, tangent, 1);
  const place = colourPlacement(points, strandStart, seedMix);
  // a point's four bytes of `along` and of `random` written as one little-endian word each (the
  // byte order of every platform WebGL runs on): a store a point instead of four
  const along32 = new Uint32Array(along.buffer);
  const random32 = new Uint32Array(random.buffer);
  for (let s = 0; s < strands; s++) {
    const a = strandStart[s];
    const b = strandStart[s + 1];
    const n = b - a;
    if (n <= 0) continue;
    const h = hash32(s ^ seedMix);
    const h2 = hash32(h ^ 0x5bd1e995);
    const r0 = h >>> 24; // value
    const r1 = (h >>> 16) & 255; // hue
    const r2 = (h >>> 8) & 255; // length appearance
    // the lock's highlight: shared by strands rooted within a lock's width of each other, with
    // a little of the strand's own
    const lock = lockNoise(points[3 * a], points[3 * a + 1], points[3 * a + 2], seedMix);
    const r3 = Math.round(255 * clamp01(0.85 * lock + 0.15 * ((h2 >>> 24) / 255)));
    random32.fill(r0 | (r1 << 8) | (r2 << 16) | (r3 << 24), a, b);
    const inv = n > 1 ? 255 / (n - 1) : 0;
    // the strand's grey rank and balayage section, the upper two bytes of each point's word
    const placed = (place.greyRank[s] << 16) | (place.piece[s] << 24);
    // the distance from the tip, summed from the tip back to the root: encodeTipDistance inlined
    // (this runs on the page for every preview; truncated, so + 0.5 rounds)
    let fromTip = 0;
    along32[b - 1] = Math.round((n - 1) * inv) | placed;
    for (let i = b - 2; i >= a; i--) {
      const dx = points[3 * i + 3] - points[3 * i];
      const dy = points[3 * i + 4] - points[3 * i + 1];
      const dz = points[3 * i + 5] - points[3 * i + 2];
      fromTip += Math.sqrt(dx * dx + dy * dy + dz * dz);
      const tip = fromTip < TIP_DISTANCE_RANGE ? (TIP_BYTE * Math.sqrt(fromTip) + 0.5) | 0 : 255;
      along32[i] = Math.round((i - a) * inv) | (tip << 8) | placed;
    }
    if (useLight)
      for (let i = 2 * a; i < 2 * b; i++) light[i] = Math.round(255 * clamp01(lighting[i]));
  }
  if (!useLight) light.fill(255);
  const box = pointCount > 0 ? new Float32Array(bounds) : new Float32Array(0);
  return { pointCount, tangent, along, random, light, box };
}

const boxScratch = new Float64Array(6);

/** The turn (radians between a point's two segments) a tangent's length tells apart: more reads
 *  as this much. */
export const MAX_TURN = 1.2;

/** The length a tangent is written at for a turn of `angle` radians at its point (writeTangents
 *  passes the turn's chord, 2 sin(angle / 2), within 6 % of the angle up to MAX_TURN): 1
 *  straight, down to ½ at MAX_TURN or more. The shaders read the turn back from the length (strandShaders.ts
 *  turnOf) and widen the highlight by it: shading at the points of a tightly curled strand
 *  sampled its narrow highlight at a few of them, as sparks. */
export function encodeTurn(angle: number): number {
  return 1 - 0.5 * Math.min(1, Math.max(0, angle) / MAX_TURN);
}

/** Writes the tangents (central differences, one-sided at the ends, Int8 ÷ 127; length
 *  encodeTurn of the strand's turn there), `per` copies a point (lines 1, strips 2); returns the
 *  points' box, min xyz then max xyz (a scratch array, overwritten by the next call). */
export function writeTangents(
  points: Float32Array,
  strandStart: Uint32Array,
  tangent: Int8Array,
  per: number,
): Float64Array {
  let minX = Infinity;
  let minY = Infinity;
  let minZ = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  let maxZ = -Infinity;
  for (let s = 0; s + 1 < strandStart.length; s++) {
    const a = strandStart[s];
    const b = strandStart[s + 1];
    let tx = 0;
    let ty = 127;
    let tz = 0;
    // the unit vector of the segment before the point (hasPrev: it has one)
    let ux = 0;
    let uy = 0;
    let uz = 0;
    let hasPrev = false;
    for (let i = a; i < b; i++) {
      const px = points[3 * i];
      const py = points[3 * i + 1];
      const pz = points[3 * i + 2];
      if (px < minX) minX = px;
      if (px > maxX) maxX = px;
      if (py < minY) minY = py;
      if (py > maxY) maxY = py;
      if (pz < minZ) minZ = pz;
      if (pz > maxZ) maxZ = pz;
      const i0 = i > a ? i - 1 : i;
      const i1 = i < b - 1 ? i + 1 : i;
      const dx = points[3 * i1] - points[3 * i0];
      const dy = points[3 * i1 + 1] - points[3 * i0 + 1];
      const dz = points[3 * i1 + 2] - points[3 * i0 + 2];
      const l = Math.sqrt(dx * dx + dy * dy + dz * dz);
      if (l > 1e-12) {
        // the turn between the two segments (none at the ends), as its chord 2 sin(angle / 2) =
        // |u0 − u1| of their unit vectors: within 6 % of the angle up to MAX_TURN; each segment's
        // unit vector is found once (this runs on the page for every preview)
        let turn = 0;
        if (i < b - 1) {
          const sx = points[3 * i + 3] - px;
          const sy = points[3 * i + 4] - py;
          const sz = points[3 * i + 5] - pz;
          const sl = Math.sqrt(sx * sx + sy * sy + sz * sz);
          if (sl > 1e-12) {
            const nx = sx / sl;
            const ny = sy / sl;
            const nz = sz / sl;
            if (i > a && hasPrev) {
              const cx = nx - ux;
              const cy = ny - uy;
              const cz = nz - uz;
              turn = Math.sqrt(cx * cx + cy * cy + cz * cz);
            }
            ux = nx;
            uy = ny;
            uz = nz;
            hasPrev = true;
          } else hasPrev = false;
        }
        const k = (127 * encodeTurn(turn)) / l;
        tx = Math.round(dx * k);
        ty = Math.round(dy * k);
        tz = Math.round(dz * k);
      } else hasPrev = false;
      const o = 3 * per * i;
      tangent[o] = tx;
      tangent[o + 1] = ty;
      tangent[o + 2] = tz;
      if (per === 2) {
        tangent[o + 3] = tx;
        tangent[o + 4] = ty;
        tangent[o + 5] = tz;
      }
    }
  }
  boxScratch[0] = minX;
  boxScratch[1] = minY;
  boxScratch[2] = minZ;
  boxScratch[3] = maxX;
  boxScratch[4] = maxY;
  boxScratch[5] = maxZ;
  return boxScratch;
}

/** The index of every segment in level-of-detail order (strands interleaved with stride
 *  LOD_GROUPS, groups in LOD_ORDER) and `lodCounts[g]`, the index count of the first g groups.
 *  Each segment from point i writes `pattern` offset by `verticesPerPoint * i`. */
export function lodIndex(
  strandStart: Uint32Array,
  pattern: readonly number[],
  verticesPerPoint = 1,
): { index: Uint32Array; lodCounts: Uint32Array } {
  const strands = Math.max(0, strandStart.length - 1);
  let segments = 0;
  for (let s = 0; s < strands; s++) {
    const n = strandStart[s + 1] - strandStart[s];
    if (n > 1) segments += n - 1;
  }
  const index = new Uint32Array(pattern.length * segments);
  const lodCounts = new Uint32Array(LOD_GROUPS + 1);
  let w = 0;
  for (let g = 0; g < LOD_GROUPS; g++) {
    for (let s = LOD_ORDER[g]; s < strands; s += LOD_GROUPS)
      for (let i = strandStart[s]; i + 1 < strandStart[s + 1]; i++) {
        const a = verticesPerPoint * i;
        for (const k of pattern) index[w++] = a + k;
      }
    lodCounts[g + 1] = w;
  }
  return { index, lodCounts };
}

function clamp01(v: number): number {
  return v > 0 ? Math.min(v, 1) : 0;
}
