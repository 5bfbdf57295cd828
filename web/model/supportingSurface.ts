// Supporting surface of a stream curve (method S4.3, paper §5 and Fig. 3a/b), relative to the
// curve's own viewpoint (eye). Two modes:
//
//  'ruled': the degenerate ruled surface between the curve and the eye. Segment i (p_i -> p_i+1)
//     spans the plane of the triangle (eye, p_i, p_i+1); for picking it is truncated to a band
//     along the view rays: p ± W r_i with r_i = unit(p_i - eye) (the near side clamped to 95% of
//     the way to the eye). Every quad lies in its segment's eye plane; consecutive quads share
//     the ray through their common point, so the band is continuous. Seen from the eye the
//     surface is edge-on: it is the set of points that keep the curve's image, for editing depth
//     from another view.
//  'strip': lines locally orthogonal to each triangle (eye, p_i, p_i+1): segment i's quad is
//     p ± W n_i (p on the segment), n_i = unit((p_i - eye) x (p_i+1 - eye)), the normal of that
//     triangle. Where consecutive normals differ, a wedge of two triangles (p_j, p_j ± W n_j-1,
//     p_j ± W n_j) closes the gap. Seen from the eye the strip faces the viewer: it keeps the
//     curve's depth while its image is redrawn.
//
// Surface coordinates of a point x on segment i's quad: the curve parameter i + u (u in [0, 1],
// point-index units) and the signed offset from the curve (world units): 'ruled' — along the
// view ray through p_i + u (p_i+1 - p_i) (positive away from the eye); 'strip' — along n_i.
// On a wedge: parameter j, offset ± |x - p_j|.
import { add, cross, dot, length, normalize, scale, sub, type Vec3 } from './vec3';

export type SurfaceMode = 'ruled' | 'strip';

export interface SupportingSurface {
  mode: SurfaceMode;
  eye: Vec3;
  curve: readonly Vec3[];
  halfWidth: number; // W, world units
  positions: Float32Array; // positions[3 * vertex + axis]
  indices: Uint32Array; // indices[3 * triangle + corner]
  /** triangleSegment[t] = segment i of triangle t; wedges at joint j use -(j + 1). */
  triangleSegment: Int32Array;
  /** Unit normal of each segment's eye triangle (eye, p_i, p_i+1): segmentNormal[i]. */
  segmentNormal: Vec3[];
}

export interface SurfaceHit {
  point: Vec3;
  rayT: number; // distance along the (unit) ray
  segment: number; // segment i, or the joint index for a wedge hit
  param: number; // curve parameter i + u, point-index units
  nearestIndex: number; // Math.round(param), clamped to the curve
  offset: number; // signed offset from the curve within the surface, world units
  distance: number; // |offset|
}

/** Unit normal of the triangle (eye, a, b), or null when degenerate. */
export function eyeTriangleNormal(eye: Vec3, a: Vec3, b: Vec3): Vec3 | null {
  const n = cross(sub(a, eye), sub(b, eye));
  const l = length(n);
  const scaleRef = length(sub(a, eye)) * length(sub(b, a));
  return l > 1e-12 * scaleRef && l > 0 ? scale(n, 1 / l) : null;
}

/**
 * Builds the surface. `halfWidth` W is in world units (e.g. 6 grid steps). Degenerate segments
 * (zero length or pointing at the eye) get a normal copied from a neighbour; a curve whose every
 * segment is degenerate gives an empty surface.
 */
export function buildSupportingSurface(
  curve: readonly Vec3[],
  eye: Vec3,
  mode: SurfaceMode,
  halfWidth: number,
): SupportingSurface {
  if (!(halfWidth > 0)) throw new RangeError(`halfWidth must be > 0, got ${halfWidth}`);
  const segs = Math.max(0, curve.length - 1);
  const normals: (Vec3 | null)[] = [];
  for (let i = 0; i < segs; i++) normals.push(eyeTriangleNormal(eye, curve[i], curve[i + 1]));
  // Fill degenerate normals from the nearest valid neighbour (forward, then backward).
  let last: Vec3 | null = null;
  for (let i = 0; i < segs; i++) {
    if (normals[i]) last = normals[i];
    else if (last) normals[i] = last;
  }
  last = null;
  for (let i = segs - 1; i >= 0; i--) {
    if (normals[i]) last = normals[i];
    else if (last) normals[i] = last;
  }
  const segmentNormal = normals.map((n) => n ?? ([0, 0, 0] as Vec3));
  const pos: number[] = [];
  const idx: number[] = [];
  const triSeg: number[] = [];
  const vert = (p: Vec3): number => {
    pos.push(p[0], p[1], p[2]);
    return pos.length / 3 - 1;
  };
  const quad = (a: number, b: number, c: number, d: number, tag: number) => {
    // a-b along the curve on one side, d-c on the other: triangles (a, b, c), (a, c, d).
    idx.push(a, b, c, a, c, d);
    triSeg.push(tag, tag);
  };
  if (segs > 0 && normals[0] !== null) {
    if (mode === 'ruled') {
      const ends = curve.map((p) => {
        const r = sub(p, eye);
        const dist = length(r);
        const u = normalize(r);
        const near = Math.min(halfWidth, 0.95 * dist);
        return [vert(sub(p, scale(u, near))), vert(add(p, scale(u, halfWidth)))];
      });
      for (let i = 0; i < segs; i++)
        quad(ends[i][0], ends[i + 1][0], ends[i + 1][1], ends[i][1], i);
    } else {
      for (let i = 0; i < segs; i++) {
        const n = scale(segmentNormal[i], halfWidth);
        const a = curve[i];
        const b = curve[i + 1];
        quad(vert(sub(a, n)), vert(sub(b, n)), vert(add(b, n)), vert(add(a, n)), i);
        if (i + 1 < segs && dot(segmentNormal[i], segmentNormal[i + 1]) < 1 - 1e-12) {
          const m = scale(segmentNormal[i + 1], halfWidth);
          const c = vert(b);
          idx.push(c, vert(add(b, n)), vert(add(b, m)));
          idx.push(c, vert(sub(b, m)), vert(sub(b, n)));
          triSeg.push(-(i + 2), -(i + 2));
        }
      }
    }
  }
  return {
    mode,
    eye,
    curve,
    halfWidth,
    positions: new Float32Array(pos),
    indices: new Uint32Array(idx),
    triangleSegment: new Int32Array(triSeg),
    segmentNormal,
  };
}

