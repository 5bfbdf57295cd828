// The worker's scheduler against a scripted engine: previews, first look then final, and a
// newer request superseding a running solve between iteration slices.
import { describe, expect, it } from 'vitest';
import { packCurves } from '../../web/model/curveSet';
import { DEFAULT_GROWTH } from '../../web/model/session';
import type { IterateProgress, SolverEngine } from '../../web/solver/engine';
import type { FromWorker, ToWorker } from '../../web/solver/protocol';
import { DEFAULT_SCHEDULER, WorkerLogic } from '../../web/solver/workerLogic';

/** An engine whose error falls by 10x per iteration from 1 (so 1e-6 takes 6 iterations). */
function scriptedEngine(log: string[]): SolverEngine {
  let it = 0;
  const progress = (): IterateProgress => ({
    iterations: it,
    errorEstimate: 10 ** -it,
    converged: 10 ** -it <= 1e-6,
  });
  return {
    setGrid: () => log.push('grid'),
    setScalp: () => log.push('scalp'),
    setCurves: (c) => {
      it = 0;
      log.push(`curves:${c.curveStart.length - 1}`);
    },
    solve: () => {},
    iterate: (k, tol) => {
      for (let i = 0; i < k && 10 ** -it > tol; i++) it++;
      log.push(`iterate:${it}`);
      return progress();
    },
    grow: (g) => {
      log.push(`grow:${g.maxStrands}`);
      return { points: new Float32Array(3), strandStart: new Uint32Array([0, 1]) };
    },
    constraints: () => ({ index: new Int32Array(), target: new Float32Array() }),
    field: () => ({ vectors: new Float32Array() }),
    stats: () => ({
      method: 'fast',
      iterations: it,
      constraints: 0,
      added: 0,
      removed: 0,
      changed: 0,
      setupMs: 0,
      solveMs: 0,
    }),
    heapBytes: () => 1 << 20,
    scalpAvoidance: (o) => {
      log.push(`avoid:${it}:${o.band}:${o.magnitude}:${o.wholeHead}`);
      return { index: new Int32Array([4]), target: new Float64Array([0, 0.3, 0]) };
    },
    dispose: () => {},
  };
}

const init: ToWorker = {
  type: 'init',
  grid: { dims: [2, 2, 2], origin: [0, 0, 0], step: 1 },
  omega: 100,
  solver: 'fast',
  scalp: {
    positions: new Float32Array(),
    indices: new Uint32Array(),
    scalp: new Uint8Array(),
    center: [0, 0, 0],
  },
};

const solve = (id: number, mode: 'preview' | 'full', n = 1): ToWorker => ({
  type: 'solve',
  id,
  curves: packCurves([]),
  growth: { ...DEFAULT_GROWTH, maxStrands: 0 },
  wantField: false,
  mode,
  ...(n ? {} : {}),
});

function harness() {
  const log: string[] = [];
  const posted: FromWorker[] = [];
  let yields: Array<() => void> = [];
  const logic = new WorkerLogic(scriptedEngine(log), (m) => posted.push(m), {
    ...DEFAULT_SCHEDULER,
    firstLookIterations: 2,
    sliceIterations: 2,
    yieldNow: () => new Promise<void>((r) => yields.push(r)),
  });
  const release = async () => {
    const y = yields;
    yields = [];
    for (const r of y) r();
    await new Promise((r) => setTimeout(r, 0));
  };
  const results = () =>
    posted.filter((m): m is Extract<FromWorker, { type: 'result' }> => m.type === 'result');
  return { logic, log, posted, results, release, pendingYields: () => yields.length };
}

