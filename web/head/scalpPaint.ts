// The scalp brush's effect on a head's scalp mask. A session keeps the brush strokes,
// not the mask: each stroke is a polyline of surface points with a radius, painting scalp or
// erasing it, applied in order over the head's default scalp. A triangle is covered by a stroke
// when its centroid lies within the radius of the polyline (a ball swept along it: on a head the
// brush reaches what is under it, not the far side). The mask is a pure function of (mesh,
// default scalp, strokes), so a link or a file that carries the strokes gives the same scalp.
//
// Centroids are indexed once per mesh in a uniform grid (CSR layout), so a stroke costs the
// triangles near it, not the whole mesh (1M-triangle heads).
import type { Vec3 } from '../model/vec3';
import type { TriangleSoup } from './head';
import type { Hairline } from './scalpRegion';

export interface ScalpPaintStroke {
  /** true: the stroke removes scalp; false: it adds scalp. */
  erase: boolean;
  /** Brush radius, world units. */
  radius: number;
  /** Surface points along the stroke (one point: a dab). */
  points: readonly Vec3[];
}

interface CentroidIndex {
  centroids: Float32Array; // 3 per triangle
  origin: Vec3;
  cell: number;
  dims: [number, number, number];
  start: Uint32Array; // start[cell] .. start[cell + 1]: that cell's triangles in `order`
  order: Uint32Array;
}

const indexCache = new WeakMap<Float32Array, Map<Uint32Array, CentroidIndex>>();

function centroidIndex(mesh: TriangleSoup): CentroidIndex {
  let byIndices = indexCache.get(mesh.positions);
  const hit = byIndices?.get(mesh.indices);
  if (hit) return hit;
  const { positions: P, indices: I } = mesh;
  const n = I.length / 3;
  const centroids = new Float32Array(3 * n);
  const lo: Vec3 = [Infinity, Infinity, Infinity];
  const hi: Vec3 = [-Infinity, -Infinity, -Infinity];
  for (let t = 0; t < n; t++) {
    for (let a = 0; a < 3; a++) {
      const c = (P[3 * I[3 * t] + a] + P[3 * I[3 * t + 1] + a] + P[3 * I[3 * t + 2] + a]) / 3;
      centroids[3 * t + a] = c;
      if (c < lo[a]) lo[a] = c;
      if (c > hi[a]) hi[a] = c;
    }
  }
  if (n === 0) for (let a = 0; a < 3; a++) lo[a] = hi[a] = 0;
  // about 4 triangles per occupied cell on a surface: cells ~ n / 4 over the bounding box's area
  const ext = [0, 1, 2].map((a) => Math.max(hi[a] - lo[a], 1e-6));
  const area = 2 * (ext[0] * ext[1] + ext[1] * ext[2] + ext[0] * ext[2]);
  const cell = Math.max(Math.sqrt((4 * area) / Math.max(n, 1)), 1e-4);
  const dims = ext.map((e) => Math.min(1024, Math.floor(e / cell) + 1)) as [number, number, number];
  const cellOf = (t: number) => {
    const k = [0, 1, 2].map((a) =>
      Math.min(dims[a] - 1, Math.max(0, Math.floor((centroids[3 * t + a] - lo[a]) / cell))),
    );
    return (k[2] * dims[1] + k[1]) * dims[0] + k[0];
  };
  const cells = dims[0] * dims[1] * dims[2];
  const start = new Uint32Array(cells + 1);
  const cellIds = new Uint32Array(n);
  for (let t = 0; t < n; t++) {
    cellIds[t] = cellOf(t);
    start[cellIds[t] + 1]++;
  }
  for (let c = 0; c < cells; c++) start[c + 1] += start[c];
  const fill = start.slice(0, cells);
  const order = new Uint32Array(n);
  for (let t = 0; t < n; t++) order[fill[cellIds[t]]++] = t;
  const index: CentroidIndex = { centroids, origin: lo, cell, dims, start, order };
  if (!byIndices) {
    byIndices = new Map();
    indexCache.set(mesh.positions, byIndices);
  }
  byIndices.set(mesh.indices, index);
  return index;
}

