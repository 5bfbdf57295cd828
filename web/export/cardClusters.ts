// Strands grouped into hair cards: seeded k-means over each strand's shape (its root and the
// points at a third, two thirds and the whole of its length, 12 numbers), so strands that start
// together and go the same way share a card. Deterministic: the first centres are the strands
// picked by a hash of (growth seed, strand index); each Lloyd step compares a strand only with
// its cluster and that cluster's nearest centres (found through a grid over the centres' roots),
// which keeps 100K strands × 5,000 cards to a fraction of a second. Plain float64 arithmetic
// (+, −, ×, ÷, √ only): the same clusters in every JS engine.
import { strandArc, strandHash } from './strandsForExport';

/** Numbers describing a strand's shape: 4 points × 3 coordinates. */
export const FEATURES = 12;
const SAMPLES = [0, 1 / 3, 2 / 3, 1];
/** Lloyd steps after the first assignment. */
const LLOYD_STEPS = 8;
/** Centres each cluster's strands are compared with besides their own. */
const NEIGHBOURS = 12;

export interface CardClusters {
  /** Clusters with at least one strand, numbered 0 .. count − 1 in order of their first strand. */
  count: number;
  /** Strand s belongs to cluster of[s]. */
  of: Int32Array;
  /** Cluster c holds strands members[start[c] .. start[c + 1] − 1], in strand order. */
  start: Int32Array;
  members: Int32Array;
}

/** The point at arc-length fraction t of the polyline points[3a .. 3(a + n) − 1], into out[o..o+2]
 *  (cum: its cumulative arc lengths, cum[0] = 0). */
export function pointAtFraction(
  points: Float32Array,
  a: number,
  n: number,
  cum: Float64Array,
  t: number,
  out: Float64Array,
  o: number,
): void {
  const total = cum[n - 1];
  const target = t * total;
  let i = 0;
  // binary search for the segment holding target: cum[i] <= target <= cum[i + 1]
  let lo = 0;
  let hi = n - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (cum[mid] <= target) lo = mid;
    else hi = mid;
  }
  i = lo;
  const len = cum[i + 1] - cum[i];
  const f = len > 0 ? Math.min(1, Math.max(0, (target - cum[i]) / len)) : 0;
  const p = 3 * (a + i);
  out[o] = points[p] + (points[p + 3] - points[p]) * f;
  out[o + 1] = points[p + 1] + (points[p + 4] - points[p + 1]) * f;
  out[o + 2] = points[p + 2] + (points[p + 5] - points[p + 2]) * f;
}

/** The shape features of every strand (every strand has at least 2 points). */
export function strandFeatures(points: Float32Array, strandStart: Uint32Array): Float64Array {
  const n = strandStart.length - 1;
  const f = new Float64Array(FEATURES * n);
  let longest = 2;
  for (let s = 0; s < n; s++) longest = Math.max(longest, strandStart[s + 1] - strandStart[s]);
  const cum = new Float64Array(longest);
  for (let s = 0; s < n; s++) {
    const m = strandArc(points, strandStart, s, cum);
    for (let k = 0; k < SAMPLES.length; k++)
      pointAtFraction(points, strandStart[s], m, cum, SAMPLES[k], f, FEATURES * s + 3 * k);
  }
  return f;
}

function dist2(a: Float64Array, i: number, b: Float64Array, j: number): number {
  let d = 0;
  for (let k = 0; k < FEATURES; k++) {
    const e = a[FEATURES * i + k] - b[FEATURES * j + k];
    d += e * e;
  }
  return d;
}

/** A uniform grid over 3D points (the first three numbers of each FEATURES-long row). */
class RootGrid {
  private readonly min = [0, 0, 0];
  private readonly dims = [1, 1, 1];
  private readonly cell: number;
  private readonly cellStart: Int32Array;
  private readonly items: Int32Array;

