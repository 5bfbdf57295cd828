// Camera arithmetic (web/viewer/viewMath.ts): orbit speed and the reset-view transition.
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../web/model/vec3';
import {
  easeInOut,
  frameBounds,
  interpolateView,
  ORBIT_DEGREES_PER_WIDTH,
  orbitDegrees,
  orbitRotateSpeed,
  sameView,
} from '../../web/viewer/viewMath';

describe('orbit speed', () => {
  it('turns 180° for a drag across the view at factor 1, whatever its size', () => {
    expect(ORBIT_DEGREES_PER_WIDTH).toBe(180);
    for (const [w, h] of [
      [1100, 685],
      [1920, 1000],
      [400, 800],
    ]) {
      const s = orbitRotateSpeed(w, h);
      expect(orbitDegrees(w, h, s)).toBeCloseTo(180, 9);
      expect(orbitDegrees(w / 2, h, s)).toBeCloseTo(90, 9);
    }
  });

  it('is about 2.5x slower than OrbitControls’ default on the app’s usual view', () => {
    // before: rotateSpeed 1 turned ~79° for 150 px on a 685 px high view
    expect(orbitDegrees(150, 685, 1)).toBeCloseTo(78.8, 1);
    expect(orbitDegrees(150, 685, orbitRotateSpeed(1100, 685))).toBeCloseTo(24.5, 1);
  });

  it('scales with the user factor; bad factors count as 1', () => {
    const base = orbitRotateSpeed(1000, 600);
    expect(orbitRotateSpeed(1000, 600, 2)).toBeCloseTo(2 * base, 12);
    expect(orbitRotateSpeed(1000, 600, 0.5)).toBeCloseTo(0.5 * base, 12);
    for (const bad of [0, -1, Number.NaN, Number.POSITIVE_INFINITY])
      expect(orbitRotateSpeed(1000, 600, bad)).toBe(base);
    expect(Number.isFinite(orbitRotateSpeed(0, 0))).toBe(true);
  });
});

describe('view transition', () => {
  const a = { position: [0, 0, 5] as Vec3, target: [0, 0, 0] as Vec3 };
  const b = { position: [6, 1, 0] as Vec3, target: [0, 1, 0] as Vec3 };
  const dist = (v: { position: Vec3; target: Vec3 }) =>
    Math.hypot(...v.position.map((p, i) => p - v.target[i]));

  it('starts at the first view and ends at the second', () => {
    expect(sameView(interpolateView(a, b, 0), a, 1e-12)).toBe(true);
    expect(sameView(interpolateView(a, b, 1), b, 1e-12)).toBe(true);
    expect(sameView(interpolateView(a, b, 1.5), b, 1e-12)).toBe(true);
  });

  it('swings around the target: the distance changes linearly, the target in a line', () => {
    const m = interpolateView(a, b, 0.5);
    expect(m.target).toEqual([0, 0.5, 0]);
    expect(dist(m)).toBeCloseTo(5.5, 9);
    // halfway along the great circle from +z to +x: 45°
    const o = m.position.map((p, i) => p - m.target[i]);
    expect(Math.atan2(o[0], o[2])).toBeCloseTo(Math.PI / 4, 9);
  });

  it('handles equal and opposite directions', () => {
    expect(sameView(interpolateView(a, a, 0.3), a, 1e-9)).toBe(true);
    const back = { position: [0, 0, -5] as Vec3, target: [0, 0, 0] as Vec3 };
    for (const t of [0.25, 0.5, 0.75]) {
      const v = interpolateView(a, back, t);
      expect(dist(v)).toBeCloseTo(5, 9);
    }
    expect(sameView(interpolateView(a, back, 1), back, 1e-9)).toBe(true);
  });

  it('eases in and out', () => {
    expect([easeInOut(0), easeInOut(0.5), easeInOut(1), easeInOut(2)]).toEqual([0, 0.5, 1, 1]);
    expect(easeInOut(0.1)).toBeLessThan(0.1);
    expect(easeInOut(0.9)).toBeGreaterThan(0.9);
  });
});

describe('framing a head', () => {
  const home = { position: [2.6, 0.9, 7.0] as Vec3, target: [0, -0.55, 0] as Vec3 };
  const builtin = { min: [-0.8, -2.6, -1] as Vec3, max: [0.8, 1, 1.3] as Vec3 };

  it('frames the reference box with the home view itself', () => {
    const v = frameBounds(builtin, builtin, home);
    expect(sameView(v, home, 1e-12)).toBe(true);
  });

  const off = (w: { position: Vec3; target: Vec3 }) =>
    w.position.map((p, a) => p - w.target[a]) as Vec3;

  it('moves with the box and backs off as it is larger on screen', () => {
    // twice as large, moved up by 1: the same direction, twice the distance
    const big = { min: [-1.6, -5.2 + 1.6, -2] as Vec3, max: [1.6, 2 + 1.6, 2.6] as Vec3 };
    const v = frameBounds(big, builtin, home, 1.6);
    for (let a = 0; a < 3; a++) expect(off(v)[a]).toBeCloseTo(2 * off(home)[a], 12);
    // the target keeps its place relative to the box: twice the offset from the centre
    expect(v.target[1]).toBeCloseTo(-1.6 + 1.6 + 2 * (-0.55 - -0.8), 12);
    // a smaller box is framed closer; a degenerate one like the reference
    const small = frameBounds({ min: [-0.4, -1, -0.5], max: [0.4, 0.8, 0.65] }, builtin, home);
    expect(Math.hypot(...off(small))).toBeLessThan(Math.hypot(...off(home)));
    const flat = frameBounds({ min: [0, 0, 0], max: [0, 0, 0] }, builtin, home);
    expect(Math.hypot(...off(flat))).toBeCloseTo(Math.hypot(...off(home)), 12);
  });

  it('uses the room a wide view leaves beside a tall head', () => {
    // as tall as the reference, three times as wide: a wide view holds it nearly as close
    const wide = { min: [-2.4, -2.6, -1] as Vec3, max: [2.4, 1, 1.3] as Vec3 };
    const inWide = Math.hypot(...off(frameBounds(wide, builtin, home, 1.66)));
    const inSquare = Math.hypot(...off(frameBounds(wide, builtin, home, 0.6)));
    const d0 = Math.hypot(...off(home));
    expect(inWide).toBeLessThan(1.5 * d0);
    expect(inSquare).toBeGreaterThan(2 * d0);
    // the reference stays where home puts it, whatever the aspect
    for (const aspect of [0.5, 1, 2])
      expect(sameView(frameBounds(builtin, builtin, home, aspect), home, 1e-12)).toBe(true);
  });
});
