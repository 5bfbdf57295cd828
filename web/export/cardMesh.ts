// Hair cards from clustered strands: each cluster becomes a strip of quads along its centre curve
// (the mean of its strands' points at the same fractions of their lengths), as wide as the
// cluster seen across the card, facing out from the head. Each card keeps its frame (centre,
// across direction, normal, extent across) at every row, so the atlas (cardAtlas.ts) can draw a
// cluster's strands in the card's own coordinates. Plain float64 arithmetic (+, −, ×, ÷, √):
// the same cards in every JS engine.
import { type CardClusters, pointAtFraction } from './cardClusters';
import { type ExportStrands, strandArc } from './strandsForExport';

/** A quad along the card per this length (world units: 1.5 cm), within QUADS_MIN..QUADS_MAX. */
export const QUAD_LENGTH = 0.15;
export const QUADS_MIN = 2;
export const QUADS_MAX = 16;
/** Narrowest card (world units: 2 mm), so a cluster of one strand still shows. */
export const MIN_CARD_WIDTH = 0.02;

export interface Cards {
  count: number;
  /** Card c has rows rowStart[c] .. rowStart[c + 1] − 1, root first (quads = rows − 1). */
  rowStart: Int32Array;
  /** Per row: centre of the cluster's strands, the across direction (unit), the normal (unit,
   *  out from the head), the extent across [lo, hi] from the centre, the fraction along. */
  centre: Float64Array; // [3 * row]
  across: Float64Array; // [3 * row]
  normal: Float64Array; // [3 * row]
  lo: Float64Array; // [row]
  hi: Float64Array; // [row]
  along: Float64Array; // [row], 0 at the root .. 1 at the tip
}

/** Where "out from the head" points from: the mean of the roots. */
export function rootCentroid(strands: ExportStrands): [number, number, number] {
  const n = strands.strandStart.length - 1;
  const o: [number, number, number] = [0, 0, 0];
  if (n === 0) return o;
  for (let s = 0; s < n; s++) {
    const p = 3 * strands.strandStart[s];
    for (let c = 0; c < 3; c++) o[c] += strands.points[p + c];
  }
  for (let c = 0; c < 3; c++) o[c] /= n;
  return o;
}

function normalise(v: number[]): number {
  const l = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (l > 0) for (let c = 0; c < 3; c++) v[c] /= l;
  return l;
}

