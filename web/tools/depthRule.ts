// Method S4.2: lifting a screen stroke onto the head. The first point takes the depth of its scalp
// hit; each next point takes the scalp depth while over the scalp, else the depth of the last
// scalp point. "Depth" is the distance along the camera's viewing direction made level (its
// horizontal part): a point off the head lies on the vertical plane through the last scalp point
// that faces the camera, so a lock or a ponytail drawn hanging from one view hangs plumb in the
// depth that view cannot show (from a camera looking a little down, the plane square to the view
// would lean it towards or away from the camera). Looking nearly straight down or up there is no
// level direction to speak of, and depth is along the view itself; there a point over the head
// off the scalp (a fringe drawn from the top view on over the forehead) lies on the head, at
// STROKE_MARGIN in front of its surface, since a view from above shows no depth to keep: the
// stroke drapes over the forehead instead of running out level past it as a visor. A point that depth
// would put inside the head (a stroke passing over the face, the ears, the neck) is brought
// forward along its ray to STROKE_MARGIN in front of the head's surface instead, so style
// curves never run inside the head.
import { add, dot, scale, sub, type Vec3 } from '../model/vec3';

export interface StrokeSample {
  origin: Vec3; // ray origin (camera position for a perspective camera)
  direction: Vec3; // unit ray direction through the pointer
  scalpHit: Vec3 | null; // first hit of the ray on the head, when it is on the scalp
  headDistance?: number | null; // distance along the ray to the first head hit (any part)
}

/** World units (0.06 = 6 mm) kept along the ray in front of a head hit by a lifted point. */
export const STROKE_MARGIN = 0.06;

/** Below this horizontal part of the viewing direction (about 72° from level), depth is taken
 *  along the view itself. */
export const LEVEL_MIN = 0.3;

export type LiftResult = { ok: true; points: Vec3[] } | { ok: false; reason: 'not-on-scalp' };

/** `forward` is the unit viewing direction of the camera. `hangFromFirst` (a tie's spine): a
 *  point over the scalp takes the scalp's depth only where the scalp is no deeper than under the
 *  first point, else the first point's depth: a pigtail drawn from the side, from behind an ear
 *  back and down, hangs beside the head where it was pressed, not round the back of the head in
 *  the middle (the scalp seen from the side curves away to the middle towards the back). */
export function liftStroke(
  samples: readonly StrokeSample[],
  eye: Vec3,
  forward: Vec3,
  hangFromFirst = false,
): LiftResult {
  if (samples.length === 0 || samples[0].scalpHit === null)
    return { ok: false, reason: 'not-on-scalp' };
  const points: Vec3[] = [];
  const level = Math.hypot(forward[0], forward[2]);
  const depthAxis: Vec3 =
    level >= LEVEL_MIN ? [forward[0] / level, 0, forward[2] / level] : forward;
  const steep = level < LEVEL_MIN;
  const depthOf = (p: Vec3) => dot(sub(p, eye), depthAxis);
  // how far along a sample's ray its depth plane lies (null: the ray runs parallel to it)
  const toPlane = (s: StrokeSample, d: number) => {
    const along = dot(s.direction, depthAxis);
    return along <= 1e-9 ? null : (d - depthOf(s.origin)) / along;
  };
  const firstDepth = depthOf(samples[0].scalpHit);
  let depth = 0;
  for (const s of samples) {
    if (s.scalpHit) {
      const d = depthOf(s.scalpHit);
      if (!(hangFromFirst && !steep && d > firstDepth)) {
        depth = d;
        points.push(s.scalpHit);
        continue;
      }
      // deeper than the first point's scalp: on the first point's depth plane
      depth = firstDepth;
      const t = toPlane(s, depth);
      if (t !== null) points.push(add(s.origin, scale(s.direction, t)));
    } else if (steep && s.headDistance != null) {
      const p = add(s.origin, scale(s.direction, Math.max(0, s.headDistance - STROKE_MARGIN)));
      depth = depthOf(p);
      points.push(p);
    } else {
      let t = toPlane(s, depth);
      if (t === null) continue; // a ray parallel to the depth plane has no point on it
      if (s.headDistance != null && t > s.headDistance - STROKE_MARGIN)
        t = Math.max(0, s.headDistance - STROKE_MARGIN);
      points.push(add(s.origin, scale(s.direction, t)));
    }
  }
  return { ok: true, points };
}