describe('WorkerLogic', () => {
  it('answers a preview with one non-final result grown with few strands', async () => {
    const h = harness();
    await h.logic.handle(init);
    const done = h.logic.handle(solve(1, 'preview'));
    await h.release(); // the job starts after one yield (a burst of messages coalesces)
    await done;
    expect(h.results().map((r) => [r.id, r.final])).toEqual([[1, false]]);
    expect(h.log).toContain(`grow:${DEFAULT_SCHEDULER.previewMaxStrands}`);
    expect(h.results()[0].stats.heapBytes).toBe(1 << 20);
    expect(h.log).toContain(`iterate:${DEFAULT_SCHEDULER.previewIterations}`);
  });

  it('posts a first look, iterates in slices, then the final hair', async () => {
    const h = harness();
    await h.logic.handle(init);
    const done = h.logic.handle(solve(1, 'full'));
    await h.release();
    // First look after 2 iterations, then slices of 2 with a yield before each.
    expect(h.results().map((r) => [r.id, r.final])).toEqual([[1, false]]);
    while (h.pendingYields() > 0) await h.release();
    await done;
    const rs = h.results();
    expect(rs.map((r) => [r.id, r.final])).toEqual([
      [1, false],
      [1, true],
    ]);
    expect(rs[1].stats.errorEstimate).toBeLessThanOrEqual(1e-6);
    // The first look is grown light; the final hair with the session's settings (no cap).
    expect(h.log.filter((l) => l.startsWith('grow'))).toEqual([
      `grow:${DEFAULT_SCHEDULER.previewMaxStrands}`,
      'grow:0',
    ]);
    expect(h.log.filter((l) => l.startsWith('iterate'))).toEqual([
      'iterate:2',
      'iterate:4',
      'iterate:6',
    ]);
  });

  it('drops a running solve when a newer request arrives', async () => {
    const h = harness();
    await h.logic.handle(init);
    const first = h.logic.handle(solve(1, 'full'));
    await h.release(); // job 1 runs to its first look and waits at a yield
    await h.logic.handle(solve(2, 'full'));
    while (h.pendingYields() > 0) await h.release();
    await first;
    const rs = h.results();
    expect(rs.filter((r) => r.id === 1).map((r) => r.final)).toEqual([false]); // never final
    expect(rs.filter((r) => r.id === 2).map((r) => r.final)).toEqual([false, true]);
  });

  it('solves only the newest of a burst of requests', async () => {
    const h = harness();
    await h.logic.handle(init);
    const first = h.logic.handle(solve(1, 'preview'));
    await h.logic.handle(solve(2, 'preview'));
    await h.logic.handle(solve(3, 'full'));
    while (h.pendingYields() > 0) await h.release();
    await first;
    expect(h.results().map((r) => [r.id, r.final])).toEqual([
      [3, false],
      [3, true],
    ]);
    expect(h.log.filter((l) => l.startsWith('curves'))).toHaveLength(1);
  });

  it('reports a solve before init as an error', async () => {
    const h = harness();
    await h.logic.handle(solve(5, 'full'));
    expect(h.posted).toEqual([{ type: 'error', id: 5, message: 'Solver is not initialised' }]);
  });

  it('answers scalp avoidance on the converged field, ahead of a waiting solve', async () => {
    const h = harness();
    await h.logic.handle(init);
    const done = h.logic.handle({
      type: 'avoidScalp',
      id: 7,
      curves: packCurves([]),
      band: 1.5,
      magnitude: 0.3,
      wholeHead: true,
      insideToo: true,
    });
    await h.logic.handle(solve(8, 'full'));
    while (h.pendingYields() > 0) await h.release();
    await done;
    // converged (error 1e-6 after 6 iterations) before the constraints are derived
    expect(h.log).toContain('avoid:6:1.5:0.3:true');
    const answer = h.posted.find((m) => m.type === 'avoidance');
    expect(answer).toEqual({
      type: 'avoidance',
      id: 7,
      index: new Int32Array([4]),
      target: new Float64Array([0, 0.3, 0]),
    });
    // then the solve that was waiting
    expect(h.results().map((r) => [r.id, r.final])).toEqual([
      [8, false],
      [8, true],
    ]);
  });
});