/** Squared distance from point q to segment ab. */
function segmentDistance2(q: ArrayLike<number>, qo: number, a: Vec3, b: Vec3): number {
  const ab0 = b[0] - a[0];
  const ab1 = b[1] - a[1];
  const ab2 = b[2] - a[2];
  const aq0 = q[qo] - a[0];
  const aq1 = q[qo + 1] - a[1];
  const aq2 = q[qo + 2] - a[2];
  const len2 = ab0 * ab0 + ab1 * ab1 + ab2 * ab2;
  let s = len2 > 0 ? (aq0 * ab0 + aq1 * ab1 + aq2 * ab2) / len2 : 0;
  s = Math.max(0, Math.min(s, 1));
  const d0 = aq0 - s * ab0;
  const d1 = aq1 - s * ab1;
  const d2 = aq2 - s * ab2;
  return d0 * d0 + d1 * d1 + d2 * d2;
}

/** Calls `visit(triangle)` for every triangle whose centroid is within the stroke's radius of its
 *  polyline (a triangle near two segments may be visited twice). */
export function forEachCovered(
  mesh: TriangleSoup,
  stroke: ScalpPaintStroke,
  visit: (triangle: number) => void,
): void {
  const ix = centroidIndex(mesh);
  const r = stroke.radius;
  if (!(r > 0) || stroke.points.length === 0) return;
  const r2 = r * r;
  const pts = stroke.points;
  const segments = Math.max(1, pts.length - 1);
  for (let s = 0; s < segments; s++) {
    const a = pts[s];
    const b = pts[Math.min(s + 1, pts.length - 1)];
    const k0 = [0, 0, 0];
    const k1 = [0, 0, 0];
    for (let axis = 0; axis < 3; axis++) {
      const lo = Math.min(a[axis], b[axis]) - r - ix.origin[axis];
      const hi = Math.max(a[axis], b[axis]) + r - ix.origin[axis];
      k0[axis] = Math.max(0, Math.floor(lo / ix.cell));
      k1[axis] = Math.min(ix.dims[axis] - 1, Math.floor(hi / ix.cell));
      if (k1[axis] < k0[axis]) k1[axis] = -1; // outside the grid on this axis
    }
    for (let z = k0[2]; z <= k1[2]; z++)
      for (let y = k0[1]; y <= k1[1]; y++)
        for (let x = k0[0]; x <= k1[0]; x++) {
          const c = (z * ix.dims[1] + y) * ix.dims[0] + x;
          for (let i = ix.start[c]; i < ix.start[c + 1]; i++) {
            const t = ix.order[i];
            if (segmentDistance2(ix.centroids, 3 * t, a, b) <= r2) visit(t);
          }
        }
  }
}

/** The scalp mask after `strokes` (in order) over `defaultScalp` (one flag per triangle; not
 *  modified). */
export function applyScalpPaint(
  mesh: TriangleSoup,
  defaultScalp: Uint8Array,
  strokes: readonly ScalpPaintStroke[],
): Uint8Array {
  const mask = defaultScalp.slice();
  for (const s of strokes) {
    const v = s.erase ? 0 : 1;
    forEachCovered(mesh, s, (t) => {
      mask[t] = v;
    });
  }
  return mask;
}

/** The scalp mask a session gives (what every caller uses: the app, the CLI, the embed): its
 *  strokes over the head's default scalp. With finished edges (`finish`: a hairline other than
 *  'classic', sessionHairline) the built-in head starts from its natural hairline (with a low nape
 *  in sessions with `nape`), and an erase leaves no lone hair: a triangle the erasing left with
 *  fewer than two scalp neighbours goes, as does a scrap of scalp under 2 cm² cut off by it. Both
 *  only touch scalp next to erased scalp, so painting the erased part back gives the mask exactly
 *  as before the erase. */
export function sessionScalpMask(
  mesh: TriangleSoup & { naturalScalp?: Uint8Array; lowNapeScalp?: Uint8Array },
  defaultScalp: Uint8Array,
  strokes: readonly ScalpPaintStroke[],
  hairline: Hairline,
): Uint8Array {
  const finish = hairline !== 'classic';
  const base =
    (hairline === 'lowNape' ? mesh.lowNapeScalp : finish ? mesh.naturalScalp : undefined) ??
    defaultScalp;
  const mask = applyScalpPaint(mesh, base, strokes);
  if (finish && strokes.some((s) => s.erase)) removeLoneScalp(mesh, base, mask);
  return mask;
}

