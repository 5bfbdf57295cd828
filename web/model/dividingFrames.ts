// Dividing curves on the TypeScript side (SPEC S4.5): the per-point scalp normals the protocol's
// dividing block needs, the local frames (the same formulas as solver-cpp/src/
// dividing_constraints.hpp, for display: the yellow lines of Fig. 2), the tilt a hint stroke
// asks for, and packing to the parameter block.

import type { TriangleSoup } from '../head/head';
import { add, dot, length, normalize, scale, sub, type Vec3 } from './vec3';

export interface DividingSettings {
  sigma: number; // grid steps (default 1)
  h: number; // grid steps (default 0.5)
  alpha0: number; // radians, tilt at the first point
  alpha1: number; // radians, tilt at the last point
}

const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];

/** Closest point of triangle (a, b, c) to p as barycentric weights (Voronoi regions). */
function closestBarycentric(p: Vec3, a: Vec3, b: Vec3, c: Vec3): Vec3 {
  const ab = sub(b, a);
  const ac = sub(c, a);
  const ap = sub(p, a);
  const d1 = dot(ab, ap);
  const d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return [1, 0, 0];
  const bp = sub(p, b);
  const d3 = dot(ab, bp);
  const d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return [0, 1, 0];
  const vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const t = d1 / (d1 - d3);
    return [1 - t, t, 0];
  }
  const cp = sub(p, c);
  const d5 = dot(ab, cp);
  const d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return [0, 0, 1];
  const vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const t = d2 / (d2 - d6);
    return [1 - t, 0, t];
  }
  const va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const t = (d4 - d3) / (d4 - d3 + (d5 - d6));
    return [0, 1 - t, t];
  }
  const den = 1 / (va + vb + vc);
  return [1 - (vb + vc) * den, vb * den, vc * den];
}

/**
 * Scalp normals at the points: the head mesh's area-weighted vertex normals (counter-clockwise
 * = outward), interpolated at each point's nearest surface point — the same definition as the
 * solver's scalp avoidance. Brute force over the triangles (fine for a stroke's few dozen
 * points; the app may instead pass normals from HeadPicker's BVH).
 */
export function scalpNormalsAt(points: readonly Vec3[], mesh: TriangleSoup): Vec3[] {
  const P = mesh.positions;
  const I = mesh.indices;
  const nv = P.length / 3;
  const vn = new Float64Array(3 * nv);
  const v = (k: number): Vec3 => [P[3 * k], P[3 * k + 1], P[3 * k + 2]];
  for (let t = 0; t < I.length; t += 3) {
    const fn = cross(sub(v(I[t + 1]), v(I[t])), sub(v(I[t + 2]), v(I[t])));
    for (let c = 0; c < 3; c++) for (let a = 0; a < 3; a++) vn[3 * I[t + c] + a] += fn[a];
  }
  const nrm = (k: number): Vec3 => normalize([vn[3 * k], vn[3 * k + 1], vn[3 * k + 2]]);
  return points.map((p) => {
    let best = Number.POSITIVE_INFINITY;
    let out: Vec3 = [0, 1, 0];
    for (let t = 0; t < I.length; t += 3) {
      const a = v(I[t]);
      const b = v(I[t + 1]);
      const c = v(I[t + 2]);
      const w = closestBarycentric(p, a, b, c);
      const q = add(add(scale(a, w[0]), scale(b, w[1])), scale(c, w[2]));
      const d = length(sub(p, q));
      if (d < best) {
        best = d;
        const n = add(
          add(scale(nrm(I[t]), w[0]), scale(nrm(I[t + 1]), w[1])),
          scale(nrm(I[t + 2]), w[2]),
        );
        out = length(n) > 0 ? normalize(n) : normalize(cross(sub(b, a), sub(c, a)));
      }
    }
    return out;
  });
}

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
