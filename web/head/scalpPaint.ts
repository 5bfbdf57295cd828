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
