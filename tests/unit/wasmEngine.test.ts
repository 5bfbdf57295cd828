// The wasm engine under Node, against references computed here in TypeScript.
// Assumes wasm-build/build.sh has run (the test script runs it first).
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import type { GrowthParams } from '../../web/model/growthParams';
import type { CurveSet, GridSpec, ScalpMesh } from '../../web/model/hairArrays';
import { SolverError } from '../../web/solver/engine';
import { loadRawSolver, loadWasmEngine } from '../../web/solver/wasmEngine';

const wasmPath = fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url));
let wasmBinary: Uint8Array;
beforeAll(() => {
  wasmBinary = new Uint8Array(readFileSync(wasmPath));
});

const OMEGA = 100;

/** Dense (DᵀD + ω²S) T = ω² S C from method S2.2/S2.3, solved by Cholesky. T[3p + axis]. */
function denseFieldSolve(
  dims: [number, number, number],
  index: ArrayLike<number>,
  target: ArrayLike<number>,
): Float64Array {
  const [nx, ny, nz] = dims;
  const n = nx * ny * nz;
  const D = Array.from({ length: n }, () => new Float64Array(n));
  for (let k = 0; k < nz; k++)
    for (let j = 0; j < ny; j++)
      for (let i = 0; i < nx; i++) {
        const p = i + nx * (j + ny * k);
        const nb: number[] = [];
        for (const [a, b, c] of [
          [1, 0, 0],
          [-1, 0, 0],
          [0, 1, 0],
          [0, -1, 0],
          [0, 0, 1],
          [0, 0, -1],
        ] as const) {
          const ii = i + a;
          const jj = j + b;
          const kk = k + c;
          if (ii >= 0 && jj >= 0 && kk >= 0 && ii < nx && jj < ny && kk < nz)
            nb.push(ii + nx * (jj + ny * kk));
        }
        D[p][p] = -1;
        for (const q of nb) D[p][q] += 1 / nb.length;
      }
  const M = Array.from({ length: n }, () => new Float64Array(n));
  for (let r = 0; r < n; r++)
    for (let a = 0; a < n; a++) {
      const dra = D[r][a];
      if (dra === 0) continue;
      for (let b = 0; b < n; b++) M[a][b] += dra * D[r][b];
    }
  const B = new Float64Array(3 * n);
  for (let c = 0; c < index.length; c++) {
    M[index[c]][index[c]] += OMEGA * OMEGA;
    for (let e = 0; e < 3; e++) B[3 * index[c] + e] = OMEGA * OMEGA * target[3 * c + e];
  }
  // Cholesky M = L Lᵀ in place (lower triangle).
  for (let j = 0; j < n; j++) {
    let d = M[j][j];
    for (let k = 0; k < j; k++) d -= M[j][k] * M[j][k];
    M[j][j] = Math.sqrt(d);
    for (let i = j + 1; i < n; i++) {
      let s = M[i][j];
      for (let k = 0; k < j; k++) s -= M[i][k] * M[j][k];
      M[i][j] = s / M[j][j];
    }
  }
  const T = new Float64Array(3 * n);
  for (let e = 0; e < 3; e++) {
    const y = new Float64Array(n);
    for (let i = 0; i < n; i++) {
      let s = B[3 * i + e];
      for (let k = 0; k < i; k++) s -= M[i][k] * y[k];
      y[i] = s / M[i][i];
    }
    for (let i = n - 1; i >= 0; i--) {
      let s = y[i];
      for (let k = i + 1; k < n; k++) s -= M[k][i] * T[3 * k + e];
      T[3 * i + e] = s / M[i][i];
    }
  }
  return T;
}

function relError(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let num = 0;
  let den = 0;
  for (let i = 0; i < a.length; i++) {
    num += (a[i] - b[i]) ** 2;
    den += b[i] ** 2;
  }
  return Math.sqrt(num / den);
}

