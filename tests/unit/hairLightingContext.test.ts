import { describe, expect, it } from 'vitest';
import {
  type HairLightingInput,
  type HeadTriangles,
  type LightingGrid,
  lightingGridFor,
} from '../../web/lighting/hairLighting';
import { HairLightingContext, softenHeadShadow } from '../../web/lighting/hairLightingContext';
import {
  boxMean,
  headDepthMarch,
  sampleInside,
  voxelizeHead,
} from '../../web/lighting/lightingKernels';
import { ShearedDepth } from '../../web/lighting/shearedDepth';

/** A closed axis-aligned box as 12 outward triangles. */
function boxMesh(min: [number, number, number], max: [number, number, number]): HeadTriangles {
  const positions: number[] = [];
  for (let i = 0; i < 8; i++)
    positions.push(i & 1 ? max[0] : min[0], i & 2 ? max[1] : min[1], i & 4 ? max[2] : min[2]);
  const quads = [
    [0, 2, 3, 1],
    [4, 5, 7, 6],
    [0, 1, 5, 4],
    [2, 6, 7, 3],
    [0, 4, 6, 2],
    [1, 3, 7, 5],
  ];
  const indices: number[] = [];
  for (const [a, b, c, d] of quads) indices.push(a, b, c, a, c, d);
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices) };
}

/** `count` wavy strands of 24 points falling from above the box and over its sides. */
function hair(count: number, seed: number): HairLightingInput {
  let s = seed;
  const rnd = () => {
    s = (s * 16807) % 2147483647;
    return s / 2147483647;
  };
  const pts: number[] = [];
  const start = [0];
  for (let k = 0; k < count; k++) {
    const x = -0.9 + 1.8 * rnd();
    const z = -0.9 + 1.8 * rnd();
    const dir = rnd() * 2 * Math.PI;
    for (let i = 0; i < 24; i++) {
      const t = i / 23;
      pts.push(
        x * (1 + 0.4 * t) + 0.05 * Math.sin(9 * t + dir),
        1.1 - 1.6 * t * t,
        z * (1 + 0.4 * t) + 0.05 * Math.cos(7 * t + dir),
      );
    }
    start.push(start[start.length - 1] + 24);
  }
  return { points: new Float32Array(pts), strandStart: new Uint32Array(start) };
}

const head = boxMesh([-0.8, -1, -0.8], [0.8, 1, 0.8]);
const solverBox = { min: [-1.6, -1.4, -1.6] as const, max: [1.6, 1.5, 1.6] as const };

/** The lighting of hairLighting.ts computed over the whole grid with nothing cached or
 *  restricted: the hair's and the head's occlusion blurred together, every node lit. */
function uncached(
  strands: HairLightingInput,
  mesh: HeadTriangles,
  grid: LightingGrid,
  towards: [number, number, number],
) {
  const norm = Math.hypot(...towards);
  const light = towards.map((v) => v / norm) as [number, number, number];
  const { dims, origin, step: h } = grid;
  const [nx, ny, nz] = dims;
  const cells = nx * ny * nz;
  const toGrid = (p: Float32Array, i: number) =>
    [0, 1, 2].map((a) => (p[3 * i + a] - origin[a]) / h);
  // density: fibre length per volume, splatted trilinearly
  const rho = new Float32Array(cells);
  const { points, strandStart } = strands;
  const seg = (i: number) =>
    Math.hypot(...[0, 1, 2].map((a) => points[3 * i + 3 + a] - points[3 * i + a]));
  for (let s = 0; s + 1 < strandStart.length; s++)
    for (let i = strandStart[s]; i < strandStart[s + 1]; i++) {
      const w =
        (i > strandStart[s] ? seg(i - 1) / 2 : 0) + (i + 1 < strandStart[s + 1] ? seg(i) / 2 : 0);
      const g = toGrid(points, i);
      const c = g.map(Math.floor);
      for (let k = 0; k < 8; k++) {
        const q = [c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + (k >> 2)];
        const wk = [0, 1, 2].reduce((p, a) => p * (1 - Math.abs(g[a] - q[a])), w);
        rho[q[0] + nx * (q[1] + ny * q[2])] += wk / h ** 3;
      }
    }
  let sum = 0;
  let sum2 = 0;
  for (const r of rho) {
    sum += r;
    sum2 += r * r;
  }
  const k = 0.45 / ((sum2 / sum) * h);
  const tau = rho.map((r) => k * r * h);
  const inside = new Float32Array(cells);
  const insideBox = voxelizeHead(mesh, inside, dims, origin, h);
  const headDepth = new Float32Array(cells);
  headDepthMarch(inside, insideBox, dims, light, 4, 2, 12, headDepth);
  softenHeadShadow(headDepth, inside, dims, 5); // checked on its own below
  const all = {
    lo: [0, 0, 0] as [number, number, number],
    hi: [nx - 1, ny - 1, nz - 1] as [number, number, number],
  };
  const hairDepth = new ShearedDepth();
  hairDepth.build(tau, dims, light, all);
  const trans = new Float32Array(cells);
  const occ = new Float32Array(cells);
  for (let z = 0; z < nz; z++)
    for (let y = 0; y < ny; y++)
      for (let x = 0; x < nx; x++) {
        const c = x + nx * (y + ny * z);
        trans[c] = Math.exp(-(hairDepth.depth(x, y, z, 1.5) + headDepth[c]));
        occ[c] = tau[c] + 0.35 * inside[c];
      }
  boxMean(occ, dims, 3);
  const ao = occ.map((o) => Math.exp(-0.9 * 3 * o));
  const n = points.length / 3;
  const strand = new Float32Array(2 * n);
  for (let i = 0; i < n; i++) {
    const [gx, gy, gz] = toGrid(points, i);
    strand[2 * i] = sampleInside(trans, dims, gx, gy, gz);
    strand[2 * i + 1] = sampleInside(ao, dims, gx, gy, gz);
  }
  const headOut = new Float32Array(mesh.positions.length / 3);
  for (let v = 0; v < headOut.length; v++) {
    const [gx, gy, gz] = toGrid(mesh.positions, v);
    headOut[v] = Math.exp(-hairDepth.depth(gx, gy, gz, 0));
  }
  return { strand, head: headOut };
}