/** Barycentric slack of a ray-triangle hit: positions are float32, so a ray through a shared
 *  vertex or edge (a stroke ending exactly on a curve point) could otherwise slip between the
 *  triangles around it. Overlaps it creates are harmless: the nearest hit is taken. */
const BARY_SLACK = 1e-5;

/** Ray (origin, unit direction) against one triangle (Möller–Trumbore, both sides). */
function rayTriangle(o: Vec3, d: Vec3, a: Vec3, b: Vec3, c: Vec3): number | null {
  const e1 = sub(b, a);
  const e2 = sub(c, a);
  const p = cross(d, e2);
  const det = dot(e1, p);
  if (Math.abs(det) < 1e-14) return null;
  const inv = 1 / det;
  const s = sub(o, a);
  const u = dot(s, p) * inv;
  if (u < -BARY_SLACK || u > 1 + BARY_SLACK) return null;
  const q = cross(s, e1);
  const v = dot(d, q) * inv;
  if (v < -BARY_SLACK || u + v > 1 + BARY_SLACK) return null;
  const t = dot(e2, q) * inv;
  return t > 0 ? t : null;
}

/** Surface coordinates (param, offset) of a point x on segment i's quad (see the header). */
export function surfaceCoordinates(
  surf: SupportingSurface,
  x: Vec3,
  segment: number,
): { param: number; offset: number } {
  const a = surf.curve[segment];
  const b = surf.curve[segment + 1];
  const e = sub(b, a);
  if (surf.mode === 'strip') {
    const ee = dot(e, e);
    const u = ee > 0 ? Math.min(1, Math.max(0, dot(sub(x, a), e) / ee)) : 0;
    return { param: segment + u, offset: dot(sub(x, a), surf.segmentNormal[segment]) };
  }
  // Ruled: intersect the line (eye, x) with the segment line, in their common plane.
  const eye = surf.eye;
  const r = sub(x, eye);
  // Solve eye + s r = a + u e in least squares (the two lines are coplanar).
  const w = sub(a, eye);
  const rr = dot(r, r);
  const re = dot(r, e);
  const ee = dot(e, e);
  const rw = dot(r, w);
  const ew = dot(e, w);
  const det = rr * ee - re * re;
  let u = 0;
  if (Math.abs(det) > 1e-18 * rr * ee) u = (re * rw - rr * ew) / det;
  u = Math.min(1, Math.max(0, u));
  const c = add(a, scale(e, u));
  const toC = sub(c, eye);
  const dist = length(sub(x, c));
  const sign = length(r) >= length(toC) ? 1 : -1;
  return { param: segment + u, offset: sign * dist };
}

/** Nearest hit of the ray (origin, unit direction) on the surface, or null. */
export function intersectSupportingSurface(
  surf: SupportingSurface,
  origin: Vec3,
  direction: Vec3,
): SurfaceHit | null {
  const P = surf.positions;
  const I = surf.indices;
  const v = (k: number): Vec3 => [P[3 * k], P[3 * k + 1], P[3 * k + 2]];
  let bestT = Number.POSITIVE_INFINITY;
  let bestTri = -1;
  for (let t = 0; t < I.length / 3; t++) {
    const hit = rayTriangle(origin, direction, v(I[3 * t]), v(I[3 * t + 1]), v(I[3 * t + 2]));
    if (hit !== null && hit < bestT) {
      bestT = hit;
      bestTri = t;
    }
  }
  if (bestTri < 0) return null;
  const point = add(origin, scale(direction, bestT));
  const tag = surf.triangleSegment[bestTri];
  let param: number;
  let offset: number;
  let segment: number;
  if (tag >= 0) {
    segment = tag;
    ({ param, offset } = surfaceCoordinates(surf, point, tag));
  } else {
    segment = -tag - 1;
    param = segment;
    const n = surf.segmentNormal[segment - 1];
    const rel = sub(point, surf.curve[segment]);
    offset = (dot(rel, n) >= 0 ? 1 : -1) * length(rel);
  }
  const last = surf.curve.length - 1;
  return {
    point,
    rayT: bestT,
    segment,
    param,
    nearestIndex: Math.min(last, Math.max(0, Math.round(param))),
    offset,
    distance: Math.abs(offset),
  };
}
