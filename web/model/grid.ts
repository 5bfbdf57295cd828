// Grid presets over the fixed bounding volume of the built-in head (method S1.2).
import type { GridSpec } from './hairArrays';
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

/** The longest hair a session may ask for (growth.maxLength, world units: 100 cm). */
export const MAX_HAIR_LENGTH = 10;

/** The constraint weight ω of the field's energy (method S3: ω = 100), every solve's. */
export const FIELD_OMEGA = 100;
/** Lowest y of the built-in head's scalp (its hairline at the nape, world units): hair of the
 *  session's maximum length hangs from here. A loaded head's cranium is placed where the built-in
 *  head's is (head/loadHead.ts) and its default scalp is the same region, so it ends about as
 *  low; scalp painted lower than the nape may grow hair that reaches the floor sooner. */
export const SCALP_BOTTOM_Y = -0.48;
/** Room beside hair hanging below the default box, as a fraction of the depth it hangs past the
 *  box's floor, per side in x and z (hair falling over the back and the chest drifts away from
 *  the head as it falls), at most HANG_MAX_SIDE (world units) per side. */
export const HANG_SIDE_ROOM = 0.1;
export const HANG_MAX_SIDE = 0.5;

/** The preset's grid, grown (same step, same lattice) until the bounding volume holds every
 *  point of `curves` with a step to spare and each curve's end with FIT_MARGIN_STEPS, so the
 *  hair the curves ask for is not cut flat where the default box ends; and downward until hair
 *  of `maxLength` hanging from the scalp's lowest root (SCALP_BOTTOM_Y) ends a step above the
 *  floor, with room beside it (HANG_SIDE_ROOM). The default box when all of that fits in it. */
export function gridForSession(
  preset: GridPreset,
  curves: readonly { points: readonly Vec3[] }[],
  /** A loaded head's bounds (undefined for the built-in head, which the default box holds): the
   *  volume also holds the head above the box's floor with the built-in head's room around it
   *  (HEAD_ROOM), so long hair on a bigger head has space. */
  headBounds: { min: Vec3; max: Vec3 } | undefined,
  /** How far hair may hang below the scalp (session.ts hangLength: the session's maximum length
   *  with natural fall, 0 without; at most MAX_HAIR_LENGTH is held). */
  maxLength: number,
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
  const steps = (need: number) => Math.max(0, Math.ceil(need / g.step - 1e-9));
  const capped = (need: number) => Math.min(steps(need), Math.floor(FIT_MAX_GROWTH / g.step));
  const below = [0, 1, 2].map((a) => capped(g.origin[a] - lo[a]));
  const above = [0, 1, 2].map((a) => capped(hi[a] - (g.origin[a] + g.step * (g.dims[a] - 1))));
  // long hair: the floor a step below its tips, and room beside it (not capped by
  // FIT_MAX_GROWTH: the session reader caps maxLength at MAX_HAIR_LENGTH)
  const length = Math.min(MAX_HAIR_LENGTH, Math.max(0, maxLength));
  const hang = steps(g.origin[1] - (SCALP_BOTTOM_Y - length - g.step));
  below[1] = Math.max(below[1], hang);
  const side = Math.min(Math.floor(HANG_SIDE_ROOM * hang), Math.floor(HANG_MAX_SIDE / g.step));
  for (const a of [0, 2]) {
    below[a] = Math.max(below[a], side);
    above[a] = Math.max(above[a], side);
  }
  const origin = [0, 1, 2].map((a) => g.origin[a] - below[a] * g.step) as Vec3;
  const dims = [0, 1, 2].map((a) => g.dims[a] + below[a] + above[a]) as [number, number, number];
  return { dims, origin, step: g.step };
}

export const sameGrid = (a: GridSpec, b: GridSpec): boolean =>
  a.step === b.step &&
  a.dims.every((d, i) => d === b.dims[i]) &&
  a.origin.every((o, i) => o === b.origin[i]);

export const gridPointCount = (g: GridSpec): number => g.dims[0] * g.dims[1] * g.dims[2];
