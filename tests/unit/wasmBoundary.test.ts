// The typed wasm boundary (wasmStructs.ts structs and status kinds, binding.cpp) under Node with the
// real module: each failure kind from the input that causes it, stats read as fixed fields
// against what the engine did, struct layouts against C's alignment rules worked out by hand,
// and curve parameters packed from CURVE_PARAMS against the hand-written block layout.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { CURVE_PARAMS } from '../../web/model/curveParams';
import { packCurves } from '../../web/model/curveSet';
import type { CurveSet, GridSpec } from '../../web/model/hairArrays';
import type { StyleCurve } from '../../web/model/session';
import { SolverError } from '../../web/solver/engine';
import type { SolverErrorKind } from '../../web/solver/protocol';
import { loadRawSolver, loadWasmEngine } from '../../web/solver/wasmEngine';
import {
  CURVE_SET_HEADER,
  GRID_INPUT,
  ITERATE_PROGRESS,
  STATS_OUTPUT,
  solverErrorKind,
  structLayout,
} from '../../web/solver/wasmStructs';

const wasmPath = fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url));
let wasmBinary: Uint8Array;
beforeAll(() => {
  wasmBinary = new Uint8Array(readFileSync(wasmPath));
});

/** The kind of the SolverError fn throws (fails the test when it throws nothing else). */
function kindOf(fn: () => unknown): SolverErrorKind {
  try {
    fn();
  } catch (e) {
    if (e instanceof SolverError) return e.kind;
    throw e;
  }
  throw new Error('did not throw');
}

const grid: GridSpec = { dims: [12, 12, 12], origin: [-1.5, -1.5, -1.5], step: 0.25 };
const vp = (): { position: [number, number, number]; target: [number, number, number] } => ({
  position: [0, 0, 5],
  target: [0, 0, 0],
});
const line = (n: number, y: number, z = 0): [number, number, number][] =>
  Array.from({ length: n }, (_, i) => [-0.8 + 0.25 * i, y, z] as [number, number, number]);

describe('struct layouts', () => {
  it('follow C alignment on wasm32 (offsets worked out by hand)', () => {
    // 8-byte doubles on 8-byte boundaries, 4-byte ints and pointers on 4, size rounded to 8.
    const L = structLayout([
      ['a', 'i32'],
      ['b', 'f64'],
      ['c', 'ptr'],
    ]);
    expect([L.fields.a.offset, L.fields.b.offset, L.fields.c.offset, L.size]).toEqual([
      0, 8, 16, 24,
    ]);
    expect(CURVE_SET_HEADER.size).toBe(12 * 4);
    expect(CURVE_SET_HEADER.fields.extraCount.offset).toBe(44);
    expect(GRID_INPUT.fields.nx.offset).toBe(5 * 8);
    expect(GRID_INPUT.size).toBe(5 * 8 + 4 * 4);
    expect(ITERATE_PROGRESS.size).toBe(16);
    // 4 doubles, 5 ints, then char[32] at 52: 84 bytes, padded to 88.
    expect(STATS_OUTPUT.fields.method.offset).toBe(52);
    expect(STATS_OUTPUT.size).toBe(88);
  });

  it('maps status codes to kinds', () => {
    expect([1, 2, 3, 4, 5, 99].map(solverErrorKind)).toEqual([
      'invalid_input',
      'non_finite',
      'over_memory_cap',
      'not_ready',
      'internal',
      'internal',
    ]);
  });
});