  constructor(
    private readonly rows: Float64Array,
    private readonly count: number,
  ) {
    const max = [0, 0, 0];
    for (let c = 0; c < 3; c++) {
      this.min[c] = Number.POSITIVE_INFINITY;
      max[c] = Number.NEGATIVE_INFINITY;
    }
    for (let i = 0; i < count; i++)
      for (let c = 0; c < 3; c++) {
        const v = rows[FEATURES * i + c];
        if (v < this.min[c]) this.min[c] = v;
        if (v > max[c]) max[c] = v;
      }
    const ext = [0, 1, 2].map((c) => Math.max(1e-6, max[c] - this.min[c]));
    // roots lie on a surface: about count cells over its area, ~1-2 items per occupied cell
    const area = ext[0] * ext[1] + ext[1] * ext[2] + ext[0] * ext[2];
    this.cell = Math.max(1e-6, Math.sqrt(area / Math.max(1, count)));
    for (let c = 0; c < 3; c++)
      this.dims[c] = Math.min(256, Math.max(1, Math.floor(ext[c] / this.cell) + 1));
    const cells = this.dims[0] * this.dims[1] * this.dims[2];
    this.cellStart = new Int32Array(cells + 1);
    const cellOf = new Int32Array(count);
    for (let i = 0; i < count; i++) {
      cellOf[i] = this.cellIndex(rows, i);
      this.cellStart[cellOf[i] + 1]++;
    }
    for (let c = 0; c < cells; c++) this.cellStart[c + 1] += this.cellStart[c];
    const fill = this.cellStart.slice(0, cells);
    this.items = new Int32Array(count);
    for (let i = 0; i < count; i++) this.items[fill[cellOf[i]]++] = i;
  }

  private coord(v: number, c: number): number {
    return Math.min(this.dims[c] - 1, Math.max(0, Math.floor((v - this.min[c]) / this.cell)));
  }

  private cellIndex(rows: Float64Array, i: number): number {
    const x = this.coord(rows[FEATURES * i], 0);
    const y = this.coord(rows[FEATURES * i + 1], 1);
    const z = this.coord(rows[FEATURES * i + 2], 2);
    return x + this.dims[0] * (y + this.dims[1] * z);
  }

  /** Up to `want` items nearest to row q of `from` by root distance (ascending; ties by item),
   *  into out; returns how many. */
  nearest(from: Float64Array, q: number, want: number, outItem: Int32Array, outD: Float64Array) {
    const qx = from[FEATURES * q];
    const qy = from[FEATURES * q + 1];
    const qz = from[FEATURES * q + 2];
    const cx = this.coord(qx, 0);
    const cy = this.coord(qy, 1);
    const cz = this.coord(qz, 2);
    let found = 0;
    const maxRing = Math.max(this.dims[0], this.dims[1], this.dims[2]);
    for (let r = 0; r <= maxRing; r++) {
      // every cell of the shell at Chebyshev distance r
      for (let z = cz - r; z <= cz + r; z++) {
        if (z < 0 || z >= this.dims[2]) continue;
        for (let y = cy - r; y <= cy + r; y++) {
          if (y < 0 || y >= this.dims[1]) continue;
          const shell = Math.abs(z - cz) === r || Math.abs(y - cy) === r;
          for (let x = cx - r; x <= cx + r; x += shell ? 1 : Math.max(1, 2 * r)) {
            if (x < 0 || x >= this.dims[0]) continue;
            const cell = x + this.dims[0] * (y + this.dims[1] * z);
            for (let k = this.cellStart[cell]; k < this.cellStart[cell + 1]; k++) {
              const it = this.items[k];
              const dx = this.rows[FEATURES * it] - qx;
              const dy = this.rows[FEATURES * it + 1] - qy;
              const dz = this.rows[FEATURES * it + 2] - qz;
              const d = dx * dx + dy * dy + dz * dz;
              // insertion into the sorted list of the best `want`
              if (found === want && !(d < outD[want - 1])) continue;
              let j = found < want ? found++ : want - 1;
              while (j > 0 && (outD[j - 1] > d || (outD[j - 1] === d && outItem[j - 1] > it))) {
                outD[j] = outD[j - 1];
                outItem[j] = outItem[j - 1];
                j--;
              }
              outD[j] = d;
              outItem[j] = it;
            }
          }
        }
      }
      // every item outside the rings searched is at least r · cell away
      if (found === Math.min(want, this.count) && outD[found - 1] <= (r * this.cell) ** 2) break;
      if (found === this.count) break;
    }
    return found;
  }
}

