import { describe, expect, it } from 'vitest';
import { computeHairLighting, type HeadTriangles } from '../../web/lighting/hairLighting';

/** Straight strands along x over [x0, x0 + length], one per (y, z) in the lists, points every
 *  `dx`. */
function strandsAlongX(ys: number[], zs: number[], x0: number, length: number, dx: number) {
  const n = Math.round(length / dx) + 1;
  const pts: number[] = [];
  const start = [0];
  for (const z of zs)
    for (const y of ys) {
      for (let i = 0; i < n; i++) pts.push(x0 + i * dx, y, z);
      start.push(start[start.length - 1] + n);
    }
  return { points: new Float32Array(pts), strandStart: new Uint32Array(start) };
}

const range = (a: number, b: number, step: number): number[] => {
  const out: number[] = [];
  for (let v = a; v <= b + 1e-9; v += step) out.push(v);
  return out;
};

/** Index of the point nearest to p. */
function nearest(points: Float32Array, p: [number, number, number]): number {
  let best = 0;
  let bd = Infinity;
  for (let i = 0; i < points.length / 3; i++) {
    const d =
      (points[3 * i] - p[0]) ** 2 +
      (points[3 * i + 1] - p[1]) ** 2 +
      (points[3 * i + 2] - p[2]) ** 2;
    if (d < bd) {
      bd = d;
      best = i;
    }
  }
  return best;
}

/** A closed axis-aligned box as 12 outward triangles. */
function boxMesh(min: [number, number, number], max: [number, number, number]): HeadTriangles {
  const positions: number[] = [];
  for (let i = 0; i < 8; i++)
    positions.push(i & 1 ? max[0] : min[0], i & 2 ? max[1] : min[1], i & 4 ? max[2] : min[2]);
  const quads = [
    [0, 2, 3, 1], // z min
    [4, 5, 7, 6], // z max
    [0, 1, 5, 4], // y min
    [2, 6, 7, 3], // y max
    [0, 4, 6, 2], // x min
    [1, 3, 7, 5], // x max
  ];
  const indices: number[] = [];
  for (const [a, b, c, d] of quads) indices.push(a, b, c, a, c, d);
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices) };
}

