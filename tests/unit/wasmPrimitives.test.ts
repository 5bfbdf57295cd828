// The wasm engine's style primitives (method S4.5–S4.7): dividing and ponytail parameter blocks,
// explicit extra constraints and scalp avoidance, under Node. Assumes wasm-build/build.sh ran.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import type { CurveSet, GridSpec, ScalpMesh } from '../../web/model/hairArrays';
import { SolverError } from '../../web/solver/engine';
import { loadWasmEngine } from '../../web/solver/wasmEngine';

const wasmPath = fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url));
let wasmBinary: Uint8Array;
beforeAll(() => {
  wasmBinary = new Uint8Array(readFileSync(wasmPath));
});

const GRID: GridSpec = { dims: [16, 16, 16], origin: [-2, -2, -2], step: 4 / 15 };

/** Unit UV sphere at the origin, outward winding; scalp = centroid y > 0.2. */
function sphere(rings = 24, segments = 48): ScalpMesh {
  const pos: number[] = [];
  for (let i = 0; i <= rings; i++)
    for (let j = 0; j <= segments; j++) {
      const t = (Math.PI * i) / rings;
      const p = (2 * Math.PI * j) / segments;
      pos.push(Math.sin(t) * Math.sin(p), Math.cos(t), Math.sin(t) * Math.cos(p));
    }
  const v = (i: number, j: number) => i * (segments + 1) + j;
  const idx: number[] = [];
  for (let i = 0; i < rings; i++)
    for (let j = 0; j < segments; j++) {
      if (i > 0) idx.push(v(i, j), v(i + 1, j), v(i, j + 1));
      if (i + 1 < rings) idx.push(v(i, j + 1), v(i + 1, j), v(i + 1, j + 1));
    }
  const scalp = new Uint8Array(idx.length / 3);
  for (let t = 0; t < scalp.length; t++) {
    const y =
      (pos[3 * idx[3 * t] + 1] + pos[3 * idx[3 * t + 1] + 1] + pos[3 * idx[3 * t + 2] + 1]) / 3;
    scalp[t] = y > 0.2 ? 1 : 0;
  }
  return {
    positions: new Float32Array(pos),
    indices: new Uint32Array(idx),
    scalp,
    center: [0, 0, 0],
  };
}

/** A dividing curve along z over the top of the unit sphere (radius 1.02), normals radial. */
function dividingSet(
  extraIndex: Int32Array = new Int32Array(0),
  extraTarget: Float64Array = new Float64Array(0),
): CurveSet {
  const pts: number[] = [];
  const params: number[] = [1, 0.5, 0, 0];
  for (let i = -3; i <= 3; i++) {
    const a = (i * GRID.step) / 1.02;
    const p = [0, 1.02 * Math.cos(a), 1.02 * Math.sin(a)];
    pts.push(...p);
    params.push(p[0] / 1.02, p[1] / 1.02, p[2] / 1.02);
  }
  return {
    points: new Float64Array(pts),
    curveStart: new Uint32Array([0, 7]),
    kinds: new Uint8Array([1]),
    extend: new Uint8Array([0]),
    params: new Float64Array(params),
    paramStart: new Uint32Array([0, params.length]),
    extraIndex,
    extraTarget,
  };
}

describe('wasm primitives', () => {
  it('parts the field along a dividing curve', async () => {
    const e = await loadWasmEngine({ wasmBinary });
    e.setGrid(GRID, 100, 'cg');
    e.setScalp(sphere());
    e.setCurves(dividingSet());
    e.solve();
    const f = e.field().vectors;
    // Grid points two steps to either side of the parting, just above the top of the sphere.
    const [nx, ny] = GRID.dims;
    const at = (x: number, y: number, z: number) => {
      const i = Math.round((x - GRID.origin[0]) / GRID.step);
      const j = Math.round((y - GRID.origin[1]) / GRID.step);
      const k = Math.round((z - GRID.origin[2]) / GRID.step);
      return i + nx * (j + ny * k);
    };
    const plus = at(2 * GRID.step, 1.07, 0);
    const minus = at(-2 * GRID.step, 1.07, 0);
    expect(f[3 * plus]).toBeGreaterThan(0.2);
    expect(f[3 * minus]).toBeLessThan(-0.2);
    // Blue and red constraints, coloured per constraint.
    const colours = e.constraintColours();
    expect(colours.length).toBe(e.constraints().index.length);
    expect(new Set(colours)).toEqual(new Set([0, 1]));
    e.dispose();
  });

  it('returns scalp-avoidance constraints that the next solve accepts as extras', async () => {
    const e = await loadWasmEngine({ wasmBinary });
    e.setGrid(GRID, 100, 'cg');
    expect(() => e.scalpAvoidance()).toThrow(SolverError); // no scalp yet
    e.setScalp(sphere());
    e.setCurves(dividingSet());
    e.solve();
    const a = e.scalpAvoidance();
    expect(a.index.length).toBeGreaterThan(50);
    expect(a.target.length).toBe(3 * a.index.length);
    // each target is min(0.3, |v|) long (v: the field there, turned along the surface when it
    // points inwards, which only shortens it): never longer than 0.3 nor than the field
    const f = e.field().vectors;
    const fieldAt = (g: number) => Math.hypot(f[3 * g], f[3 * g + 1], f[3 * g + 2]);
    let atCap = 0;
    for (let c = 0; c < a.index.length; c++) {
      const m = Math.hypot(a.target[3 * c], a.target[3 * c + 1], a.target[3 * c + 2]);
      expect(m).toBeGreaterThan(0);
      expect(m).toBeLessThanOrEqual(0.3 + 1e-12);
      expect(m).toBeLessThanOrEqual(fieldAt(a.index[c]) * (1 + 1e-6) + 1e-6); // float32 field
      if (Math.abs(m - 0.3) < 1e-12) atCap++;
      if (c > 0) expect(a.index[c]).toBeGreaterThan(a.index[c - 1]);
    }
    expect(atCap).toBeGreaterThan(0);
    // minField: no constraint where the field is weaker than it (the growth threshold)
    const strongest = Math.max(...Array.from(a.index, fieldAt));
    const minField = strongest / 2;
    const strong = e.scalpAvoidance({ minField });
    expect(strong.index.length).toBeGreaterThan(0);
    expect(strong.index.length).toBeLessThan(a.index.length);
    const all = new Set(a.index);
    for (const g of strong.index) {
      expect(all.has(g)).toBe(true);
      expect(fieldAt(g)).toBeGreaterThanOrEqual(minField * (1 - 1e-6));
    }
    const before = e.constraints().index.length;
    e.setCurves(dividingSet(a.index, a.target));
    e.solve();
    expect(e.constraints().index.length).toBeGreaterThan(before);
    // Malformed extras and parameter blocks are rejected with a message naming the problem.
    expect(() => e.setCurves(dividingSet(new Int32Array([1 << 20]), new Float64Array(3)))).toThrow(
      /extra constraint 0/,
    );
    const bad = dividingSet();
    bad.paramStart = new Uint32Array([0, bad.params.length - 1]);
    bad.params = bad.params.slice(0, -1);
    expect(() => e.setCurves(bad)).toThrow(/curve 0 \(dividing\)/);
    e.dispose();
  });
});
