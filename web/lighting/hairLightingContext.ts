// The hair lighting on a fixed grid, with what depends only on the head computed once
// (hairLighting.ts describes the model). A context is made per head and grid (the solver
// worker's 'init'): the first result builds the head's caches — its inside voxels, its optical
// depth towards the light at every node (the head part of the march), its blurred occlusion
// term — and every result then does only the hair's part:
//   1. splat the fibre density (σ·h per node) over the box of nodes its points touch, marking
//      the cells the points lie in;
//   2. sum σ·h along light-parallel columns through that box (shearedDepth.ts);
//   3. at the corners of the marked cells only: transmittance exp(−(hair depth from the first
//      counted step on + head depth)) and occlusion exp(−strength·radius·(box mean of the hair's
//      σ·h, summed over the box grown by the radius, + the head's cached term));
//   4. trilinear look-ups per strand point, and the hair's depth from each head vertex.
// The march's sum splits exactly into hair and head parts (apart from its stop at optical depth
// 12, T < 1e-5), and the box blur is linear, so the head's parts are added per node.
import type {
  HairLighting,
  HairLightingInput,
  HairLightingOptions,
  LightingGrid,
} from './hairLighting';
import {
  boxCounts,
  boxGrow,
  boxMean,
  boxSumRegion,
  type Dims,
  emptyBox,
  type HeadTriangles,
  headDepthMarch,
  type NodeBox,
  voxelizeHead,
} from './lightingKernels';
import { ShearedDepth } from './shearedDepth';

/** Optical depth past which the head's march stops (T < 1e-5). */
export const MAX_DEPTH = 12;

/** HairLightingOptions with every default filled in (light made unit). */
export interface ResolvedLightingOptions {
  light: [number, number, number];
  extinction: number | undefined;
  autoOpacity: number;
  headOpacity: number;
  /** The first counted step of the hair's march, in cells (integer ≥ 1). */
  firstStep: number;
  aoRadius: number;
  aoStrength: number;
  headAoOpacity: number;
  penumbra: number;
  headShadow: boolean;
}

export function resolveOptions(options: HairLightingOptions): ResolvedLightingOptions {
  const [lx, ly, lz] = options.light;
  const ll = Math.hypot(lx, ly, lz);
  return {
    light: ll > 0 && ll < Infinity ? [lx / ll, ly / ll, lz / ll] : [0, 1, 0],
    extinction: options.extinction,
    autoOpacity: options.autoOpacity ?? 0.45,
    headOpacity: options.headOpacity ?? 4,
    firstStep: Math.max(1, Math.ceil(Math.max(0, options.selfCells ?? 2))),
    aoRadius: Math.max(0, Math.round(options.aoRadiusCells ?? 3)),
    aoStrength: options.aoStrength ?? 0.9,
    headAoOpacity: options.headAoOpacity ?? 0.35,
    penumbra: Math.max(0, Math.round(options.penumbraCells ?? 5)),
    headShadow: options.headShadow !== false,
  };
}

/** What depends only on the head (and the grid and light). */
interface HeadCache {
  /** The head's optical depth towards the light from the head's first step (2 cells) on, its
   *  edge softened over the penumbra (softenHeadShadow). */
  depth: Float32Array;
  /** headAoOpacity × the box mean of the head's inside. */
  occ: Float32Array;
}

export class HairLightingContext {
  readonly grid: LightingGrid;
  readonly options: ResolvedLightingOptions;
  /** How many times the head's caches were built (once per context). */
  headBuilds = 0;
  private readonly dims: Dims;
  private headCache: HeadCache | null = null;
  /** Per node, reused by every result: the hair's σ·h (then its box sums), its optical depth,
   *  and the interleaved transmittance and occlusion thickness at the hair's nodes. */
  private readonly tau: Float32Array;
  private readonly sheared = new ShearedDepth();
  private readonly node: Float32Array;
  private readonly counts: Float32Array[];
  /** Per cell: a strand point lies in it (this result); per node: a corner of such a cell. */
  private readonly cellUsed: Uint8Array;
  private readonly nodeUsed: Uint8Array;
  /** The nodes strand points interpolate from (the first usedCount entries). */
  private used = new Int32Array(0);
  private usedCount = 0;