function expectClose(a: Float32Array, b: Float32Array): void {
  expect(a.length).toBe(b.length);
  let worst = 0;
  for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
  expect(worst).toBeLessThan(1e-5);
}

describe('HairLightingContext', () => {
  const grid = lightingGridFor(head, solverBox, 40);

  it('its grid holds the head and the solver box', () => {
    const far = grid.origin.map((o, a) => o + grid.step * (grid.dims[a] - 1));
    for (let a = 0; a < 3; a++) {
      expect(grid.origin[a]).toBeLessThanOrEqual(solverBox.min[a]);
      expect(far[a]).toBeGreaterThanOrEqual(solverBox.max[a]);
    }
    expect(grid.step).toBeCloseTo(2 / 40, 9); // the head's longest side / resolution
  });

  for (const light of [
    [0.45, 0.8, 0.55],
    [-0.3, 0.5, -0.8],
    [0.9, -0.2, 0.1],
  ] as [number, number, number][]) {
    it(`equals an uncached computation on the same grid, light ${light}`, () => {
      const strands = hair(300, 7);
      const ctx = new HairLightingContext(head, grid, { light });
      const r = ctx.compute(strands);
      const ref = uncached(strands, head, grid, light);
      expectClose(r.strand, ref.strand);
      expectClose(r.head, ref.head);
      // the head's shadow and some hair's too, so the comparison says something
      expect(Math.min(...r.head)).toBeLessThan(0.5);
      expect(Math.min(...r.strand.filter((_, i) => i % 2 === 0))).toBeLessThan(0.2);
    });
  }

  it('new hair on the same head reuses the head caches and equals a fresh computation', () => {
    const light: [number, number, number] = [0.45, 0.8, 0.55];
    const ctx = new HairLightingContext(head, grid, { light });
    expect(ctx.headBuilds).toBe(0);
    ctx.compute(hair(400, 3));
    expect(ctx.headBuilds).toBe(1);
    const other = hair(120, 11); // fewer strands: what the last hair touched must not remain
    const preview = ctx.compute(other, false);
    const full = ctx.compute(other);
    expect(ctx.headBuilds).toBe(1);
    const fresh = new HairLightingContext(head, grid, { light }).compute(other);
    expect(full.strand).toEqual(fresh.strand);
    expect(full.head).toEqual(fresh.head);
    expect(preview.strand).toEqual(fresh.strand);
    expect(Array.from(preview.head)).toEqual(new Array(8).fill(1));
    const ref = uncached(other, head, grid, light);
    expectClose(full.strand, ref.strand);
    expectClose(full.head, ref.head);
  });
});

describe('softenHeadShadow', () => {
  // a row of 40 nodes (8 × 8 across): the head's shadow covers x < 20; the head's inside is x < 3
  const dims: [number, number, number] = [40, 8, 8];
  const at = (x: number) => x + 40 * (4 + 8 * 4);
  function softened(insideBelow: number, shadowBelow: number, r: number) {
    const n = 40 * 8 * 8;
    const depth = new Float32Array(n);
    const inside = new Float32Array(n);
    for (let c = 0; c < n; c++) {
      const x = c % 40;
      depth[c] = x < shadowBelow ? 12 : 0;
      inside[c] = x < insideBelow ? 1 : 0;
    }
    softenHeadShadow(depth, inside, dims, r);
    return depth;
  }

  it("spreads the shadow's edge over the box: the transmittance is the box's share of lit nodes", () => {
    const d = softened(0, 20, 5);
    // x = 20: nodes 15..25 along x, 6 of 11 lit (the box is the same across)
    expect(Math.exp(-d[at(20)])).toBeCloseTo(6 / 11, 5);
    expect(Math.exp(-d[at(17)])).toBeCloseTo(3 / 11, 5);
    expect(d[at(14)]).toBeCloseTo(12, 4); // all 11 in the shadow
    expect(d[at(25)]).toBe(0); // all lit
  });

  it("hair by the lit scalp stays lit: the head's inside does not count", () => {
    // the inside (x < 3) is deep in its own shadow; the hair beside it (x ≥ 3) is lit
    const d = softened(3, 3, 5);
    expect(d[at(4)]).toBe(0); // nodes 0..9: the 7 outside are all lit
    expect(d[at(1)]).toBe(12); // inside: kept
  });

  it('r = 0 leaves the shadow as marched', () => {
    const d = softened(0, 20, 0);
    expect(d[at(19)]).toBe(12);
    expect(d[at(20)]).toBe(0);
  });
});
