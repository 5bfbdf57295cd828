// The threaded wasm module (hairsolver-mt, pthreads over node:worker_threads here) against the
// single-threaded one: the same field to 1e-12 on the wasm test problems (tests/fixtures, every
// solver, and a 63K-point edit sequence where the fast solver's multigrid loops run in parallel)
// and the same strands bit for bit (growth and keepOutsideHead run in parallel chunks).
import { readFileSync } from 'node:fs';
import { afterAll, describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { growSessionHair } from '../../web/export/growSession';
import { Head } from '../../web/head/head';
import { gridForPreset } from '../../web/model/grid';
import type { SessionState } from '../../web/model/session';
import {
  singleNodeOptions,
  stopThreadWorkers,
  threadedNodeOptions,
} from '../../web/solver/nodeThreads';
import {
  type LoadOptions,
  loadRawSolver,
  loadSolverEngine,
  loadWasmEngine,
} from '../../web/solver/wasmEngine';

interface Problem {
  grid: [number, number, number];
  omega: number;
  steps: { set?: number[][]; unset?: number[][] }[];
}

const fixture = (name: string): Problem =>
  JSON.parse(readFileSync(new URL(`../fixtures/${name}.json`, import.meta.url), 'utf8'));

/** The field after every step of a problem (constraints persist between steps). */
async function fields(load: LoadOptions, solver: string, p: Problem): Promise<Float64Array[]> {
  const s = await loadRawSolver(solver, load);
  try {
    s.setGrid(p.grid, p.omega);
    const [nx, ny] = p.grid;
    const on = new Map<number, number[]>();
    const out: Float64Array[] = [];
    for (const step of p.steps) {
      for (const [i, j, k] of step.unset ?? []) on.delete(i + nx * (j + ny * k));
      for (const [i, j, k, x, y, z] of step.set ?? []) on.set(i + nx * (j + ny * k), [x, y, z]);
      const keys = [...on.keys()].sort((a, b) => a - b);
      s.setConstraints(
        Int32Array.from(keys),
        Float64Array.from(keys.flatMap((q) => on.get(q) ?? [])),
      );
      s.solve();
      out.push(s.field());
    }
    return out;
  } finally {
    s.dispose();
  }
}

/** A 40 x 36 x 44 problem (63K points): big enough that the fast solver's sweeps, transfers,
 *  mat-vecs and CG sums run in parallel chunks (tests/native/parallel_test.cpp counts them at
 *  this size). Step 0: 8 random walks of 150 points (the 8 corners of the cell round each step get
 *  its direction); step 1: the first 300 removed and a walk of 400 added. */
function walkProblem(): Problem {
  const grid: [number, number, number] = [40, 36, 44];
  let seed = 11;
  const rand = () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const used = new Set<number>();
  const walk = (count: number): number[][] => {
    const out: number[][] = [];
    const p = grid.map((n) => rand() * (n - 1));
    let d = [rand() - 0.5, rand() - 0.5, 1];
    for (let guard = 0; out.length < count && guard < 20000; guard++) {
      d = d.map((x) => x + 0.6 * (rand() - 0.5));
      const len = Math.hypot(d[0], d[1], d[2]);
      d = d.map((x) => x / len);
      for (let a = 0; a < 3; a++) {
        p[a] += 0.7 * d[a];
        const hi = grid[a] - 1.001;
        if (p[a] < 0 || p[a] > hi) {
          d[a] = -d[a];
          p[a] = Math.min(hi, Math.max(0, p[a]));
        }
      }
      for (let c = 0; c < 8 && out.length < count; c++) {
        const ijk = [0, 1, 2].map((a) => Math.min(Math.floor(p[a]) + ((c >> a) & 1), grid[a] - 1));
        const key = ijk[0] + grid[0] * (ijk[1] + grid[1] * ijk[2]);
        if (used.has(key)) continue;
        used.add(key);
        out.push([...ijk, ...d]);
      }
    }
    return out;
  };
  const first: number[][] = [];
  for (let c = 0; c < 8; c++) first.push(...walk(150));
  const removed = first.slice(0, 300).map(([i, j, k]) => [i, j, k]);
  return { grid, omega: 100, steps: [{ set: first }, { unset: removed, set: walk(400) }] };
}

const bytes = (a: ArrayBufferView) => Buffer.from(a.buffer, a.byteOffset, a.byteLength);

const maxDiff = (a: Float64Array, b: Float64Array) => {
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
};

describe('threaded wasm module', () => {
  afterAll(stopThreadWorkers);

  it('loads under Node with the thread count asked for and says so', async () => {
    const e = await loadWasmEngine(await threadedNodeOptions(2));
    expect(e.moduleLabel()).toBe('threads: 2');
    e.dispose();
    const s = await loadWasmEngine({ ...singleNodeOptions(), singleReason: 'test' });
    expect(s.moduleLabel()).toBe('single-threaded: test');
    s.dispose();
  });

  for (const solver of ['fast', 'cg', 'exact'])
    for (const name of ['problem-small', 'problem-edits'])
      it(`gives the single-threaded field to 1e-12: ${solver}, ${name}`, async () => {
        const p = fixture(name);
        const one = await fields(singleNodeOptions(), solver, p);
        const two = await fields(await threadedNodeOptions(2), solver, p);
        expect(two.length).toBe(one.length);
        for (let k = 0; k < one.length; k++) {
          expect(two[k].length).toBe(one[k].length);
          expect(maxDiff(one[k], two[k])).toBeLessThanOrEqual(1e-12);
        }
      });

  it('gives the single-threaded field to 1e-12 where the multigrid loops run in parallel: fast, 63K points', async () => {
    const p = walkProblem();
    expect(p.steps[0].set?.length).toBe(1200);
    const one = await fields(singleNodeOptions(), 'fast', p);
    for (const threads of [2, 3]) {
      const many = await fields(await threadedNodeOptions(threads), 'fast', p);
      expect(many.length).toBe(2);
      for (let k = 0; k < one.length; k++) {
        expect(many[k].length).toBe(one[k].length);
        expect(maxDiff(one[k], many[k])).toBeLessThanOrEqual(1e-12);
      }
    }
    expect(maxDiff(one[0], new Float64Array(one[0].length))).toBeGreaterThan(0.1); // not all zero
  }, 240_000);

  const head = Head.builtin();
  const grid = gridForPreset('25k');
  // curly: detail everywhere, so keepOutsideHead runs after it (in chunks too)
  const sessions: [string, SessionState, number][] = [
    ['default', presetSession('default', head, '25k', 0), 0],
    ['curly', presetSession('curly', head, '25k', 0), 12000],
  ];
  for (const [name, session, maxStrands] of sessions)
    it(`grows the same strands bit for bit: ${name}`, async () => {
      const grow = async (load: LoadOptions) => {
        const engine = await loadSolverEngine(load);
        try {
          return growSessionHair(engine, session, head.scalpMesh(), {
            grid,
            solver: 'fast',
            ...(maxStrands ? { maxStrands } : {}),
          });
        } finally {
          engine.dispose();
        }
      };
      const one = await grow(singleNodeOptions());
      // 3 threads on a pool sized for them: chunk boundaries differ from 2 threads
      for (const threads of [2, 3]) {
        const many = await grow(await threadedNodeOptions(threads));
        expect(many.strands.strandStart).toEqual(one.strands.strandStart);
        expect(bytes(many.strands.points).equals(bytes(one.strands.points))).toBe(true);
      }
      expect(one.strands.strandStart.length).toBeGreaterThan(1000);
    }, 240_000);
});