  constructor(
    private readonly head: HeadTriangles | null,
    grid: LightingGrid,
    options: HairLightingOptions,
  ) {
    this.grid = { dims: [...grid.dims], origin: [...grid.origin], step: grid.step };
    this.dims = this.grid.dims;
    this.options = resolveOptions(options);
    const cells = grid.dims[0] * grid.dims[1] * grid.dims[2];
    this.tau = new Float32Array(cells);
    this.node = new Float32Array(2 * cells);
    this.cellUsed = new Uint8Array(cells);
    this.nodeUsed = new Uint8Array(cells);
    this.counts = this.dims.map((n) => boxCounts(n, this.options.aoRadius));
  }

  /** The lighting of one hair revision. headShadow: the hair's shadow on the head too (default:
   *  the context's option). */
  compute(strands: HairLightingInput, headShadow = this.options.headShadow): HairLighting {
    const head = this.headCaches();
    const { points, strandStart } = strands;
    const strandCount = Math.max(0, strandStart.length - 1);
    const pointCount = strandCount > 0 ? strandStart[strandCount] : 0;
    const headVertices = this.head ? this.head.positions.length / 3 : 0;
    const strandOut = new Float32Array(2 * pointCount);
    const headOut = new Float32Array(headVertices).fill(1);
    const result = { strand: strandOut, head: headOut, grid: this.grid, extinction: 0 };
    if (this.dims.some((n) => n < 2)) return { ...result, strand: strandOut.fill(1) };

    this.tau.fill(0);
    const box = this.splat(points, strandStart, strandCount);
    this.listUsedNodes(box);
    const typical = this.toOpticalThickness(box);
    result.extinction = this.extinction;
    const o = this.options;
    const shadeHead = headShadow && this.head !== null && typical > 0;
    this.sheared.build(this.tau, this.dims, o.light, box);
    this.nodeTransmittance(head.depth);
    this.nodeOcclusion(box, head.occ);
    this.lookUpPoints(points, pointCount, strandOut);
    if (shadeHead && this.head) this.headShadow(this.head.positions, headOut);

    return result;
  }

  private extinction = 0;

  /** The head's caches, built on first use. */
  private headCaches(): HeadCache {
    if (this.headCache) return this.headCache;
    const cells = this.tau.length;
    const o = this.options;
    const inside = new Float32Array(cells);
    const { origin, step } = this.grid;
    const insideBox =
      this.head && cells > 0
        ? voxelizeHead(this.head, inside, this.dims, origin, step)
        : emptyBox();
    const depth = new Float32Array(cells);
    headDepthMarch(inside, insideBox, this.dims, o.light, o.headOpacity, 2, MAX_DEPTH, depth);
    softenHeadShadow(depth, inside, this.dims, o.penumbra);
    const occ = inside; // reused in place
    for (let c = 0; c < cells; c++) occ[c] *= o.headAoOpacity;
    boxMean(occ, this.dims, o.aoRadius);
    this.headCache = { depth, occ };
    this.headBuilds++;
    return this.headCache;
  }

