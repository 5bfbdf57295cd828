// A loaded head's own UVs at points on (or near) it: the closest point on the mesh, found through
// a uniform grid of the triangles' bounding boxes (its occupied cells hashed) searched in growing
// rings, and the corner UVs
// of its triangle interpolated there (barycentric: exact for a UV that is affine on the
// triangle, and each side of a UV seam keeps its own corners). Plain typed arrays, no three.js:
// it runs in the export worker and in `hairsketch grow` alike.

import { triangleNormal } from '../head/triangleNormal';

/** A triangle mesh with UVs per corner (HeadMesh.cornerUvs: 6 per triangle, v up). */
export interface UvSurface {
  positions: Float32Array; // positions[3 * vertex + axis]
  indices: Uint32Array; // indices[3 * triangle + corner]
  cornerUvs: Float32Array; // cornerUvs[6 * triangle + 2 * corner + k]
}

/** A UV in [0, 1] as a texture with repeat wrapping reads it: values in [0, 1] as they are,
 *  others by their fractional part (a UDIM tile's UV becomes its place in the tile). */
export function wrapUv(x: number): number {
  return x >= 0 && x <= 1 ? x : x - Math.floor(x);
}

/** Closest-point and UV queries on `surface`. */
export class SurfaceUvLookup {
  private readonly lo = [0, 0, 0];
  private readonly dims = [1, 1, 1];
  private readonly cell: number;
  /** Occupied cells only (a head is a surface: most of its box is empty), in an open-addressed
   *  hash: table[slot] = cell id + 1 (0: empty), keys[cell id] = the cell's linear index. */
  private table: Int32Array;
  private readonly keys: Float64Array;
  /** Triangles of cell id c: list[first[c] .. first[c + 1]). */
  private readonly first: Uint32Array;
  private readonly list: Uint32Array;
  private readonly w = new Float64Array(3);
  private readonly normal = new Float64Array(3); // triangleArea's scratch

  constructor(private readonly s: UvSurface) {
    const P = s.positions;
    const I = s.indices;
    const triangles = I.length / 3;
    const hi = [-Infinity, -Infinity, -Infinity];
    this.lo.fill(Infinity);
    for (let i = 0; i < P.length; i++) {
      const a = i % 3;
      if (P[i] < this.lo[a]) this.lo[a] = P[i];
      if (P[i] > hi[a]) hi[a] = P[i];
    }
    if (triangles === 0 || !(hi[0] >= this.lo[0])) this.lo.fill(0);
    const size = [0, 1, 2].map((a) => Math.max(hi[a] - this.lo[a], 0));
    const longest = Math.max(size[0], size[1], size[2]);
    // cells whose face holds about eight triangles (by the mean area), at most 2048 a side; larger
    // while the triangles' boxes would cover more than 8 cells a triangle on average
    let area = 0;
    for (let t = 0; t < triangles; t++) area += this.triangleArea(t);
    let cell = Math.max(Math.sqrt((8 * area) / Math.max(triangles, 1)), longest / 2048, 1e-9);
    const box = new Int32Array(6);
    for (;;) {
      this.cell = cell;
      for (let a = 0; a < 3; a++) this.dims[a] = Math.max(1, Math.ceil(size[a] / cell));
      let pairs = 0;
      for (let t = 0; t < triangles; t++) {
        this.triangleCells(t, box);
        pairs += (box[3] - box[0] + 1) * (box[4] - box[1] + 1) * (box[5] - box[2] + 1);
      }
      if (pairs <= 8 * triangles + 65536) break;
      cell *= 1.5;
    }
    const [nx, ny] = this.dims;
    // at most half full: doubled (and filled again) as cells come
    this.table = new Int32Array(1 << 12);
    let keys = new Float64Array(1024);
    let counts = new Uint32Array(1024);
    let used = 0;
    for (let t = 0; t < triangles; t++) {
      this.triangleCells(t, box);
      for (let k = box[2]; k <= box[5]; k++)
        for (let j = box[1]; j <= box[4]; j++)
          for (let i = box[0]; i <= box[3]; i++) {
            const key = i + nx * (j + ny * k);
            let slot = this.slotOf(i, j, k);
            let id = -1;
            for (;;) {
              const e = this.table[slot];
              if (e === 0) break;
              if (keys[e - 1] === key) {
                id = e - 1;
                break;
              }
              slot = (slot + 1) & (this.table.length - 1);
            }
            if (id < 0) {
              if (2 * (used + 1) > this.table.length) {
                this.rehash(keys, used, 2 * this.table.length);
                slot = this.slotOf(i, j, k);
                while (this.table[slot] !== 0) slot = (slot + 1) & (this.table.length - 1);
              }
              if (used === keys.length) {
                const k2 = new Float64Array(2 * used);
                k2.set(keys);
                keys = k2;
                const c2 = new Uint32Array(2 * used);
                c2.set(counts);
                counts = c2;
              }
              id = used++;
              keys[id] = key;
              this.table[slot] = id + 1;
            }
            counts[id]++;
          }
    }
    this.keys = keys.slice(0, used);
    this.first = new Uint32Array(used + 1);
    for (let c = 0; c < used; c++) this.first[c + 1] = this.first[c] + counts[c];
    this.list = new Uint32Array(this.first[used]);
    const fill = this.first.slice(0, used);
    for (let t = 0; t < triangles; t++) {
      this.triangleCells(t, box);
      for (let k = box[2]; k <= box[5]; k++)
        for (let j = box[1]; j <= box[4]; j++)
          for (let i = box[0]; i <= box[3]; i++) this.list[fill[this.cellId(i, j, k)]++] = t;
    }
  }

