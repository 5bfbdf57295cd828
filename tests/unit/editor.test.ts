// The editor without a browser: each command, undo/redo of each, the selection rules, the one
// load path, and one notification per change.
import { describe, expect, it } from 'vitest';
import type { Command } from '../../web/editor/commands';
import { Editor, type EditorChange } from '../../web/editor/editor';
import { POSITION_SCALE, quantize } from '../../web/model/gridNumbers';
import { STROKE_KINDS } from '../../web/model/kinds';
import { ONE_STROKE_RADIUS } from '../../web/model/ponytailFromSpine';
import {
  emptySession,
  type SessionState,
  type StreamCurve,
  type Viewpoint,
} from '../../web/model/session';
import type { Vec3 } from '../../web/model/vec3';

const vp: Viewpoint = { position: [0, 0, 7], target: [0, 0, 0] };
const line = (x: number, n = 6): Vec3[] =>
  Array.from({ length: n }, (_, i) => [x, 1 - 0.1 * i, 0.5] as Vec3);

const addStream = (x: number): Command => ({
  kind: 'addCurve',
  curve: { type: 'stream', points: line(x), extend: true, viewpoint: vp },
  what: 'stream curve {id}',
});
const addDividing = (): Command => ({
  kind: 'addCurve',
  curve: {
    type: 'dividing',
    points: line(0.2),
    normals: line(0.2).map(() => [0, 1, 0] as Vec3),
    sigma: 1,
    h: 0.5,
    alpha0: 0,
    alpha1: 0,
    viewpoint: vp,
  },
  what: 'dividing curve {id}',
});

function editorWithLog(s: SessionState = emptySession('25k'), clock = { t: 0 }) {
  const e = new Editor(s, 'stream', () => clock.t);
  const log: EditorChange[] = [];
  e.listen((c) => log.push(c));
  return { e, log, clock };
}

/** Runs `cmd` on an editor holding `setup`, checks it changed the session, then that undo
 *  restores the exact session before and redo the exact session after. */
function roundTrip(setup: Command[], cmd: Command, check: (after: SessionState) => void) {
  const { e } = editorWithLog();
  for (const c of setup) e.run(c);
  const before = e.session;
  expect(e.run(cmd)).toBe(true);
  const after = e.session;
  expect(after).not.toBe(before);
  check(after);
  expect(e.undo()).toBe(true);
  expect(e.session).toBe(before);
  expect(e.redo()).toBe(true);
  expect(e.session).toBe(after);
}