describe('error kinds', () => {
  it('engine: each kind from the input that causes it', async () => {
    const e = await loadWasmEngine({ wasmBinary }); // loading checks every struct's offsets
    expect(kindOf(() => e.solve())).toBe('not_ready');
    expect(kindOf(() => e.setGrid({ ...grid, dims: [1, 4, 4] }, 100, 'cg'))).toBe('invalid_input');
    expect(kindOf(() => e.setGrid({ ...grid, dims: [200, 200, 200] }, 100, 'fast'))).toBe(
      'over_memory_cap',
    );
    expect(kindOf(() => e.setGrid({ ...grid, step: Number.NaN }, 100, 'cg'))).toBe('non_finite');
    expect(kindOf(() => e.setGrid(grid, 100, 'nope' as 'cg'))).toBe('invalid_input');
    e.setGrid(grid, 100, 'exact');
    const curves = packCurves([
      { id: 'a', type: 'stream', points: line(5, 0), extend: true, viewpoint: vp() },
    ]);
    const nan = { ...curves, points: curves.points.map((v, i) => (i === 4 ? Number.NaN : v)) };
    expect(kindOf(() => e.setCurves(nan))).toBe('non_finite');
    expect(kindOf(() => e.setCurves({ ...curves, kinds: new Uint8Array([9]) }))).toBe(
      'invalid_input',
    );
    const extra: CurveSet = {
      ...curves,
      extraIndex: new Int32Array([3]),
      extraTarget: new Float64Array([0, Number.POSITIVE_INFINITY, 0]),
    };
    expect(kindOf(() => e.setCurves(extra))).toBe('non_finite');
    e.setCurves(curves);
    e.solve();
    // No scalp yet: growth and avoidance are not ready.
    const growth = {
      thetaStepDeg: 10,
      phiStepDeg: 10,
      jitter: 0,
      seed: 1,
      stepFraction: 0.5,
      minMagnitude: 0.05,
      maxLength: 2,
      maxSegments: 50,
      maxStrands: 0,
    };
    expect(kindOf(() => e.grow(growth))).toBe('not_ready');
    expect(kindOf(() => e.scalpAvoidance({}))).toBe('not_ready');
    expect(kindOf(() => e.grow({ ...growth, seed: 1.5 }))).toBe('invalid_input');
    e.dispose();
    expect(kindOf(() => e.solve())).toBe('not_ready');
  });

  it('the exact solver on a grid whose factor is over its memory cap says over_memory_cap', async () => {
    const e = await loadWasmEngine({ wasmBinary });
    // 250K preset size (63 x 63 x 63): the factor needs more than the 1800 MB cap.
    const big: GridSpec = { dims: [63, 63, 63], origin: [-1.5, -1.5, -1.5], step: 3 / 62 };
    let err: unknown = null;
    try {
      e.setGrid(big, 100, 'exact');
    } catch (x) {
      err = x;
    }
    expect(err).toBeInstanceOf(SolverError);
    expect((err as SolverError).kind).toBe('over_memory_cap');
    e.dispose();
  });

  it('raw solver: the same kinds', async () => {
    await expect(loadRawSolver('nope', { wasmBinary })).rejects.toMatchObject({
      kind: 'invalid_input',
    });
    const s = await loadRawSolver('cg', { wasmBinary });
    const one = () => s.setConstraints(new Int32Array([0]), new Float64Array([1, 0, 0]));
    expect(kindOf(one)).toBe('not_ready');
    expect(kindOf(() => s.solve())).toBe('not_ready');
    expect(kindOf(() => s.setGrid([5000, 5000, 5000], 100))).toBe('over_memory_cap');
    s.setGrid([3, 3, 3], 100);
    expect(kindOf(() => s.setGrid([3, 3, 3], 100))).toBe('invalid_input'); // one grid per solver
    expect(kindOf(() => s.setConstraints(new Int32Array([27]), new Float64Array(3)))).toBe(
      'invalid_input',
    );
    expect(kindOf(() => s.setConstraints(new Int32Array([2]), new Float64Array([0, NaN, 0])))).toBe(
      'non_finite',
    );
    s.dispose();
  });
});

describe('stats', () => {
  it('are fixed fields matching what the engine did', async () => {
    const e = await loadWasmEngine({ wasmBinary });
    e.setGrid(grid, 100, 'exact');
    const a = packCurves([
      { id: 'a', type: 'stream', points: line(6, 0), extend: true, viewpoint: vp() },
    ]);
    e.setCurves(a);
    e.solve();
    const n = e.constraints().index.length;
    expect(n).toBeGreaterThan(8);
    let s = e.stats();
    expect(s.constraints).toBe(n);
    expect([s.added, s.removed, s.changed]).toEqual([n, 0, 0]);
    expect(s.method.length).toBeGreaterThan(0);
    for (const v of [s.setupMs, s.solveMs, s.iterations]) expect(Number.isFinite(v)).toBe(true);
    // A second curve far away: only additions; then removing it: only removals.
    const b = packCurves([
      { id: 'a', type: 'stream', points: line(6, 0), extend: true, viewpoint: vp() },
      { id: 'b', type: 'stream', points: line(6, 1, 1), extend: false, viewpoint: vp() },
    ]);
    e.setCurves(b);
    e.solve();
    const m = e.constraints().index.length;
    s = e.stats();
    expect([s.constraints, s.added, s.removed]).toEqual([m, m - n, 0]);
    e.setCurves(a);
    e.solve();
    s = e.stats();
    expect([s.constraints, s.added, s.removed]).toEqual([n, 0, m - n]);
    e.dispose();
  });

  it('raw solver stats count the merged constraints', async () => {
    const s = await loadRawSolver('exact', { wasmBinary });
    s.setGrid([4, 4, 4], 100);
    // index 5 twice: merged into one.
    s.setConstraints(new Int32Array([5, 5, 9]), new Float64Array([1, 0, 0, 0, 1, 0, 0, 0, 1]));
    s.solve();
    const st = s.stats();
    expect([st.constraints, st.added, st.removed]).toEqual([2, 2, 0]);
    expect(Number.isFinite(st.residual)).toBe(true);
    expect(st.method).toMatch(/\S/);
    s.dispose();
  });
});

