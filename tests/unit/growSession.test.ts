// growSessionHair: the one pipeline of the browser's export and `hairsketch grow`. The same
// session, grid, solver and cap give byte-identical strands on fresh engines; the cap overrides
// the session's; the hair equals the converged hair the app's worker shows for the same session.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { growSessionHair } from '../../web/export/growSession';
import { Head } from '../../web/head/head';
import { packCurves } from '../../web/model/curveSet';
import { gridForPreset } from '../../web/model/grid';
import type { FromWorker, StrandArrays } from '../../web/solver/protocol';
import { loadSolverEngine } from '../../web/solver/wasmEngine';
import { DEFAULT_SCHEDULER, WorkerLogic } from '../../web/solver/workerLogic';

const wasmPath = fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url));
let wasmBinary: Uint8Array;
beforeAll(() => {
  wasmBinary = new Uint8Array(readFileSync(wasmPath));
});

const head = Head.builtin();
const grid = gridForPreset('25k');
const session = presetSession('default', head, '25k', 0);

const bytes = (a: ArrayBufferView) => Buffer.from(a.buffer, a.byteOffset, a.byteLength);
const strandCount = (s: StrandArrays) => s.strandStart.length - 1;

async function grow(solver: 'fast' | 'exact', maxStrands?: number) {
  const engine = await loadSolverEngine({ wasmBinary });
  try {
    const phases: string[] = [];
    const hair = growSessionHair(engine, session, head.scalpMesh(), {
      grid,
      solver,
      maxStrands,
      onProgress: (phase, f) => phases.push(`${phase}:${f}`),
    });
    return { hair, phases };
  } finally {
    engine.dispose();
  }
}

describe('growSessionHair', () => {
  it('gives byte-identical strands on two fresh engines (fast)', async () => {
    const a = await grow('fast', 3000);
    const b = await grow('fast', 3000);
    expect(strandCount(a.hair.strands)).toBe(3000);
    expect(a.hair.strands.points.length).toBeGreaterThan(3 * 3000 * 10);
    expect(bytes(a.hair.strands.points).equals(bytes(b.hair.strands.points))).toBe(true);
    expect(bytes(a.hair.strands.strandStart).equals(bytes(b.hair.strands.strandStart))).toBe(true);
    expect(a.hair.iterations).toBe(b.hair.iterations);
    expect(a.hair.iterations).toBeGreaterThan(0);
    // progress: solve from 0 to 1, then grow from 0 to 1, never backwards within a phase
    const solve = a.phases.filter((p) => p.startsWith('solve:')).map((p) => Number(p.slice(6)));
    expect(solve[0]).toBe(0);
    expect(solve.at(-1)).toBe(1);
    for (let i = 1; i < solve.length; i++) expect(solve[i]).toBeGreaterThanOrEqual(solve[i - 1]);
    expect(a.phases.slice(-2)).toEqual(['grow:0', 'grow:1']);
  });

  it('caps strands by maxStrands when given, else by the session (0 = every root)', async () => {
    const capped = await grow('fast', 500);
    expect(strandCount(capped.hair.strands)).toBe(500);
    const all = await grow('fast');
    expect(strandCount(all.hair.strands)).toBeGreaterThan(10_000);
  });

  it("equals the converged hair of the app's worker for the same session", async () => {
    const engine = await loadSolverEngine({ wasmBinary });
    const results: FromWorker[] = [];
    const logic = new WorkerLogic(engine, (m) => results.push(m), {
      ...DEFAULT_SCHEDULER,
      yieldNow: () => Promise.resolve(),
    });
    await logic.handle({
      type: 'init',
      grid,
      omega: 100,
      solver: 'fast',
      scalp: head.scalpMesh(),
    });
    await logic.handle({
      type: 'solve',
      id: 1,
      curves: packCurves(session.curves, session.avoid ?? null),
      growth: { ...session.growth, maxStrands: 2000 },
      wantField: false,
      mode: 'full',
      lightMaxStrands: 500,
    });
    engine.dispose();
    const final = results.find((m) => m.type === 'result' && m.final);
    if (final?.type !== 'result') throw new Error('the worker sent no final result');
    const mine = await grow('fast', 2000);
    expect(bytes(mine.hair.strands.points).equals(bytes(final.strands.points))).toBe(true);
    expect(bytes(mine.hair.strands.strandStart).equals(bytes(final.strands.strandStart))).toBe(
      true,
    );
  });

  it("equals the worker's converged hair whatever the worker solved before (no warm-start trace)", async () => {
    const engine = await loadSolverEngine({ wasmBinary });
    const results: FromWorker[] = [];
    const logic = new WorkerLogic(engine, (m) => results.push(m), {
      ...DEFAULT_SCHEDULER,
      yieldNow: () => Promise.resolve(),
    });
    await logic.handle({ type: 'init', grid, omega: 100, solver: 'fast', scalp: head.scalpMesh() });
    const growth = { ...session.growth, maxStrands: 2000 };
    const solve = (id: number, curves: typeof session.curves, mode: 'preview' | 'full') =>
      logic.handle({
        type: 'solve',
        id,
        curves: packCurves(curves, session.avoid ?? null),
        growth,
        wantField: false,
        mode,
        lightMaxStrands: 500,
      });
    // a history: the session without its last curve, previews of a part of it, then the session
    await solve(1, session.curves.slice(0, -1), 'full');
    await solve(2, session.curves.slice(0, -2), 'preview');
    await solve(3, session.curves, 'full');
    engine.dispose();
    const final = results.find((m) => m.type === 'result' && m.final && m.id === 3);
    if (final?.type !== 'result') throw new Error('the worker sent no final result');
    const mine = await grow('fast', 2000);
    expect(bytes(mine.hair.strands.points).equals(bytes(final.strands.points))).toBe(true);
  });

  it('exact solver: deterministic too', async () => {
    const a = await grow('exact', 1000);
    const b = await grow('exact', 1000);
    expect(bytes(a.hair.strands.points).equals(bytes(b.hair.strands.points))).toBe(true);
    expect(strandCount(a.hair.strands)).toBe(1000);
  });
});
