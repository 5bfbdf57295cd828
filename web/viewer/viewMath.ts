// Camera arithmetic of the viewer, free of three.js and the DOM: orbit speed and view transitions.
import type { Vec3 } from '../model/vec3';

export interface CameraView {
  position: Vec3;
  target: Vec3;
}

/** Degrees a horizontal drag across the whole view orbits at speed factor 1. */
export const ORBIT_DEGREES_PER_WIDTH = 180;

/** OrbitControls.rotateSpeed giving ORBIT_DEGREES_PER_WIDTH · factor degrees per drag across a
 *  `width` × `height` px view. OrbitControls turns 360° · rotateSpeed per `height` px (the same
 *  rate vertically), so degrees per px = 360 · rotateSpeed / height. */
export function orbitRotateSpeed(width: number, height: number, factor = 1): number {
  const w = Math.max(1, width);
  const h = Math.max(1, height);
  const f = Number.isFinite(factor) && factor > 0 ? factor : 1;
  return (f * ORBIT_DEGREES_PER_WIDTH * h) / (360 * w);
}

/** Degrees OrbitControls turns for a drag of `px` pixels at `rotateSpeed` on a view `height` px
 *  high (its own formula, for checking orbitRotateSpeed). */
export function orbitDegrees(px: number, height: number, rotateSpeed: number): number {
  return (360 * rotateSpeed * px) / Math.max(1, height);
}

/** Smooth start and stop: 0 → 0, 1 → 1, zero slope at both ends. */
export function easeInOut(t: number): number {
  const x = Math.min(1, Math.max(0, t));
  return x * x * (3 - 2 * x);
}

/** The view a fraction t (0..1) of the way from `a` to `b`: the target moves in a straight line,
 *  the camera swings around it (direction along the great circle, distance linearly), so the head
 *  stays framed throughout. */
export function interpolateView(a: CameraView, b: CameraView, t: number): CameraView {
  const s = Math.min(1, Math.max(0, t));
  const target = lerp3(a.target, b.target, s);
  const oa = sub3(a.position, a.target);
  const ob = sub3(b.position, b.target);
  const la = len3(oa);
  const lb = len3(ob);
  const dist = la + (lb - la) * s;
  const dir = slerpDir(
    la > 0 ? scale3(oa, 1 / la) : [0, 0, 1],
    lb > 0 ? scale3(ob, 1 / lb) : [0, 0, 1],
    s,
  );
  return { target, position: add3(target, scale3(dir, dist)) };
}

/** Spherical interpolation of unit vectors (a straight lerp when they are nearly equal or
 *  opposite; opposite ones turn about an axis perpendicular to a, through "up" when possible). */
function slerpDir(a: Vec3, b: Vec3, t: number): Vec3 {
  const d = Math.min(1, Math.max(-1, dot3(a, b)));
  if (d > 0.9995) return normalize3(lerp3(a, b, t));
  let omega = Math.acos(d);
  let bb = b;
  if (d < -0.9995) {
    // opposite: go through a perpendicular direction
    const up: Vec3 = Math.abs(a[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0];
    const perp = normalize3(sub3(up, scale3(a, dot3(up, a))));
    bb = perp;
    omega = Math.PI / 2;
    t *= 2;
    if (t > 1) return slerpDir(perp, b, t - 1);
  }
  const so = Math.sin(omega);
  const ka = Math.sin((1 - t) * omega) / so;
  const kb = Math.sin(t * omega) / so;
  return add3(scale3(a, ka), scale3(bb, kb));
}

/** An axis-aligned box (world units). */
export interface Bounds {
  min: Vec3;
  max: Vec3;
}

/** The view that frames `bounds` as `home` frames `reference` (the built-in head in the default
 *  view: the head fits below the toolbar with a margin): the same direction, the target at the
 *  same place relative to the box, the distance scaled so that the box's extent on screen fits
 *  where the reference's does: its height by the reference's height, its width by the
 *  reference's width or, when wider, by the room the view's `aspect` (width / height) leaves
 *  beside it at the same fill. The extents are the boxes' sides projected on the camera's up and
 *  right axes (world y up). `reference` itself gives `home`. */
export function frameBounds(
  bounds: Bounds,
  reference: Bounds,
  home: CameraView,
  aspect = 1,
): CameraView {
  const forward = normalize3(sub3(home.target, home.position));
  let right = cross3(forward, [0, 1, 0]);
  right = len3(right) > 1e-9 ? normalize3(right) : [1, 0, 0];
  const up = cross3(right, forward);
  const extent = (b: Bounds, axis: Vec3) =>
    [0, 1, 2].reduce((sum, a) => sum + Math.abs(axis[a]) * (b.max[a] - b.min[a]), 0);
  const hRef = extent(reference, up);
  const wRef = Math.max(extent(reference, right), hRef * (aspect > 0 ? aspect : 1));
  let s = 0;
  if (hRef > 0) s = Math.max(s, extent(bounds, up) / hRef);
  if (wRef > 0) s = Math.max(s, extent(bounds, right) / wRef);
  if (!(s > 0 && Number.isFinite(s))) s = 1;
  const centre = (b: Bounds): Vec3 => scale3(add3(b.min, b.max), 0.5);
  const target = add3(centre(bounds), scale3(sub3(home.target, centre(reference)), s));
  return { target, position: add3(target, scale3(sub3(home.position, home.target), s)) };
}

/** Whether two views are the same within `eps` world units. */
export function sameView(a: CameraView, b: CameraView, eps = 1e-6): boolean {
  return len3(sub3(a.position, b.position)) <= eps && len3(sub3(a.target, b.target)) <= eps;
}

const add3 = (a: Vec3, b: Vec3): Vec3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const sub3 = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const scale3 = (a: Vec3, k: number): Vec3 => [a[0] * k, a[1] * k, a[2] * k];
const dot3 = (a: Vec3, b: Vec3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const len3 = (a: Vec3): number => Math.sqrt(dot3(a, a));
const cross3 = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
const lerp3 = (a: Vec3, b: Vec3, t: number): Vec3 => [
  a[0] + (b[0] - a[0]) * t,
  a[1] + (b[1] - a[1]) * t,
  a[2] + (b[2] - a[2]) * t,
];
function normalize3(a: Vec3): Vec3 {
  const l = len3(a);
  return l > 0 ? scale3(a, 1 / l) : [0, 0, 1];
}