describe('editor commands, each undoable', () => {
  it('addCurve assigns the next id and selects the new curve', () => {
    const { e } = editorWithLog();
    e.run(addStream(0));
    e.run(addStream(0.1));
    expect(e.session.curves.map((c) => c.id)).toEqual(['c1', 'c2']);
    expect(e.selectedId).toBe('c2');
    roundTrip([], addStream(0), (s) => expect(s.curves).toHaveLength(1));
  });

  it('deleteCurve removes it and clears the selection', () => {
    const { e } = editorWithLog();
    e.run(addStream(0));
    e.run({ kind: 'deleteCurve', id: 'c1' });
    expect(e.session.curves).toHaveLength(0);
    expect(e.selectedId).toBeNull();
    // undo brings the curve back; the selection is not restored by undo (no curve was chosen)
    e.undo();
    expect(e.session.curves.map((c) => c.id)).toEqual(['c1']);
    roundTrip([addStream(0)], { kind: 'deleteCurve', id: 'c1' }, (s) =>
      expect(s.curves).toHaveLength(0),
    );
  });

  it('deleting a curve that does not exist records nothing', () => {
    const { e, log } = editorWithLog();
    expect(e.run({ kind: 'deleteCurve', id: 'c9' })).toBe(false);
    expect(e.canUndo).toBe(false);
    expect(log).toHaveLength(1);
    expect(log[0].sessionChanged).toBe(false);
  });

  it('hintEdit replaces the points of a stream curve', () => {
    const pts = line(0.3, 9);
    // the editor keeps every point on the grid of model/quantize.ts
    const onGrid = pts.map((p) => p.map((x) => quantize(x, POSITION_SCALE)));
    roundTrip([addStream(0)], { kind: 'hintEdit', id: 'c1', op: 'insert', points: pts }, (s) =>
      expect(s.curves[0].points).toEqual(onGrid),
    );
  });

  it('setTilt sets one end of a dividing curve', () => {
    roundTrip(
      [addDividing()],
      { kind: 'setTilt', id: 'c1', end: 'alpha1', alpha: 0.5, side: 1 },
      (s) => {
        const c = s.curves[0];
        expect(c.type === 'dividing' && [c.alpha0, c.alpha1]).toEqual([0, 0.5]);
      },
    );
  });

  it('patchCurve changes only parameters the curve has, with their types', () => {
    roundTrip([addDividing()], { kind: 'patchCurve', id: 'c1', patch: { sigma: 2 } }, (s) => {
      const c = s.curves[0];
      expect(c.type === 'dividing' && c.sigma).toBe(2);
    });
    const { e } = editorWithLog();
    e.run(addStream(0));
    // a stream curve has no sigma; extend is boolean: a number does not replace it
    expect(e.run({ kind: 'patchCurve', id: 'c1', patch: { sigma: 2, extend: 1 } })).toBe(false);
    expect(e.run({ kind: 'patchCurve', id: 'c1', patch: { extend: false } })).toBe(true);
    // a parameter outside its range (protocol.ts CURVE_PARAMS) is refused with a message
    const d = editorWithLog();
    d.e.run(addDividing());
    expect(d.e.run({ kind: 'patchCurve', id: 'c1', patch: { sigma: 1e9 } })).toBe(false);
    expect(d.log.at(-1)?.message).toContain('must be a number from');
    expect(d.e.run({ kind: 'patchCurve', id: 'c1', patch: { h: Number.NaN } })).toBe(false);
    expect((e.session.curves[0] as StreamCurve).extend).toBe(false);
  });

  it('setViewpoint, setSurfaceMode, setAvoidScalp, setHairColor', () => {
    const other: Viewpoint = { position: [5, 0, 0], target: [0, 0, 0] };
    roundTrip([addStream(0)], { kind: 'setViewpoint', id: 'c1', viewpoint: other }, (s) =>
      expect(s.curves[0].viewpoint).toEqual(other),
    );
    roundTrip([addStream(0)], { kind: 'setSurfaceMode', id: 'c1', mode: 'strip' }, (s) =>
      expect((s.curves[0] as StreamCurve).surfaceMode).toBe('strip'),
    );
    roundTrip([], { kind: 'setAvoidScalp', on: true }, (s) => expect(s.avoidScalp).toBe(true));
    roundTrip([{ kind: 'setAvoidScalp', on: true }], { kind: 'setAvoidScalp', on: false }, (s) =>
      expect(Object.keys(s)).not.toContain('avoidScalp'),
    );
    roundTrip([], { kind: 'setHairColor', color: '#112233' }, (s) =>
      expect(s.hairColor).toBe('#112233'),
    );
  });

  it('setAvoidScalp to what it is already changes nothing and says so', () => {
    const { e, log } = editorWithLog();
    expect(e.run({ kind: 'setAvoidScalp', on: false })).toBe(false);
    expect(log.at(-1)?.message).toContain('already off');
    expect(e.run({ kind: 'setAvoidScalp', on: true })).toBe(true);
    expect(e.run({ kind: 'setAvoidScalp', on: true })).toBe(false);
    expect(log.at(-1)?.message).toContain('already on');
    expect(e.undo()).toBe(true);
    expect(e.session.avoidScalp).toBeUndefined();
    expect(e.canUndo).toBe(false);
  });

  it('setDetail of the session: set, replace, off; each undoable', () => {
    const curl = { radius: 0.05, frequency: 3, start: 0.15, randomOffset: 1 };
    roundTrip([], { kind: 'setDetail', curveId: null, detail: { curl } }, (s) =>
      expect(s.detail).toEqual({ curl }),
    );
    roundTrip(
      [{ kind: 'setDetail', curveId: null, detail: { curl } }],
      { kind: 'setDetail', curveId: null, detail: { lengthJitter: 0.4 } },
      (s) => expect(s.detail).toEqual({ lengthJitter: 0.4 }),
    );
    // a detail that changes no strand is no detail
    for (const off of [undefined, {}, { lengthJitter: 0 }])
      roundTrip(
        [{ kind: 'setDetail', curveId: null, detail: { curl } }],
        { kind: 'setDetail', curveId: null, detail: off },
        (s) => expect(Object.keys(s)).not.toContain('detail'),
      );
    const { e } = editorWithLog();
    expect(e.run({ kind: 'setDetail', curveId: null, detail: { lengthJitter: 0 } })).toBe(false);
    expect(e.run({ kind: 'setDetail', curveId: null, detail: { curl } })).toBe(true);
    expect(e.run({ kind: 'setDetail', curveId: null, detail: { curl: { ...curl } } })).toBe(false);
  });

  it('setDetail says which blocks are on: one set to 0 in the panel (Flyaway share 0) is not', () => {
    const { e, log } = editorWithLog();
    const flyaway = { share: 0.01, distance: 0.3, start: 0.5 };
    const clump = { factor: 0.3, shape: 0, tipSpread: 0.02, guideDistance: 0.3 };
    e.run({ kind: 'setDetail', curveId: null, detail: { clump, flyaway } });
    expect(log.at(-1)?.message).toBe('Detail: clump, flyaway.');
    e.run({
      kind: 'setDetail',
      curveId: null,
      detail: { clump, flyaway: { ...flyaway, share: 0 } },
    });
    expect(log.at(-1)?.message).toBe('Detail: clump.');
  });

  it('setCurlType: a coily type brings its root lift as the Volume in the same edit', () => {
    // emptySession has the shape rules and the default Volume (none stored): 4B sets its curl
    // (radius 2.2-3 mm, 8.5-10.5 turns per 10 cm) and Volume 2.5 cm, undone together
    roundTrip([], { kind: 'setCurlType', curveId: null, type: '4B' }, (s) => {
      expect(s.detail?.curl?.radius).toBeGreaterThanOrEqual(0.022);
      expect(s.detail?.curl?.radius).toBeLessThanOrEqual(0.03);
      expect(s.detail?.curl?.frequency).toBeGreaterThanOrEqual(8.5);
      expect(s.detail?.curl?.frequency).toBeLessThanOrEqual(10.5);
      expect(s.volume).toBe(0.25);
    });
    // waves lie on the head: no Volume
    roundTrip([], { kind: 'setCurlType', curveId: null, type: '2B' }, (s) => {
      expect(s.detail?.curl?.radius).toBeGreaterThanOrEqual(0.04);
      expect(s.volume).toBeUndefined();
    });
    // a Volume the user set stays
    roundTrip(
      [{ kind: 'setVolume', volume: 0.12 }],
      { kind: 'setCurlType', curveId: null, type: '3A' },
      (s) => expect(s.volume).toBe(0.12),
    );
    // a curve's own curl type leaves the whole head's Volume
    roundTrip([addStream(0.1)], { kind: 'setCurlType', curveId: 'c1', type: '4C' }, (s) => {
      expect(s.curves[0].detail?.curl?.radius).toBeGreaterThanOrEqual(0.015);
      expect(s.volume).toBeUndefined();
    });
    const { e, log } = editorWithLog();
    expect(e.run({ kind: 'setCurlType', curveId: null, type: '4A' })).toBe(true);
    expect(log.at(-1)?.message).toContain('Volume 2.5 cm');
    expect(e.undo()).toBe(true);
    expect(e.session.detail).toBeUndefined();
    expect(e.session.volume).toBeUndefined();
  });

  it("setDetail of a curve: its own detail (even none), then back to the session's", () => {
    const frizz = { distance: 0.006, shape: 0.5 };
    roundTrip([addStream(0)], { kind: 'setDetail', curveId: 'c1', detail: { frizz } }, (s) =>
      expect(s.curves[0].detail).toEqual({ frizz }),
    );
    roundTrip([addStream(0)], { kind: 'setDetail', curveId: 'c1', detail: {} }, (s) =>
      expect(s.curves[0].detail).toEqual({}),
    );
    roundTrip(
      [addStream(0), { kind: 'setDetail', curveId: 'c1', detail: { frizz } }],
      { kind: 'setDetail', curveId: 'c1', detail: undefined },
      (s) => expect(Object.keys(s.curves[0])).not.toContain('detail'),
    );
    const { e } = editorWithLog();
    expect(e.run({ kind: 'setDetail', curveId: 'c9', detail: { frizz } })).toBe(false);
  });

  it('setDetail out of range changes nothing (the editor holds only sessions the reader accepts)', () => {
    const { e } = editorWithLog();
    e.run(addStream(0));
    const before = e.session;
    const bad = { curl: { radius: 5, frequency: 3, start: 0.15, randomOffset: 1 } };
    expect(e.run({ kind: 'setDetail', curveId: null, detail: bad })).toBe(false);
    expect(e.run({ kind: 'setDetail', curveId: 'c1', detail: bad })).toBe(false);
    expect(e.session).toBe(before);
  });

  it('setGrowth: a patch of growth settings, checked by the reader, undoable', () => {
    roundTrip([], { kind: 'setGrowth', patch: { maxStrands: 5000, maxLength: 2 } }, (s) => {
      expect(s.growth.maxStrands).toBe(5000);
      expect(s.growth.maxLength).toBe(2);
      expect(s.growth.seed).toBe(emptySession('25k').growth.seed);
    });
    const { e, log } = editorWithLog();
    const before = e.session;
    expect(e.run({ kind: 'setGrowth', patch: { maxSegments: 1e9 } })).toBe(false);
    expect(log.at(-1)?.message).toContain('session.growth.maxSegments');
    expect(e.run({ kind: 'setGrowth', patch: { jitter: Number.NaN } })).toBe(false);
    expect(e.run({ kind: 'setGrowth', patch: { seed: 1.5 } })).toBe(false);
    expect(
      e.run({
        kind: 'setGrowth',
        patch: { speed: 2 } as unknown as Partial<SessionState['growth']>,
      }),
    ).toBe(false);
    expect(e.run({ kind: 'setGrowth', patch: { maxStrands: before.growth.maxStrands } })).toBe(
      false,
    );
    expect(e.session).toBe(before);
  });

  it('a hair colour that is not #rrggbb changes nothing', () => {
    const { e } = editorWithLog();
    expect(e.run({ kind: 'setHairColor', color: 'red; x' })).toBe(false);
    expect(e.session.hairColor).toBe('#5a3825');
  });

  it('a colour dragged in the picker is one undo step', () => {
    const { e, clock } = editorWithLog();
    const start = e.session;
    for (const c of ['#101010', '#202020', '#303030']) {
      clock.t += 100;
      e.run({ kind: 'setHairColor', color: c });
    }
    expect(e.session.hairColor).toBe('#303030');
    e.undo();
    expect(e.session).toBe(start);
    expect(e.canUndo).toBe(false);
    // after a pause, a new colour is a new step
    e.redo();
    clock.t += 5000;
    e.run({ kind: 'setHairColor', color: '#404040' });
    e.undo();
    expect(e.session.hairColor).toBe('#303030');
  });
});

