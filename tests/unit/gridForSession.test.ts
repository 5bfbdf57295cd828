// The session's bounding volume: the preset's grid when the curves fit, grown on the same lattice
// (same step, origin moved by whole steps) until every curve point has FIT_MARGIN_STEPS steps to
// the faces, and never by more than FIT_MAX_GROWTH per side; and downward (with room beside it)
// until hair of the session's maximum length hangs from the scalp's lowest root inside it.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import {
  FIT_MARGIN_STEPS,
  FIT_MAX_GROWTH,
  GRID_PRESETS,
  type GridPreset,
  gridForPreset,
  gridForSession,
  gridPointCount,
  HANG_MAX_SIDE,
  HEAD_ROOM,
  MAX_HAIR_LENGTH,
  SCALP_BOTTOM_Y,
  sameGrid,
} from '../../web/model/grid';
import type { Vec3 } from '../../web/model/vec3';
import { loadRawSolver } from '../../web/solver/wasmEngine';

/** A maximum length whose hair hangs inside the default box (20 cm). */
const SHORT = 2;

const g25 = gridForPreset('25k');
const top = (g: typeof g25, a: number) => g.origin[a] + g.step * (g.dims[a] - 1);

describe('gridForSession', () => {
  it('is the preset grid when the curves fit inside it with the margin', () => {
    const pts: Vec3[] = [
      [0, 1, 0],
      [0.5, -1.5, 0.3],
    ];
    expect(sameGrid(gridForSession('25k', [{ points: pts }], undefined, SHORT), g25)).toBe(true);
    expect(sameGrid(gridForSession('25k', [], undefined, SHORT), g25)).toBe(true);
  });

  it('grows downward to hold a long curve, on the same lattice', () => {
    const low: Vec3 = [0.2, g25.origin[1] - 0.5, 0];
    const g = gridForSession('25k', [{ points: [[0, 1, 0], low] }], undefined, SHORT);
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
    const g = gridForSession('25k', [{ points: [far] }], undefined, SHORT);
    expect(g25.origin[1] - g.origin[1]).toBeLessThanOrEqual(FIT_MAX_GROWTH + 1e-9);
    expect(top(g, 0) - top(g25, 0)).toBeLessThanOrEqual(FIT_MAX_GROWTH + 1e-9);
    expect(top(g, 0) - top(g25, 0)).toBeGreaterThan(FIT_MAX_GROWTH - g.step);
  });

  it('holds a loaded head with the built-in head’s room around it (not below the floor)', () => {
    // a head 1.5× the built-in one: bounds from a hand-made box
    const head = { min: [-1.2, -4, -1.6] as Vec3, max: [1.2, 1.5, 1.8] as Vec3 };
    const g = gridForSession('25k', [], head, SHORT);
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
    expect(sameGrid(gridForSession('25k', [], small, SHORT), g25)).toBe(true);
  });

  it('holds hair of the maximum length (100 cm) hanging from the lowest scalp root', () => {
    const g = gridForSession('25k', [], undefined, MAX_HAIR_LENGTH);
    expect(g.step).toBe(g25.step);
    // the tips of hair hanging straight down from the nape have a step to the floor, and the
    // floor is less than a step lower than that
    const tip = SCALP_BOTTOM_Y - MAX_HAIR_LENGTH;
    expect(tip - g.origin[1]).toBeGreaterThanOrEqual(g.step - 1e-9);
    expect(tip - g.origin[1]).toBeLessThan(2 * g.step);
    // same lattice, same top
    const shift = (g25.origin[1] - g.origin[1]) / g.step;
    expect(Math.abs(shift - Math.round(shift))).toBeLessThan(1e-9);
    expect(top(g, 1)).toBeCloseTo(top(g25, 1), 12);
    // room beside the hanging hair: more than the default box, at most HANG_MAX_SIDE a side
    for (const a of [0, 2]) {
      expect(g.origin[a]).toBeLessThan(g25.origin[a] - 1e-9);
      expect(g25.origin[a] - g.origin[a]).toBeLessThanOrEqual(HANG_MAX_SIDE + 1e-9);
      expect(top(g, a) - top(g25, a)).toBeCloseTo(g25.origin[a] - g.origin[a], 9);
    }
    // a longer setting holds no more (the session reader refuses it anyway)
    expect(sameGrid(gridForSession('25k', [], undefined, 50), g)).toBe(true);
    // shorter hair needs a smaller box; the default 32 cm needs some of it
    const g32 = gridForSession('25k', [], undefined, 3.2);
    expect(g32.origin[1]).toBeGreaterThan(g.origin[1]);
    expect(g32.origin[1]).toBeLessThan(g25.origin[1]);
  });

  it('prints the grid points of each preset for 20, 32, 60 and 100 cm; the fast solver fits', async () => {
    const wasmBinary = readFileSync('web/generated/hairsolver.wasm');
    const s = await loadRawSolver('fast', { wasmBinary });
    for (const preset of Object.keys(GRID_PRESETS) as GridPreset[]) {
      const row = [SHORT, 3.2, 6, MAX_HAIR_LENGTH].map((L) => {
        const g = gridForSession(preset, [], undefined, L);
        expect(gridPointCount(g)).toBe(g.dims[0] * g.dims[1] * g.dims[2]);
        const { needsBytes, capBytes } = s.estimate(g.dims);
        expect(needsBytes).toBeLessThan(capBytes);
        return `${L * 10} cm ${gridPointCount(g).toLocaleString('en-US')} (${g.dims.join('×')}, ${(needsBytes / 2 ** 20).toFixed(0)} MB)`;
      });
      console.log(
        `[grid] ${preset} (preset ${gridPointCount(gridForPreset(preset)).toLocaleString('en-US')}): ${row.join(' · ')}`,
      );
    }
    s.dispose();
    // 100 cm at 25k: about four times the default box
    const g = gridForSession('25k', [], undefined, MAX_HAIR_LENGTH);
    expect(gridPointCount(g)).toBeGreaterThan(3 * gridPointCount(g25));
    expect(gridPointCount(g)).toBeLessThan(5 * gridPointCount(g25));
  });
});
