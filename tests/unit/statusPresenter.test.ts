// The status line's words and progress, without a browser: progress never goes backwards within
// one solve (the worker reports a first look at 95 % and then solve fractions from 5 %), solver
// internals stay in the tooltip, a bald head reports no strands, and an over-cap error says what
// to do.
import { describe, expect, it } from 'vitest';
import { visibleStrands } from '../../web/app/hairPresenter';
import { StatusPresenter } from '../../web/app/statusPresenter';
import type { EditorChange } from '../../web/editor/editor';
import type { SolveResult } from '../../web/solver/solverClient';
import { StatusLine } from '../../web/ui/status';

function fakeElement() {
  return { dataset: {} as Record<string, string>, textContent: '', title: '' };
}

function setup(pending = { now: true }, drawing = { now: false }) {
  const el = fakeElement();
  const line = new StatusLine(
    el as unknown as HTMLElement,
    fakeElement() as unknown as HTMLElement,
  );
  const p = new StatusPresenter(line, {
    get pending() {
      return pending.now;
    },
    get previewing() {
      return drawing.now;
    },
  });
  return { el, line, p, pending, drawing };
}

const percent = (text: string) => Number(/(\d+) %/.exec(text)?.[1] ?? Number.NaN);

const result = (strands: number): SolveResult =>
  ({
    type: 'result',
    id: 1,
    final: true,
    strands: { points: new Float32Array(0), strandStart: new Uint32Array(strands + 1) },
    constraints: {
      index: new Int32Array(0),
      target: new Float32Array(0),
      colour: new Uint8Array(0),
    },
    field: null,
    stats: {
      method: 'mg-pcg',
      iterations: 40,
      errorEstimate: 1e-7,
      constraints: 1234,
      added: 0,
      removed: 0,
      changed: 0,
      setupMs: 1,
      solveMs: 250,
      growMs: 30,
      heapBytes: 0,
    },
  }) as SolveResult;

describe('StatusPresenter', () => {
  it('progress never counts down through a first look and the slices after it', () => {
    const { el, p } = setup();
    // the worker's sequence for one full solve on a large grid
    const seq: Array<['solving' | 'growing', number]> = [
      ['solving', 0],
      ['solving', 0.05],
      ['growing', 0.95], // the first look's growth
    ];
    const shown: number[] = [];
    for (const [ph, f] of seq) {
      p.busy(ph, f, false);
      shown.push(percent(el.textContent));
    }
    p.result({ ...result(100), final: false } as SolveResult, false); // the first look
    for (const f of [0.05, 0.2, 0.4, 0.38, 0.7, 0.95]) {
      p.busy('solving', f, false);
      shown.push(percent(el.textContent));
    }
    p.busy('growing', 0.95, false);
    shown.push(percent(el.textContent));
    for (let i = 1; i < shown.length; i++) expect(shown[i]).toBeGreaterThanOrEqual(shown[i - 1]);
    expect(shown.at(-1)).toBe(95);
    expect(el.textContent).toContain('Growing the hair');
  });

  it('says Ready with the strand count in plain words; solver internals go to the tooltip', () => {
    const { el, line, p, pending } = setup();
    line.counts(30000, 10);
    p.result(result(30000), true);
    pending.now = false;
    p.ready();
    expect(el.dataset.state).toBe('ready');
    expect(el.textContent).toBe('Ready — 30,000 strands');
    expect(el.title).toContain('mg-pcg, 40 iterations');
    expect(el.textContent).not.toContain('mg-pcg');
  });

  it("says a stroke's preview is one while drawing, and Ready once the stroke ends", () => {
    const { el, line, p, pending, drawing } = setup();
    pending.now = false;
    drawing.now = true;
    line.counts(800, 3);
    p.result({ ...result(800), final: false } as SolveResult, false);
    p.ready();
    expect(el.dataset.state).toBe('ready');
    expect(el.textContent).toBe('Preview — 800 strands; release to grow all');
    drawing.now = false;
    line.counts(30000, 3);
    p.ready();
    expect(el.textContent).toBe('Ready — 30,000 strands');
  });

  it('says Solving as soon as an edit that asked for a solve is counted, before any progress', () => {
    const { el, line, p, pending, drawing } = setup();
    // a stroke's preview is on screen and the worker is idle
    pending.now = false;
    drawing.now = true;
    line.counts(800, 3);
    p.ready();
    expect(el.dataset.state).toBe('ready');
    // pointer-up: the bridge (which hears first) has asked for the new curve's solve
    drawing.now = false;
    pending.now = true;
    const session = { curves: [{}, {}, {}, {}] } as unknown as EditorChange['session'];
    p.editorChanged({
      cause: 'command',
      sessionChanged: true,
      session,
      message: 'Added a curve',
    } as EditorChange);
    expect(el.dataset.curves).toBe('4');
    expect(el.dataset.state).toBe('solving');
    expect(el.textContent).toBe('Solving… 0 % · Added a curve');
    // an edit that needs no solve (the hair came from the cache) stays Ready
    pending.now = false;
    p.ready();
    p.editorChanged({
      cause: 'command',
      sessionChanged: true,
      session,
      message: 'Undone',
    } as EditorChange);
    expect(el.dataset.state).toBe('ready');
  });

  it('does not report strands on a bald head', () => {
    const { el, line, p, pending } = setup();
    pending.now = false;
    line.counts(0, 0);
    p.ready();
    expect(el.textContent).toContain('no hair yet');
    line.counts(0, 2);
    p.ready();
    expect(el.textContent).not.toMatch(/\d strands/);
  });

  it('is not Ready while work is pending', () => {
    const { el, p } = setup();
    p.busy('solving', 0.3, false);
    p.ready();
    expect(el.dataset.state).toBe('solving');
  });

  it('an over-cap error says what to do', () => {
    const { el, p } = setup();
    p.solverError('the factor needs 3 GB', 'over_memory_cap', false);
    expect(el.dataset.state).toBe('error');
    expect(el.textContent).toContain('solver=fast');
    p.solverError('bad input', 'invalid_input', false);
    expect(el.textContent).not.toContain('solver=fast');
    // the fast solver over the cap: the volume (long hair grows it) is what to shrink
    p.solverError(
      'fast solver: over the memory cap (needs ~2300 MB, cap 1900 MB)',
      'over_memory_cap',
      false,
    );
    expect(el.textContent).toContain('shorter Max length');
    expect(el.textContent).not.toContain('solver=fast');
    p.solverError('grow: too many strand points', 'over_memory_cap', false);
    expect(el.textContent).toContain('fewer strands');
  });

  it('the tooltip says how many grid points the bounding volume has', () => {
    const el = fakeElement();
    const line = new StatusLine(
      el as unknown as HTMLElement,
      fakeElement() as unknown as HTMLElement,
    );
    const p = new StatusPresenter(line, {
      pending: false,
      previewing: false,
      grid: { dims: [33, 65, 33], origin: [0, 0, 0], step: 0.1267 },
    });
    p.result(result(100), true);
    line.counts(100, 1);
    p.ready();
    expect(el.title).toContain('bounding volume 70,785 grid points (33 × 65 × 33');
    expect(el.textContent).not.toContain('grid points');
  });

  it('counts only strands that grew a segment (a bald head grows one-point strands)', () => {
    const points = new Float32Array(3 * 7);
    // three roots that grew nothing, one strand of 3 points, one of 1 point
    expect(visibleStrands({ points, strandStart: new Uint32Array([0, 1, 2, 3, 6, 7]) })).toBe(1);
    expect(visibleStrands({ points, strandStart: new Uint32Array([0]) })).toBe(0);
  });
});