describe('one load path', () => {
  const saved = (): SessionState => ({
    ...emptySession('50k'),
    hairColor: '#aa0000',
    curves: [{ id: 'c7', type: 'stream', points: line(0), extend: true, viewpoint: vp }],
  });

  it('a loaded session brings its hair colour and curves, keeps the page grid, and is undoable', () => {
    const { e, log } = editorWithLog();
    e.run(addStream(0.4));
    const before = e.session;
    e.run({ kind: 'loadSession', session: saved(), what: 'Opened x', camera: vp });
    expect(e.session.hairColor).toBe('#aa0000');
    expect(e.session.grid).toBe('25k');
    expect(e.session.curves.map((c) => c.id)).toEqual(['c7']);
    expect(e.selectedId).toBeNull();
    const last = log[log.length - 1];
    expect(last.camera).toEqual(vp);
    expect(last.message).toContain('Opened x (1 curves)');
    // undo restores the previous session, colour included, and subscribers see the colour change
    e.undo();
    expect(e.session).toBe(before);
    const u = log[log.length - 1];
    expect([u.previous.hairColor, u.session.hairColor]).toEqual(['#aa0000', '#5a3825']);
  });

  it('a link opened with the page starts the history', () => {
    const { e } = editorWithLog();
    e.run(addStream(0));
    e.run({ kind: 'loadSession', session: saved(), what: 'Opened a link', resetHistory: true });
    expect(e.canUndo).toBe(false);
    expect(e.session.hairColor).toBe('#aa0000');
  });
});

