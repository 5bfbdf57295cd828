// growSessionHair: the one pipeline of the browser's export and `hairsketch grow`. The same
// session, grid, solver and cap give byte-identical strands on fresh engines; the cap overrides
// the session's; the hair equals the converged hair the app's worker shows for the same session.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { growSessionHair } from '../../web/export/growSession';
import { Head } from '../../web/head/head';
import { packCurves, packHairOptions } from '../../web/model/curveSet';
import { gridForPreset } from '../../web/model/grid';
import type { GridSpec, StrandArrays } from '../../web/model/hairArrays';
import { NEW_SESSION_DETAIL } from '../../web/model/presetDetail';
import type { SessionState } from '../../web/model/session';
import type { SolverEngine } from '../../web/solver/engine';
import type { FromWorker } from '../../web/solver/protocol';
import { loadSolverEngine } from '../../web/solver/wasmEngine';
import { DEFAULT_SCHEDULER, WorkerLogic } from '../../web/worker/workerLogic';

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

/** Avoid scalp on, the curly preset's session-wide detail, and a curve with its own. */
const curly = presetSession('curly', head, '25k', 0);
const styled: SessionState = {
  ...curly,
  avoidScalp: true,
  curves: curly.curves.map((c, i) =>
    i === 2 ? { ...c, detail: { frizz: { distance: 0.02, shape: 0 }, lengthJitter: 0.4 } } : c,
  ),
};

/** Grows on a fresh engine. */
async function grow(
  solver: 'fast' | 'exact',
  maxStrands?: number,
  s: SessionState = session,
  on: GridSpec = grid,
) {
  const engine = await loadSolverEngine({ wasmBinary });
  try {
    const phases: string[] = [];
    const hair = growSessionHair(engine, s, head.scalpMesh(), {
      grid: on,
      solver,
      maxStrands,
      onProgress: (phase, f) => phases.push(`${phase}:${f}`),
    });
    return { hair, phases };
  } finally {
    engine.dispose();
  }
}

/** One engine for the file's other growths, as the app's worker keeps one: the request runner
 *  sets up the head once and grows from the field it holds when only growth or detail changed,
 *  so a session grown again costs its growth alone. The first test checks it grows what a fresh
 *  engine grows. */