describe('computeHairLighting', () => {
  // a slab of strands along x, spaced s in y and z over y ∈ [0, 1], z ∈ [0, 1]: fibre density
  // ρ = 1 / s²; light straight down onto it from +y. s is a third of the grid step (2 / 32), so
  // the splat does not alias.
  const s = 1 / 48;
  const slab = strandsAlongX(range(0, 1, s), range(0, 1, s), 0, 2, 0.02);
  const rho = 1 / (s * s);
  const k = 3 / rho; // optical depth 3 per unit of depth
  const resolution = 32;
  const lit = computeHairLighting(slab, null, { light: [0, 1, 0], extinction: k, resolution });
  const h = lit.grid.step;

  it('transmittance falls monotonically into a uniform slab, as Beer–Lambert says', () => {
    let previous = Infinity;
    const top = 1 + s / 2; // each strand layer stands for a layer of thickness s
    for (const y of range(0, 1, s).reverse()) {
      const i = nearest(slab.points, [1, y, 0.5]);
      const t = lit.strand[2 * i];
      expect(t).toBeLessThanOrEqual(previous + 1e-6);
      previous = t;
      // the march's samples start 2 cells out, so the nearest 1.5 cells do not count (a point
      // never shadows itself)
      const depth = Math.max(0, top - y - 1.5 * h);
      const tau = -Math.log(Math.max(t, 1e-9));
      expect(Math.abs(tau - k * rho * depth)).toBeLessThan(0.3 * k * rho * h);
    }
    const bottom = lit.strand[2 * nearest(slab.points, [1, 0, 0.5])];
    expect(bottom).toBeCloseTo(Math.exp(-k * rho * (top - 1.5 * h)), 2);
    expect(bottom).toBeLessThan(0.15);
    expect(lit.strand[2 * nearest(slab.points, [1, 1, 0.5])]).toBeGreaterThan(0.9);
  });

  it('an isolated strand is fully lit', () => {
    const one = strandsAlongX([0.3], [-0.2], -1, 2, 0.02);
    for (const light of [
      [0, 1, 0],
      [0.45, 0.8, 0.55],
      [-0.3, 0.5, -0.8],
    ] as [number, number, number][]) {
      const r = computeHairLighting(one, null, { light }); // automatic extinction
      for (let i = 0; i < one.points.length / 3; i++) {
        expect(r.strand[2 * i]).toBeGreaterThan(0.95);
        expect(r.strand[2 * i + 1]).toBeGreaterThan(0.5);
      }
    }
  });

  it('ambient occlusion is lower inside a dense block than at its surface', () => {
    const block = strandsAlongX(range(0, 1, s), range(0, 1, s), 0, 1, 0.02);
    const r = computeHairLighting(block, null, { light: [0.45, 0.8, 0.55] });
    const ao = (p: [number, number, number]) => r.strand[2 * nearest(block.points, p) + 1];
    const centre = ao([0.5, 0.5, 0.5]);
    expect(centre).toBeLessThan(ao([0.5, 1, 0.5]) - 0.1);
    expect(centre).toBeLessThan(ao([0, 0.5, 0.5]) - 0.1);
    expect(ao([0.5, 1, 0.5])).toBeLessThan(ao([1, 1, 1]) + 1e-6); // a corner is the most open
  });

  it('the head shadows hair behind it, and hair shadows the head', () => {
    // a closed box under a thin hair layer, and a strand under the box; light from +y
    const box = boxMesh([0, -1, 0], [1, 0, 1]);
    const layer = strandsAlongX(range(0.2, 0.4, s), range(-0.3, 1.3, s), -0.3, 0.8, 0.02);
    const under = strandsAlongX([-1.3], [0.5], 0, 1, 0.02);
    const points = new Float32Array([...layer.points, ...under.points]);
    const n = layer.strandStart[layer.strandStart.length - 1];
    const strandStart = new Uint32Array([
      ...layer.strandStart,
      ...Array.from(under.strandStart.subarray(1), (v) => v + n),
    ]);
    const r = computeHairLighting({ points, strandStart }, box, {
      light: [0, 1, 0],
      extinction: k,
      resolution: 48,
    });
    // the strand under the box is in its shadow
    const u = nearest(points, [0.5, -1.3, 0.5]);
    expect(r.strand[2 * u]).toBeLessThan(0.01);
    // the box's corners at x = 0 lie under the hair layer (x −0.3 … 0.5, y 0.2 … 0.4), those at
    // x = 1 do not; the box's own shadow does not count for the head
    for (let v = 0; v < 8; v++) {
      if (v & 1) expect(r.head[v]).toBeGreaterThan(0.99);
      else expect(r.head[v]).toBeLessThan(0.8);
    }
    // the top of the hair layer is lit
    expect(r.strand[2 * nearest(points, [0.5, 0.4, 0.5])]).toBeGreaterThan(0.9);
    // without the head's shadow (a preview): the hair is lit the same, the head left unshadowed
    const quick = computeHairLighting({ points, strandStart }, box, {
      light: [0, 1, 0],
      extinction: k,
      resolution: 48,
      headShadow: false,
    });
    expect(quick.strand).toEqual(r.strand);
    expect(Array.from(quick.head)).toEqual(new Array(8).fill(1));
  });

  it('handles no hair and non-finite points', () => {
    const empty = computeHairLighting(
      { points: new Float32Array(0), strandStart: new Uint32Array([0]) },
      null,
      { light: [0, 1, 0] },
    );
    expect(empty.strand.length).toBe(0);
    const bad = computeHairLighting(
      {
        points: new Float32Array([0, 0, 0, Number.NaN, 1, 0]),
        strandStart: new Uint32Array([0, 2]),
      },
      null,
      { light: [0, 1, 0] },
    );
    for (const v of bad.strand) expect(Number.isFinite(v)).toBe(true);
  });
});
