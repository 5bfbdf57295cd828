// The worker's scheduler against a scripted engine: previews, first look then final, and a
// newer request superseding a running solve between iteration slices.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { packCurves, packHairOptions } from '../../web/model/curveSet';
import type { GridSpec, HairOptions } from '../../web/model/hairArrays';
import { DEFAULT_GROWTH } from '../../web/model/session';
import { type IterateProgress, SolverError } from '../../web/solver/engine';
import type { EngineCore } from '../../web/solver/engineCore';
import type { FromWorker, ToWorker } from '../../web/solver/protocol';
import { engineOver } from '../../web/solver/requestRunner';
import { loadSolverEngine } from '../../web/solver/wasmEngine';
import { lineAttributes } from '../../web/viewer/strandAttributes';
import { DEFAULT_SCHEDULER, WorkerLogic } from '../../web/worker/workerLogic';

/** An engine core whose error falls by 10x per iteration from 1 (so 1e-6 takes 6 iterations). */
function scriptedEngine(log: string[], colours = new Uint8Array([0, 1, 3])): EngineCore {
  let it = 0;
  const progress = (): IterateProgress => ({
    iterations: it,
    errorEstimate: 10 ** -it,
    converged: 10 ** -it <= 1e-6,
  });
  return {
    setGrid: (g, omega, solver) => log.push(`grid:${g.dims.join('x')}:${omega}:${solver}`),
    setScalp: () => log.push('scalp'),
    setScalpMask: (m) => {
      if (m.length !== 8) throw new SolverError(`mask of ${m.length} for 8`, 'invalid_input');
      log.push(`mask:${Array.from(m).join('')}`);
    },
    setDetail: (d) => log.push(`detail:${d.groups.length}:${d.groups[13]}`),
    setBody: () => {},
    setSettings: () => {},
    deferPreconditionerUpdate: () => {},
    startMotion: () => {
      throw new SolverError('the scripted engine plays no motion', 'internal');
    },
    setCurves: (c) => {
      it = 0;
      log.push(`curves:${c.curveStart.length - 1}:extra${c.extraIndex.length}`);
    },
    // a direct solver: nothing to forget (the scheduler then goes on without a restart)
    forgetWarmStart: () => {
      log.push('forget');
      return false;
    },
    solve: () => {},
    iterate: (k, tol) => {
      for (let i = 0; i < k && 10 ** -it > tol; i++) it++;
      log.push(`iterate:${it}`);
      return progress();
    },
    grow: (g) => {
      log.push(`grow:${g.maxStrands}`);
      // one strand of 5 points along x: (0, 0, 0) … (4, 0, 0)
      const points = new Float32Array(15);
      for (let i = 0; i < 5; i++) points[3 * i] = i;
      return { points, strandStart: new Uint32Array([0, 5]) };
    },
    constraints: () => ({ index: new Int32Array([4, 9, 12]), target: new Float32Array(9) }),
    constraintColours: () => colours,
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
      log.push(`avoid:${it}:${o.band}:${o.magnitude}:${o.wholeHead}:${o.insideToo}:${o.minField}`);
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

type SolveMsg = Extract<ToWorker, { type: 'solve' }>;

/** The light strand cap the tests' app asks for (previews, first looks). */
const LIGHT = 1234;

const NO_OPTIONS: HairOptions = packHairOptions({}, []);

const solve = (
  id: number,
  mode: 'preview' | 'full',
  lightMaxStrands = LIGHT,
  options = NO_OPTIONS,
): ToWorker => ({
  type: 'solve',
  id,
  curves: packCurves([]),
  growth: { ...DEFAULT_GROWTH, maxStrands: 0 },
  options,
  wantField: false,
  mode,
  lightMaxStrands,
});

function harness(colours?: Uint8Array<ArrayBuffer>, convergedSample = false) {
  const log: string[] = [];
  const posted: FromWorker[] = [];
  let yields: Array<() => void> = [];
  const logic = new WorkerLogic(engineOver(scriptedEngine(log, colours)), (m) => posted.push(m), {
    ...DEFAULT_SCHEDULER,
    firstLookIterations: 2,
    sliceIterations: 2,
    convergedSample,
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
    expect(h.results()).toEqual([]); // and yields once more after its iterations
    while (h.pendingYields() > 0) await h.release();
    await done;
    expect(h.results().map((r) => [r.id, r.final])).toEqual([[1, false]]);
    expect(h.log).toContain(`grow:${LIGHT}`);
    // drawn with every other point of the grown strand, and its tip
    const strands = h.results()[0].strands;
    expect(Array.from(strands.strandStart)).toEqual([0, 3]);
    expect(Array.from(strands.points)).toEqual([0, 0, 0, 2, 0, 0, 4, 0, 0]);
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
    // first look and final hair keep every grown point (only previews are thinned)
    for (const r of rs) expect(Array.from(r.strands.strandStart)).toEqual([0, 5]);
    // The first look is grown light; the final hair with the session's settings (no cap).
    expect(h.log.filter((l) => l.startsWith('grow'))).toEqual([`grow:${LIGHT}`, 'grow:0']);
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

  it("moves the engine to another grid in place, with init's omega and solver, and drops the job running", async () => {
    const h = harness();
    await h.logic.handle(init);
    const done = h.logic.handle(solve(1, 'full'));
    await h.release(); // job 1: first look posted, waiting at a yield
    expect(h.results().map((r) => r.id)).toEqual([1]);
    await h.logic.handle({ type: 'grid', grid: { dims: [3, 4, 5], origin: [0, 0, 0], step: 1 } });
    expect(h.log.at(-1)).toBe('grid:3x4x5:100:fast');
    const next = h.logic.handle(solve(2, 'full'));
    while (h.pendingYields() > 0) await h.release();
    await Promise.all([done, next]);
    // job 1 never finished; job 2 did, on the new grid
    expect(h.results().map((r) => [r.id, r.final])).toEqual([
      [1, false],
      [2, false],
      [2, true],
    ]);
    expect(h.posted.filter((m) => m.type === 'error')).toEqual([]);
  });

  it('drops a preview whose iterations a full request followed, without growing it', async () => {
    const h = harness();
    await h.logic.handle(init);
    const preview = h.logic.handle(solve(1, 'preview'));
    await h.release(); // the preview runs one iteration, then yields
    expect(h.log.slice(-2)).toEqual(['curves:0:extra0', 'iterate:1']);
    const full = h.logic.handle(solve(2, 'full'));
    while (h.pendingYields() > 0) await h.release();
    await Promise.all([preview, full]);
    // the preview stopped there: the next thing done is the full request's set-up
    const at = h.log.indexOf('iterate:1');
    expect(h.log.slice(at, at + 3)).toEqual(['iterate:1', 'detail:14:0', 'curves:0:extra0']);
    expect(h.results().map((r) => [r.id, r.final])).toEqual([
      [2, false],
      [2, true],
    ]);
    // grown: the full request's first look and final hair, not the preview
    expect(h.log.filter((l) => l.startsWith('grow'))).toEqual([`grow:${LIGHT}`, 'grow:0']);
  });

  it('sends each constraint with its colour, in the same order', async () => {
    const h = harness();
    await h.logic.handle(init);
    const done = h.logic.handle(solve(1, 'preview'));
    while (h.pendingYields() > 0) await h.release();
    await done;
    const c = h.results()[0].constraints;
    expect(Array.from(c.index)).toEqual([4, 9, 12]);
    expect(Array.from(c.colour)).toEqual([0, 1, 3]);
  });

  it('pads missing colours as "extra" so colour and index always have one entry each', async () => {
    const h = harness(new Uint8Array([2]));
    await h.logic.handle(init);
    const done = h.logic.handle(solve(1, 'preview'));
    while (h.pendingYields() > 0) await h.release();
    await done;
    expect(Array.from(h.results()[0].constraints.colour)).toEqual([2, 4, 4]);
  });

  it('reports a solve before init as an error', async () => {
    const h = harness();
    await h.logic.handle(solve(5, 'full'));
    expect(h.posted).toEqual([
      { type: 'error', id: 5, message: 'Solver is not initialised', kind: 'not_ready' },
    ]);
  });

  it("posts the converged field's hair light, then in full; a newer request between them drops the full growth", async () => {
    const h = harness(undefined, true);
    await h.logic.handle(init);
    let done = h.logic.handle(solve(1, 'full'));
    while (h.pendingYields() > 0) await h.release();
    await done;
    const rs = h.results();
    // first look, the converged field grown light, then the final hair
    expect(rs.map((r) => [r.id, r.final, r.converged])).toEqual([
      [1, false, false],
      [1, false, true],
      [1, true, true],
    ]);
    expect(h.log.filter((l) => l.startsWith('grow'))).toEqual([
      `grow:${LIGHT}`,
      `grow:${LIGHT}`,
      'grow:0',
    ]);
    // the sample is grown from the converged field: no iteration between it and the final hair
    const log = h.log;
    const at = log.lastIndexOf(`grow:${LIGHT}`);
    expect(log.slice(at)).toEqual([`grow:${LIGHT}`, 'grow:0']);
    expect(rs[1].stats.errorEstimate).toBeLessThanOrEqual(1e-6);

    // a request (for other settings: a field to solve) that arrives after the sample was
    // posted: the full growth is not done
    const before = h.log.length;
    done = h.logic.handle(solve(2, 'full', LIGHT, { ...NO_OPTIONS, fall: true }));
    while (!h.results().some((r) => r.id === 2 && r.converged)) await h.release();
    const newer = h.logic.handle(solve(3, 'preview'));
    while (h.pendingYields() > 0) await h.release();
    await Promise.all([done, newer]);
    expect(h.results().filter((r) => r.id === 2 && r.final)).toEqual([]);
    expect(h.log.slice(before).filter((l) => l === 'grow:0')).toEqual([]);
    expect(h.results().at(-1)?.id).toBe(3);
  });

  it('a change of growth or detail alone grows from the field it has, without solving again', async () => {
    const h = harness();
    await h.logic.handle(init);
    let done = h.logic.handle(solve(1, 'full'));
    while (h.pendingYields() > 0) await h.release();
    await done;
    // the same curves and settings, another detail: no iteration, no new curves, one final growth
    const before = h.log.length;
    const curly = { ...NO_OPTIONS, detail: { ...NO_OPTIONS.detail, groups: new Float64Array(14) } };
    curly.detail.groups[13] = 0.3;
    done = h.logic.handle(solve(2, 'full', LIGHT, curly));
    while (h.pendingYields() > 0) await h.release();
    await done;
    const after = h.log.slice(before);
    expect(after.filter((l) => l.startsWith('iterate') || l.startsWith('curves'))).toEqual([]);
    expect(after.filter((l) => l.startsWith('grow'))).toEqual(['grow:0']);
    expect(
      h
        .results()
        .filter((r) => r.id === 2)
        .map((r) => r.final),
    ).toEqual([true]);
    // other settings (a different field): solved again
    const again = h.log.length;
    done = h.logic.handle(solve(3, 'full', LIGHT, { ...NO_OPTIONS, fall: true }));
    while (h.pendingYields() > 0) await h.release();
    await done;
    expect(h.log.slice(again).some((l) => l.startsWith('iterate'))).toBe(true);
  });

  it('posts no light growth of the converged field when the full hair is no heavier', async () => {
    const h = harness(undefined, true);
    await h.logic.handle(init);
    const done = h.logic.handle(solve(1, 'full', 0)); // no light cap: the full hair is as light
    while (h.pendingYields() > 0) await h.release();
    await done;
    expect(h.results().map((r) => [r.final, r.converged])).toEqual([
      [false, false],
      [true, true],
    ]);
  });

  it("grows previews and first looks with the request's light cap, the final hair without it", async () => {
    const h = harness();
    await h.logic.handle(init);
    let done = h.logic.handle(solve(1, 'preview', 77));
    while (h.pendingYields() > 0) await h.release();
    await done;
    done = h.logic.handle(solve(2, 'full', 0)); // 0: no light cap of its own
    while (h.pendingYields() > 0) await h.release();
    await done;
    expect(h.log.filter((l) => l.startsWith('grow'))).toEqual(['grow:77', 'grow:0', 'grow:0']);
  });

  it('with avoid scalp on, a full solve derives the avoidance from the converged field and solves again with it', async () => {
    const h = harness();
    await h.logic.handle(init);
    const msg = solve(1, 'full', LIGHT, packHairOptions({ avoidScalp: true }, [])) as SolveMsg;
    const done = h.logic.handle({ ...msg, growth: { ...msg.growth, minMagnitude: 0.07 } });
    while (h.pendingYields() > 0) await h.release();
    await done;
    // converged (error 1e-6 after 6 iterations), then the constraints: the scalp only (not the
    // whole head), band 1.5 steps, magnitude 0.3, inside too, none where |v| < minMagnitude
    const i = h.log.indexOf('avoid:6:1.5:0.3:false:true:0.07');
    expect(i).toBeGreaterThan(0);
    // the curves again with the derived constraints as extras, warm-started from the converged
    // (history-free) field: no forgetting, to convergence
    expect(h.log.slice(i + 1)).toEqual([
      'curves:0:extra1',
      'iterate:2',
      'iterate:4',
      'iterate:6',
      'grow:0',
    ]);
    expect(h.log.filter((l) => l.startsWith('avoid'))).toHaveLength(1);
    // one first look (before avoidance) and one final hair (after it)
    expect(h.results().map((r) => [r.id, r.final])).toEqual([
      [1, false],
      [1, true],
    ]);
    expect(h.results()[1].stats.errorEstimate).toBeLessThanOrEqual(1e-6);
  });

  it('with avoid scalp off, or in a preview, derives no avoidance', async () => {
    const h = harness();
    await h.logic.handle(init);
    let done = h.logic.handle(solve(1, 'full'));
    while (h.pendingYields() > 0) await h.release();
    await done;
    done = h.logic.handle(solve(2, 'preview', LIGHT, packHairOptions({ avoidScalp: true }, [])));
    while (h.pendingYields() > 0) await h.release();
    await done;
    expect(h.log.filter((l) => l.startsWith('avoid'))).toEqual([]);
    expect(h.log.filter((l) => l.startsWith('curves'))).toEqual([
      'curves:0:extra0',
      'curves:0:extra0',
    ]);
    expect(h.results().map((r) => [r.id, r.final])).toEqual([
      [1, false],
      [1, true],
      [2, false],
    ]);
  });

  it('a newer request supersedes a solve while it solves again with the avoidance', async () => {
    const h = harness();
    await h.logic.handle(init);
    const first = h.logic.handle(
      solve(1, 'full', LIGHT, packHairOptions({ avoidScalp: true }, [])),
    );
    // run until it solves again with the avoidance, and is waiting between slices
    while (!h.log.includes('curves:0:extra1')) await h.release();
    expect(h.log.at(-1)).toBe('iterate:2');
    await h.logic.handle(solve(2, 'full'));
    while (h.pendingYields() > 0) await h.release();
    await first;
    expect(
      h
        .results()
        .filter((r) => r.id === 1)
        .map((r) => r.final),
    ).toEqual([false]);
    expect(
      h
        .results()
        .filter((r) => r.id === 2)
        .map((r) => r.final),
    ).toEqual([false, true]);
  });

  it("hands each request's detail to the engine before its curves", async () => {
    const h = harness();
    await h.logic.handle(init);
    const options = packHairOptions({ detail: { lengthJitter: 0.25 } }, []);
    const done = h.logic.handle(solve(1, 'preview', LIGHT, options));
    while (h.pendingYields() > 0) await h.release();
    await done;
    const d = h.log.indexOf('detail:14:0.25'); // one group of 14, lengthJitter 0.25
    expect(d).toBeGreaterThanOrEqual(0);
    expect(h.log[d + 1]).toBe('curves:0:extra0');
  });
});

/** A small octahedron, every face scalp: enough for root sampling. */
/** A full solve of one stream curve over the octahedron head (octahedron(·, 1)) at grid step
 *  `step`, grown densely with no cap: the real-wasm tests' request. */
function fullOverOctahedron(id: number, step: number): SolveMsg {
  const points: [number, number, number][] = [];
  for (let i = 0; i < 8; i++) points.push([-0.9 + i * step, 1.1, 0]);
  const curves = packCurves([
    {
      id: 'c1',
      type: 'stream',
      points,
      extend: true,
      viewpoint: { position: [0, 0, 5], target: [0, 0, 0] },
    },
  ]);
  const growth = { ...DEFAULT_GROWTH, thetaStepDeg: 3, phiStepDeg: 3, maxStrands: 0 };
  return { ...(solve(id, 'full') as SolveMsg), curves, growth };
}

function octahedron(c: [number, number, number], r: number) {
  const v = [
    [r, 0, 0],
    [-r, 0, 0],
    [0, r, 0],
    [0, -r, 0],
    [0, 0, r],
    [0, 0, -r],
  ].flatMap((p) => [c[0] + p[0], c[1] + p[1], c[2] + p[2]]);
  const f = [0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5];
  return {
    positions: new Float32Array(v),
    indices: new Uint32Array(f),
    scalp: new Uint8Array(8).fill(1),
    center: c,
  };
}

describe('WorkerLogic: a new scalp mask', () => {
  it('hands the mask to the engine at once; the next solve grows after it, no set-up again', async () => {
    const h = harness();
    await h.logic.handle(init);
    h.log.length = 0;
    await h.logic.handle({ type: 'scalpMask', scalp: new Uint8Array([1, 1, 0, 0, 1, 0, 1, 0]) });
    expect(h.log).toEqual(['mask:11001010']);
    expect(h.posted.filter((m) => m.type === 'error')).toEqual([]);
    const done = h.logic.handle(solve(1, 'preview'));
    while (h.pendingYields() > 0) await h.release();
    await done;
    expect(h.log.indexOf('mask:11001010')).toBeLessThan(h.log.indexOf(`grow:${LIGHT}`));
    expect(h.log.filter((l) => l.startsWith('grid'))).toEqual([]);
    expect(h.log).not.toContain('scalp');
  });

  it('reports a refused mask (id null, its kind) and keeps going', async () => {
    const h = harness();
    await h.logic.handle(init);
    await h.logic.handle({ type: 'scalpMask', scalp: new Uint8Array(7) });
    expect(h.posted.at(-1)).toMatchObject({ type: 'error', id: null, kind: 'invalid_input' });
    expect((h.posted.at(-1) as { message: string }).message).toMatch(/^Scalp mask: mask of 7/);
    const done = h.logic.handle(solve(2, 'preview'));
    while (h.pendingYields() > 0) await h.release();
    await done;
    expect(h.results().map((r) => r.id)).toEqual([2]);
  });

  it('refuses a mask before init', async () => {
    const h = harness();
    await h.logic.handle({ type: 'scalpMask', scalp: new Uint8Array(8) });
    expect(h.posted).toEqual([
      {
        type: 'error',
        id: null,
        message: 'Scalp mask: the solver is not initialised',
        kind: 'not_ready',
      },
    ]);
  });
});

describe('WorkerLogic over the real wasm engine', () => {
  it('colours a stream curve blue and its fading extension red, one colour per constraint', async () => {
    const wasmPath = fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url));
    const engine = await loadSolverEngine({ wasmBinary: new Uint8Array(readFileSync(wasmPath)) });
    const posted: FromWorker[] = [];
    const logic = new WorkerLogic(engine, (m) => posted.push(m));
    const step = 0.25;
    await logic.handle({
      ...init,
      grid: { dims: [12, 12, 12], origin: [-1.5, -1.5, -1.5], step },
      solver: 'cg',
      scalp: octahedron([0, -1, 0], 0.3),
    } as ToWorker);
    const points: [number, number, number][] = [];
    for (let i = 0; i < 6; i++) points.push([-0.6 + i * step, 0, 0]);
    const curves = packCurves([
      {
        id: 'c1',
        type: 'stream',
        points,
        extend: true,
        viewpoint: { position: [0, 0, 5], target: [0, 0, 0] },
      },
    ]);
    await logic.handle({ ...(solve(1, 'preview') as SolveMsg), curves });
    const r = posted.find((m) => m.type === 'result');
    if (r?.type !== 'result') throw new Error(`no result: ${JSON.stringify(posted)}`);
    const c = r.constraints;
    expect(c.index.length).toBeGreaterThan(5);
    expect(c.colour.length).toBe(c.index.length);
    expect(new Set(c.colour)).toEqual(new Set([0, 1]));
    engine.dispose();
  });

  it('after a scalp mask, grows the hair a worker started with that scalp grows', async () => {
    const wasmPath = fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url));
    const wasmBinary = new Uint8Array(readFileSync(wasmPath));
    const step = 0.25;
    const setUp: ToWorker = {
      ...init,
      grid: { dims: [12, 12, 12], origin: [-1.5, -1.5, -1.5], step },
      solver: 'cg',
      scalp: octahedron([0, 0, 0], 1),
    } as ToWorker;
    const full = (id: number) => fullOverOctahedron(id, step);
    const finals = (posted: FromWorker[]) =>
      posted.filter((m): m is Extract<FromWorker, { type: 'result' }> =>
        m.type === 'result' ? m.final : false,
      );
    const upper = new Uint8Array([1, 1, 0, 0, 1, 1, 0, 0]); // the faces round (0, 1, 0)

    const engine = await loadSolverEngine({ wasmBinary });
    const posted: FromWorker[] = [];
    const logic = new WorkerLogic(engine, (m) => posted.push(m));
    await logic.handle(setUp);
    await logic.handle(full(1));
    await logic.handle({ type: 'scalpMask', scalp: upper });
    await logic.handle(full(2));
    const [all, painted] = finals(posted);

    const freshEngine = await loadSolverEngine({ wasmBinary });
    const freshPosted: FromWorker[] = [];
    const fresh = new WorkerLogic(freshEngine, (m) => freshPosted.push(m));
    const scalp = (setUp as Extract<ToWorker, { type: 'init' }>).scalp;
    await fresh.handle({ ...setUp, scalp: { ...scalp, scalp: upper } } as ToWorker);
    await fresh.handle(full(1));
    const [reference] = finals(freshPosted);

    expect(posted.filter((m) => m.type === 'error')).toEqual([]);
    // the final hair comes with its vertex attributes, as the page would build them from it
    for (const r of [all, painted]) {
      const a = r.attributes;
      if (!a) throw new Error('a final result without vertex attributes');
      const mine = lineAttributes(r.strands.points, r.strands.strandStart, 0, r.lighting?.strand);
      expect(a).toEqual(mine);
      // checked by hand too: roots at along 0, tips at 255 and 0 from the tip, tangents along the
      // segments
      const { points: P, strandStart: S } = r.strands;
      let segments = 0;
      for (let k = 0; k + 1 < S.length; k++) {
        const [i0, i1] = [S[k], S[k + 1] - 1];
        if (i1 <= i0) continue;
        segments += i1 - i0;
        expect([a.along[4 * i0], a.along[4 * i1], a.along[4 * i1 + 1]]).toEqual([0, 255, 0]);
        const d = [0, 1, 2].map((c) => P[3 * (i0 + 1) + c] - P[3 * i0 + c]);
        const t = [0, 1, 2].map((c) => a.tangent[3 * i0 + c] / 127);
        const cos = (d[0] * t[0] + d[1] * t[1] + d[2] * t[2]) / Math.hypot(...d) / Math.hypot(...t);
        expect(cos).toBeGreaterThan(0.99);
      }
      expect(a.index.length).toBe(2 * segments);
    }
    expect(posted.filter((m) => m.type === 'result' && !m.final && m.attributes)).toEqual([]);
    expect(painted.strands.points).toEqual(reference.strands.points);
    expect(painted.strands.strandStart).toEqual(reference.strands.strandStart);
    expect(painted.strands.strandStart.length).toBeLessThan(all.strands.strandStart.length);
    const s = painted.strands;
    for (let k = 0; k + 1 < s.strandStart.length; k++)
      expect(s.points[3 * s.strandStart[k] + 1]).toBeGreaterThan(-1e-3); // roots on the upper half
    engine.dispose();
    freshEngine.dispose();
  });

  it('after a grid message, grows the hair a worker started on that grid grows', async () => {
    const wasmPath = fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url));
    const wasmBinary = new Uint8Array(readFileSync(wasmPath));
    const step = 0.25;
    const small: GridSpec = { dims: [12, 12, 12], origin: [-1.5, -1.5, -1.5], step };
    const big: GridSpec = { dims: [14, 13, 12], origin: [-1.75, -1.5, -1.5], step };
    const setUp = (grid: GridSpec): ToWorker =>
      ({ ...init, grid, solver: 'fast', scalp: octahedron([0, 0, 0], 1) }) as ToWorker;
    const full = (id: number) => fullOverOctahedron(id, step);
    const final = (posted: FromWorker[]) => {
      const r = posted.filter((m) => m.type === 'result' && m.final).at(-1);
      if (r?.type !== 'result') throw new Error(`no final result: ${JSON.stringify(posted)}`);
      return r;
    };

    const engine = await loadSolverEngine({ wasmBinary });
    const posted: FromWorker[] = [];
    const logic = new WorkerLogic(engine, (m) => posted.push(m));
    await logic.handle(setUp(small));
    await logic.handle(full(1));
    await logic.handle({ type: 'grid', grid: big });
    await logic.handle(full(2));
    const moved = final(posted);

    const freshEngine = await loadSolverEngine({ wasmBinary });
    const freshPosted: FromWorker[] = [];
    const fresh = new WorkerLogic(freshEngine, (m) => freshPosted.push(m));
    await fresh.handle(setUp(big));
    await fresh.handle(full(1));
    const reference = final(freshPosted);

    expect(posted.filter((m) => m.type === 'error')).toEqual([]);
    expect(moved.id).toBe(2);
    expect(moved.strands.strandStart.length).toBeGreaterThan(10);
    expect(moved.strands.points).toEqual(reference.strands.points);
    expect(moved.strands.strandStart).toEqual(reference.strands.strandStart);
    // the constraints are on the new grid: its point indices
    expect(moved.constraints.index).toEqual(reference.constraints.index);
    engine.dispose();
    freshEngine.dispose();
  });

  it('posts the kind of a solver error: a non-finite curve point is non_finite', async () => {
    const wasmPath = fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url));
    const engine = await loadSolverEngine({ wasmBinary: new Uint8Array(readFileSync(wasmPath)) });
    const posted: FromWorker[] = [];
    const logic = new WorkerLogic(engine, (m) => posted.push(m));
    await logic.handle({
      ...init,
      grid: { dims: [6, 6, 6], origin: [0, 0, 0], step: 1 },
      solver: 'cg',
      scalp: octahedron([3, 1, 3], 0.5),
    } as ToWorker);
    expect(posted).toEqual([{ type: 'ready', gridPoints: 216, roots: 0 }]);
    const vp = { position: [0, 0, 5] as const, target: [0, 0, 0] as const };
    const curves = packCurves([
      {
        id: 'c1',
        type: 'stream',
        points: [
          [1, 1, 1],
          [2, Number.NaN, 1],
        ],
        extend: false,
        viewpoint: { position: [...vp.position], target: [...vp.target] },
      },
    ]);
    await logic.handle({ ...(solve(1, 'full') as SolveMsg), curves });
    const e = posted.find((m) => m.type === 'error');
    expect(e).toMatchObject({ type: 'error', id: 1, kind: 'non_finite' });
    engine.dispose();
  });
});
