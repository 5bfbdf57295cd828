// Mirror editing: a new curve with Mirror on gets a twin reflected across x = 0 (hand-reflected
// points), the twins name each other, one edit changes both in one undo step, deleting one
// deletes both, a curve on the plane gets no twin, and the reader checks the pairing.
import { describe, expect, it } from 'vitest';
import { Editor } from '../../web/editor/editor';
import { isSelfMirror, mirrorCurve } from '../../web/model/mirror';
import {
  DEFAULT_GROWTH,
  type DividingCurve,
  emptySession,
  type StyleCurve,
} from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';
import type { Vec3 } from '../../web/model/vec3';

const vp = { position: [1, 0.5, 5] as Vec3, target: [0.2, -0.5, 0] as Vec3 };
const stroke: Vec3[] = [
  [0.3, 1.0, 0.2],
  [0.4, 0.95, 0.25],
  [0.5, 0.85, 0.3],
];
const reflect = (p: Vec3): Vec3 => [-p[0], p[1], p[2]];

function editor() {
  return new Editor(emptySession('25k', DEFAULT_GROWTH), 'stream');
}

describe('mirror editing', () => {
  it('adds a twin reflected across x = 0, the two naming each other', () => {
    const e = editor();
    e.run({
      kind: 'addCurve',
      curve: { type: 'stream', points: stroke, extend: true, viewpoint: vp },
      what: 'stream curve {id}',
      mirror: true,
    });
    const [a, b] = e.session.curves;
    expect(e.session.curves).toHaveLength(2);
    expect(a.mirror).toBe(b.id);
    expect(b.mirror).toBe(a.id);
    expect(b.points).toEqual(stroke.map(reflect));
    expect(b.viewpoint).toEqual({ position: reflect(vp.position), target: reflect(vp.target) });
    // the session the editor holds is one the reader accepts, unchanged
    const read = parseSession(JSON.parse(JSON.stringify(e.session)));
    expect(read.ok && read.value.curves).toEqual(e.session.curves);
    // one undo removes both
    e.undo();
    expect(e.session.curves).toHaveLength(0);
  });

  it('edits and deletes both twins in one undoable step', () => {
    const e = editor();
    e.run({
      kind: 'addCurve',
      curve: { type: 'stream', points: stroke, extend: true, viewpoint: vp },
      what: 'c',
      mirror: true,
    });
    const [a] = e.session.curves;
    const edited: Vec3[] = [...stroke, [0.6, 0.7, 0.35]];
    e.run({ kind: 'hintEdit', id: a.id, op: 'concatenate', points: edited });
    expect(e.session.curves[1].points).toEqual(edited.map(reflect));
    e.run({ kind: 'patchCurve', id: e.session.curves[1].id, patch: { extend: false } });
    expect(e.session.curves.map((c) => (c.type === 'stream' ? c.extend : null))).toEqual([
      false,
      false,
    ]);
    e.run({ kind: 'deleteCurve', id: e.session.curves[1].id });
    expect(e.session.curves).toHaveLength(0);
    e.undo();
    expect(e.session.curves).toHaveLength(2);
    expect(e.session.curves[1].points).toEqual(edited.map(reflect));
  });

  it('gives no twin to a curve drawn on the plane, and without Mirror none', () => {
    const onPlane: Vec3[] = [
      [0, 1.1, 0.3],
      [0, 1.12, 0.1],
    ];
    expect(isSelfMirror({ type: 'stream', points: onPlane } as StyleCurve)).toBe(true);
    const e = editor();
    e.run({
      kind: 'addCurve',
      curve: { type: 'stream', points: onPlane, extend: true, viewpoint: vp },
      what: 'c',
      mirror: true,
    });
    e.run({
      kind: 'addCurve',
      curve: { type: 'stream', points: stroke, extend: true, viewpoint: vp },
      what: 'c',
    });
    expect(e.session.curves).toHaveLength(2);
    expect(e.session.curves.every((c) => c.mirror === undefined)).toBe(true);
  });

  it('reflects a dividing curve: normals reflected, tilts negated; mirroring twice is the identity', () => {
    const d: DividingCurve = {
      id: 'c1',
      type: 'dividing',
      points: stroke,
      normals: [
        [0.6, 0.8, 0],
        [0.6, 0.8, 0],
        [0.6, 0.8, 0],
      ],
      sigma: 1,
      h: 0.5,
      alpha0: 0.2,
      alpha1: -0.1,
      viewpoint: vp,
    };
    const m = mirrorCurve(d, 'c2', 'c1') as DividingCurve;
    expect(m.normals[0]).toEqual([-0.6, 0.8, 0]);
    expect([m.alpha0, m.alpha1]).toEqual([-0.2, 0.1]);
    expect(mirrorCurve(m, 'c1', 'c2')).toEqual({ ...d, mirror: 'c2' });
  });

  it('the reader refuses a mirror that names no twin, or one that does not name it back', () => {
    const base = emptySession('25k', DEFAULT_GROWTH);
    const c = { id: 'c1', type: 'stream', points: stroke, extend: true, viewpoint: vp };
    const lone = parseSession({ ...base, curves: [{ ...c, mirror: 'c9' }] });
    expect(lone.ok).toBe(false);
    if (!lone.ok)
      expect(lone.error).toBe(
        'session.curves[0].mirror: "c9" must be another stream curve of the session whose mirror is "c1"',
      );
    const oneWay = parseSession({
      ...base,
      curves: [
        { ...c, mirror: 'c2' },
        { ...c, id: 'c2', points: stroke.map(reflect) },
      ],
    });
    expect(oneWay.ok).toBe(false);
  });
});