  /** A table of `size` slots holding the first `used` cells of `keys`. */
  private rehash(keys: Float64Array, used: number, size: number): void {
    const [nx, ny] = this.dims;
    this.table = new Int32Array(size);
    for (let c = 0; c < used; c++) {
      const key = keys[c];
      const i = key % nx;
      const j = Math.floor(key / nx) % ny;
      const k = Math.floor(key / (nx * ny));
      let slot = this.slotOf(i, j, k);
      while (this.table[slot] !== 0) slot = (slot + 1) & (size - 1);
      this.table[slot] = c + 1;
    }
  }

  /** The first hash slot of cell (i, j, k). */
  private slotOf(i: number, j: number, k: number): number {
    let h = Math.imul(i, 0x9e3779b1) ^ Math.imul(j, 0x85ebca77) ^ Math.imul(k, 0xc2b2ae3d);
    h ^= h >>> 15;
    return h & (this.table.length - 1);
  }

  /** The id of cell (i, j, k), or -1 when no triangle touches it. */
  private cellId(i: number, j: number, k: number): number {
    const key = i + this.dims[0] * (j + this.dims[1] * k);
    const mask = this.table.length - 1;
    for (let slot = this.slotOf(i, j, k); ; slot = (slot + 1) & mask) {
      const e = this.table[slot];
      if (e === 0) return -1;
      if (this.keys[e - 1] === key) return e - 1;
    }
  }

  private triangleArea(t: number): number {
    const I = this.s.indices;
    const n = triangleNormal(
      this.s.positions,
      3 * I[3 * t],
      3 * I[3 * t + 1],
      3 * I[3 * t + 2],
      this.normal,
    );
    return 0.5 * Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }

  /** The UV at the point of the surface closest to (x, y, z), wrapped into [0, 1], written to
   *  out[at], out[at + 1]. */
  uvAt(x: number, y: number, z: number, out: Float32Array, at: number): void {
    const t = this.closestTriangle(x, y, z);
    const U = this.s.cornerUvs;
    const w = this.w;
    for (let k = 0; k < 2; k++) {
      const o = 6 * t + k;
      out[at + k] = wrapUv(w[0] * U[o] + w[1] * U[o + 2] + w[2] * U[o + 4]);
    }
  }

  /** The triangle closest to p, with the barycentric weights of the closest point in this.w
   *  (ties: the lower triangle index). */
  closestTriangle(x: number, y: number, z: number): number {
    const [nx, ny, nz] = this.dims;
    const ci = this.cellOf(x, 0);
    const cj = this.cellOf(y, 1);
    const ck = this.cellOf(z, 2);
    // how far p is from the faces of its cell (0 when outside the grid on that side): a
    // triangle in a cell r + 1 rings out is at least r cells plus that far away
    const h = this.cell;
    const lo = this.lo;
    const margin = Math.max(
      0,
      Math.min(
        x - (lo[0] + ci * h),
        lo[0] + (ci + 1) * h - x,
        y - (lo[1] + cj * h),
        lo[1] + (cj + 1) * h - y,
        z - (lo[2] + ck * h),
        lo[2] + (ck + 1) * h - z,
      ),
    );
    this.best = Infinity;
    this.bestT = -1;
    const reach = Math.max(nx, ny, nz);
    for (let r = 0; r <= reach; r++) {
      // the cells r steps away (Chebyshev) from p's cell
      for (let k = Math.max(0, ck - r); k <= Math.min(nz - 1, ck + r); k++)
        for (let j = Math.max(0, cj - r); j <= Math.min(ny - 1, cj + r); j++) {
          if (Math.abs(k - ck) === r || Math.abs(j - cj) === r) {
            const i1 = Math.min(nx - 1, ci + r);
            for (let i = Math.max(0, ci - r); i <= i1; i++) this.visit(i, j, k, x, y, z);
          } else {
            if (ci - r >= 0) this.visit(ci - r, j, k, x, y, z);
            if (ci + r < nx) this.visit(ci + r, j, k, x, y, z);
          }
        }
      if (this.bestT >= 0 && Math.sqrt(this.best) < r * h + margin) break;
    }
    if (this.bestT < 0) throw new Error('the head has no triangles');
    this.w[0] = this.bw[0];
    this.w[1] = this.bw[1];
    this.w[2] = this.bw[2];
    return this.bestT;
  }