/** Clusters the strands (features from strandFeatures) into at most `k` cards, seeded. */
export function clusterStrands(features: Float64Array, k: number, seed: number): CardClusters {
  const n = features.length / FEATURES;
  const kk = Math.max(1, Math.min(k, n));
  const of = new Int32Array(n);
  if (n === 0) return { count: 0, of, start: new Int32Array(1), members: new Int32Array(0) };

  // first centres: the kk strands with the smallest hashes (ties by index)
  const order = Array.from({ length: n }, (_, i) => i);
  const hash = new Uint32Array(n);
  for (let i = 0; i < n; i++) hash[i] = strandHash(seed ^ 0x5ca1ab1e, i);
  order.sort((a, b) => hash[a] - hash[b] || a - b);
  const centres = new Float64Array(FEATURES * kk);
  for (let c = 0; c < kk; c++)
    centres.set(features.subarray(FEATURES * order[c], FEATURES * (order[c] + 1)), FEATURES * c);

  // first assignment: the nearest centres by root, the best of them by shape
  const want = Math.min(kk, NEIGHBOURS + 1);
  const item = new Int32Array(want);
  const d = new Float64Array(want);
  let grid = new RootGrid(centres, kk);
  for (let s = 0; s < n; s++) {
    const m = grid.nearest(features, s, want, item, d);
    let best = item[0];
    let bestD = Number.POSITIVE_INFINITY;
    for (let j = 0; j < m; j++) {
      const e = dist2(features, s, centres, item[j]);
      if (e < bestD || (e === bestD && item[j] < best)) {
        bestD = e;
        best = item[j];
      }
    }
    of[s] = best;
  }

  const sums = new Float64Array(FEATURES * kk);
  const sizes = new Int32Array(kk);
  const neighbours = new Int32Array(kk * want);
  for (let step = 0; step < LLOYD_STEPS; step++) {
    sums.fill(0);
    sizes.fill(0);
    for (let s = 0; s < n; s++) {
      const c = of[s];
      sizes[c]++;
      for (let q = 0; q < FEATURES; q++) sums[FEATURES * c + q] += features[FEATURES * s + q];
    }
    for (let c = 0; c < kk; c++)
      if (sizes[c] > 0)
        for (let q = 0; q < FEATURES; q++)
          centres[FEATURES * c + q] = sums[FEATURES * c + q] / sizes[c];
    grid = new RootGrid(centres, kk);
    for (let c = 0; c < kk; c++) {
      const m = grid.nearest(centres, c, want, item, d);
      for (let j = 0; j < want; j++) neighbours[c * want + j] = j < m ? item[j] : c;
    }
    let moved = 0;
    for (let s = 0; s < n; s++) {
      const own = of[s];
      let best = own;
      let bestD = dist2(features, s, centres, own);
      for (let j = 0; j < want; j++) {
        const c = neighbours[own * want + j];
        if (sizes[c] === 0 || c === own) continue;
        const e = dist2(features, s, centres, c);
        if (e < bestD || (e === bestD && c < best)) {
          bestD = e;
          best = c;
        }
      }
      if (best !== own) {
        of[s] = best;
        moved++;
      }
    }
    if (moved === 0) break;
  }

  // number the non-empty clusters in order of their first strand
  const renum = new Int32Array(kk).fill(-1);
  let count = 0;
  for (let s = 0; s < n; s++) {
    if (renum[of[s]] < 0) renum[of[s]] = count++;
    of[s] = renum[of[s]];
  }
  const start = new Int32Array(count + 1);
  for (let s = 0; s < n; s++) start[of[s] + 1]++;
  for (let c = 0; c < count; c++) start[c + 1] += start[c];
  const fill = start.slice(0, count);
  const members = new Int32Array(n);
  for (let s = 0; s < n; s++) members[fill[of[s]]++] = s;
  return { count, of, start, members };
}