describe('selection and tools', () => {
  it('selects only curves that exist; undoing the curve away drops the selection', () => {
    const { e } = editorWithLog();
    e.select('c1');
    expect(e.selectedId).toBeNull();
    e.run(addStream(0));
    e.select(null);
    e.select('c1');
    expect(e.selectedId).toBe('c1');
    e.undo(); // removes c1
    expect(e.selectedId).toBeNull();
    e.redo();
    expect(e.selectedId).toBeNull();
  });

  it('the selection survives edits of other curves', () => {
    const { e } = editorWithLog();
    e.run(addStream(0));
    e.run(addStream(0.2));
    e.select('c1');
    e.run({ kind: 'deleteCurve', id: 'c2' });
    expect(e.selectedId).toBe('c1');
  });

  it('setTool changes the tool and notifies once; the same tool again is silent', () => {
    const { e, log } = editorWithLog();
    e.setTool('select');
    e.setTool('select');
    expect(e.tool).toBe('select');
    expect(log.map((c) => c.cause)).toEqual(['tool']);
  });
});

describe('subscriptions', () => {
  it('fire once per change, with what changed', () => {
    const { e, log } = editorWithLog();
    e.run(addStream(0));
    expect(log).toHaveLength(1);
    expect(log[0]).toMatchObject({
      cause: 'command',
      sessionChanged: true,
      selectionChanged: true,
    });
    e.select(null);
    expect(log).toHaveLength(2);
    expect(log[1]).toMatchObject({
      cause: 'select',
      sessionChanged: false,
      selectionChanged: true,
    });
    e.undo();
    e.redo();
    expect(log.map((c) => c.cause)).toEqual(['command', 'select', 'undo', 'redo']);
    expect(e.undo()).toBe(true);
    expect(e.undo()).toBe(false); // nothing left: no notification
    expect(log).toHaveLength(5);
  });

  it('unsubscribe stops notifications', () => {
    const e = new Editor(emptySession('25k'));
    let n = 0;
    const off = e.listen(() => n++);
    e.run(addStream(0));
    off();
    e.run(addStream(0.1));
    expect(n).toBe(1);
  });
});

