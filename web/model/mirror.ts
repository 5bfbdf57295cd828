// Mirror editing: a curve and its twin reflected across the head's symmetry plane (x = 0 for the
// built-in head: +x is the head's left; a loaded head's best left-right symmetry plane,
// head/symmetryPlane.ts, kept in the session as `symmetry`). The twins name each other in their
// `mirror` field; an edit of one is made to the other, mirrored, in the same command (one undo
// step).
import { defOf } from './kinds';
import type { StyleCurve, Viewpoint } from './session';
import type { Vec3 } from './vec3';

/** A mirror plane: the points p with normal · p = offset (normal a unit vector). */
export interface MirrorPlane {
  normal: Vec3;
  offset: number;
}

/** The built-in head's symmetry plane, x = 0. */
export const X_PLANE: MirrorPlane = { normal: [1, 0, 0], offset: 0 };

/** The reflection of point p across the plane (+ 0: no negative zeros in a session). */
export function reflectPoint(p: Vec3, plane: MirrorPlane = X_PLANE): Vec3 {
  const n = plane.normal;
  const k = 2 * (n[0] * p[0] + n[1] * p[1] + n[2] * p[2] - plane.offset);
  return [p[0] - k * n[0] + 0, p[1] - k * n[1] + 0, p[2] - k * n[2] + 0];
}

/** The reflection of direction v (no offset). */
export function reflectDirection(v: Vec3, plane: MirrorPlane = X_PLANE): Vec3 {
  const n = plane.normal;
  const k = 2 * (n[0] * v[0] + n[1] * v[1] + n[2] * v[2]);
  return [v[0] - k * n[0] + 0, v[1] - k * n[1] + 0, v[2] - k * n[2] + 0];
}

/** `c` reflected across the plane, named `id`, its twin `twinId`: its points and viewpoint here,
 *  its kind's own fields by its kind (kinds/; a parting's tilts change sign, the reflection
 *  turning its handedness); everything else is kept. */
export function mirrorCurve(
  c: StyleCurve,
  id: string,
  twinId: string,
  plane: MirrorPlane = X_PLANE,
): StyleCurve {
  const flip = (p: Vec3) => reflectPoint(p, plane);
  const flipDir = (v: Vec3) => reflectDirection(v, plane);
  const flipView = (v: Viewpoint): Viewpoint => ({
    position: flip(v.position),
    target: flip(v.target),
  });
  return {
    ...c,
    id,
    mirror: twinId,
    points: c.points.map(flip),
    viewpoint: flipView(c.viewpoint),
    ...defOf(c).mirror(c, flip, flipDir),
  } as StyleCurve;
}

/** True when the curve is its own mirror image (drawn along the plane, e.g. a centre parting):
 *  it gets no twin. */
export function isSelfMirror(
  c: StyleCurve,
  plane: MirrorPlane = X_PLANE,
  tolerance = 1e-3,
): boolean {
  const n = plane.normal;
  return c.points.every(
    (p) => Math.abs(n[0] * p[0] + n[1] * p[1] + n[2] * p[2] - plane.offset) < tolerance,
  );
}

/** After a command turned `prev` into `next`: a curve deleted takes its twin with it, and a curve
 *  the command changed (but not its twin) makes its twin its mirror image again. */
export function syncMirrorTwins(
  prev: readonly StyleCurve[],
  next: readonly StyleCurve[],
  plane: MirrorPlane = X_PLANE,
): StyleCurve[] | null {
  const before = new Map(prev.map((c) => [c.id, c]));
  const ids = new Set(next.map((c) => c.id));
  let out = next.filter((c) => !(c.mirror && !ids.has(c.mirror) && before.has(c.mirror)));
  let changed = out.length !== next.length;
  const byId = new Map(out.map((c) => [c.id, c]));
  const replace = new Map<string, StyleCurve>();
  for (const c of out) {
    if (!c.mirror || before.get(c.id) === c) continue; // unchanged
    const twin = byId.get(c.mirror);
    if (!twin || before.get(twin.id) !== twin) continue; // gone, or changed by the command too
    replace.set(twin.id, mirrorCurve(c, twin.id, c.id, plane));
  }
  if (replace.size) {
    out = out.map((c) => replace.get(c.id) ?? c);
    changed = true;
  }
  return changed ? out : null;
}

/** A ponytail's spine drawn within this distance of the symmetry plane (world units, 1.5 cm: a
 *  hand's error drawing on the head's middle) is put on it, so a centred tail is centred. */
export const SNAP_TO_PLANE = 0.15;
/** Drawn in a side view (looking along the plane's normal, within about 25 degrees), where the
 *  middle of the head is its outline and a press just inside it lands a few centimetres off the
 *  middle, the spine is put on the plane from this far (world units, 5.5 cm: a press 30 px
 *  inside the outline at the back of the crown, 1280×800, lands 5 cm off it; fresh eyes round
 *  14, following the guide's "just inside", got a tail 5 cm off the middle at 4 cm). The side of
 *  the head, where a side ponytail sits, is 6.5 cm or more off the middle. */
export const SNAP_FROM_SIDE = 0.55;

/** `points` put on the plane when its first point and its points on average lie within
 *  SNAP_TO_PLANE of it (SNAP_FROM_SIDE when drawn looking along `view`, a side view), else as
 *  they are. sideOnly: only when drawn in a side view (a stream curve: from the front, a stroke
 *  near the middle is meant where it is drawn). */
export function snapToPlane(
  points: Vec3[],
  plane: MirrorPlane = X_PLANE,
  view?: Vec3,
  sideOnly = false,
): { points: Vec3[]; snapped: boolean } {
  if (points.length === 0) return { points, snapped: false };
  const n = plane.normal;
  const off = (p: Vec3) => n[0] * p[0] + n[1] * p[1] + n[2] * p[2] - plane.offset;
  const mean = points.reduce((m, p) => m + Math.abs(off(p)), 0) / points.length;
  const along = view ? Math.abs(n[0] * view[0] + n[1] * view[1] + n[2] * view[2]) : 0;
  if (sideOnly && !(along > 0.9)) return { points, snapped: false };
  const reach = along > 0.9 ? SNAP_FROM_SIDE : SNAP_TO_PLANE;
  if (Math.abs(off(points[0])) > reach || mean > reach) return { points, snapped: false };
  return {
    points: points.map((p) => {
      const k = off(p);
      return [p[0] - k * n[0] + 0, p[1] - k * n[1] + 0, p[2] - k * n[2] + 0];
    }),
    snapped: true,
  };
}