  /** Splats every strand point into `tau` trilinearly, weighted by the strand length it stands
   *  for (half of each adjacent segment). Returns the box of the nodes the strand points
   *  interpolate from (the splat stays inside it). */
  private splat(points: Float32Array, strandStart: Uint32Array, strandCount: number): NodeBox {
    const [nx, ny, nz] = this.dims;
    const nxy = nx * ny;
    const { origin, step } = this.grid;
    const [ox, oy, oz] = origin;
    const inv = 1 / step;
    const g = this.tau;
    const cellUsed = this.cellUsed;
    cellUsed.fill(0);
    let x0 = nx;
    let y0 = ny;
    let z0 = nz;
    let x1 = -1;
    let y1 = -1;
    let z1 = -1;
    for (let s = 0; s < strandCount; s++) {
      const a = strandStart[s];
      const b = strandStart[s + 1];
      let before = 0; // half the segment before the point
      for (let i = a; i < b; i++) {
        const px = points[3 * i];
        const py = points[3 * i + 1];
        const pz = points[3 * i + 2];
        let after = 0;
        if (i + 1 < b) {
          const dx = points[3 * i + 3] - px;
          const dy = points[3 * i + 4] - py;
          const dz = points[3 * i + 5] - pz;
          after = 0.5 * Math.sqrt(dx * dx + dy * dy + dz * dz);
        }
        const w = before + after;
        before = after;
        const gx = (px - ox) * inv;
        const gy = (py - oy) * inv;
        const gz = (pz - oz) * inv;
        if (!(gx >= 0 && gy >= 0 && gz >= 0 && gx <= nx - 1 && gy <= ny - 1 && gz <= nz - 1))
          continue;
        const ix = Math.min(gx | 0, nx - 2);
        const iy = Math.min(gy | 0, ny - 2);
        const iz = Math.min(gz | 0, nz - 2);
        if (ix < x0) x0 = ix;
        if (ix > x1) x1 = ix;
        if (iy < y0) y0 = iy;
        if (iy > y1) y1 = iy;
        if (iz < z0) z0 = iz;
        if (iz > z1) z1 = iz;
        cellUsed[ix + nx * iy + nxy * iz] = 1;
        if (!(w > 0 && w < Infinity) || gx >= nx - 1 || gy >= ny - 1 || gz >= nz - 1) continue;
        const fx = gx - ix;
        const fy = gy - iy;
        const fz = gz - iz;
        const c = ix + nx * iy + nxy * iz;
        const w00 = w * (1 - fy) * (1 - fz);
        const w10 = w * fy * (1 - fz);
        const w01 = w * (1 - fy) * fz;
        const w11 = w * fy * fz;
        g[c] += (1 - fx) * w00;
        g[c + 1] += fx * w00;
        g[c + nx] += (1 - fx) * w10;
        g[c + nx + 1] += fx * w10;
        g[c + nxy] += (1 - fx) * w01;
        g[c + nxy + 1] += fx * w01;
        g[c + nxy + nx] += (1 - fx) * w11;
        g[c + nxy + nx + 1] += fx * w11;
      }
    }
    return x1 < 0 ? emptyBox() : { lo: [x0, y0, z0], hi: [x1 + 1, y1 + 1, z1 + 1] };
  }

  /** Turns the splatted fibre length into σ·h per node (k·ρ·h, ρ = length / cell volume) over
   *  `box`, setting this.extinction (k); returns the typical (density-weighted mean) ρ. */
  private toOpticalThickness(box: NodeBox): number {
    const h = this.grid.step;
    const volume = h * h * h;
    const g = this.tau;
    const [nx, ny] = this.dims;
    let sum = 0;
    let sum2 = 0;
    for (let z = box.lo[2]; z <= box.hi[2]; z++)
      for (let y = box.lo[1]; y <= box.hi[1]; y++)
        for (let c = box.lo[0] + nx * (y + ny * z), e = c + box.hi[0] - box.lo[0]; c <= e; c++) {
          const r = g[c] / volume;
          sum += r;
          sum2 += r * r;
        }
    const typical = sum > 0 ? sum2 / sum : 0;
    const o = this.options;
    const k = o.extinction ?? (typical > 0 ? o.autoOpacity / (typical * h) : 0);
    this.extinction = k;
    const scale = (k * h) / volume;
    for (let z = box.lo[2]; z <= box.hi[2]; z++)
      for (let y = box.lo[1]; y <= box.hi[1]; y++)
        for (let c = box.lo[0] + nx * (y + ny * z), e = c + box.hi[0] - box.lo[0]; c <= e; c++)
          g[c] *= scale;
    return typical;
  }

