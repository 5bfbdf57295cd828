// Mirror editing: a curve and its twin reflected across the head's symmetry plane (x = 0 for the
// built-in head: +x is the head's left). The twins name each other in their `mirror` field; an
// edit of one is made to the other, mirrored, in the same command (one undo step).
import type { PonytailCircle } from './ponytailGeometry';
import type { StyleCurve, Viewpoint } from './session';
import type { Vec3 } from './vec3';

/** x of the built-in head's symmetry plane. */
export const MIRROR_PLANE_X = 0;

const flip = (p: Vec3): Vec3 => [2 * MIRROR_PLANE_X - p[0] + 0, p[1], p[2]];
const flipDir = (v: Vec3): Vec3 => [-v[0] + 0, v[1], v[2]];
const flipView = (v: Viewpoint): Viewpoint => ({
  position: flip(v.position),
  target: flip(v.target),
});

/** `c` reflected across the plane, named `id`, its twin `twinId`. Tilts change sign (the
 *  reflection turns the curve's handedness); everything else is kept. */
export function mirrorCurve(c: StyleCurve, id: string, twinId: string): StyleCurve {
  const base = {
    ...c,
    id,
    mirror: twinId,
    points: c.points.map(flip),
    viewpoint: flipView(c.viewpoint),
  };
  switch (c.type) {
    case 'stream':
      return base as StyleCurve;
    case 'dividing':
      return {
        ...(base as typeof c),
        normals: c.normals.map(flipDir),
        alpha0: -c.alpha0 + 0,
        alpha1: -c.alpha1 + 0,
      };
    case 'ponytail':
      return {
        ...(base as typeof c),
        crossSection: c.crossSection.map(flip),
        profiles: [c.profiles[0].map(flip), c.profiles[1].map(flip)],
        circles: c.circles.map(
          (q): PonytailCircle => ({ ...q, centre: flip(q.centre), axis: flipDir(q.axis) }),
        ),
      };
  }
}

/** True when the curve is its own mirror image (drawn along the plane, e.g. a centre parting):
 *  it gets no twin. */
export function isSelfMirror(c: StyleCurve, tolerance = 1e-3): boolean {
  return c.points.every((p) => Math.abs(p[0] - MIRROR_PLANE_X) < tolerance);
}

/** After a command turned `prev` into `next`: a curve deleted takes its twin with it, and a curve
 *  the command changed (but not its twin) makes its twin its mirror image again. */
export function syncMirrorTwins(
  prev: readonly StyleCurve[],
  next: readonly StyleCurve[],
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
    replace.set(twin.id, mirrorCurve(c, twin.id, c.id));
  }
  if (replace.size) {
    out = out.map((c) => replace.get(c.id) ?? c);
    changed = true;
  }
  return changed ? out : null;
}
