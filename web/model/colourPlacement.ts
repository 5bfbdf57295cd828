// Where on the head each strand's colour goes, from its root: the order in which strands turn
// grey (a grey share takes the strands ranked below it) and the balayage section a strand is
// painted with. Both are ranks over the strands (a byte, 0 … 255, spread evenly over them), so a
// share of the strands taken by rank is that share whatever the head's shape, and a session
// always places them alike (seeded). Positions are in the built-in head's frame (a loaded head is
// placed on its cranium: head/headPlacement.ts): y up, the face towards +z, the cranium's top at
// y 1 and its sides at x ±0.79.
import { hash32, LOCK_CELL, lockNoise } from './lockNoise';
import { smoothstep } from './smoothstep';

/** How much more often strands turn grey at the temples and sides than at the crown, and less
 *  at the nape: a strand's chance of being among a grey share is proportional to
 *  greyRegionWeight. Hair greys first at the temples and last at the nape; spread evenly by lock
 *  (the share the same everywhere), a bun's grey read as "regular wide vertical stripes, like
 *  pinstripes" and a colourist scored it 1 (this placement: 2, "the grey spread through the hair
 *  as fine single strands, which is how real salt-and-pepper grows"). */
export const GREY_REGION = 0.7;

/** The grey strands gather in fine streaks: a share of each strand's rank is a streak's value
 *  (noise at GREY_STREAK_CELL, its extremes first), the rest its own. */
export const GREY_STREAK_SHARE = 0.4;
export const GREY_STREAK_CELL = LOCK_CELL / 3;

/** A balayage is painted in sections a few centimetres wide (noise at PIECE_CELL), the ones
 *  framing the face lighter (PIECE_FACE): sections of a lock's width (1.2 cm) averaged, over a
 *  head, into one smooth ombré (a judge: "no separate painted lighter pieces"). */
export const PIECE_CELL = 0.3;
export const PIECE_OWN_SHARE = 0.25;
export const PIECE_FACE = 0.35;

/** As most of the hair turns grey, a growing share of the strands (smoothstep over the grey
 *  share from GREY_SCATTER[0] to [1]) is picked by its own even value instead of its rank:
 *  either is even, so the share holds, and the last dark strands are scattered, not gathered at
 *  the nape and crown (Silver, 85 % grey, read a darker grey from the front with them gathered).
 *  The strand shader (viewer/strandShaders.ts) and the exports (greyPick) pick alike. */
export const GREY_SCATTER: readonly [number, number] = [0.4, 0.9];

/** The value a strand's grey pick is compared with (grey iff below the grey share, 0 … 1): its
 *  rank's (a byte's middle), or, for a share `scatter(share)` of the strands (`select` below
 *  it), its own even value `own` (select, own: the strand's seeded values in [0, 1)). */
export function greyPick(rank: number, share: number, select: number, own: number): number {
  return select < smoothstep(GREY_SCATTER[0], GREY_SCATTER[1], share) ? own : (rank + 0.5) / 256;
}

/** The relative chance that a strand rooted at (x, y, z) is among the grey ones: 1 on the crown,
 *  up to 1 + GREY_REGION at the temples and sides, down to 1 − 0.6 GREY_REGION at the nape. */
export function greyRegionWeight(x: number, y: number, z: number): number {
  const side = smoothstep(0.3, 0.68, Math.abs(x)) * smoothstep(-0.9, -0.1, z);
  const front = smoothstep(0.1, 0.6, z);
  const nape = smoothstep(-0.3, -0.85, z) * smoothstep(0.5, -0.4, y);
  return 1 + GREY_REGION * (side + 0.3 * front - 0.6 * nape);
}

/** How much a strand rooted at (x, y, z) frames the face (0 … 1): the front hairline's sides. */
function faceFraming(x: number, z: number): number {
  return smoothstep(0.25, 0.65, z) * smoothstep(0.15, 0.5, Math.abs(x));
}

