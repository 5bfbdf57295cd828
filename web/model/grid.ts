// Grid presets over the fixed bounding volume of the built-in head (SPEC S1.2).
import type { GridSpec } from '../solver/protocol';
import type { Vec3 } from './vec3';

export const BOX_MIN: Vec3 = [-1.7, -2.9, -1.7];
export const BOX_MAX: Vec3 = [1.7, 1.5, 1.7];

/** Grid points per preset: the paper's two (§6) and two finer ones for the multigrid path. */
export const GRID_PRESETS = {
  '25k': 25_000,
  '50k': 50_000,
  '100k': 100_000,
  '250k': 250_000,
} as const;
export type GridPreset = keyof typeof GRID_PRESETS;

export function isGridPreset(s: string): s is GridPreset {
  return Object.hasOwn(GRID_PRESETS, s);
}

/** The grid whose point count is closest to the preset's target, centred in the box. */
export function gridForPreset(preset: GridPreset): GridSpec {
  const target = GRID_PRESETS[preset];
  const ext = [0, 1, 2].map((a) => BOX_MAX[a] - BOX_MIN[a]);
  const dimsFor = (d: number) =>
    ext.map((e) => Math.floor(e / d + 1e-9) + 1) as [number, number, number];
  let d = Math.cbrt((ext[0] * ext[1] * ext[2]) / target);
  let best = d;
  let bestErr = Number.POSITIVE_INFINITY;
  for (let i = 0; i < 200; i++) {
    const dims = dimsFor(d);
    const err = Math.abs(dims[0] * dims[1] * dims[2] - target);
    if (err < bestErr) {
      bestErr = err;
      best = d;
    }
    d *= 0.999;
  }
  const dims = dimsFor(best);
  const origin = [0, 1, 2].map(
    (a) => (BOX_MIN[a] + BOX_MAX[a]) / 2 - ((dims[a] - 1) * best) / 2,
  ) as Vec3;
  return { dims, origin, step: best };
}

/** Grid steps kept between a curve's last point and the faces of a fitted volume: the fading
 *  extension past a curve's end (4 steps, S4.1) and the strands' fall to below the growth
 *  threshold. Every other point keeps one step. */
export const FIT_MARGIN_STEPS = 6;
/** A fitted volume grows past the default box by at most this on each side (world units), so
 *  a stroke at the edge of the working volume cannot ask for an unbounded grid. */
export const FIT_MAX_GROWTH = 2.0;

/** Room the default box leaves around the built-in head (x each side, above, z each side). */
export const HEAD_ROOM: Vec3 = [0.9, 0.5, 0.5];

/** The preset's grid, grown (same step, same lattice) until the bounding volume holds every
 *  point of `curves` with a step to spare and each curve's end with FIT_MARGIN_STEPS, so the
 *  hair the curves ask for is not cut flat where the default box ends. The default box when the
 *  curves fit in it. */
export function gridForSession(
  preset: GridPreset,
  curves: readonly { points: readonly Vec3[] }[],
  /** A loaded head's bounds (absent for the built-in head, which the default box holds): the
   *  volume also holds the head above the box's floor with the built-in head's room around it
   *  (HEAD_ROOM), so long hair on a bigger head has space. */
  headBounds?: { min: Vec3; max: Vec3 },
): GridSpec {
  const g = gridForPreset(preset);
  const lo: Vec3 = [...g.origin];
  const hi = [0, 1, 2].map((a) => g.origin[a] + g.step * (g.dims[a] - 1)) as Vec3;
  const hold = (p: Vec3, m: number) => {
    for (let a = 0; a < 3; a++) {
      if (p[a] - m < lo[a]) lo[a] = p[a] - m;
      if (p[a] + m > hi[a]) hi[a] = p[a] + m;
    }
  };
  if (headBounds) {
    for (let a = 0; a < 3; a++) {
      const bottom = a === 1 ? Math.max(headBounds.min[a], g.origin[a]) : headBounds.min[a];
      lo[a] = Math.min(lo[a], bottom - (a === 1 ? 0 : HEAD_ROOM[a]));
      hi[a] = Math.max(hi[a], headBounds.max[a] + HEAD_ROOM[a]);
    }
  }
  for (const c of curves) {
    for (const p of c.points) hold(p, g.step);
    if (c.points.length) hold(c.points[c.points.length - 1], FIT_MARGIN_STEPS * g.step);
  }
  const origin = [...g.origin] as Vec3;
  const dims = [...g.dims] as [number, number, number];
  for (let a = 0; a < 3; a++) {
    const below = Math.min(
      Math.ceil((g.origin[a] - lo[a]) / g.step - 1e-9),
      Math.floor(FIT_MAX_GROWTH / g.step),
    );
    const top = g.origin[a] + g.step * (g.dims[a] - 1);
    const above = Math.min(
      Math.ceil((hi[a] - top) / g.step - 1e-9),
      Math.floor(FIT_MAX_GROWTH / g.step),
    );
    if (below > 0) {
      origin[a] = g.origin[a] - below * g.step;
      dims[a] += below;
    }
    if (above > 0) dims[a] += above;
  }
  return { dims, origin, step: g.step };
}

export const sameGrid = (a: GridSpec, b: GridSpec): boolean =>
  a.step === b.step &&
  a.dims.every((d, i) => d === b.dims[i]) &&
  a.origin.every((o, i) => o === b.origin[i]);

export const gridPointCount = (g: GridSpec): number => g.dims[0] * g.dims[1] * g.dims[2];