  private best = Infinity;
  private bestT = -1;
  private readonly bw = new Float64Array(3);

  private visit(i: number, j: number, k: number, x: number, y: number, z: number): void {
    const c = this.cellId(i, j, k);
    if (c < 0) return;
    const end = this.first[c + 1];
    for (let e = this.first[c]; e < end; e++) {
      const t = this.list[e];
      const d = this.distanceTo(t, x, y, z);
      if (d < this.best || (d === this.best && t < this.bestT)) {
        this.best = d;
        this.bestT = t;
        this.bw[0] = this.w[0];
        this.bw[1] = this.w[1];
        this.bw[2] = this.w[2];
      }
    }
  }

  private cellOf(v: number, a: number): number {
    const c = Math.floor((v - this.lo[a]) / this.cell);
    return Math.min(this.dims[a] - 1, Math.max(0, c));
  }

  /** Cell range of triangle t's bounding box: box = [i0, j0, k0, i1, j1, k1]. */
  private triangleCells(t: number, box: Int32Array): void {
    const P = this.s.positions;
    const I = this.s.indices;
    for (let a = 0; a < 3; a++) {
      const p0 = P[3 * I[3 * t] + a];
      const p1 = P[3 * I[3 * t + 1] + a];
      const p2 = P[3 * I[3 * t + 2] + a];
      box[a] = this.cellOf(Math.min(p0, p1, p2), a);
      box[a + 3] = this.cellOf(Math.max(p0, p1, p2), a);
    }
  }

  /** Squared distance from p to the point (u, v, s) of triangle t, the weights kept in this.w. */
  private settle(
    t: number,
    px: number,
    py: number,
    pz: number,
    u: number,
    v: number,
    s: number,
  ): number {
    const P = this.s.positions;
    const I = this.s.indices;
    const a = 3 * I[3 * t];
    const b = 3 * I[3 * t + 1];
    const c = 3 * I[3 * t + 2];
    this.w[0] = u;
    this.w[1] = v;
    this.w[2] = s;
    const qx = px - (u * P[a] + v * P[b] + s * P[c]);
    const qy = py - (u * P[a + 1] + v * P[b + 1] + s * P[c + 1]);
    const qz = pz - (u * P[a + 2] + v * P[b + 2] + s * P[c + 2]);
    return qx * qx + qy * qy + qz * qz;
  }

  /** Squared distance from p to triangle t; the closest point's barycentric weights in this.w
   *  (the region tests of Ericson, Real-Time Collision Detection, 5.1.5). */
  private distanceTo(t: number, px: number, py: number, pz: number): number {
    const P = this.s.positions;
    const I = this.s.indices;
    const a = 3 * I[3 * t];
    const b = 3 * I[3 * t + 1];
    const c = 3 * I[3 * t + 2];
    const abx = P[b] - P[a];
    const aby = P[b + 1] - P[a + 1];
    const abz = P[b + 2] - P[a + 2];
    const acx = P[c] - P[a];
    const acy = P[c + 1] - P[a + 1];
    const acz = P[c + 2] - P[a + 2];
    const apx = px - P[a];
    const apy = py - P[a + 1];
    const apz = pz - P[a + 2];
    const d1 = abx * apx + aby * apy + abz * apz;
    const d2 = acx * apx + acy * apy + acz * apz;
    if (d1 <= 0 && d2 <= 0) return this.settle(t, px, py, pz, 1, 0, 0);
    const bpx = px - P[b];
    const bpy = py - P[b + 1];
    const bpz = pz - P[b + 2];
    const d3 = abx * bpx + aby * bpy + abz * bpz;
    const d4 = acx * bpx + acy * bpy + acz * bpz;
    if (d3 >= 0 && d4 <= d3) return this.settle(t, px, py, pz, 0, 1, 0);
    const vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
      const v = d1 / (d1 - d3);
      return this.settle(t, px, py, pz, 1 - v, v, 0);
    }
    const cpx = px - P[c];
    const cpy = py - P[c + 1];
    const cpz = pz - P[c + 2];
    const d5 = abx * cpx + aby * cpy + abz * cpz;
    const d6 = acx * cpx + acy * cpy + acz * cpz;
    if (d6 >= 0 && d5 <= d6) return this.settle(t, px, py, pz, 0, 0, 1);
    const vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
      const s = d2 / (d2 - d6);
      return this.settle(t, px, py, pz, 1 - s, 0, s);
    }
    const va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
      const s = (d4 - d3) / (d4 - d3 + (d5 - d6));
      return this.settle(t, px, py, pz, 0, 1 - s, s);
    }
    const den = va + vb + vc;
    if (!(den > 0)) return this.settle(t, px, py, pz, 1, 0, 0); // a degenerate triangle: its first corner
    const v = vb / den;
    const s = vc / den;
    return this.settle(t, px, py, pz, 1 - v - s, v, s);
  }
}
