// Precomputed hair lighting, once per hair revision (in the solver worker): self-shadowing
// towards a key light fixed in world space, ambient occlusion, and the shadow the hair casts on
// the head. Pure arithmetic on typed arrays: no three.js, no DOM.
//
// 1. Density: every strand point is splatted trilinearly into a grid (about 64³ cells over the
//    bounds of hair and head), weighted by the strand length it stands for (half of each
//    adjacent segment), so a node holds fibre length per unit volume ρ (1 / area).
// 2. Extinction: σ = k·ρ (k = `extinction`; by default chosen so that one cell of typical hair,
//    the density-weighted mean, has optical depth `autoOpacity`: the look then does not depend
//    on how many strands stand for the hair). Inside the head (voxelised by ray parity) a cell
//    adds `headOpacity`.
// 3. Transmittance: from every grid node near hair, march towards the light in steps of one cell
//    and sum σ·step: T = exp(−∫σ ds) (Beer–Lambert). Samples start `selfCells` cells out, so
//    the nearest selfCells − ½ cells do not count (a point does not shadow itself: splat and
//    lookup each blur a strand over ±1 cell), and the
//    head only counts past one cell (roots on the lit side are not shadowed by the scalp they sit
//    on). A strand point takes the trilinear interpolation of its 8 nodes: the same march as one
//    per point, at grid resolution, 30× cheaper at 2M points.
// 4. Ambient occlusion: the mean optical thickness of the cells within `aoRadiusCells` (a box
//    blur of the hair's σ·h plus a weaker head term), times the radius: ao = exp(−aoStrength·that).
// 5. Head: for each head vertex, the march through the hair alone (from half a cell out).
//
// Output layouts (protocol.ts result.lighting):
//   strand[2 * point]     = transmittance towards the light, in [0, 1]
//   strand[2 * point + 1] = ambient occlusion (1 = open), in [0, 1]
//   head[vertex]          = transmittance through the hair towards the light, in [0, 1]

export type V3 = readonly [number, number, number];

export interface HairLightingOptions {
  /** Direction towards the key light, world space (need not be unit). */
  light: V3;
  /** Grid cells along the longest side of the bounds (64). */
  resolution?: number;
  /** k: optical depth per unit distance per unit fibre density (fibre length / volume). Default:
   *  autoOpacity / (typical ρ · cell size). */
  extinction?: number;
  /** With `extinction` unset: optical depth of one cell of typical hair (0.45). */
  autoOpacity?: number;
  /** Optical depth of one cell inside the head (4: nearly opaque). */
  headOpacity?: number;
  /** The march's first sample, in cells from the point (2: the nearest 1.5 cells do not shadow
   *  it). */
  selfCells?: number;
  /** Half-width of the ambient-occlusion neighbourhood, in cells (3). */
  aoRadiusCells?: number;
  /** Scale of the occlusion's optical depth (0.9). */
  aoStrength?: number;
  /** Optical thickness per cell the head adds to the occlusion (0.35). */
  headAoOpacity?: number;
  /** Compute the hair's shadow on every head vertex (step 5; default true). Previews skip it:
   *  the view keeps the converged hair's shadow on the head while the pen moves, and on a
   *  million-triangle head it is most of the cost. */
  headShadow?: boolean;
}

export interface HairLightingInput {
  points: Float32Array; // points[3 * point + axis]
  strandStart: Uint32Array; // strand s owns points strandStart[s] .. strandStart[s + 1] - 1
}

export interface HeadTriangles {
  positions: Float32Array; // positions[3 * vertex + axis]
  indices: Uint32Array; // indices[3 * triangle + corner]
}

export interface LightingGrid {
  dims: [number, number, number];
  origin: [number, number, number]; // node (0, 0, 0)
  step: number;
}

export interface HairLighting {
  /** 2 per strand point: transmittance, ambient occlusion. */
  strand: Float32Array;
  /** 1 per head vertex: transmittance through the hair (empty without a head). */
  head: Float32Array;
  grid: LightingGrid;
  /** The extinction k used (auto or given). */
  extinction: number;
}

const MAX_DEPTH = 12; // optical depth past which a march stops (T < 1e-5)