/** UV sphere; triangles with centroid y above yScalp are scalp. */
function sphere(
  c: [number, number, number],
  r: number,
  rings: number,
  segs: number,
  yScalp: number,
): ScalpMesh {
  const pos: number[] = [];
  for (let i = 0; i <= rings; i++)
    for (let j = 0; j <= segs; j++) {
      const th = (Math.PI * i) / rings;
      const ph = (2 * Math.PI * j) / segs;
      pos.push(
        c[0] + r * Math.sin(th) * Math.sin(ph),
        c[1] + r * Math.cos(th),
        c[2] + r * Math.sin(th) * Math.cos(ph),
      );
    }
  const idx: number[] = [];
  const v = (i: number, j: number) => i * (segs + 1) + j;
  for (let i = 0; i < rings; i++)
    for (let j = 0; j < segs; j++) {
      if (i > 0) idx.push(v(i, j), v(i + 1, j), v(i, j + 1));
      if (i + 1 < rings) idx.push(v(i, j + 1), v(i + 1, j), v(i + 1, j + 1));
    }
  const scalp = new Uint8Array(idx.length / 3);
  for (let t = 0; t < scalp.length; t++) {
    const y =
      (pos[3 * idx[3 * t] + 1] + pos[3 * idx[3 * t + 1] + 1] + pos[3 * idx[3 * t + 2] + 1]) / 3;
    scalp[t] = y > yScalp ? 1 : 0;
  }
  return {
    positions: new Float32Array(pos),
    indices: new Uint32Array(idx),
    scalp,
    center: c,
  };
}

/** One stream curve over the top of a sphere (radius r about c) and down the back, step d. */
function streamCurve(c: [number, number, number], r: number, d: number, extend = true): CurveSet {
  const pts: number[] = [];
  for (let a = 0.05; a < Math.PI / 2; a += d / r)
    pts.push(c[0], c[1] + r * Math.cos(a), c[2] - r * Math.sin(a));
  for (let y = c[1]; y > c[1] - r; y -= d) pts.push(c[0], y, c[2] - r);
  return {
    points: new Float64Array(pts),
    curveStart: new Uint32Array([0, pts.length / 3]),
    kinds: new Uint8Array([0]),
    extend: new Uint8Array([extend ? 1 : 0]),
    params: new Float64Array(0),
    paramStart: new Uint32Array(2),
    extraIndex: new Int32Array(0),
    extraTarget: new Float64Array(0),
  };
}

const growth: GrowthParams = {
  thetaStepDeg: 4,
  phiStepDeg: 4,
  jitter: 0.5,
  seed: 7,
  stepFraction: 0.5,
  minMagnitude: 0.05,
  maxLength: 2,
  maxSegments: 200,
  maxStrands: 0,
};

