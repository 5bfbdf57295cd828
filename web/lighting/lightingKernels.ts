// The grid kernels of the hair lighting (hairLightingContext.ts): node-valued scalar fields on a
// regular grid (node (x, y, z) at index x + nx·y + nx·ny·z), and the operations the lighting
// builds from them — trilinear samples, the head's voxels by ray parity, the head's optical
// depth by a march towards the light, and box sums (the hair's optical depth: shearedDepth.ts). Pure arithmetic on typed arrays. Coordinates are in cells (grid units).

export type Dims = readonly [number, number, number];

/** An inclusive range of nodes per axis: lo[a] ≤ index ≤ hi[a]; empty when lo > hi on an axis. */
export interface NodeBox {
  lo: [number, number, number];
  hi: [number, number, number];
}

export interface HeadTriangles {
  positions: Float32Array; // positions[3 * vertex + axis]
  indices: Uint32Array; // indices[3 * triangle + corner]
}

export const emptyBox = (): NodeBox => ({ lo: [0, 0, 0], hi: [-1, -1, -1] });

export const boxIsEmpty = (b: NodeBox): boolean =>
  b.lo[0] > b.hi[0] || b.lo[1] > b.hi[1] || b.lo[2] > b.hi[2];

/** The smallest box holding both (either may be empty). */
export function boxUnion(p: NodeBox, q: NodeBox): NodeBox {
  if (boxIsEmpty(p)) return { lo: [...q.lo], hi: [...q.hi] };
  if (boxIsEmpty(q)) return { lo: [...p.lo], hi: [...p.hi] };
  return {
    lo: [Math.min(p.lo[0], q.lo[0]), Math.min(p.lo[1], q.lo[1]), Math.min(p.lo[2], q.lo[2])],
    hi: [Math.max(p.hi[0], q.hi[0]), Math.max(p.hi[1], q.hi[1]), Math.max(p.hi[2], q.hi[2])],
  };
}

/** `b` grown by `r` nodes on every side, clipped to the grid. */
export function boxGrow(b: NodeBox, r: number, dims: Dims): NodeBox {
  if (boxIsEmpty(b)) return emptyBox();
  const lo = b.lo.map((v) => Math.max(0, v - r)) as [number, number, number];
  const hi = b.hi.map((v, a) => Math.min(dims[a] - 1, v + r)) as [number, number, number];
  return { lo, hi };
}

/** Trilinear sample at grid coordinates inside [0, n − 1] on each axis (the far faces use the
 *  last cell with weight 1 on its far nodes). */
export function sampleInside(g: Float32Array, dims: Dims, x: number, y: number, z: number): number {
  const [nx, ny, nz] = dims;
  let ix = x | 0;
  let iy = y | 0;
  let iz = z | 0;
  if (ix >= nx - 1) ix = nx - 2;
  if (iy >= ny - 1) iy = ny - 2;
  if (iz >= nz - 1) iz = nz - 2;
  const fx = x - ix;
  const fy = y - iy;
  const fz = z - iz;
  const nxy = nx * ny;
  const c = ix + nx * iy + nxy * iz;
  const a = g[c] + fx * (g[c + 1] - g[c]);
  const b = g[c + nx] + fx * (g[c + nx + 1] - g[c + nx]);
  const d = g[c + nxy] + fx * (g[c + nxy + 1] - g[c + nxy]);
  const e = g[c + nxy + nx] + fx * (g[c + nxy + nx + 1] - g[c + nxy + nx]);
  const ab = a + fy * (b - a);
  const de = d + fy * (e - d);
  return ab + fz * (de - ab);
}

/** Trilinear sample anywhere: nodes outside the grid count as 0. */
export function sampleOrZero(g: Float32Array, dims: Dims, x: number, y: number, z: number): number {
  const [nx, ny, nz] = dims;
  if (!(x > -1 && y > -1 && z > -1 && x < nx && y < ny && z < nz)) return 0;
  const ix = Math.floor(x);
  const iy = Math.floor(y);
  const iz = Math.floor(z);
  const fx = x - ix;
  const fy = y - iy;
  const fz = z - iz;
  let sum = 0;
  for (let k = 0; k < 2; k++) {
    const Z = iz + k;
    if (Z < 0 || Z >= nz) continue;
    const wz = k ? fz : 1 - fz;
    for (let j = 0; j < 2; j++) {
      const Y = iy + j;
      if (Y < 0 || Y >= ny) continue;
      const wyz = wz * (j ? fy : 1 - fy);
      const row = nx * (Y + ny * Z);
      if (ix >= 0) sum += wyz * (1 - fx) * g[row + ix];
      if (ix + 1 < nx) sum += wyz * fx * g[row + ix + 1];
    }
  }
  return sum;
}