  /** Lists the corners of the cells strand points lie in (this.used). */
  private listUsedNodes(box: NodeBox): void {
    const [nx, ny] = this.dims;
    const nxy = nx * ny;
    const cellUsed = this.cellUsed;
    const nodeUsed = this.nodeUsed;
    nodeUsed.fill(0);
    let count = 0;
    for (let z = box.lo[2]; z < box.hi[2]; z++)
      for (let y = box.lo[1]; y < box.hi[1]; y++)
        for (let c = box.lo[0] + nx * (y + ny * z), e = c + box.hi[0] - box.lo[0]; c < e; c++) {
          if (!cellUsed[c]) continue;
          for (const q of [c, c + 1, c + nx, c + nx + 1]) {
            if (!nodeUsed[q]) count++;
            nodeUsed[q] = 1;
            if (!nodeUsed[q + nxy]) count++;
            nodeUsed[q + nxy] = 1;
          }
        }
    if (this.used.length < count) this.used = new Int32Array(Math.ceil(count * 1.25));
    let k = 0;
    for (let z = box.lo[2]; z <= box.hi[2]; z++)
      for (let y = box.lo[1]; y <= box.hi[1]; y++)
        for (let c = box.lo[0] + nx * (y + ny * z), e = c + box.hi[0] - box.lo[0]; c <= e; c++)
          if (nodeUsed[c]) this.used[k++] = c;
    this.usedCount = k;
  }

  /** node[2c] = transmittance at each used node: the hair's depth from half a step before
   *  the march's first counted step (its samples stand for a step each) and the head's. */
  private nodeTransmittance(headDepth: Float32Array): void {
    const [nx, ny] = this.dims;
    const nxy = nx * ny;
    const s0 = this.options.firstStep - 0.5;
    const node = this.node;
    const sheared = this.sheared;
    const used = this.used;
    for (let k = 0; k < this.usedCount; k++) {
      const c = used[k];
      const z = Math.floor(c / nxy);
      const y = Math.floor((c - z * nxy) / nx);
      const x = c - z * nxy - y * nx;
      node[2 * c] = Math.exp(-(sheared.depth(x, y, z, s0) + headDepth[c]));
    }
  }

  /** node[2c + 1] = the occlusion's mean optical thickness at each node of `box`: the box mean
   *  of the hair's σ·h (summed over `box` grown by the radius, where all of it lies) plus the
   *  head's term. Overwrites `tau` there with the box sums. */
  private nodeOcclusion(box: NodeBox, headOcc: Float32Array): void {
    const r = this.options.aoRadius;
    boxSumRegion(this.tau, this.dims, boxGrow(box, r, this.dims), r);
    const [nx, ny] = this.dims;
    const nxy = nx * ny;
    const [cx, cy, cz] = this.counts;
    const tau = this.tau;
    const node = this.node;
    const aoScale = this.options.aoStrength * Math.max(1, r);
    const used = this.used;
    for (let k = 0; k < this.usedCount; k++) {
      const c = used[k];
      const z = Math.floor(c / nxy);
      const y = Math.floor((c - z * nxy) / nx);
      const x = c - z * nxy - y * nx;
      const mean = tau[c] / (cx[x] * cy[y] * cz[z]) + headOcc[c];
      node[2 * c + 1] = Math.exp(-aoScale * mean);
    }
  }