export function computeHairLighting(
  strands: HairLightingInput,
  head: HeadTriangles | null,
  options: HairLightingOptions,
): HairLighting {
  const resolution = Math.max(4, Math.round(options.resolution ?? 64));
  const autoOpacity = options.autoOpacity ?? 0.45;
  const headOpacity = options.headOpacity ?? 4;
  const selfCells = options.selfCells ?? 2;
  const aoRadius = Math.max(0, Math.round(options.aoRadiusCells ?? 3));
  const aoStrength = options.aoStrength ?? 0.9;
  const headAoOpacity = options.headAoOpacity ?? 0.35;
  const [lx0, ly0, lz0] = options.light;
  const ll = Math.hypot(lx0, ly0, lz0) || 1;
  const lx = lx0 / ll;
  const ly = ly0 / ll;
  const lz = lz0 / ll;

  const { points, strandStart } = strands;
  const strandCount = Math.max(0, strandStart.length - 1);
  const pointCount = strandCount > 0 ? strandStart[strandCount] : 0;
  const headVertices = head ? head.positions.length / 3 : 0;
  const strandOut = new Float32Array(2 * pointCount);
  const headOut = new Float32Array(headVertices).fill(1);

  // ---- bounds of hair and head, the grid ----
  let minX = Infinity;
  let minY = Infinity;
  let minZ = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  let maxZ = -Infinity;
  const extend = (arr: Float32Array, n: number) => {
    for (let i = 0; i < n; i++) {
      const x = arr[3 * i];
      const y = arr[3 * i + 1];
      const z = arr[3 * i + 2];
      if (!(Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z))) continue;
      if (x < minX) minX = x;
      if (x > maxX) maxX = x;
      if (y < minY) minY = y;
      if (y > maxY) maxY = y;
      if (z < minZ) minZ = z;
      if (z > maxZ) maxZ = z;
    }
  };
  extend(points, pointCount);
  if (head) extend(head.positions, headVertices);
  if (!(minX <= maxX)) {
    for (let i = 0; i < pointCount; i++) {
      strandOut[2 * i] = 1;
      strandOut[2 * i + 1] = 1;
    }
    return {
      strand: strandOut,
      head: headOut,
      grid: { dims: [0, 0, 0], origin: [0, 0, 0], step: 0 },
      extinction: 0,
    };
  }
  const extent = Math.max(maxX - minX, maxY - minY, maxZ - minZ, 1e-6);
  const h = extent / resolution;
  const pad = 2;
  const nx = Math.ceil((maxX - minX) / h) + 1 + 2 * pad;
  const ny = Math.ceil((maxY - minY) / h) + 1 + 2 * pad;
  const nz = Math.ceil((maxZ - minZ) / h) + 1 + 2 * pad;
  const ox = minX - pad * h;
  const oy = minY - pad * h;
  const oz = minZ - pad * h;
  const nxy = nx * ny;
  const cells = nxy * nz;
  const inv = 1 / h;

  // ---- 1. density: fibre length per volume at each node ----
  const density = new Float32Array(cells);
  for (let s = 0; s < strandCount; s++) {
    const a = strandStart[s];
    const b = strandStart[s + 1];
    for (let i = a; i < b; i++) {
      let w = 0;
      if (i > a) w += 0.5 * segLength(points, i - 1, i);
      if (i + 1 < b) w += 0.5 * segLength(points, i, i + 1);
      if (w <= 0 || !Number.isFinite(w)) continue;
      const gx = (points[3 * i] - ox) * inv;
      const gy = (points[3 * i + 1] - oy) * inv;
      const gz = (points[3 * i + 2] - oz) * inv;
      if (!(gx >= 0 && gy >= 0 && gz >= 0 && gx < nx - 1 && gy < ny - 1 && gz < nz - 1)) continue;
      const ix = gx | 0;
      const iy = gy | 0;
      const iz = gz | 0;
      const fx = gx - ix;
      const fy = gy - iy;
      const fz = gz - iz;
      const c = ix + nx * iy + nxy * iz;
      const w00 = w * (1 - fy) * (1 - fz);
      const w10 = w * fy * (1 - fz);
      const w01 = w * (1 - fy) * fz;
      const w11 = w * fy * fz;
      density[c] += (1 - fx) * w00;
      density[c + 1] += fx * w00;
      density[c + nx] += (1 - fx) * w10;
      density[c + nx + 1] += fx * w10;
      density[c + nxy] += (1 - fx) * w01;
      density[c + nxy + 1] += fx * w01;
      density[c + nxy + nx] += (1 - fx) * w11;
      density[c + nxy + nx + 1] += fx * w11;
    }
  }
  const volume = h * h * h;
  let sum = 0;
  let sum2 = 0;
  for (let c = 0; c < cells; c++) {
    const r = density[c] / volume;
    density[c] = r;
    sum += r;
    sum2 += r * r;
  }
  const typical = sum > 0 ? sum2 / sum : 0; // density-weighted mean density
  const k = options.extinction ?? (typical > 0 ? autoOpacity / (typical * h) : 0);

  // optical thickness of one cell of hair at each node (σ·h)
  const hairTau = density; // reused in place
  for (let c = 0; c < cells; c++) hairTau[c] *= k * h;

  // ---- 2. the head's inside, by ray parity along z through node columns ----
  const inside = new Float32Array(cells);
  if (head) voxelizeHead(head, inside, nx, ny, nz, ox, oy, oz, h);

  // ---- 3. transmittance at nodes near hair ----
  // nodes within 2 cells of a node with hair are the ones strand points interpolate from
  const near = new Uint8Array(cells);
  for (let z = 0; z < nz; z++)
    for (let y = 0; y < ny; y++)
      for (let x = 0; x < nx; x++) {
        const c = x + nx * y + nxy * z;
        if (hairTau[c] <= 0) continue;
        for (let dz = -1; dz <= 1; dz++)
          for (let dy = -1; dy <= 1; dy++)
            for (let dx = -1; dx <= 1; dx++) {
              const X = x + dx;
              const Y = y + dy;
              const Z = z + dz;
              if (X >= 0 && Y >= 0 && Z >= 0 && X < nx && Y < ny && Z < nz)
                near[X + nx * Y + nxy * Z] = 1;
            }
      }
  const trans = new Float32Array(cells).fill(1);
  const sx = lx; // step in cells along the light
  const sy = ly;
  const sz = lz;
  const skip = Math.max(0, selfCells);
  for (let z = 0; z < nz; z++)
    for (let y = 0; y < ny; y++)
      for (let x = 0; x < nx; x++) {
        const c = x + nx * y + nxy * z;
        if (!near[c]) continue;
        let tau = 0;
        for (let t = 1; ; t++) {
          const px = x + sx * t;
          const py = y + sy * t;
          const pz = z + sz * t;
          if (px < 0 || py < 0 || pz < 0 || px > nx - 1 || py > ny - 1 || pz > nz - 1) break;
          if (t >= skip) tau += sample(hairTau, px, py, pz, nx, nxy);
          if (t >= 1.5) tau += headOpacity * sample(inside, px, py, pz, nx, nxy);
          if (tau > MAX_DEPTH) break;
        }
        trans[c] = Math.exp(-tau);
      }

  // ---- 4. ambient occlusion: box mean of the cells' optical thickness ----
  const occ = new Float32Array(cells);
  for (let c = 0; c < cells; c++) occ[c] = hairTau[c] + headAoOpacity * inside[c];
  boxBlur(occ, nx, ny, nz, aoRadius);
  const aoScale = aoStrength * Math.max(1, aoRadius);

  // ---- strand points: trilinear lookups ----
  for (let i = 0; i < pointCount; i++) {
    const gx = (points[3 * i] - ox) * inv;
    const gy = (points[3 * i + 1] - oy) * inv;
    const gz = (points[3 * i + 2] - oz) * inv;
    if (!(gx >= 0 && gy >= 0 && gz >= 0 && gx <= nx - 1 && gy <= ny - 1 && gz <= nz - 1)) {
      strandOut[2 * i] = 1;
      strandOut[2 * i + 1] = 1;
      continue;
    }
    strandOut[2 * i] = clamp01(sample(trans, gx, gy, gz, nx, nxy));
    strandOut[2 * i + 1] = clamp01(Math.exp(-aoScale * sample(occ, gx, gy, gz, nx, nxy)));
  }

  // ---- 5. head vertices: through the hair alone ----
  if (head && typical > 0 && options.headShadow !== false) {
    const P = head.positions;
    for (let v = 0; v < headVertices; v++) {
      const gx = (P[3 * v] - ox) * inv;
      const gy = (P[3 * v + 1] - oy) * inv;
      const gz = (P[3 * v + 2] - oz) * inv;
      let tau = 0;
      for (let t = 0.5; ; t += 1) {
        const px = gx + sx * t;
        const py = gy + sy * t;
        const pz = gz + sz * t;
        if (px < 0 || py < 0 || pz < 0 || px > nx - 1 || py > ny - 1 || pz > nz - 1) break;
        tau += sample(hairTau, px, py, pz, nx, nxy);
        if (tau > MAX_DEPTH) break;
      }
      headOut[v] = Math.exp(-tau);
    }
  }

  return {
    strand: strandOut,
    head: headOut,
    grid: { dims: [nx, ny, nz], origin: [ox, oy, oz], step: h },
    extinction: k,
  };
}

