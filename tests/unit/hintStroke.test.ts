// Hint strokes (method S4.4, Fig. 3c–h): constructed strokes on a straight curve's strip surface,
// one per operation, and strokes that fit none.
import { describe, expect, it } from 'vitest';
import { resamplePolyline } from '../../web/model/resample';
import { buildSupportingSurface, type SupportingSurface } from '../../web/model/supportingSurface';
import { distance, dot, normalize, sub, type Vec3 } from '../../web/model/vec3';
import {
  classifyHintStroke,
  editWithHintStroke,
  type HintSample,
  liftHintStroke,
  scalpHintEdit,
} from '../../web/tools/hintStroke';

const d = 0.1;
// Curve along +x from the origin, 11 points; viewpoint straight in front (+z): the strip lies in
// the plane z = 0 with normal (0, -1, 0), so offset = -y.
const curve: Vec3[] = Array.from({ length: 11 }, (_, i) => [i * d, 0, 0]);
const eye: Vec3 = [0.5, 0, 5];
const forward: Vec3 = [0, 0, -1];
const strip = buildSupportingSurface(curve, eye, 'strip', 6 * d);

/** Rays from the eye through points of the plane z = 0 along the polyline, ~d/4 apart. */
function strokeThrough(pts: Vec3[], surf: SupportingSurface = strip, from: Vec3 = eye) {
  const dense = resamplePolyline(pts, d / 4);
  return liftHintStroke(
    dense.map((p) => ({ origin: from, direction: normalize(sub(p, from)) })),
    surf,
    from,
    forward,
  );
}