describe('raw solver', () => {
  it('matches a dense TypeScript solve on a 3×3×3 grid', async () => {
    const s = await loadRawSolver('cg', { wasmBinary });
    s.setGrid([3, 3, 3], OMEGA);
    const index = new Int32Array([0, 13, 26, 13]); // 13 twice: averaged
    const target = new Float64Array([1, 0, 0, 0, 1, 0, 0, 0, -1, 0, 0.5, 0.5]);
    s.setConstraints(index, target);
    s.solve();
    const field = s.field();
    expect(field.length).toBe(81);
    const ref = denseFieldSolve([3, 3, 3], [0, 13, 26], [1, 0, 0, 0, 0.75, 0.25, 0, 0, -1]);
    expect(relError(field, ref)).toBeLessThan(1e-7);
    const st = s.stats();
    expect(st.method).toBe('cg');
    expect(st.iterations).toBeGreaterThan(0);
    expect(st.constraints).toBe(3);
    s.dispose();
  });

  it('fast (multigrid PCG) equals exact to 1e-6 after every edit of a random sequence', async () => {
    // A seeded edit sequence on an irregular box: add a clustered "curve" of points, retarget
    // some, remove some. The exact solver is the reference (itself checked against dense
    // solves natively and in the CLI test); the dense solve checks the first step here too.
    const dims: [number, number, number] = [11, 9, 13];
    const n = dims[0] * dims[1] * dims[2];
    let seed = 12345;
    const rand = () => {
      seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
      return seed / 2 ** 32;
    };
    const fast = await loadRawSolver('fast', { wasmBinary });
    const exact = await loadRawSolver('exact', { wasmBinary });
    fast.setGrid(dims, OMEGA);
    exact.setGrid(dims, OMEGA);
    const live = new Map<number, [number, number, number]>();
    const unit = (): [number, number, number] => {
      const v = [rand() - 0.5, rand() - 0.5, rand() - 0.5];
      const l = Math.hypot(v[0], v[1], v[2]) || 1;
      return [v[0] / l, v[1] / l, v[2] / l];
    };
    for (let step = 0; step < 8; step++) {
      // a random walk of 15 points, as a stroke constrains them
      let p = Math.floor(rand() * n);
      for (let k = 0; k < 15; k++) {
        live.set(p, unit());
        const axis = [1, dims[0], dims[0] * dims[1]][Math.floor(rand() * 3)];
        p = Math.min(n - 1, Math.max(0, p + (rand() < 0.5 ? -axis : axis)));
      }
      const keys = [...live.keys()];
      for (const k of keys) {
        const r = rand();
        if (r < 0.15) live.delete(k);
        else if (r < 0.3) live.set(k, unit());
      }
      const index = new Int32Array([...live.keys()].sort((a, b) => a - b));
      const target = new Float64Array(3 * index.length);
      for (let c = 0; c < index.length; c++) target.set(live.get(index[c]) as number[], 3 * c);
      fast.setConstraints(index, target);
      exact.setConstraints(index, target);
      fast.solve();
      exact.solve();
      const ref = exact.field();
      expect(relError(fast.field(), ref)).toBeLessThan(1e-6);
      if (step === 0)
        expect(relError(ref, denseFieldSolve(dims, index, target))).toBeLessThan(1e-10);
    }
    expect(fast.stats().method).toMatch(/mg/);
    fast.dispose();
    exact.dispose();
  });

  it('reports errors as SolverError messages', async () => {
    await expect(loadRawSolver('nope', { wasmBinary })).rejects.toThrow(/unknown solver 'nope'/);
    const s = await loadRawSolver('cg', { wasmBinary });
    expect(() => s.setConstraints(new Int32Array([0]), new Float64Array([1, 0, 0]))).toThrow(
      SolverError,
    );
    expect(() => s.setGrid([1, 3, 3], OMEGA)).toThrow(/>= 2/);
    s.setGrid([3, 3, 3], OMEGA);
    expect(() => s.setConstraints(new Int32Array([27]), new Float64Array([1, 0, 0]))).toThrow(
      /outside the grid/,
    );
    expect(() =>
      s.setConstraints(new Int32Array([2]), new Float64Array([Number.NaN, 0, 0])),
    ).toThrow(/not finite/);
    s.dispose();
  });
});