/** Marks nodes inside the closed mesh (1) by the parity of crossings of a ray along +z from
 *  each node; columns with an odd number of crossings (an open mesh there) stay outside. The
 *  mesh is given in world units; the grid by its origin and step. Returns the box of the nodes
 *  marked. */
export function voxelizeHead(
  head: HeadTriangles,
  inside: Float32Array,
  dims: Dims,
  origin: readonly [number, number, number],
  h: number,
): NodeBox {
  const [nx, ny, nz] = dims;
  const [ox, oy, oz] = origin;
  const P = head.positions;
  const I = head.indices;
  const columns = new Map<number, number[]>();
  const tris = I.length / 3;
  for (let t = 0; t < tris; t++) {
    const a = 3 * I[3 * t];
    const b = 3 * I[3 * t + 1];
    const c = 3 * I[3 * t + 2];
    const ax = (P[a] - ox) / h;
    const ay = (P[a + 1] - oy) / h;
    const az = (P[a + 2] - oz) / h;
    const bx = (P[b] - ox) / h;
    const by = (P[b + 1] - oy) / h;
    const bz = (P[b + 2] - oz) / h;
    const cx = (P[c] - ox) / h;
    const cy = (P[c + 1] - oy) / h;
    const cz = (P[c + 2] - oz) / h;
    const det = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
    if (det === 0 || !Number.isFinite(det)) continue;
    const x0 = Math.max(0, Math.ceil(Math.min(ax, bx, cx)));
    const x1 = Math.min(nx - 1, Math.floor(Math.max(ax, bx, cx)));
    const y0 = Math.max(0, Math.ceil(Math.min(ay, by, cy)));
    const y1 = Math.min(ny - 1, Math.floor(Math.max(ay, by, cy)));
    for (let y = y0; y <= y1; y++)
      for (let x = x0; x <= x1; x++) {
        // barycentric coordinates of the column, nudged off the lattice by a tiny offset so a
        // column never passes exactly through a shared edge or vertex (counted twice or never)
        const qx = x + 1.37e-5;
        const qy = y + 2.91e-5;
        const u = ((bx - qx) * (cy - qy) - (cx - qx) * (by - qy)) / det;
        const v = ((cx - qx) * (ay - qy) - (ax - qx) * (cy - qy)) / det;
        const w = 1 - u - v;
        if (!(u > 0 && v > 0 && w > 0)) continue;
        const key = x + nx * y;
        let list = columns.get(key);
        if (!list) {
          list = [];
          columns.set(key, list);
        }
        list.push(u * az + v * bz + w * cz);
      }
  }
  const nxy = nx * ny;
  const box = emptyBox();
  for (const [key, list] of columns) {
    if (list.length % 2) continue;
    list.sort((p, q) => p - q);
    for (let k = 0; k + 1 < list.length; k += 2) {
      const z0 = Math.max(0, Math.ceil(list[k]));
      const z1 = Math.min(nz - 1, Math.floor(list[k + 1]));
      for (let z = z0; z <= z1; z++) inside[key + nxy * z] = 1;
      if (z0 <= z1) {
        const marked = { lo: [key % nx, (key / nx) | 0, z0], hi: [key % nx, (key / nx) | 0, z1] };
        const u = boxUnion(box, marked as NodeBox);
        box.lo = u.lo;
        box.hi = u.hi;
      }
    }
  }
  return box;
}

/** The ray parameters [t0, t1] along one axis for which p + t·l lies in the open slab
 *  (lo, hi) (an empty span when the ray runs outside it). */
function slabSpan(p: number, l: number, lo: number, hi: number, span: Float64Array): void {
  if (l === 0) {
    const inSlab = p > lo && p < hi;
    span[0] = inSlab ? -Infinity : 1;
    span[1] = inSlab ? Infinity : 0;
    return;
  }
  const ta = (lo - p) / l;
  const tb = (hi - p) / l;
  span[0] = Math.min(ta, tb);
  span[1] = Math.max(ta, tb);
}

/** The head's optical depth towards the light at every node: `opacity` times the trilinear
 *  inside fraction sampled at integer steps t = first, first + 1, … cells along the unit
 *  direction L (the samples of the full per-node march, so the same sum), until the sample
 *  leaves the grid or the depth passes `maxDepth`. Steps that cannot reach a marked node (outside
 *  `insideBox` grown by one cell) are skipped: they would add 0. */
