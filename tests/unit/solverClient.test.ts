// The client's scheduling against a fake worker: full requests sent at once, previews paced one
// in flight, newest wins, results are cached by content, and a dead worker is replaced and sent
// the session again.
import { describe, expect, it } from 'vitest';
import { packCurves, packHairOptions } from '../../web/model/curveSet';
import type { HairDetail } from '../../web/model/detail';
import { DEFAULT_GROWTH, type StyleCurve } from '../../web/model/session';
import type { FromWorker, ToWorker } from '../../web/solver/protocol';
import { type InitMessage, type SolveResult, SolverClient } from '../../web/solver/solverClient';

class FakeWorker {
  sent: ToWorker[] = [];
  terminated = false;
  onmessage: ((ev: MessageEvent<FromWorker>) => void) | null = null;
  onerror: ((ev: ErrorEvent) => void) | null = null;
  postMessage(m: ToWorker) {
    this.sent.push(m);
  }
  terminate() {
    this.terminated = true;
  }
  reply(m: FromWorker) {
    this.onmessage?.({ data: m } as MessageEvent<FromWorker>);
  }
  die() {
    this.onerror?.({ message: 'RuntimeError: abort(OOM)', preventDefault() {} } as ErrorEvent);
  }
  solves() {
    return this.sent.filter((m): m is Extract<ToWorker, { type: 'solve' }> => m.type === 'solve');
  }
}

const init: InitMessage = {
  type: 'init',
  grid: { dims: [2, 2, 2], origin: [0, 0, 0], step: 1 },
  omega: 100,
  solver: 'cg',
  scalp: {
    positions: new Float32Array(),
    indices: new Uint32Array(),
    scalp: new Uint8Array(),
    center: [0, 0, 0],
  },
};

const streams = (n: number) =>
  Array.from(
    { length: n },
    (_, i): StyleCurve => ({
      id: `c${i}`,
      type: 'stream',
      points: [
        [i, 0, 0],
        [i, 1, 0],
      ],
      extend: true,
      viewpoint: { position: [0, 0, 5], target: [0, 0, 0] },
    }),
  );
const curves = (n: number) => packCurves(streams(n));
/** The solve options of n curves: avoid scalp off and no detail unless given. */
const opts = (n: number, s: { avoidScalp?: boolean; detail?: HairDetail } = {}) =>
  packHairOptions(s, streams(n));

const result = (id: number, final = true): SolveResult => ({
  type: 'result',
  id,
  strands: { points: new Float32Array([id, 0, 0]), strandStart: new Uint32Array([0, 1]) },
  constraints: { index: new Int32Array(), target: new Float32Array(), colour: new Uint8Array() },
  field: null,
  final,
  stats: {
    method: 'cg',
    iterations: 0,
    errorEstimate: 0,
    constraints: 0,
    added: 0,
    removed: 0,
    changed: 0,
    setupMs: 0,
    solveMs: 0,
    growMs: 0,
    heapBytes: 0,
  },
});

/** A head of four triangles (the tests only count them), scalp everywhere. */
const fourTriangles = (scalp = new Uint8Array([1, 1, 1, 1])): InitMessage['scalp'] => ({
  positions: new Float32Array(18),
  indices: new Uint32Array([0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5]),
  scalp,
  center: [0, 0, 0],
});

function setup(initMessage: InitMessage = init) {
  const workers: FakeWorker[] = [];
  const shown: Array<{ id: number; cached: boolean }> = [];
  const errors: string[] = [];
  const kinds: string[] = [];
  const client = new SolverClient(
    () => {
      const w = new FakeWorker();
      workers.push(w);
      return w as unknown as Worker;
    },
    initMessage,
    {
      onBusy() {},
      onResult: (r, _latest, cached) => shown.push({ id: r.id, cached }),
      onError: (m, _restarting, kind) => {
        errors.push(m);
        kinds.push(kind);
      },
      onIdle() {},
    },
  );
  return { client, workers, shown, errors, kinds };
}

