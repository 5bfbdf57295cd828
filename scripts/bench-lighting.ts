// npm run bench:lighting — the solver worker's hair lighting (web/lighting/) against a
// straightforward reference (marchLighting below: a fresh grid over hair and head per call, the
// head voxelised every call, a march of trilinear samples from every node near hair, a box blur
// over the whole grid). The default preset's hair is grown on the built-in head with the real
// wasm engine under Node (growSessionHair, 25k grid), then lit as the worker lights it: previews
// capped at 800 and 6000 strands without the head's shadow, the full hair with it. Printed per
// case: medians of BENCH_RUNS runs (default 7) of the reference and of the app's lighting
// (ResultLighting, as the worker holds it: its head caches are built by a first call, timed
// apart), and how far the app's output is from the reference: mean and 99th percentile of |Δ| of
// the strands' transmittance and occlusion and of the head's transmittance.
// Writes bench-results/lighting.{json,md}.
//   npx tsx scripts/bench-lighting.ts

import { presetSession } from '../web/cli/presetSession';
import { growSessionHair } from '../web/export/growSession';
import { Head } from '../web/head/head';
import { KEY_LIGHT_DIRECTION } from '../web/lighting/keyLight';
import { type HeadTriangles, voxelizeHead } from '../web/lighting/lightingKernels';
import { ResultLighting } from '../web/lighting/resultLighting';
import { gridForSession } from '../web/model/grid';
import type { StrandArrays } from '../web/model/hairArrays';
import { hangLength } from '../web/model/session';
import { singleNodeOptions } from '../web/solver/nodeThreads';
import { engineOver } from '../web/solver/requestRunner';
import { loadWasmEngine } from '../web/solver/wasmEngine';
import { writeBenchResults } from './benchResults.mjs';

const RUNS = Math.max(1, Number(process.env.BENCH_RUNS ?? 7));

// ---- the reference: every call builds its own grid and voxelises the head
// (voxelizeHead from lightingKernels.ts) ----

interface MarchOptions {
  light: readonly [number, number, number];
  resolution?: number;
  extinction?: number;
  autoOpacity?: number;
  headOpacity?: number;
  selfCells?: number;
  aoRadiusCells?: number;
  aoStrength?: number;
  headAoOpacity?: number;
  headShadow?: boolean;
}

const MAX_DEPTH = 12;

function marchLighting(
  strands: StrandArrays,
  head: HeadTriangles | null,
  options: MarchOptions,
): { strand: Float32Array; head: Float32Array } {
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
    return { strand: strandOut, head: headOut };
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
  if (head) voxelizeHead(head, inside, [nx, ny, nz], [ox, oy, oz], h);

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

  return { strand: strandOut, head: headOut };
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

// ---- the benchmark ----

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[xs.length >> 1];

/** Mean and 99th percentile of |a − b| over every `stride`-th value from `offset`. */
function difference(a: Float32Array, b: Float32Array, offset: number, stride: number): string {
  const d: number[] = [];
  for (let i = offset; i < a.length; i += stride) d.push(Math.abs(a[i] - b[i]));
  d.sort((p, q) => p - q);
  const mean = d.reduce((s, v) => s + v, 0) / Math.max(1, d.length);
  return `mean ${mean.toFixed(4)}, p99 ${(d[Math.floor(0.99 * (d.length - 1))] ?? 0).toFixed(4)}`;
}

function timed<T>(f: () => T): [T, number] {
  const t0 = performance.now();
  const r = f();
  return [r, performance.now() - t0];
}

const head = Head.builtin();
const session = presetSession('default', head, '25k', 0);
const spec = gridForSession('25k', session.curves, undefined, hangLength(session));
const scalp = head.scalpMesh();
const core = await loadWasmEngine(singleNodeOptions());
const engine = engineOver(core);
const grown = growSessionHair(engine, session, scalp, { grid: spec, solver: 'fast' });
const cases: { name: string; strands: StrandArrays; headShadow: boolean }[] = [800, 6000].map(
  (cap) => ({
    name: `preview ${cap} strands`,
    strands: core.grow({ ...session.growth, maxStrands: cap }),
    headShadow: false,
  }),
);
cases.push({ name: 'full hair', strands: grown.strands, headShadow: true });
engine.dispose();

const march = (c: (typeof cases)[number]) =>
  marchLighting(c.strands, scalp, { light: KEY_LIGHT_DIRECTION, headShadow: c.headShadow });
const lighting = new ResultLighting(scalp, spec);
const [, firstMs] = timed(() => lighting.of(cases[0].strands, undefined, false));
const g = lighting.context.grid;
const lines = [
  `Lighting grid ${g.dims.join('×')}, step ${g.step.toFixed(4)}; the context's head caches, built by the first result: ${firstMs.toFixed(1)} ms.`,
  '',
  '| case | strands | points | reference march ms | app (ResultLighting) ms | T |Δ| | AO |Δ| | head T |Δ| |',
  '| --- | --- | --- | --- | --- | --- | --- | --- |',
];
const results: unknown[] = [];
console.log(
  `default preset, 25k grid, built-in head (${scalp.positions.length / 3} vertices); medians of ${RUNS}`,
);
for (const l of lines) console.log(l);
for (const c of cases) {
  const oldMs: number[] = [];
  const newMs: number[] = [];
  let old = march(c);
  let now = lighting.of(c.strands, undefined, c.headShadow);
  for (let r = 0; r < RUNS; r++) {
    let ms: number;
    [old, ms] = timed(() => march(c));
    oldMs.push(ms);
    now = lighting.of(c.strands, undefined, c.headShadow);
    newMs.push(now.ms);
  }
  const strands = c.strands.strandStart.length - 1;
  const points = c.strands.points.length / 3;
  const headDiff = c.headShadow ? difference(now.head, old.head, 0, 1) : '–';
  const row = {
    case: c.name,
    strands,
    points,
    referenceMs: median(oldMs),
    appMs: median(newMs),
    transmittanceDiff: difference(now.strand, old.strand, 0, 2),
    occlusionDiff: difference(now.strand, old.strand, 1, 2),
    headTransmittanceDiff: headDiff,
  };
  results.push(row);
  const line = `| ${c.name} | ${strands} | ${points} | ${row.referenceMs.toFixed(1)} | ${row.appMs.toFixed(1)} | ${row.transmittanceDiff} | ${row.occlusionDiff} | ${headDiff} |`;
  console.log(line);
  lines.push(line);
}
writeBenchResults('lighting', {
  title: "The worker's hair lighting against a reference march",
  script: 'scripts/bench-lighting.ts',
  command: 'npm run bench:lighting',
  measures:
    "The default preset's hair grown on the built-in head (wasm under Node, 25k grid) and lit " +
    'as the solver worker lights it: previews capped at 800 and 6,000 strands without the ' +
    "head's shadow, the full hair with it. Per case, medians of BENCH_RUNS runs of the app's " +
    'lighting (ResultLighting, its head caches built by a first call timed apart) and of a ' +
    'straightforward reference (a fresh grid and head voxelisation per call, a march of ' +
    'trilinear samples, a box blur over the whole grid), and how far the two outputs are apart: ' +
    "mean and 99th percentile of |Δ| of the strands' transmittance (T) and occlusion (AO) and " +
    "of the head's transmittance.",
  config: { preset: 'default', grid: '25k', runs: RUNS },
  results,
  table: lines.join('\n'),
});
process.exit(0);
