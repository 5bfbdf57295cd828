// The session's bounding volume: the preset's grid when the curves fit, grown on the same lattice
// (same step, origin moved by whole steps) until every curve point has FIT_MARGIN_STEPS steps to
// the faces, and never by more than FIT_MAX_GROWTH per side.
import { describe, expect, it } from 'vitest';
import {
  FIT_MARGIN_STEPS,
  FIT_MAX_GROWTH,
  gridForPreset,
  gridForSession,
  HEAD_ROOM,
  sameGrid,
} from '../../web/model/grid';
import type { Vec3 } from '../../web/model/vec3';

const g25 = gridForPreset('25k');
const top = (g: typeof g25, a: number) => g.origin[a] + g.step * (g.dims[a] - 1);

describe('gridForSession', () => {
  it('is the preset grid when the curves fit inside it with the margin', () => {
    const pts: Vec3[] = [
      [0, 1, 0],
      [0.5, -1.5, 0.3],
    ];
    expect(sameGrid(gridForSession('25k', [{ points: pts }]), g25)).toBe(true);
    expect(sameGrid(gridForSession('25k', []), g25)).toBe(true);
  });

  it('grows downward to hold a long curve, on the same lattice', () => {
    const low: Vec3 = [0.2, g25.origin[1] - 0.5, 0];
    const g = gridForSession('25k', [{ points: [[0, 1, 0], low] }]);
    expect(g.step).toBe(g25.step);
    // the lowest point has at least the margin below it, and less than one more step
    const below = low[1] - g.origin[1];
    expect(below).toBeGreaterThanOrEqual(FIT_MARGIN_STEPS * g.step - 1e-9);
    expect(below).toBeLessThan((FIT_MARGIN_STEPS + 1) * g.step);
    // whole steps: the old grid points are grid points of the new one
    const shift = (g25.origin[1] - g.origin[1]) / g.step;
    expect(Math.abs(shift - Math.round(shift))).toBeLessThan(1e-9);
    expect(g.dims[1]).toBe(g25.dims[1] + Math.round(shift));
    // the other axes and the top are unchanged
    expect(top(g, 1)).toBeCloseTo(top(g25, 1), 12);
    expect([g.dims[0], g.dims[2]]).toEqual([g25.dims[0], g25.dims[2]]);
  });

  it('grows at most FIT_MAX_GROWTH per side for strokes far outside', () => {
    const far: Vec3 = [30, -30, 0];
    const g = gridForSession('25k', [{ points: [far] }]);
    expect(g25.origin[1] - g.origin[1]).toBeLessThanOrEqual(FIT_MAX_GROWTH + 1e-9);
    expect(top(g, 0) - top(g25, 0)).toBeLessThanOrEqual(FIT_MAX_GROWTH + 1e-9);
    expect(top(g, 0) - top(g25, 0)).toBeGreaterThan(FIT_MAX_GROWTH - g.step);
  });

  it('holds a loaded head with the built-in head’s room around it (not below the floor)', () => {
    // a head 1.5× the built-in one: bounds from a hand-made box
    const head = { min: [-1.2, -4, -1.6] as Vec3, max: [1.2, 1.5, 1.8] as Vec3 };
    const g = gridForSession('25k', [], head);
    expect(g.step).toBe(g25.step);
    expect(g.origin[0]).toBeLessThanOrEqual(head.min[0] - HEAD_ROOM[0] + 1e-9);
    expect(top(g, 0)).toBeGreaterThanOrEqual(head.max[0] + HEAD_ROOM[0] - 1e-9);
    expect(top(g, 1)).toBeGreaterThanOrEqual(head.max[1] + HEAD_ROOM[1] - 1e-9);
    expect(g.origin[2]).toBeLessThanOrEqual(head.min[2] - HEAD_ROOM[2] + 1e-9);
    expect(top(g, 2)).toBeGreaterThanOrEqual(head.max[2] + HEAD_ROOM[2] - 1e-9);
    // the floor stays the preset's: a body below it is not hair space
    expect(g.origin[1]).toBeCloseTo(g25.origin[1], 12);
    // a head inside the default box leaves the preset grid
    const small = { min: [-0.5, -1, -0.5] as Vec3, max: [0.5, 0.9, 0.6] as Vec3 };
    expect(sameGrid(gridForSession('25k', [], small), g25)).toBe(true);
  });
});