describe('the editor holds only sessions the reader accepts', () => {
  it('a curve past the working volume is refused with a message; nothing changes', () => {
    const { e, log } = editorWithLog();
    const far: Command = {
      kind: 'addCurve',
      curve: {
        type: 'stream',
        points: [
          [0, 1, 0.5],
          [0, 1, 900],
        ],
        extend: true,
        viewpoint: vp,
      },
      what: 'stream curve {id}',
    };
    expect(e.run(far)).toBe(false);
    expect(e.session.curves).toHaveLength(0);
    expect(log.at(-1)?.message).toContain('Nothing changed');
    expect(log.at(-1)?.message).toContain('curve.points[1]');
  });

  it('a session loaded onto another grid keeps avoid scalp and detail (settings, not grid points)', () => {
    const { e, log } = editorWithLog();
    const detail = { lengthJitter: 0.3 };
    const other: SessionState = { ...emptySession('50k'), avoidScalp: true, detail };
    e.run({ kind: 'loadSession', session: other, what: 'Opened x' });
    expect(e.session.grid).toBe('25k');
    expect(e.session.avoidScalp).toBe(true);
    expect(e.session.detail).toEqual(detail);
    expect(log.at(-1)?.message).toBe('Opened x (0 curves).');
    e.run({ kind: 'loadSession', session: emptySession('25k'), what: 'Opened y' });
    expect(Object.keys(e.session)).not.toContain('avoidScalp');
    expect(Object.keys(e.session)).not.toContain('detail');
  });
});

describe('shapePonytail', () => {
  it('keeps the band as tight as it was: the profiles shape the tail below it (fresh eyes 16)', () => {
    // a spine from the back of the crown up, over and down (a high ponytail drawn from the side)
    const spine: Vec3[] = Array.from({ length: 24 }, (_, i) => {
      const a = Math.min(i, 6) / 6;
      return [
        0,
        0.64 + 0.2 * Math.sin(a * Math.PI * 0.5) - 0.08 * Math.max(0, i - 6),
        -0.64 - 0.1 * i,
      ];
    });
    const e = new Editor(emptySession('25k'), 'stream');
    e.run({
      kind: 'addCurve',
      curve: STROKE_KINDS.ponytail.fromStroke(spine, vp, false),
      what: 'ponytail {id}',
    });
    const made = e.session.curves[0];
    if (made?.type !== 'ponytail') throw new Error('no ponytail');
    expect(made.circles[0].radius).toBe(ONE_STROKE_RADIUS);
    // profiles drawn from the head cross the band's plane 3 cm from the spine
    const circles = made.circles.map((q, i) => ({ ...q, radius: i === 0 ? 0.3 : 0.25 }));
    expect(
      e.run({
        kind: 'shapePonytail',
        id: made.id,
        crossSection: made.crossSection,
        profiles: made.profiles,
        circles,
      }),
    ).toBe(true);
    const shaped = e.session.curves[0];
    if (shaped?.type !== 'ponytail') throw new Error('no ponytail');
    expect(shaped.circles.map((q) => q.radius)).toEqual([
      ONE_STROKE_RADIUS,
      ...circles.slice(1).map(() => 0.25),
    ]);
    e.undo();
    expect(e.session.curves[0]).toEqual(made);
  });
});
