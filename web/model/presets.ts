// Built-in hairstyles, made of stream curves sketched in code the way a user would: each curve
// starts on the scalp, follows the head a little above it and then falls (SPEC S4.1).
import { resamplePolyline } from './resample';
import type { SessionState, StyleCurve, Viewpoint } from './session';
import { add, scale, sphericalDirection, type Vec3 } from './vec3';

export interface PresetContext {
  /** Outermost head point at spherical angles from the head center, or null. */
  headPoint(thetaDeg: number, phiDeg: number): Vec3 | null;
  center: Vec3;
  step: number; // grid step d
  viewpoint: Viewpoint;
}

export const PRESET_NAMES = ['default', 'empty'] as const;
export type PresetName = (typeof PRESET_NAMES)[number];

export function isPresetName(s: string): s is PresetName {
  return (PRESET_NAMES as readonly string[]).includes(s);
}

interface SweepSpec {
  theta: [number, number]; // θ from → to, degrees
  phi: [number, number]; // φ from → to, degrees
  lift: number; // height above the head at the end of the sweep, world units
  fall: number; // length of the free fall below the sweep, world units
}

// Shoulder-length hair swept back from the face and falling behind the ears.
const DEFAULT_SWEEPS: SweepSpec[] = [
  // Front hairline: combed to the sides, away from the face (a centre parting).
  { theta: [46, 86], phi: [6, 84], lift: 0.14, fall: 1.1 },
  { theta: [46, 86], phi: [-6, -84], lift: 0.14, fall: 1.1 },
  { theta: [18, 92], phi: [25, 75], lift: 0.16, fall: 1.2 },
  { theta: [18, 92], phi: [-25, -75], lift: 0.16, fall: 1.2 },
  { theta: [22, 98], phi: [70, 112], lift: 0.16, fall: 1.4 },
  { theta: [22, 98], phi: [-70, -112], lift: 0.16, fall: 1.4 },
  { theta: [15, 104], phi: [120, 145], lift: 0.15, fall: 1.5 },
  { theta: [15, 104], phi: [-120, -145], lift: 0.15, fall: 1.5 },
  { theta: [10, 110], phi: [170, 178], lift: 0.14, fall: 1.5 },
  { theta: [10, 110], phi: [-170, -178], lift: 0.14, fall: 1.5 },
];

function sweepCurve(ctx: PresetContext, spec: SweepSpec): Vec3[] | null {
  const dense: Vec3[] = [];
  const n = 80;
  for (let i = 0; i <= n; i++) {
    const s = i / n;
    const theta = spec.theta[0] + (spec.theta[1] - spec.theta[0]) * s;
    const phi = spec.phi[0] + (spec.phi[1] - spec.phi[0]) * s;
    const hit = ctx.headPoint(theta, phi);
    if (!hit) return null;
    const lift = spec.lift * Math.min(1, s / 0.25);
    dense.push(add(hit, scale(sphericalDirection(theta, phi), lift)));
  }
  // Free fall: straight down, easing slightly outward.
  const last = dense[dense.length - 1];
  const out = sphericalDirection(90, spec.phi[1]);
  for (let i = 1; i <= 40; i++) {
    const s = i / 40;
    dense.push(add(last, add(scale([0, -1, 0], spec.fall * s), scale(out, 0.12 * s * s))));
  }
  return dense;
}

export function presetCurves(name: PresetName, ctx: PresetContext): StyleCurve[] {
  if (name === 'empty') return [];
  const curves: StyleCurve[] = [];
  for (const spec of DEFAULT_SWEEPS) {
    const dense = sweepCurve(ctx, spec);
    if (!dense) continue;
    const points = resamplePolyline(dense, ctx.step);
    if (points.length < 2) continue;
    curves.push({
      id: `c${curves.length + 1}`,
      type: 'stream',
      points,
      extend: true,
      viewpoint: ctx.viewpoint,
    });
  }
  return curves;
}

export function applyPreset(s: SessionState, name: PresetName, ctx: PresetContext): SessionState {
  return { ...s, curves: presetCurves(name, ctx) };
}