let shared: SolverEngine | null = null;
const scalp = head.scalpMesh();
afterAll(() => shared?.dispose());
async function growShared(maxStrands: number | undefined, s: SessionState = session) {
  shared ??= await loadSolverEngine({ wasmBinary });
  return growSessionHair(shared, s, scalp, { grid, solver: 'fast', maxStrands });
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
    // a used engine grows the same bytes: after another session with another field (avoid
    // scalp), another detail (kept field) and another cap
    await growShared(500, { ...styled });
    await growShared(800, curly);
    const again = await growShared(3000);
    expect(bytes(again.strands.points).equals(bytes(a.hair.strands.points))).toBe(true);
    expect(again.iterations).toBe(a.hair.iterations);
  });

  it('caps strands by maxStrands when given, else by the session (0 = every root)', async () => {
    const capped = await growShared(500);
    expect(strandCount(capped.strands)).toBe(500);
    const all = await growShared(undefined);
    expect(strandCount(all.strands)).toBeGreaterThan(10_000);
  });

  /** The final hair the app's worker shows for `s` (2,000 strands). */
  async function workerHair(s: SessionState): Promise<StrandArrays> {
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
      curves: packCurves(s.curves),
      growth: { ...s.growth, maxStrands: 2000 },
      options: packHairOptions(s, s.curves),
      wantField: false,
      mode: 'full',
      lightMaxStrands: 500,
    });
    engine.dispose();
    const final = results.find((m) => m.type === 'result' && m.final);
    if (final?.type !== 'result') throw new Error('the worker sent no final result');
    return final.strands;
  }

  for (const [label, s] of [
    ['the default session', session],
    ['avoid scalp on, detail of the session and of a curve', styled],
  ] as const)
    it(`equals the converged hair of the app's worker for the same session: ${label}`, async () => {
      const final = await workerHair(s);
      const mine = await growShared(2000, s);
      expect(strandCount(mine.strands)).toBe(2000);
      expect(bytes(mine.strands.points).equals(bytes(final.points))).toBe(true);
      expect(bytes(mine.strands.strandStart).equals(bytes(final.strandStart))).toBe(true);
    });

  it('avoid scalp, the session detail and a curve detail each change the hair', async () => {
    const points = async (s: SessionState) => bytes((await growShared(2000, s)).strands.points);
    const plain = await points(session);
    const avoiding = await points({ ...session, avoidScalp: true });
    expect(avoiding.equals(plain)).toBe(false);
    const { avoidScalp: _, ...noAvoid } = styled;
    const withDetail = await points(curly);
    expect(withDetail.equals(plain)).toBe(false); // curly: the default curves with a detail
    const withOwn = await points(noAvoid);
    expect(withOwn.equals(withDetail)).toBe(false);
  });

  it("flyaways: a block that is off changes no bit (a session saved before them keeps its hair); on, the new session's detail moves strands", async () => {
    const points = async (s: SessionState) => bytes((await growShared(2000, s)).strands.points);
    const before = await points(curly);
    const off = { share: 0, distance: 0.15, start: 0.5 };
    expect(
      (await points({ ...curly, detail: { ...curly.detail, flyaway: off } })).equals(before),
    ).toBe(true);
    const on = { ...curly, detail: { ...curly.detail, flyaway: { ...off, share: 0.05 } } };
    expect((await points(on)).equals(before)).toBe(false);
    const { detail: _detail, ...smooth } = session;
    const natural = await points({ ...smooth, detail: NEW_SESSION_DETAIL });
    expect(natural.equals(await points(smooth))).toBe(false);
  });

  it('keeps every grown point after the root outside the head, with and without detail', async () => {
    for (const [label, s] of [
      ['default', session],
      ['default, avoid scalp', { ...session, avoidScalp: true }],
      ['curly', curly],
      ['styled', styled],
      // a new session's detail, with more (and farther) flyaways than it has
      [
        'natural',
        {
          ...session,
          detail: { ...NEW_SESSION_DETAIL, flyaway: { share: 0.2, distance: 0.5, start: 0.2 } },
        },
      ],
    ] as const) {
      const { strands } = await growShared(2000, s);
      const P = strands.points;
      let inside = 0;
      let deepest = 0;
      for (let i = 0; i < strandCount(strands); i++)
        for (let k = strands.strandStart[i] + 1; k < strands.strandStart[i + 1]; k++) {
          const d = head.signedDistance([P[3 * k], P[3 * k + 1], P[3 * k + 2]]);
          if (d < 0) inside++;
          deepest = Math.min(deepest, d);
        }
      expect({ label, inside, deepest }).toEqual({ label, inside: 0, deepest: 0 });
    }
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
        curves: packCurves(curves),
        growth,
        options: packHairOptions(session, curves),
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
    const mine = await growShared(2000);
    expect(bytes(mine.strands.points).equals(bytes(final.strands.points))).toBe(true);
  });

  it('exact solver: deterministic too', async () => {
    // on a grid of half the resolution (an eighth of the points): the exact factor at 25k costs
    // tens of seconds and determinism does not depend on the grid's size
    const coarse: GridSpec = {
      dims: grid.dims.map((d) => Math.ceil(d / 2)) as GridSpec['dims'],
      origin: grid.origin,
      step: 2 * grid.step,
    };
    const a = await grow('exact', 1000, session, coarse);
    const b = await grow('exact', 1000, session, coarse);
    expect(bytes(a.hair.strands.points).equals(bytes(b.hair.strands.points))).toBe(true);
    expect(strandCount(a.hair.strands)).toBe(1000);
  });
});
