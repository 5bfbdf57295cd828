// Dividing curves on the TypeScript side (method S4.5; their scalp normals come from
// head/head.ts Head.normalAt): the local frames (the same formulas as solver-cpp/src/
// dividing_constraints.hpp, for display: the yellow lines of Fig. 2), the tilt a hint stroke
// asks for.
import type { CurveParamValues } from './curveParams';
import { add, cross, dot, length, normalize, scale, sub, type Vec3 } from './vec3';

/** A parting's profile and tilts: its rows of curveParams.ts CURVE_PARAMS.dividing (sigma and h
 *  in grid steps, alpha0 and alpha1 in radians at its first and last point). */
export type DividingSettings = CurveParamValues<'dividing'>;

export interface DividingFrame {
  origin: Vec3;
  x: Vec3;
  y: Vec3;
  z: Vec3;
  alpha: number;
}

/** Frames as in dividing_constraints.hpp; null where the tangent is parallel to the normal. */
export function dividingFrames(
  points: readonly Vec3[],
  normals: readonly Vec3[],
  alpha0: number,
  alpha1: number,
): (DividingFrame | null)[] {
  const n = points.length;
  if (n < 2) return points.map(() => null);
  return points.map((p, i) => {
    const y = normalize(normals[i]);
    let t = sub(points[Math.min(n - 1, i + 1)], points[Math.max(0, i - 1)]);
    t = sub(t, scale(y, dot(t, y)));
    if (length(t) < 1e-12) return null;
    t = normalize(t);
    const alpha = alpha0 + ((alpha1 - alpha0) * i) / (n - 1);
    const z = add(scale(t, Math.cos(alpha)), scale(cross(y, t), Math.sin(alpha)));
    return { origin: p, x: cross(y, z), y, z, alpha };
  });
}

/**
 * The tilt a hint stroke drawn beside the curve asks for, at the frame nearest the stroke's
 * first point: the side is sign((start - p) . x(0)); the stroke's direction D, flattened onto
 * the tangent plane, should become side * x(α). With b = y × t, x(α) = cos α b − sin α t, so
 * α = atan2(−(side D) · t, (side D) · b). `end` says which parameter to set: 'alpha0' when the
 * nearest frame is in the curve's first half, else 'alpha1'. Null for a degenerate stroke.
 */
export function tiltFromHint(
  points: readonly Vec3[],
  normals: readonly Vec3[],
  stroke: readonly Vec3[],
): { alpha: number; side: 1 | -1; end: 'alpha0' | 'alpha1'; index: number } | null {
  if (stroke.length < 2 || points.length < 2) return null;
  const frames = dividingFrames(points, normals, 0, 0);
  let index = -1;
  let best = Number.POSITIVE_INFINITY;
  frames.forEach((f, i) => {
    if (!f) return;
    const d = length(sub(stroke[0], f.origin));
    if (d < best) {
      best = d;
      index = i;
    }
  });
  if (index < 0) return null;
  const f = frames[index] as DividingFrame;
  const side: 1 | -1 = dot(sub(stroke[0], f.origin), f.x) >= 0 ? 1 : -1;
  let D = sub(stroke[stroke.length - 1], stroke[0]);
  D = sub(D, scale(f.y, dot(D, f.y)));
  if (length(D) < 1e-12) return null;
  D = scale(normalize(D), side);
  // With alpha = 0: t = z, b = x.
  const alpha = Math.atan2(-dot(D, f.z), dot(D, f.x));
  return { alpha, side, end: index <= (points.length - 1) / 2 ? 'alpha0' : 'alpha1', index };
}
