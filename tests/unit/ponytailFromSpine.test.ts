// A ponytail in one stroke (web/model/ponytailFromSpine.ts) and the snap of a spine drawn near
// the head's middle (web/model/mirror.ts snapToPlane), against values computed by hand.
import { describe, expect, it } from 'vitest';
import { snapToPlane, X_PLANE } from '../../web/model/mirror';
import {
  BAND_ARC,
  bandIndex,
  ONE_STROKE_RADIUS,
  ponytailFromSpine,
  widenPonytail,
} from '../../web/model/ponytailFromSpine';
import type { Vec3 } from '../../web/model/vec3';

// a spine from (0, 1, -0.9) going back 0.3, then straight down 2 units, every 0.05
const spine: Vec3[] = [];
for (let i = 0; i <= 6; i++) spine.push([0, 1, -0.9 - 0.05 * i]);
for (let i = 1; i <= 40; i++) spine.push([0, 1 - 0.05 * i, -1.2]);
const fromSide = { position: [8, 1, -1] as Vec3, target: [0, 0.5, -1] as Vec3 };

describe('ponytailFromSpine', () => {
  it('gives circles of the made radius on the spine from the band on, C1 first', () => {
    const p = ponytailFromSpine(spine, fromSide);
    expect(p.circles.length).toBeGreaterThan(15);
    // the band: the first point BAND_ARC (0.12) along the spine: index 3 (0.15); every second
    // point has a circle, so C1 sits on point 3 or 4
    expect(BAND_ARC).toBeCloseTo(0.12, 9);
    expect([3, 4]).toContain(p.circles[0].spineIndex);
    for (const c of p.circles) {
      expect(c.radius).toBeCloseTo(ONE_STROKE_RADIUS, 6);
      const s = spine[c.spineIndex];
      expect(Math.hypot(c.centre[0] - s[0], c.centre[1] - s[1], c.centre[2] - s[2])).toBe(0);
    }
    // down the straight part the axis is straight down
    const last = p.circles[p.circles.length - 1];
    expect(last.axis[1]).toBeCloseTo(-1, 6);
    // the profiles lie across the spine from the view (the side view: along z... across x)
    expect(Math.abs(p.profiles[0][5][0] - p.profiles[1][5][0])).toBeLessThan(1e-9);
    expect(p.crossSection).toHaveLength(2);
  });

  it('makes nothing of a spine of fewer than three points', () => {
    expect(ponytailFromSpine(spine.slice(0, 2), fromSide).circles).toEqual([]);
  });
});

describe('snapToPlane', () => {
  it('puts a spine drawn within 1.5 cm of the middle on it, and leaves one 2 cm off', () => {
    const near = spine.map((p, i) => [0.1 + 0.02 * Math.sin(i), p[1], p[2]] as Vec3);
    const a = snapToPlane(near, X_PLANE);
    expect(a.snapped).toBe(true);
    for (const [i, p] of a.points.entries()) {
      expect(p[0]).toBe(0);
      expect(p[1]).toBe(near[i][1]);
    }
    const off = spine.map((p) => [0.2, p[1], p[2]] as Vec3);
    const b = snapToPlane(off, X_PLANE);
    expect(b.snapped).toBe(false);
    expect(b.points).toBe(off);
    // drawn in a side view (looking along x), 5 cm off is put on the middle; 6 cm is not
    const side = spine.map((p) => [0.5, p[1], p[2]] as Vec3);
    expect(snapToPlane(side, X_PLANE, [-1, -0.14, 0]).snapped).toBe(true);
    expect(snapToPlane(side, X_PLANE, [0, -0.14, -1]).snapped).toBe(false);
    expect(
      snapToPlane(
        off.map((p) => [0.6, p[1], p[2]] as Vec3),
        X_PLANE,
        [-1, 0, 0],
      ).snapped,
    ).toBe(false);
    // another plane: x = 0.5
    const c = snapToPlane(off, { normal: [1, 0, 0], offset: 0.3 });
    expect(c.snapped).toBe(true);
    expect(c.points[0][0]).toBeCloseTo(0.3, 12);
  });
});

describe('ponytailFromSpine on a spine that rises and falls', () => {
  it('puts no circle before the band (a plane there meets the falling part far away)', () => {
    // up and back from the crown, over, then down past the root's height
    const arc: Vec3[] = [];
    for (let i = 0; i <= 60; i++) {
      const t = (Math.PI * i) / 40;
      arc.push([0, 1 + 0.3 * Math.sin(t) - 0.02 * i, -0.5 - 0.3 * (1 - Math.cos(t))]);
    }
    const p = ponytailFromSpine(arc, fromSide);
    expect(p.circles.length).toBeGreaterThan(10);
    for (const c of p.circles) {
      expect(c.spineIndex).toBeGreaterThanOrEqual(2);
      expect(c.radius).toBeCloseTo(ONE_STROKE_RADIUS, 6);
    }
  });
});

describe('widenPonytail (the curve panel width)', () => {
  it('scales the circles and the strokes about the spine', () => {
    const p = ponytailFromSpine(spine, fromSide);
    const w = widenPonytail(spine, p, 2.5);
    for (const [i, c] of w.circles.entries())
      expect(c.radius).toBeCloseTo(2.5 * p.circles[i].radius, 9);
    // a profile point 8 mm off its spine point is 2 cm off it now, on the same side
    const k = 10;
    const s = spine[bandIndex(spine) + k];
    const before = p.profiles[0][k];
    const after = w.profiles[0][k];
    for (let e = 0; e < 3; e++) expect(after[e] - s[e]).toBeCloseTo(2.5 * (before[e] - s[e]), 9);
  });
});

describe('ponytailFromSpine on a high ponytail drawn from the side', () => {
  it('keeps the made radius where the spine bends at the band (a circle before the band set the scale: 0.36 cm)', () => {
    // a spine recorded from a one-stroke high ponytail in the left view (ties.spec's gesture)
    const high: Vec3[] = [
      [0, 0.8741, -0.497],
      [0, 0.9439, -0.6028],
      [0, 1.0136, -0.7085],
      [0, 0.9747, -0.8291],
      [0, 0.9206, -0.9437],
      [0, 0.8054, -0.9963],
      [0, 0.6901, -1.049],
      [0, 0.5748, -1.1016],
      [0, 0.4536, -1.1385],
      [0, 0.3278, -1.1539],
      [0, 0.2021, -1.1693],
      [0, 0.0763, -1.1846],
      [0, -0.0495, -1.2],
      [0, -0.1753, -1.2154],
      [0, -0.301, -1.2308],
      [0, -0.4268, -1.2462],
      [0, -0.5526, -1.2616],
      [0, -0.6791, -1.2687],
      [0, -0.8058, -1.2668],
      [0, -0.9325, -1.265],
      [0, -1.0592, -1.2631],
      [0, -1.1859, -1.2613],
      [0, -1.3126, -1.2594],
      [0, -1.4393, -1.2576],
      [0, -1.566, -1.2557],
    ];
    const p = ponytailFromSpine(high, { position: [7.5327, 0.5087, 0], target: [0, -0.55, 0] });
    expect(p.circles.length).toBeGreaterThan(3);
    for (const c of p.circles) expect(c.radius).toBeCloseTo(ONE_STROKE_RADIUS, 9);
  });
});
