// Ponytail cross sections (method S4.6): circles between the profiles with the right radii, C1
// nearest the scalp, the cross-section curve's scale, and the protocol block.

import { describe, expect, it } from 'vitest';
import { curveParams } from '../../web/model/curveSet';
import {
  MAX_PONYTAIL_RADIUS,
  planeCrossing,
  ponytailCircles,
} from '../../web/model/ponytailGeometry';
import type { Vec3 } from '../../web/model/vec3';

// Spine straight down from the scalp at y = 1 to y = -1 (21 points, step 0.1).
const spine: Vec3[] = Array.from({ length: 21 }, (_, i) => [0, 1 - 0.1 * i, 0]);
// Profiles in the plane z = 0 between y = 0.55 and y = -0.55, at x = ±(0.25 + 0.1 y): the
// radius half-way between them is r(y) = 0.25 + 0.1 y.
const line = (x0: number, y0: number, x1: number, y1: number, n = 12): Vec3[] =>
  Array.from({ length: n }, (_, k) => {
    const t = k / (n - 1);
    return [x0 + (x1 - x0) * t, y0 + (y1 - y0) * t, 0];
  });
const profileA = line(-0.305, 0.55, -0.195, -0.55);
const profileB = line(0.305, 0.55, 0.195, -0.55);

describe('ponytail circles', () => {
  it('sit on the spine between the profiles, radius half the profile distance', () => {
    const g = ponytailCircles(spine, [], profileA, profileB);
    expect(g.scale).toBe(1);
    expect(g.circles.length).toBe(11); // spine points y = 0.5 .. -0.5
    g.circles.forEach((c, k) => {
      const y = 0.5 - 0.1 * k;
      expect(c.spineIndex).toBe(5 + k);
      expect(c.centre).toEqual(spine[5 + k]);
      expect(c.axis[0]).toBeCloseTo(0, 12);
      expect(c.axis[1]).toBeCloseTo(-1, 12);
      expect(c.radius).toBeCloseTo(0.25 + 0.1 * y, 10);
    });
    // C1 is the one nearest the scalp (the spine's root).
    expect(g.circles[0].centre[1]).toBeCloseTo(0.5, 12);
  });

  it('take their scale from the cross-section curve where it is drawn', () => {
    // A circle of radius 0.3 around the spine at y = 0, where the profiles give 0.25.
    const cs: Vec3[] = Array.from({ length: 24 }, (_, k) => {
      const a = (2 * Math.PI * k) / 24;
      return [0.3 * Math.cos(a), 0, 0.3 * Math.sin(a)];
    });
    const g = ponytailCircles(spine, cs, profileA, profileB);
    expect(g.scale).toBeCloseTo(1.2, 10);
    expect(g.circles[10].radius).toBeCloseTo(0.2 * 1.2, 10);
    // 0.3 * 1.2 = 0.36 is past the widest a ponytail may be
    expect(g.circles[0].radius).toBe(MAX_PONYTAIL_RADIUS);
  });

  it('are no wider than 1.25 times their neighbours where a profile crosses far from the spine', () => {
    // narrow profiles, r(y) = 0.1 + 0.02 y; profile A runs in from far out above them (as a new
    // user's profile drawn from the head down), profile B straight up
    const a = [[-0.5, 0.65, 0] as Vec3, ...line(-0.111, 0.55, -0.089, -0.55)];
    const b = [[0.111, 0.65, 0] as Vec3, ...line(0.111, 0.55, 0.089, -0.55)];
    const g = ponytailCircles(spine, [], a, b);
    const at = (y: number) => g.circles.find((c) => Math.abs(c.centre[1] - y) < 1e-9);
    // by hand: at y = 0.6 profile A is at x = -0.3055, B at 0.111: radius 0.208 as drawn
    expect(at(0.5)?.radius).toBeCloseTo(0.11, 10);
    expect(at(0.6)?.radius).toBeCloseTo(1.25 * 0.11, 10);
    expect(at(0)?.radius).toBeCloseTo(0.1, 10);
  });

  it('every other spine point with every = 2; none without profiles', () => {
    // Counted from the root: spine points 6, 8, .., 14.
    expect(ponytailCircles(spine, [], profileA, profileB, { every: 2 }).circles.length).toBe(5);
    expect(ponytailCircles(spine, [], profileA, []).circles.length).toBe(0);
  });

  it('start no nearer the root than `from` (the one-stroke band), wherever the profiles begin', () => {
    // profiles from the scalp down: without `from` C1 would sit on the spine's root
    const a = line(-0.3, 1, -0.2, -0.5);
    const b = line(0.3, 1, 0.2, -0.5);
    expect(ponytailCircles(spine, [], a, b, { every: 2 }).circles[0].spineIndex).toBe(0);
    const g = ponytailCircles(spine, [], a, b, { every: 2, from: 3 });
    // counted from the root every other point: 4 is the first at or past 3
    expect(g.circles[0].spineIndex).toBe(4);
    expect(g.circles.every((c) => c.spineIndex >= 3)).toBe(true);
  });

  it('keep the band as tight as given (bandRadius), however far apart the profiles cross its plane', () => {
    // profiles drawn from the scalp down, 3 cm either side of the spine at the band (spine point 4)
    const a = line(-0.3, 1, -0.2, -0.5);
    const b = line(0.3, 1, 0.2, -0.5);
    const loose = ponytailCircles(spine, [], a, b, { every: 2, from: 3 });
    // by hand: at y = 0.6 the profiles are at x = -+(0.3 - 0.1 * 0.4 / 1.5) = 0.2733
    expect(loose.circles[0].radius).toBeCloseTo(0.3 - 0.04 / 1.5, 10);
    const tight = ponytailCircles(spine, [], a, b, { every: 2, from: 3, bandRadius: 0.08 });
    expect(tight.circles[0].spineIndex).toBe(4);
    expect(tight.circles[0].radius).toBe(0.08);
    // the tail below it as the profiles say
    expect(tight.circles.slice(1)).toEqual(loose.circles.slice(1));
    // profiles that begin well below the band leave their first circle as drawn
    const low = ponytailCircles(spine, [], profileA, profileB, {
      every: 2,
      from: 3,
      bandRadius: 0.08,
    });
    expect(low.circles[0].spineIndex).toBe(6);
    expect(low.circles[0].radius).toBeCloseTo(0.25 + 0.1 * 0.4, 10);
  });

  it('packs to the protocol block', () => {
    const g = ponytailCircles(spine, [], profileA, profileB);
    const p = curveParams({
      id: 'c1',
      type: 'ponytail',
      points: spine,
      extend: true,
      viewpoint: { position: [0, 0, 7], target: [0, 0, 0] },
      crossSection: [],
      profiles: [profileA, profileB],
      circles: g.circles,
      tightness: 0.7,
      section: 1,
    });
    expect(p.length).toBe(2 + 7 * 11);
    expect(p.slice(0, 2)).toEqual([0.7, 11]);
    expect(p.slice(2, 9).map((v) => Math.round(v * 1e9) / 1e9)).toEqual([0, 0.5, 0, 0, -1, 0, 0.3]);
  });

  it('plane crossing picks the intersection nearest the point', () => {
    const zig: Vec3[] = [
      [-2, -1, 0],
      [-2, 1, 0],
      [1, -1, 0],
    ];
    const x = planeCrossing(zig, [0, 0, 0], [0, 1, 0]);
    expect(x).not.toBeNull();
    expect((x as Vec3)[0]).toBeCloseTo(-0.5, 12);
  });
});