describe('curve parameters from CURVE_PARAMS', () => {
  const normals = (n: number): [number, number, number][] =>
    Array.from({ length: n }, () => [0, 1, 0] as [number, number, number]);
  const spine: [number, number, number][] = Array.from({ length: 7 }, (_, i) => [
    0.4,
    0.6 - 0.25 * i,
    0.1,
  ]);
  const circles = [
    {
      centre: [0.4, 0.35, 0.1] as [number, number, number],
      axis: [0, -1, 0] as [number, number, number],
      radius: 0.4,
      spineIndex: 1,
    },
    {
      centre: [0.4, -0.4, 0.1] as [number, number, number],
      axis: [0, -1, 0] as [number, number, number],
      radius: 0.2,
      spineIndex: 4,
    },
  ];
  const session = (sigma: number, h: number, a0: number, a1: number, t: number): StyleCurve[] => [
    { id: 's', type: 'stream', points: line(5, -1), extend: true, viewpoint: vp() },
    {
      id: 'd',
      type: 'dividing',
      points: line(6, 0.2),
      normals: normals(6),
      viewpoint: vp(),
      sigma,
      h,
      alpha0: a0,
      alpha1: a1,
    },
    {
      id: 'p',
      type: 'ponytail',
      points: spine,
      extend: false,
      viewpoint: vp(),
      crossSection: [],
      profiles: [[], []],
      circles,
      tightness: t,
      section: 1,
    },
  ];
  /** The blocks as they were written by hand before the table: stream [volume] (0: none),
   *  dividing [sigma, h, alpha0, alpha1, normals...], ponytail [tightness, m, (centre, axis,
   *  radius) per circle]. */
  function handPacked(sigma: number, h: number, a0: number, a1: number, t: number): number[] {
    const div = [sigma, h, a0, a1, ...normals(6).flat()];
    const pony = [t, 2, ...circles.flatMap((c) => [...c.centre, ...c.axis, c.radius])];
    return [0, ...div, ...pony];
  }
  const cases: Array<[number, number, number, number, number]> = [
    [1, 0.5, 0, 0, 0.6],
    [1.7, 1.2, 0.3, -0.4, 0.9],
    [0.6, 0.1, -0.2, 0.5, 0.2],
  ];

  it('packs the same blocks as the hand-written layout', () => {
    for (const c of cases) {
      const packed = packCurves(session(...c));
      expect(Array.from(packed.params)).toEqual(handPacked(...c));
      expect(Array.from(packed.paramStart)).toEqual([0, 1, 1 + 4 + 18, 1 + 4 + 18 + 16]);
    }
    expect(CURVE_PARAMS.dividing.map((p) => p.name)).toEqual(['sigma', 'h', 'alpha0', 'alpha1']);
  });

  it('gives the constraints of the hand-written packing, parameter by parameter', async () => {
    const e = await loadWasmEngine({ wasmBinary });
    e.setGrid(grid, 100, 'cg');
    const results: string[] = [];
    for (const c of cases) {
      const table = packCurves(session(...c));
      const hand: CurveSet = { ...table, params: new Float64Array(handPacked(...c)) };
      e.setCurves(hand);
      const want = e.constraints();
      e.setCurves(table);
      const got = e.constraints();
      expect(got.index).toEqual(want.index);
      expect(got.target).toEqual(want.target);
      results.push(`${got.index.join()}|${got.target.join()}`);
    }
    // The parameters do reach the C++ code: each case gives different constraints.
    expect(new Set(results).size).toBe(cases.length);
    e.dispose();
  });
});
