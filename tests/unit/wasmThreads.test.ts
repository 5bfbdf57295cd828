// The threaded wasm module (hairsolver-mt, pthreads over node:worker_threads here) against the
// single-threaded one: the same field to 1e-12 on the wasm test problems (tests/fixtures, every
// solver) and the same strands bit for bit (growth and keepOutsideHead run in parallel chunks).
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
import { type LoadOptions, loadRawSolver, loadSolverEngine } from '../../web/solver/wasmEngine';

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

const bytes = (a: ArrayBufferView) => Buffer.from(a.buffer, a.byteOffset, a.byteLength);

const maxDiff = (a: Float64Array, b: Float64Array) => {
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
};

describe('threaded wasm module', () => {
  afterAll(stopThreadWorkers);

  it('loads under Node with the thread count asked for and says so', async () => {
    const e = await loadSolverEngine(await threadedNodeOptions(2));
    expect(e.moduleLabel()).toBe('threads: 2');
    e.dispose();
    const s = await loadSolverEngine({ ...singleNodeOptions(), singleReason: 'test' });
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