function clamp01(v: number): number {
  return v > 0 ? Math.min(v, 1) : 0;
}

function segLength(p: Float32Array, i: number, j: number): number {
  const dx = p[3 * j] - p[3 * i];
  const dy = p[3 * j + 1] - p[3 * i + 1];
  const dz = p[3 * j + 2] - p[3 * i + 2];
  return Math.sqrt(dx * dx + dy * dy + dz * dz);
}

/** Trilinear sample of node values at grid coordinates (inside [0, n − 1] on each axis). */
function sample(g: Float32Array, x: number, y: number, z: number, nx: number, nxy: number): number {
  let ix = x | 0;
  let iy = y | 0;
  let iz = z | 0;
  // the far faces: use the last cell with weight 1 on its far nodes
  const ny = nxy / nx;
  const nz = g.length / nxy;
  if (ix >= nx - 1) ix = nx - 2;
  if (iy >= ny - 1) iy = ny - 2;
  if (iz >= nz - 1) iz = nz - 2;
  const fx = x - ix;
  const fy = y - iy;
  const fz = z - iz;
  const c = ix + nx * iy + nxy * iz;
  const a = g[c] + fx * (g[c + 1] - g[c]);
  const b = g[c + nx] + fx * (g[c + nx + 1] - g[c + nx]);
  const d = g[c + nxy] + fx * (g[c + nxy + 1] - g[c + nxy]);
  const e = g[c + nxy + nx] + fx * (g[c + nxy + nx + 1] - g[c + nxy + nx]);
  const ab = a + fy * (b - a);
  const de = d + fy * (e - d);
  return ab + fz * (de - ab);
}