describe('hint stroke classifier', () => {
  it('cut: a long stroke across the curve cuts it there (Fig. 3c, d)', () => {
    const s = strokeThrough([
      [0.55, 0.4, 0],
      [0.55, -0.4, 0],
    ]);
    const op = classifyHintStroke(s, curve.length, d);
    expect(op.kind).toBe('cut');
    if (op.kind === 'cut') expect(op.at).toBeCloseTo(5.5, 6);
    const r = editWithHintStroke(curve, s, d);
    expect(r.points.length).toBe(6); // root .. x = 0.5 (the 0.05 tail is shorter than d)
    expect(distance(r.points[5], [0.5, 0, 0])).toBeLessThan(1e-9);
  });

  it('concatenate: starts near the end, ends far, off the surface (Fig. 3e, f)', () => {
    const s = strokeThrough([
      [0.97, 0.02, 0],
      [1.2, 0.15, 0],
      [1.5, 0.35, 0],
    ]);
    expect(s.some((x) => !x.onSurface)).toBe(true); // leaves the strip past the curve's end
    const r = editWithHintStroke(curve, s, d);
    expect(r.op.kind).toBe('concatenate');
    expect(r.points.length).toBeGreaterThan(curve.length + 3);
    for (let i = 1; i < r.points.length; i++)
      expect(distance(r.points[i - 1], r.points[i])).toBeCloseTo(d, 9);
    // The first 10 points are the curve's; the end follows the stroke, at the plane's depth.
    for (let i = 0; i < 10; i++) expect(distance(r.points[i], curve[i])).toBeLessThan(1e-9);
    const end = r.points[r.points.length - 1];
    expect(distance(end, [1.5, 0.35, 0])).toBeLessThan(d);
  });

  it('concatenate extrapolates depth from the last on-surface segment', () => {
    // A curve receding from the viewer: depth grows along the strip.
    const rec: Vec3[] = Array.from({ length: 11 }, (_, i) => [i * d, 0, -i * d]);
    const surf = buildSupportingSurface(rec, eye, 'strip', 6 * d);
    const target: Vec3[] = [
      [0.9, 0.01, -0.9],
      [1.0, 0.02, -1.0],
      [1.4, 0.06, -1.4],
    ];
    // Project the target path to rays from the eye.
    const dense = resamplePolyline(target, d / 4);
    const s = liftHintStroke(
      dense.map((p) => ({ origin: eye, direction: normalize(sub(p, eye)) })),
      surf,
      eye,
      forward,
    );
    const lastOn = s.map((x) => x.onSurface).lastIndexOf(true);
    expect(lastOn).toBeGreaterThan(1);
    expect(lastOn).toBeLessThan(s.length - 1);
    const depth = (x: Vec3) => dot(sub(x, eye), forward);
    const a = s[lastOn - 1].point;
    const b = s[lastOn].point;
    const lat = (v: Vec3) => Math.hypot(v[0], v[1]);
    const k = (depth(b) - depth(a)) / lat(sub(b, a));
    expect(k).toBeGreaterThan(0.5); // the strip recedes
    for (const x of s.slice(lastOn + 1)) {
      expect(x.onSurface).toBe(false);
      expect(depth(x.point)).toBeGreaterThan(depth(b));
    }
    // The off-surface points keep receding roughly along the curve's direction (z = -x).
    const end = s[s.length - 1].point;
    expect(Math.abs(end[2] + end[0])).toBeLessThan(0.1);
    expect(classifyHintStroke(s, rec.length, d).kind).toBe('concatenate');
  });

  it('insert: starts and ends near the curve; the part between is replaced (Fig. 3g, h)', () => {
    const path: Vec3[] = [
      [0.2, 0.02, 0],
      [0.35, 0.3, 0],
      [0.65, 0.3, 0],
      [0.8, -0.01, 0],
    ];
    const s = strokeThrough(path);
    const op = classifyHintStroke(s, curve.length, d);
    expect(op.kind).toBe('insert');
    if (op.kind === 'insert') {
      expect(op.from).toBeCloseTo(2, 6);
      expect(op.to).toBeCloseTo(8, 1); // the resampled stroke ends a little short
      expect(op.reversed).toBe(false);
    }
    const r = editWithHintStroke(curve, s, d);
    expect(Math.max(...r.points.map((p) => p[1]))).toBeGreaterThan(0.25);
    expect(distance(r.points[0], curve[0])).toBe(0);
    expect(distance(r.points[r.points.length - 1], curve[10])).toBeLessThan(d);
    // Drawn backwards, the same insertion.
    const back = strokeThrough(path.slice().reverse());
    const op2 = classifyHintStroke(back, curve.length, d);
    expect(op2.kind === 'insert' && op2.reversed).toBe(true);
    const r2 = editWithHintStroke(curve, back, d);
    expect(r2.points.length).toBeGreaterThan(curve.length);
    expect(r2.points[3][1]).toBeGreaterThan(0); // goes up the bump in curve order
  });

  it('none: strokes that fit no operation change nothing and say why', () => {
    const none = (pts: Vec3[]) => {
      const s = strokeThrough(pts);
      const r = editWithHintStroke(curve, s, d);
      expect(r.points).toEqual(curve);
      return r.op.kind === 'none' ? r.op.reason : r.op.kind;
    };
    // Starts off the surface (beyond the band).
    expect(
      none([
        [0.5, 0.9, 0],
        [0.5, 0.0, 0],
      ]),
    ).toBe('not-on-surface');
    // Too short.
    expect(
      none([
        [0.5, 0.3, 0],
        [0.52, 0.3, 0],
      ]),
    ).toBe('too-short');
    // Starts far, ends far on the same side: no crossing.
    expect(
      none([
        [0.2, 0.4, 0],
        [0.8, 0.4, 0],
      ]),
    ).toBe('no-operation');
    // Starts far, ends near: neither cut nor concatenate.
    expect(
      none([
        [0.2, 0.4, 0],
        [0.5, 0.01, 0],
      ]),
    ).toBe('no-operation');
    // Starts near the middle and leaves: concatenation must start near the end.
    expect(
      none([
        [0.5, 0.01, 0],
        [0.5, 0.5, 0],
      ]),
    ).toBe('concatenate-not-at-end');
    // Out and back to (almost) the same place.
    expect(
      none([
        [0.5, 0.01, 0],
        [0.5, 0.3, 0],
        [0.53, 0.01, 0],
      ]),
    ).toBe('insert-too-short');
  });

  it('classifies samples given directly (no surface)', () => {
    const mk = (param: number, offset: number): HintSample => ({
      point: [param * d, -offset, 0],
      onSurface: true,
      param,
      offset,
    });
    const cross = [mk(4, 0.3), mk(4.2, 0.1), mk(4.4, -0.1), mk(4.6, -0.3)];
    const op = classifyHintStroke(cross, 11, d);
    expect(op.kind).toBe('cut');
    if (op.kind === 'cut') expect(op.at).toBeCloseTo(4.3, 12);
    // A crossing that does not go far enough on one side is not a cut.
    const shallow = [mk(4, 0.3), mk(4.2, 0.2), mk(4.4, -0.05), mk(4.6, -0.2), mk(4.6, -0.1)];
    expect(classifyHintStroke(shallow, 11, d)).toEqual({ kind: 'none', reason: 'no-operation' });
  });
});