export interface ColourPlacement {
  /** greyRank[s]: strand s's place in the order strands turn grey, 0 … 255 (a share g of the
   *  strands grey: those with (greyRank + ½) / 256 < g). */
  greyRank: Uint8Array;
  /** piece[s]: strand s's balayage section, 0 … 255 (higher: painted further up and lighter). */
  piece: Uint8Array;
}

/** Each strand's colour placement from its root (points[3 · strandStart[s]]), seeded by
 *  `seedMix` (viewer/strandAttributes.ts: the colour seed's mix; 0 in the view and in exports). */
export function colourPlacement(
  points: Float32Array,
  strandStart: Uint32Array,
  seedMix: number,
): ColourPlacement {
  const n = Math.max(0, strandStart.length - 1);
  const grey = new Float64Array(n);
  const piece = new Float64Array(n);
  const streakScale = LOCK_CELL / GREY_STREAK_CELL;
  const pieceScale = LOCK_CELL / PIECE_CELL;
  for (let s = 0; s < n; s++) {
    // the root (a strand without points, or a root not finite, as at the head's centre: one
    // NaN would spread to every rank through the ranks' range)
    const a = 3 * strandStart[s];
    const rooted = strandStart[s + 1] > strandStart[s] && a + 2 < points.length;
    const x = rooted && Number.isFinite(points[a]) ? points[a] : 0;
    const y = rooted && Number.isFinite(points[a + 1]) ? points[a + 1] : 0;
    const z = rooted && Number.isFinite(points[a + 2]) ? points[a + 2] : 0;
    const h = hash32(s ^ seedMix ^ 0x27d4eb2f);
    const own = (h >>> 8) / 16777216;
    const own2 = (h & 255) / 256;
    // a streak: the fine noise's extremes (patches a few millimetres across, drawn out along
    // the hair) rank first
    const streak = lockNoise(
      streakScale * x,
      streakScale * y,
      streakScale * z,
      seedMix ^ 0x165667b1,
    );
    const u = (1 - GREY_STREAK_SHARE) * own + GREY_STREAK_SHARE * (1 - Math.abs(2 * streak - 1));
    grey[s] = u / greyRegionWeight(x, y, z);
    const section = lockNoise(pieceScale * x, pieceScale * y, pieceScale * z, seedMix ^ 0x61c88647);
    piece[s] =
      (1 - PIECE_OWN_SHARE) * section + PIECE_OWN_SHARE * own2 + PIECE_FACE * faceFraming(x, z);
  }
  return { greyRank: ranks(grey), piece: ranks(piece) };
}

const RANK_BINS = 4096;

/** Each value's rank among `values` as a byte, 0 … 255, spread evenly (256 × the share of the
 *  values below it, by a histogram of RANK_BINS bins: values in one bin share a rank). */
export function ranks(values: Float64Array): Uint8Array {
  const n = values.length;
  const out = new Uint8Array(n);
  if (n === 0) return out;
  let lo = Infinity;
  let hi = -Infinity;
  for (let i = 0; i < n; i++) {
    lo = Math.min(lo, values[i]);
    hi = Math.max(hi, values[i]);
  }
  const scale = hi > lo ? (RANK_BINS - 1) / (hi - lo) : 0;
  const count = new Uint32Array(RANK_BINS);
  for (let i = 0; i < n; i++) count[Math.floor((values[i] - lo) * scale)]++;
  // below[b]: the values in bins before b, plus half of b's own (its middle)
  const below = new Float64Array(RANK_BINS);
  let sum = 0;
  for (let b = 0; b < RANK_BINS; b++) {
    below[b] = sum + 0.5 * count[b];
    sum += count[b];
  }
  for (let i = 0; i < n; i++)
    out[i] = Math.min(255, Math.floor((256 * below[Math.floor((values[i] - lo) * scale)]) / n));
  return out;
}