// Scraps of scalp smaller than this (world units², 2 cm²) cut off by an erase go with it.
const SCRAP_AREA = 0.02;
// Peeling rounds: a strip up to about two triangles wide left between erased parts goes.
const PEEL_ROUNDS = 3;

interface EdgeAdjacency {
  /** neighbours[start[t] .. start[t + 1]]: the triangles sharing an edge with t. */
  start: Uint32Array;
  neighbours: Uint32Array;
  area: Float64Array;
}

const adjacencyCache = new WeakMap<Uint32Array, EdgeAdjacency>();

function edgeAdjacency(mesh: TriangleSoup): EdgeAdjacency {
  const hit = adjacencyCache.get(mesh.indices);
  if (hit) return hit;
  const { positions: P, indices: I } = mesh;
  const n = I.length / 3;
  const byEdge = new Map<number, number[]>();
  const vertices = P.length / 3;
  for (let t = 0; t < n; t++)
    for (let k = 0; k < 3; k++) {
      const a = I[3 * t + k];
      const b = I[3 * t + ((k + 1) % 3)];
      const key = Math.min(a, b) * vertices + Math.max(a, b);
      const list = byEdge.get(key);
      if (list) list.push(t);
      else byEdge.set(key, [t]);
    }
  const lists: number[][] = Array.from({ length: n }, () => []);
  for (const tris of byEdge.values())
    for (const t of tris) for (const u of tris) if (u !== t) lists[t].push(u);
  const start = new Uint32Array(n + 1);
  for (let t = 0; t < n; t++) start[t + 1] = start[t] + lists[t].length;
  const neighbours = new Uint32Array(start[n]);
  for (let t = 0; t < n; t++) neighbours.set(lists[t], start[t]);
  const area = new Float64Array(n);
  for (let t = 0; t < n; t++) {
    const [a, b, c] = [3 * I[3 * t], 3 * I[3 * t + 1], 3 * I[3 * t + 2]];
    const u = [P[b] - P[a], P[b + 1] - P[a + 1], P[b + 2] - P[a + 2]];
    const v = [P[c] - P[a], P[c + 1] - P[a + 1], P[c + 2] - P[a + 2]];
    area[t] =
      0.5 *
      Math.hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
  }
  const adjacency = { start, neighbours, area };
  adjacencyCache.set(mesh.indices, adjacency);
  return adjacency;
}

/** Clears, in `mask`, scalp that erasing (base 1, mask 0) left alone: see sessionScalpMask. */
function removeLoneScalp(mesh: TriangleSoup, base: Uint8Array, mask: Uint8Array): void {
  const { start, neighbours, area } = edgeAdjacency(mesh);
  const lost = (t: number) => base[t] === 1 && mask[t] === 0;
  const nextToLost = (t: number) => {
    for (let i = start[t]; i < start[t + 1]; i++) if (lost(neighbours[i])) return true;
    return false;
  };
  for (let round = 0; round < PEEL_ROUNDS; round++) {
    const peel: number[] = [];
    for (let t = 0; t < mask.length; t++) {
      if (mask[t] !== 1 || !nextToLost(t)) continue;
      let kept = 0;
      for (let i = start[t]; i < start[t + 1]; i++) kept += mask[neighbours[i]];
      if (kept < 2) peel.push(t);
    }
    if (peel.length === 0) break;
    for (const t of peel) mask[t] = 0;
  }
  // small components of scalp that touch erased scalp
  const seen = new Uint8Array(mask.length);
  for (let t0 = 0; t0 < mask.length; t0++) {
    if (mask[t0] !== 1 || seen[t0]) continue;
    const component = [t0];
    seen[t0] = 1;
    let sum = 0;
    let touches = false;
    for (let k = 0; k < component.length; k++) {
      const t = component[k];
      sum += area[t];
      if (!touches && nextToLost(t)) touches = true;
      for (let i = start[t]; i < start[t + 1]; i++) {
        const u = neighbours[i];
        if (mask[u] === 1 && !seen[u]) {
          seen[u] = 1;
          component.push(u);
        }
      }
    }
    if (touches && sum < SCRAP_AREA) for (const t of component) mask[t] = 0;
  }
}