// Strokes pressed on the scalp must clearly be hints (scalpHintEdit); otherwise the tool draws a
// new curve. The view is straight down on the plane z = 0 at 100 px per world unit (10 px per
// grid step): a sample's screen distance is its distance to the curve's segment in the plane.
describe('hint strokes pressed on the scalp', () => {
  const screen = (s: readonly HintSample[]) =>
    s.map((h) => {
      const x = Math.min(1, Math.max(0, h.point[0]));
      return 100 * Math.hypot(h.point[0] - x, h.point[1]);
    });
  const fromScalp = (pts: Vec3[]) => {
    const s = strokeThrough(pts);
    const r = scalpHintEdit(curve, s, screen(s), d);
    return r ? r.op.kind : 'new curve';
  };

  it('keeps the Fig. 3 operations: cut, concatenate, insert', () => {
    const cut: Vec3[] = [
      [0.55, 0.4, 0],
      [0.55, -0.4, 0],
    ];
    const s = strokeThrough(cut);
    const r = scalpHintEdit(curve, s, screen(s), d);
    expect(r?.op.kind).toBe('cut');
    expect(r?.points.length).toBe(6);
    expect(
      fromScalp([
        [0.97, 0.02, 0],
        [1.2, 0.15, 0],
        [1.5, 0.35, 0],
      ]),
    ).toBe('concatenate');
    // the insert of Fig. 3g: out 3 grid steps (30 px) between its ends, either way round
    const insert: Vec3[] = [
      [0.2, 0.02, 0],
      [0.35, 0.3, 0],
      [0.65, 0.3, 0],
      [0.8, -0.01, 0],
    ];
    expect(fromScalp(insert)).toBe('insert');
    expect(fromScalp(insert.slice().reverse())).toBe('insert');
  });

  it('is a new curve when it only runs along the curve, however close (not an insert)', () => {
    const along: Vec3[] = [
      [0.2, 0.02, 0],
      [0.5, 0.03, 0],
      [0.8, 0.02, 0],
    ];
    expect(classifyHintStroke(strokeThrough(along), curve.length, d).kind).toBe('insert');
    expect(fromScalp(along)).toBe('new curve');
    // leaving by less than near + leave (2 steps < 2.5): still running along it
    const wavy: Vec3[] = [
      [0.2, 0.02, 0],
      [0.35, 0.2, 0],
      [0.65, 0.2, 0],
      [0.8, -0.01, 0],
    ];
    expect(classifyHintStroke(strokeThrough(wavy), curve.length, d).kind).toBe('insert');
    expect(fromScalp(wavy)).toBe('new curve');
  });

  it('is a new curve when it does not start on the curve itself, or fits no operation', () => {
    // near the end in surface terms (1 step), but 10 px from the curve's image: not "on" it
    const offEnd: Vec3[] = [
      [0.95, 0.1, 0],
      [1.3, 0.4, 0],
    ];
    expect(classifyHintStroke(strokeThrough(offEnd), curve.length, d).kind).toBe('concatenate');
    expect(fromScalp(offEnd)).toBe('new curve');
    // the 'none' strokes of Fig. 3's counter-examples
    expect(
      fromScalp([
        [0.2, 0.4, 0],
        [0.8, 0.4, 0],
      ]),
    ).toBe('new curve');
    expect(
      fromScalp([
        [0.5, 0.01, 0],
        [0.5, 0.5, 0],
      ]),
    ).toBe('new curve');
  });

  it('cuts only when it really crosses the curve, clear of it at both ends', () => {
    // starts 1.55 steps off (far in surface terms, so the classifier says cut) but 15.5 px
    // from the curve's image: too close to be clearly across it
    const close: Vec3[] = [
      [0.55, 0.155, 0],
      [0.55, -0.4, 0],
    ];
    expect(classifyHintStroke(strokeThrough(close), curve.length, d).kind).toBe('cut');
    expect(fromScalp(close)).toBe('new curve');
    // the same crossing hidden behind the head
    const s = strokeThrough([
      [0.55, 0.4, 0],
      [0.55, -0.4, 0],
    ]);
    const hidden = s.map((h) => ({ ...h, hidden: Math.abs(h.point[1]) < 0.05 }));
    expect(scalpHintEdit(curve, hidden, screen(s), d)).toBeNull();
    // a sign change between samples far from the curve (the stroke jumped across the surface)
    const mk = (param: number, offset: number, y: number): HintSample => ({
      point: [param * d, y, 0],
      onSurface: true,
      param,
      offset,
    });
    const jump = [mk(4, 0.3, 0.3), mk(4, 0.25, 0.25), mk(6, -0.25, 0.5), mk(6, -0.3, 0.6)];
    expect(classifyHintStroke(jump, curve.length, d).kind).toBe('cut');
    expect(scalpHintEdit(curve, jump, [30, 25, 50, 60], d)).toBeNull();
  });
});