/** Marks nodes inside the closed mesh (1) by the parity of crossings of a ray along +z from
 *  each node; columns with an odd number of crossings (an open mesh there) stay outside. */
function voxelizeHead(
  head: HeadTriangles,
  inside: Float32Array,
  nx: number,
  ny: number,
  nz: number,
  ox: number,
  oy: number,
  oz: number,
  h: number,
): void {
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
        const z = u * az + v * bz + w * cz;
        const key = x + nx * y;
        let list = columns.get(key);
        if (!list) {
          list = [];
          columns.set(key, list);
        }
        list.push(z);
      }
  }
  const nxy = nx * ny;
  for (const [key, list] of columns) {
    if (list.length % 2) continue;
    list.sort((p, q) => p - q);
    for (let k = 0; k + 1 < list.length; k += 2) {
      const z0 = Math.max(0, Math.ceil(list[k]));
      const z1 = Math.min(nz - 1, Math.floor(list[k + 1]));
      for (let z = z0; z <= z1; z++) inside[key + nxy * z] = 1;
    }
  }
}

/** In-place mean over the (2r + 1)³ box around each node (clamped at the faces: the box counts
 *  only nodes inside the grid). */
function boxBlur(g: Float32Array, nx: number, ny: number, nz: number, r: number): void {
  if (r <= 0) return;
  const strides = [1, nx, nx * ny];
  const lens = [nx, ny, nz];
  const line = new Float64Array(Math.max(nx, ny, nz));
  for (let axis = 0; axis < 3; axis++) {
    const stride = strides[axis];
    const n = lens[axis];
    const [ua, ub] = [0, 1, 2].filter((a) => a !== axis);
    for (let j = 0; j < lens[ub]; j++)
      for (let i = 0; i < lens[ua]; i++) {
        const base = i * strides[ua] + j * strides[ub];
        for (let t = 0; t < n; t++) line[t] = g[base + t * stride];
        let acc = 0;
        for (let t = 0; t < Math.min(r, n); t++) acc += line[t];
        for (let t = 0; t < n; t++) {
          if (t + r < n) acc += line[t + r];
          if (t - r - 1 >= 0) acc -= line[t - r - 1];
          const lo = Math.max(0, t - r);
          const hi = Math.min(n - 1, t + r);
          g[base + t * stride] = acc / (hi - lo + 1);
        }
      }
  }
}