  /** Per strand point: the trilinear transmittance and exp(−strength · radius · occlusion
   *  thickness); 1 and 1 for points outside the grid. */
  private lookUpPoints(points: Float32Array, pointCount: number, out: Float32Array): void {
    const [nx, ny, nz] = this.dims;
    const nxy = nx * ny;
    const { origin, step } = this.grid;
    const [ox, oy, oz] = origin;
    const inv = 1 / step;
    const node = this.node;
    const sy = 2 * nx;
    const sz = 2 * nxy;
    for (let i = 0; i < pointCount; i++) {
      const gx = (points[3 * i] - ox) * inv;
      const gy = (points[3 * i + 1] - oy) * inv;
      const gz = (points[3 * i + 2] - oz) * inv;
      if (!(gx >= 0 && gy >= 0 && gz >= 0 && gx <= nx - 1 && gy <= ny - 1 && gz <= nz - 1)) {
        out[2 * i] = 1;
        out[2 * i + 1] = 1;
        continue;
      }
      let ix = gx | 0;
      let iy = gy | 0;
      let iz = gz | 0;
      if (ix > nx - 2) ix = nx - 2;
      if (iy > ny - 2) iy = ny - 2;
      if (iz > nz - 2) iz = nz - 2;
      const fx = gx - ix;
      const gx0 = 1 - fx;
      const fy = gy - iy;
      const fz = gz - iz;
      const w0 = (1 - fy) * (1 - fz);
      const w1 = fy * (1 - fz);
      const w2 = (1 - fy) * fz;
      const w3 = fy * fz;
      const c0 = 2 * (ix + nx * iy + nxy * iz);
      const c1 = c0 + sy;
      const c2 = c0 + sz;
      const c3 = c2 + sy;
      const trans =
        w0 * (gx0 * node[c0] + fx * node[c0 + 2]) +
        w1 * (gx0 * node[c1] + fx * node[c1 + 2]) +
        w2 * (gx0 * node[c2] + fx * node[c2 + 2]) +
        w3 * (gx0 * node[c3] + fx * node[c3 + 2]);
      const ao =
        w0 * (gx0 * node[c0 + 1] + fx * node[c0 + 3]) +
        w1 * (gx0 * node[c1 + 1] + fx * node[c1 + 3]) +
        w2 * (gx0 * node[c2 + 1] + fx * node[c2 + 3]) +
        w3 * (gx0 * node[c3 + 1] + fx * node[c3 + 3]);
      out[2 * i] = trans > 0 ? Math.min(trans, 1) : 0;
      out[2 * i + 1] = ao > 0 ? Math.min(ao, 1) : 0;
    }
  }

  /** Per head vertex: the transmittance through the hair alone, from the vertex on. */
  private headShadow(P: Float32Array, out: Float32Array): void {
    const { origin, step } = this.grid;
    const [ox, oy, oz] = origin;
    for (let v = 0; v < out.length; v++) {
      const d = this.sheared.depth(
        (P[3 * v] - ox) / step,
        (P[3 * v + 1] - oy) / step,
        (P[3 * v + 2] - oz) / step,
        0,
      );
      out[v] = Number.isFinite(d) ? Math.exp(-d) : 1;
    }
  }
}

/** The head's shadow with a soft edge, as a key light of some size casts (a softbox a few tens
 *  of degrees wide: the edge of the head's shadow on hair a hand's width behind it blurs over
 *  several centimetres; a hard edge reads as a stain on the hair). Per node outside the head:
 *  the mean transmittance exp(−depth) over the nodes outside the head within `r` cells (a box),
 *  back to a depth; nodes inside keep theirs (hair near the lit scalp is not darkened by the
 *  head's inside). */
export function softenHeadShadow(depth: Float32Array, inside: Float32Array, dims: Dims, r: number) {
  if (r <= 0) return;
  const lit = new Float32Array(depth.length);
  const outside = new Float32Array(depth.length);
  for (let c = 0; c < depth.length; c++) {
    outside[c] = inside[c] < 0.5 ? 1 : 0;
    lit[c] = outside[c] * Math.exp(-depth[c]);
  }
  boxMean(lit, dims, r);
  boxMean(outside, dims, r);
  for (let c = 0; c < depth.length; c++)
    if (inside[c] < 0.5 && outside[c] > 0)
      depth[c] = Math.min(MAX_DEPTH, Math.max(0, -Math.log(lit[c] / outside[c])));
}