export function headDepthMarch(
  inside: Float32Array,
  insideBox: NodeBox,
  dims: Dims,
  L: readonly [number, number, number],
  opacity: number,
  first: number,
  maxDepth: number,
  out: Float32Array,
): void {
  out.fill(0);
  if (boxIsEmpty(insideBox) || opacity === 0) return;
  const [nx, ny, nz] = dims;
  const lo = insideBox.lo.map((v) => v - 1);
  const hi = insideBox.hi.map((v) => v + 1);
  const sx = new Float64Array(2);
  const sy = new Float64Array(2);
  const sz = new Float64Array(2);
  for (let z = 0; z < nz; z++) {
    slabSpan(z, L[2], lo[2], hi[2], sz);
    for (let y = 0; y < ny; y++) {
      slabSpan(y, L[1], lo[1], hi[1], sy);
      const yz0 = Math.max(sy[0], sz[0]);
      const yz1 = Math.min(sy[1], sz[1]);
      if (yz1 < first || yz1 < yz0) continue;
      for (let x = 0; x < nx; x++) {
        slabSpan(x, L[0], lo[0], hi[0], sx);
        const t0 = Math.max(sx[0], yz0);
        const t1 = Math.min(sx[1], yz1);
        if (t1 < first || t1 < t0) continue;
        let tau = 0;
        for (let t = Math.max(first, Math.ceil(t0)); t <= t1; t++) {
          const px = x + L[0] * t;
          const py = y + L[1] * t;
          const pz = z + L[2] * t;
          if (px < 0 || py < 0 || pz < 0 || px > nx - 1 || py > ny - 1 || pz > nz - 1) break;
          tau += opacity * sampleInside(inside, dims, px, py, pz);
          if (tau > maxDepth) break;
        }
        out[x + nx * (y + ny * z)] = tau;
      }
    }
  }
}

/** Per node of `box`: Σ over the (2r + 1)³ box around it of g (nodes outside the grid count 0),
 *  in place. Exact for every node of `box` when g is 0 outside `box` shrunk by r. */
export function boxSumRegion(g: Float32Array, dims: Dims, box: NodeBox, r: number): void {
  if (r <= 0 || boxIsEmpty(box)) return;
  const stride = [1, dims[0], dims[0] * dims[1]];
  const line = new Float64Array(Math.max(...dims));
  for (let axis = 0; axis < 3; axis++) {
    const [ua, ub] = [0, 1, 2].filter((q) => q !== axis);
    const s = stride[axis];
    const lo = box.lo[axis];
    const n = box.hi[axis] - lo + 1;
    for (let j = box.lo[ub]; j <= box.hi[ub]; j++)
      for (let i = box.lo[ua]; i <= box.hi[ua]; i++) {
        const base = i * stride[ua] + j * stride[ub] + lo * s;
        for (let t = 0; t < n; t++) line[t] = g[base + t * s];
        let acc = 0;
        for (let t = 0; t < Math.min(r, n); t++) acc += line[t];
        for (let t = 0; t < n; t++) {
          if (t + r < n) acc += line[t + r];
          if (t - r - 1 >= 0) acc -= line[t - r - 1];
          g[base + t * s] = acc;
        }
      }
  }
}

/** Per index along an axis of n nodes: how many nodes the box of half-width r around it holds
 *  (clamped at the faces). */
export function boxCounts(n: number, r: number): Float32Array {
  const out = new Float32Array(n);
  for (let t = 0; t < n; t++) out[t] = Math.min(n - 1, t + r) - Math.max(0, t - r) + 1;
  return out;
}

/** In-place mean over the (2r + 1)³ box around each node of the whole grid (clamped at the
 *  faces: the box counts only nodes inside the grid). */
export function boxMean(g: Float32Array, dims: Dims, r: number): void {
  if (r <= 0) return;
  boxSumRegion(g, dims, { lo: [0, 0, 0], hi: [dims[0] - 1, dims[1] - 1, dims[2] - 1] }, r);
  const [cx, cy, cz] = dims.map((n) => boxCounts(n, r));
  const [nx, ny] = dims;
  for (let z = 0; z < dims[2]; z++)
    for (let y = 0; y < ny; y++)
      for (let x = 0; x < nx; x++) g[x + nx * (y + ny * z)] /= cx[x] * cy[y] * cz[z];
}