function cross(a: number[], b: number[]): number[] {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** The cards of `clusters` over `strands`. */
export function buildCards(strands: ExportStrands, clusters: CardClusters): Cards {
  const { points, strandStart, widths } = strands;
  const n = strandStart.length - 1;
  const origin = rootCentroid(strands);
  let longest = 2;
  for (let s = 0; s < n; s++) longest = Math.max(longest, strandStart[s + 1] - strandStart[s]);
  const cum = new Float64Array(longest);
  const lengths = new Float64Array(n);
  for (let s = 0; s < n; s++) {
    const m = strandArc(points, strandStart, s, cum);
    lengths[s] = cum[m - 1];
  }

  // rows per card from the mean length of its strands
  const rowStart = new Int32Array(clusters.count + 1);
  for (let c = 0; c < clusters.count; c++) {
    let sum = 0;
    for (let k = clusters.start[c]; k < clusters.start[c + 1]; k++)
      sum += lengths[clusters.members[k]];
    const mean = sum / (clusters.start[c + 1] - clusters.start[c]);
    const quads = Math.min(QUADS_MAX, Math.max(QUADS_MIN, Math.ceil(mean / QUAD_LENGTH)));
    rowStart[c + 1] = rowStart[c] + quads + 1;
  }
  const rows = rowStart[clusters.count];
  const cards: Cards = {
    count: clusters.count,
    rowStart,
    centre: new Float64Array(3 * rows),
    across: new Float64Array(3 * rows),
    normal: new Float64Array(3 * rows),
    lo: new Float64Array(rows),
    hi: new Float64Array(rows),
    along: new Float64Array(rows),
  };
  let biggest = 1;
  for (let c = 0; c < clusters.count; c++)
    biggest = Math.max(biggest, clusters.start[c + 1] - clusters.start[c]);
  // the cluster's strands sampled at every row: samples[3 * (row * size + member)]
  let samples = new Float64Array(3 * 17 * biggest);
  const sampleWidth = new Float64Array(17 * biggest);

  for (let c = 0; c < clusters.count; c++) {
    const r0 = rowStart[c];
    const nr = rowStart[c + 1] - r0;
    const m0 = clusters.start[c];
    const size = clusters.start[c + 1] - m0;
    if (samples.length < 3 * nr * size) samples = new Float64Array(3 * nr * size);
    for (let k = 0; k < size; k++) {
      const s = clusters.members[m0 + k];
      const np = strandArc(points, strandStart, s, cum);
      const a = strandStart[s];
      for (let r = 0; r < nr; r++) {
        const t = r / (nr - 1);
        pointAtFraction(points, a, np, cum, t, samples, 3 * (r * size + k));
        // the strand's diameter there (tapered linearly, as strandsForExport writes it)
        sampleWidth[r * size + k] = widths[a] + (widths[a + np - 1] - widths[a]) * t;
      }
    }
    for (let r = 0; r < nr; r++) {
      const o = 3 * (r0 + r);
      for (let q = 0; q < 3; q++) {
        let sum = 0;
        for (let k = 0; k < size; k++) sum += samples[3 * (r * size + k) + q];
        cards.centre[o + q] = sum / size;
      }
      cards.along[r0 + r] = r / (nr - 1);
    }
    let prevAcross: number[] | null = null;
    for (let r = 0; r < nr; r++) {
      const o = 3 * (r0 + r);
      const a = 3 * (r0 + Math.max(0, r - 1));
      const b = 3 * (r0 + Math.min(nr - 1, r + 1));
      const tangent = [0, 1, 2].map((q) => cards.centre[b + q] - cards.centre[a + q]);
      if (normalise(tangent) === 0) tangent.splice(0, 3, 0, -1, 0);
      const out = [0, 1, 2].map((q) => cards.centre[o + q] - origin[q]);
      let across = cross(tangent, out);
      // hair pointing straight out from the head: keep the previous row's across direction
      if (normalise(across) < 1e-9 * (1 + normalise(out.slice()))) {
        across = prevAcross ? prevAcross.slice() : [1, 0, 0];
        const along = dot(across, tangent);
        for (let q = 0; q < 3; q++) across[q] -= along * tangent[q];
        if (normalise(across) === 0) {
          across = cross(tangent, [0, 0, 1]);
          if (normalise(across) === 0) across = [1, 0, 0];
        }
      }
      if (prevAcross && dot(across, prevAcross) < 0) for (let q = 0; q < 3; q++) across[q] *= -1;
      prevAcross = across;
      const normal = cross(across, tangent);
      normalise(normal);
      if (dot(normal, out) < 0) for (let q = 0; q < 3; q++) normal[q] *= -1;
      let lo = Number.POSITIVE_INFINITY;
      let hi = Number.NEGATIVE_INFINITY;
      for (let k = 0; k < size; k++) {
        const p = 3 * (r * size + k);
        const d =
          (samples[p] - cards.centre[o]) * across[0] +
          (samples[p + 1] - cards.centre[o + 1]) * across[1] +
          (samples[p + 2] - cards.centre[o + 2]) * across[2];
        const half = sampleWidth[r * size + k] / 2;
        lo = Math.min(lo, d - half);
        hi = Math.max(hi, d + half);
      }
      if (hi - lo < MIN_CARD_WIDTH) {
        const mid = (lo + hi) / 2;
        lo = mid - MIN_CARD_WIDTH / 2;
        hi = mid + MIN_CARD_WIDTH / 2;
      }
      cards.lo[r0 + r] = lo;
      cards.hi[r0 + r] = hi;
      for (let q = 0; q < 3; q++) {
        cards.across[o + q] = across[q];
        cards.normal[o + q] = normal[q];
      }
    }
  }
  return cards;
}

export interface CardGeometry {
  /** Two vertices per row (the lo side, then the hi side). */
  positions: Float32Array; // [3 * vertex]
  normals: Float32Array; // [3 * vertex]
  uvs: Float32Array; // [2 * vertex], u across (0 at lo) and v along (0 at the root) in the tile
  indices: Uint32Array; // two triangles per quad
  triangles: number;
  min: [number, number, number];
  max: [number, number, number];
}

/** Vertex arrays of `cards`; card c's UVs map into the atlas rectangle tiles[c] = [u0, v0, u1, v1]
 *  (v down, glTF's convention: v0 at the root). */
export function cardGeometry(cards: Cards, tileRect: (card: number) => number[]): CardGeometry {
  const rows = cards.rowStart[cards.count];
  const positions = new Float32Array(6 * rows);
  const normals = new Float32Array(6 * rows);
  const uvs = new Float32Array(4 * rows);
  const quads = rows - cards.count;
  const indices = new Uint32Array(6 * quads);
  let ii = 0;
  for (let c = 0; c < cards.count; c++) {
    const [u0, v0, u1, v1] = tileRect(c);
    for (let r = cards.rowStart[c]; r < cards.rowStart[c + 1]; r++) {
      for (let side = 0; side < 2; side++) {
        const v = 2 * r + side;
        const off = side === 0 ? cards.lo[r] : cards.hi[r];
        for (let q = 0; q < 3; q++) {
          positions[3 * v + q] = cards.centre[3 * r + q] + off * cards.across[3 * r + q];
          normals[3 * v + q] = cards.normal[3 * r + q];
        }
        uvs[2 * v] = side === 0 ? u0 : u1;
        uvs[2 * v + 1] = v0 + (v1 - v0) * cards.along[r];
      }
      if (r + 1 < cards.rowStart[c + 1]) {
        const a = 2 * r;
        // counter-clockwise seen from the normal's side (across × along = normal)
        indices.set([a, a + 1, a + 3, a, a + 3, a + 2], ii);
        ii += 6;
      }
    }
  }
  const min: [number, number, number] = [0, 0, 0];
  const max: [number, number, number] = [0, 0, 0];
  if (rows > 0)
    for (let q = 0; q < 3; q++) {
      min[q] = Number.POSITIVE_INFINITY;
      max[q] = Number.NEGATIVE_INFINITY;
      for (let v = 0; v < 2 * rows; v++) {
        min[q] = Math.min(min[q], positions[3 * v + q]);
        max[q] = Math.max(max[q], positions[3 * v + q]);
      }
    }
  return { positions, normals, uvs, indices, triangles: 2 * quads, min, max };
}