describe('SolverClient', () => {
  it('sends requests at once and shows only the newest, first look then final', () => {
    const { client, workers, shown } = setup();
    const w = workers[0];
    expect(w.sent[0].type).toBe('init');
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    expect(w.solves()).toHaveLength(0); // not ready yet: sent on ready
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    expect(w.solves()).toHaveLength(1);
    client.request({ curves: curves(2), growth: DEFAULT_GROWTH, options: opts(2) });
    client.request({ curves: curves(3), growth: DEFAULT_GROWTH, options: opts(3) });
    expect(w.solves()).toHaveLength(3); // the worker supersedes; the client does not queue
    const [a, , c] = w.solves();
    w.reply(result(a.id, false));
    w.reply(result(a.id, true));
    expect(shown).toEqual([]); // superseded answers are never shown
    w.reply(result(c.id, false));
    expect(shown.map((s) => s.id)).toEqual([c.id]);
    expect(client.pending).toBe(true); // a first look: the final answer is still due
    w.reply(result(c.id, true));
    expect(shown.map((s) => s.id)).toEqual([c.id, c.id]);
    expect(client.pending).toBe(false);
  });

  it('treats a preview answer as complete and never caches it', () => {
    const { client, workers, shown } = setup();
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }, 'preview');
    expect(w.solves()[0].mode).toBe('preview');
    w.reply(result(w.solves()[0].id, false));
    expect(client.pending).toBe(false);
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }, 'full');
    expect(w.solves()).toHaveLength(2); // not answered from a cache
    expect(shown).toHaveLength(1);
  });

  it('keeps one preview in flight and sends the newest waiting one when it is answered', () => {
    const { client, workers, shown } = setup();
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }, 'preview');
    client.request({ curves: curves(2), growth: DEFAULT_GROWTH, options: opts(2) }, 'preview');
    client.request({ curves: curves(3), growth: DEFAULT_GROWTH, options: opts(3) }, 'preview');
    expect(w.solves()).toHaveLength(1); // the drag does not queue solves in the worker
    const first = w.solves()[0];
    w.reply(result(first.id, false));
    // The answer is newer than the screen: shown, and the newest waiting preview goes out.
    expect(shown.map((s) => s.id)).toEqual([first.id]);
    expect(w.solves()).toHaveLength(2);
    expect(w.solves()[1].curves.curveStart).toEqual(curves(3).curveStart);
    expect(client.pending).toBe(true);
    w.reply(result(w.solves()[1].id, false));
    expect(client.pending).toBe(false);
  });

  it('a preview that errors does not hold up the previews after it', () => {
    const { client, workers } = setup();
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }, 'preview');
    client.request({ curves: curves(2), growth: DEFAULT_GROWTH, options: opts(2) }, 'preview');
    expect(w.solves()).toHaveLength(1);
    w.reply({ type: 'error', id: w.solves()[0].id, message: 'bad curve', kind: 'invalid_input' });
    // the waiting preview goes out, and so does the next one once that is answered
    expect(w.solves()).toHaveLength(2);
    w.reply(result(w.solves()[1].id, false));
    client.request({ curves: curves(3), growth: DEFAULT_GROWTH, options: opts(3) }, 'preview');
    expect(w.solves()).toHaveLength(3);
  });

  it('never shows an answer older than the newest full request', () => {
    const { client, workers, shown } = setup();
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }, 'preview');
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }, 'full'); // pointer-up: sent at once
    expect(w.solves().map((m) => m.mode)).toEqual(['preview', 'full']);
    const [p, f] = w.solves();
    w.reply(result(p.id, false)); // late preview answer
    expect(shown).toEqual([]);
    w.reply(result(f.id, false));
    w.reply(result(f.id, true));
    expect(shown.map((s) => s.id)).toEqual([f.id, f.id]);
    // A preview after the full request is sent at once (nothing in flight), its answer shown.
    client.request({ curves: curves(2), growth: DEFAULT_GROWTH, options: opts(2) }, 'preview');
    expect(w.solves()).toHaveLength(3);
  });

  it('answers a repeated state from its cache without the worker', () => {
    const { client, workers, shown } = setup();
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    w.reply(result(w.solves()[0].id));
    client.request({ curves: curves(2), growth: DEFAULT_GROWTH, options: opts(2) });
    w.reply(result(w.solves()[1].id));
    expect(client.pending).toBe(false);
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }); // undo
    expect(w.solves()).toHaveLength(2);
    expect(shown.at(-1)).toEqual({ id: w.solves()[0].id, cached: true });
  });

  it('asks for the field only while wanted, and does not answer a field request from a cache without it', () => {
    const { client, workers, shown } = setup();
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    expect(w.solves()[0].wantField).toBe(false);
    w.reply(result(w.solves()[0].id));
    client.wantField = true;
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }); // same state, but the cached answer has no field
    expect(w.solves()).toHaveLength(2);
    expect(w.solves()[1].wantField).toBe(true);
    w.reply({ ...result(w.solves()[1].id), field: { vectors: new Float32Array(24) } });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }); // now cached with its field
    expect(w.solves()).toHaveLength(2);
    expect(shown.at(-1)).toEqual({ id: w.solves()[1].id, cached: true });
    client.wantField = false;
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }); // a field in the cache does no harm
    expect(w.solves()).toHaveLength(2);
  });

  it('restarts a dead worker and re-sends the newest state', () => {
    const { client, workers, errors } = setup();
    workers[0].reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(2), growth: DEFAULT_GROWTH, options: opts(2) });
    workers[0].die();
    expect(workers[0].terminated).toBe(true);
    expect(errors[0]).toMatch(/restarting/);
    expect(workers).toHaveLength(2);
    const w = workers[1];
    expect(w.sent[0].type).toBe('init');
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    expect(w.solves()).toHaveLength(1);
    expect(w.solves()[0].curves.curveStart.length).toBe(3);
  });

  it('moves to another grid in place: the worker is sent the grid, then the request; the cache is dropped', () => {
    const { client, workers } = setup();
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    w.reply(result(w.solves()[0].id));
    const bigger = {
      dims: [2, 3, 2] as [number, number, number],
      origin: [0, -1, 0] as [number, number, number],
      step: 1,
    };
    client.setGrid(bigger);
    expect(client.grid).toEqual(bigger);
    // no new worker: the grid goes to the one there is
    expect(workers).toHaveLength(1);
    expect(w.terminated).toBe(false);
    expect(w.sent.at(-1)).toEqual({ type: 'grid', grid: bigger });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }); // the same state: not from the old grid's cache
    expect(w.solves()).toHaveLength(2);
    expect(w.sent.at(-1)).toMatchObject({ type: 'solve' });
    expect(client.pending).toBe(true);
    // a worker that dies later is replaced by one set up on the new grid
    w.die();
    expect(workers).toHaveLength(2);
    expect(workers[1].sent[0]).toMatchObject({ type: 'init', grid: bigger });
  });

  it('a result cached for one scalp mask is not shown for another; going back to it is', () => {
    const { client, workers, shown } = setup({ ...init, scalp: fourTriangles() });
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    const onA = w.solves()[0].id;
    w.reply(result(onA));
    const maskB = new Uint8Array([1, 0, 0, 1]);
    client.setScalpMask(maskB);
    // the worker is sent the mask and kept (no restart, no new init)
    expect(workers).toHaveLength(1);
    expect(w.sent.at(-1)).toEqual({ type: 'scalpMask', scalp: maskB });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }); // same curves, other scalp
    expect(w.solves()).toHaveLength(2);
    expect(shown.at(-1)).toEqual({ id: onA, cached: false });
    const onB = w.solves()[1].id;
    w.reply(result(onB));
    expect(shown.at(-1)).toEqual({ id: onB, cached: false });
    // back to the first mask (an undo): its hair from the cache, without the worker
    client.setScalpMask(new Uint8Array([1, 1, 1, 1]));
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    expect(w.solves()).toHaveLength(2);
    expect(shown.at(-1)).toEqual({ id: onA, cached: true });
    client.setScalpMask(maskB);
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    expect(shown.at(-1)).toEqual({ id: onB, cached: true });
  });

  it('never caches a result asked for before the scalp changed (the worker may have grown it on either)', () => {
    const { client, workers, shown } = setup({ ...init, scalp: fourTriangles() });
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    client.setScalpMask(new Uint8Array([0, 1, 0, 1]));
    client.setScalpMask(new Uint8Array([1, 1, 1, 1])); // back, before the answer came
    w.reply(result(w.solves()[0].id));
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    expect(w.solves()).toHaveLength(2); // asked again, not answered from the cache
    expect(shown.every((s) => !s.cached)).toBe(true);
  });

  it('a restart sends the scalp mask in force with the head; a mask of the wrong length changes nothing', () => {
    const { client, workers, errors, kinds } = setup({ ...init, scalp: fourTriangles() });
    workers[0].reply({ type: 'ready', gridPoints: 8, roots: 0 });
    const mask = new Uint8Array([0, 0, 1, 1]);
    client.setScalpMask(mask);
    const sent = workers[0].sent.length;
    client.setScalpMask(new Uint8Array(5));
    expect(workers[0].sent).toHaveLength(sent);
    expect(errors.at(-1)).toMatch(/5 triangles for a head of 4/);
    expect(kinds.at(-1)).toBe('invalid_input');
    workers[0].die();
    expect(workers[1].sent[0]).toMatchObject({ type: 'init', scalp: { scalp: mask } });
  });

  it('setHead restarts the worker with the new head (and grid), drops the cache and solves the open request', () => {
    const { client, workers } = setup({ ...init, scalp: fourTriangles() });
    workers[0].reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    workers[0].reply(result(workers[0].solves()[0].id));
    const head = fourTriangles(new Uint8Array([1, 1, 1, 1]));
    head.positions[0] = 0.5; // another head with the same scalp mask
    const grid = {
      dims: [3, 3, 3] as [number, number, number],
      origin: [-1, -1, -1] as [number, number, number],
      step: 1,
    };
    client.setHead(head, grid);
    expect(workers[0].terminated).toBe(true);
    expect(workers).toHaveLength(2);
    const w = workers[1];
    expect(w.sent).toHaveLength(1);
    expect(w.sent[0]).toEqual({ ...init, grid, scalp: head });
    expect(client.grid).toEqual(grid);
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) }); // same state: not from the old head's cache
    expect(w.solves()).toHaveLength(0); // waits for the new worker
    w.reply({ type: 'ready', gridPoints: 27, roots: 0 });
    expect(w.solves()).toHaveLength(1);
    // the grid stays when none is given; masks are now checked against the new head
    client.setHead(fourTriangles(new Uint8Array(4)));
    expect(workers[2].sent[0]).toMatchObject({ type: 'init', grid });
  });

  it('gives up after repeated deaths with a message that keeps the session', () => {
    const { workers, errors } = setup();
    for (let i = 0; i < 4; i++) workers[workers.length - 1].die();
    expect(workers).toHaveLength(4);
    expect(errors.at(-1)).toMatch(/reload the page/);
  });

  it("passes the worker's error kind on", () => {
    const { client, workers, errors, kinds } = setup();
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    const id = w.solves()[0].id;
    w.reply({ type: 'error', id, message: 'exact: over the cap', kind: 'over_memory_cap' });
    expect(errors).toEqual(['exact: over the cap']);
    expect(kinds).toEqual(['over_memory_cap']);
    w.die();
    expect(kinds.at(-1)).toBe('internal');
  });

  it('sends the solve options (avoid scalp, detail groups) with each request, and again after a restart', () => {
    const { client, workers } = setup();
    workers[0].reply({ type: 'ready', gridPoints: 8, roots: 0 });
    const o = opts(2, { avoidScalp: true, detail: { lengthJitter: 0.4 } });
    client.request({ curves: curves(2), growth: DEFAULT_GROWTH, options: o });
    const sent = workers[0].solves()[0].options;
    expect(sent.avoidScalp).toBe(true);
    expect(sent.detail.groups[13]).toBe(0.4); // group 0's lengthJitter
    expect(Array.from(sent.detail.curveGroup)).toEqual([0, 0]);
    workers[0].die();
    workers[1].reply({ type: 'ready', gridPoints: 8, roots: 0 });
    expect(workers[1].solves()[0].options).toEqual(o);
  });

  it('a cached answer is for the same options only: avoid scalp and detail are part of the state', () => {
    const { client, workers, shown } = setup();
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    w.reply(result(w.solves()[0].id));
    client.request({
      curves: curves(1),
      growth: DEFAULT_GROWTH,
      options: opts(1, { avoidScalp: true }),
    });
    expect(w.solves()).toHaveLength(2); // the same curves with avoid scalp: solved again
    expect(w.solves()[1].options.avoidScalp).toBe(true);
    w.reply(result(w.solves()[1].id));
    client.request({
      curves: curves(1),
      growth: DEFAULT_GROWTH,
      options: opts(1, { detail: { lengthJitter: 0.2 } }),
    });
    expect(w.solves()).toHaveLength(3); // another detail: grown again
    w.reply(result(w.solves()[2].id));
    client.request({
      curves: curves(1),
      growth: DEFAULT_GROWTH,
      options: opts(1, { detail: { lengthJitter: 0.3 } }),
    });
    expect(w.solves()).toHaveLength(4);
    w.reply(result(w.solves()[3].id));
    // undo back to avoid scalp off: from the cache
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    expect(w.solves()).toHaveLength(4);
    expect(shown.at(-1)).toEqual({ id: w.solves()[0].id, cached: true });
    client.request({
      curves: curves(1),
      growth: DEFAULT_GROWTH,
      options: opts(1, { avoidScalp: true }),
    });
    expect(w.solves()).toHaveLength(4);
    expect(shown.at(-1)).toEqual({ id: w.solves()[1].id, cached: true });
  });

  it('sends the light strand cap with each request (none of its own unless the caller names one)', () => {
    const { client, workers } = setup();
    const w = workers[0];
    w.reply({ type: 'ready', gridPoints: 8, roots: 0 });
    client.request({ curves: curves(1), growth: DEFAULT_GROWTH, options: opts(1) });
    client.request({ curves: curves(2), growth: DEFAULT_GROWTH, options: opts(2) }, 'full', 900);
    client.request({ curves: curves(3), growth: DEFAULT_GROWTH, options: opts(3) }, 'preview', 450);
    expect(w.solves().map((m) => [m.mode, m.lightMaxStrands])).toEqual([
      ['full', 0],
      ['full', 900],
      ['preview', 450],
    ]);
  });
});