describe('engine', () => {
  const c: [number, number, number] = [0, 0, 0];
  const grid: GridSpec = { dims: [16, 16, 16], origin: [-2, -2, -2], step: 4 / 15 };
  const head = sphere(c, 1, 24, 48, 0.2);
  const curves = streamCurve(c, 1.05, grid.step);

  it('solves the curve into a field that follows it and matches a dense solve', async () => {
    const small: GridSpec = { dims: [6, 6, 6], origin: [-1.5, -1.5, -1.5], step: 0.6 };
    const e = await loadWasmEngine({ wasmBinary });
    e.setGrid(small, OMEGA, 'cg');
    e.setCurves(streamCurve(c, 1.05, small.step));
    e.solve();
    const cons = e.constraints();
    expect(cons.index.length).toBeGreaterThan(8);
    for (let i = 1; i < cons.index.length; i++)
      expect(cons.index[i]).toBeGreaterThan(cons.index[i - 1]);
    const field = e.field().vectors;
    const ref = denseFieldSolve(small.dims, cons.index, cons.target);
    expect(relError(field, ref)).toBeLessThan(1e-5); // float32 output
    e.dispose();
  });

  it('grows non-empty, seed-deterministic strands on a sphere scalp', async () => {
    const run = async (seed: number) => {
      const e = await loadWasmEngine({ wasmBinary });
      e.setGrid(grid, OMEGA, 'cg');
      e.setScalp(head);
      e.setCurves(curves);
      e.solve();
      const strands = e.grow({ ...growth, seed });
      return { e, strands };
    };
    const { e, strands } = await run(7);
    // Field near the middle of the curve follows its tangent.
    const p = curves.points;
    const m = 3; // a segment on the arc over the top
    const mid = [0, 1, 2].map((a) => 0.5 * (p[3 * m + a] + p[3 * m + 3 + a]));
    const tan = [0, 1, 2].map((a) => p[3 * m + 3 + a] - p[3 * m + a]);
    const ijk = mid.map((x, a) => Math.floor((x - grid.origin[a]) / grid.step));
    const q = ijk[0] + 16 * (ijk[1] + 16 * ijk[2]);
    const v = Array.from(e.field().vectors.subarray(3 * q, 3 * q + 3));
    const cos =
      (v[0] * tan[0] + v[1] * tan[1] + v[2] * tan[2]) / (Math.hypot(...v) * Math.hypot(...tan));
    expect(cos).toBeGreaterThan(0.95);
    expect(e.stats().method).toBe('cg');
    expect(e.stats().constraints).toBe(e.constraints().index.length);

    const count = strands.strandStart.length - 1;
    expect(count).toBeGreaterThan(100);
    expect(strands.strandStart[count]).toBe(strands.points.length / 3);
    expect(strands.points.length / 3).toBeGreaterThan(2 * count); // they grew
    // Roots lie on the sphere, on the scalp side.
    for (let s = 0; s < count; s += 17) {
      const i = 3 * strands.strandStart[s];
      const r = Math.hypot(strands.points[i], strands.points[i + 1], strands.points[i + 2]);
      expect(r).toBeGreaterThan(0.99);
      expect(r).toBeLessThan(1.001);
      expect(strands.points[i + 1]).toBeGreaterThan(0.1);
    }
    const again = await run(7);
    expect(again.strands.points).toEqual(strands.points);
    expect(again.strands.strandStart).toEqual(strands.strandStart);
    const other = await run(8);
    expect(other.strands.points).not.toEqual(strands.points);
    // Results are copies: a later grow does not change them.
    const before = strands.points.slice(0, 30);
    e.grow({ ...growth, seed: 99 });
    expect(strands.points.slice(0, 30)).toEqual(before);
    for (const x of [e, again.e, other.e]) x.dispose();
  });

  it('setScalpMask grows the hair a fresh engine given that scalp grows; a wrong length is refused', async () => {
    // the left half above the equator instead of the cap above y = 0.2
    const left = new Uint8Array(head.scalp.length);
    for (let t = 0; t < left.length; t++) {
      let x = 0;
      let y = 0;
      for (let k = 0; k < 3; k++) {
        x += head.positions[3 * head.indices[3 * t + k]];
        y += head.positions[3 * head.indices[3 * t + k] + 1];
      }
      left[t] = x > 0 && y > 0 ? 1 : 0;
    }
    const grown = async (scalp: ScalpMesh, mask?: Uint8Array) => {
      const e = await loadWasmEngine({ wasmBinary });
      e.setGrid(grid, OMEGA, 'cg');
      e.setScalp(scalp);
      e.setCurves(curves);
      e.solve();
      const first = e.grow(growth);
      if (mask) e.setScalpMask(mask);
      return { e, first, strands: e.grow(growth) };
    };
    const changed = await grown(head, left);
    const fresh = await grown({ ...head, scalp: left });
    expect(changed.strands.points).toEqual(fresh.strands.points);
    expect(changed.strands.strandStart).toEqual(fresh.strands.strandStart);
    expect(changed.strands.points).not.toEqual(changed.first.points);
    const e = changed.e;
    const count = e.rootCount();
    expect(() => e.setScalpMask(left.subarray(1))).toThrow(/flags for a head of/);
    const refused = (() => {
      try {
        e.setScalpMask(new Uint8Array(left.length + 1));
        return null;
      } catch (err) {
        return err;
      }
    })();
    expect(refused).toBeInstanceOf(SolverError);
    expect((refused as SolverError).kind).toBe('invalid_input');
    expect(e.grow(growth).points).toEqual(fresh.strands.points); // the mask in force stayed
    expect(e.rootCount()).toBe(count);
    for (const x of [e, fresh.e]) x.dispose();
  });

  it('throws SolverError with the C++ message on bad input', async () => {
    const e = await loadWasmEngine({ wasmBinary });
    expect(() => e.solve()).toThrow(/before setGrid/);
    expect(() => e.setGrid(grid, OMEGA, 'nope' as 'cg')).toThrow(/unknown solver/);
    e.setGrid(grid, OMEGA, 'cg');
    expect(() => e.setCurves({ ...curves, kinds: new Uint8Array([5]) })).toThrow(/unknown kind 5/);
    expect(() => e.grow(growth)).toThrow(SolverError); // no scalp
    const bad = { ...head, indices: head.indices.map((i) => i + 100000) };
    expect(() => e.setScalp(bad)).toThrow(/out of range/);
    e.dispose();
  });
});
