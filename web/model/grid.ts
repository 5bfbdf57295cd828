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

export const gridPointCount = (g: GridSpec): number => g.dims[0] * g.dims[1] * g.dims[2];
