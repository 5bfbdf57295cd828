// SPEC S4.2: lifting a screen stroke onto the head. The first point takes the depth of its scalp
// hit; each next point takes the scalp depth while over the scalp, else the depth of the last
// scalp point. "Depth" is the distance along the camera's viewing direction.
import { add, dot, scale, sub, type Vec3 } from '../model/vec3';

export interface StrokeSample {
  origin: Vec3; // ray origin (camera position for a perspective camera)
  direction: Vec3; // unit ray direction through the pointer
  scalpHit: Vec3 | null; // first hit of the ray on the head, when it is on the scalp
  headDistance?: number | null; // distance along the ray to the first head hit (any part)
}

export type LiftResult = { ok: true; points: Vec3[] } | { ok: false; reason: 'not-on-scalp' };

/** `forward` is the unit viewing direction of the camera. */
export function liftStroke(samples: readonly StrokeSample[], eye: Vec3, forward: Vec3): LiftResult {
  if (samples.length === 0 || samples[0].scalpHit === null)
    return { ok: false, reason: 'not-on-scalp' };
  const points: Vec3[] = [];
  let depth = 0;
  for (const s of samples) {
    if (s.scalpHit) {
      depth = dot(sub(s.scalpHit, eye), forward);
      points.push(s.scalpHit);
    } else {
      const along = dot(s.direction, forward);
      if (along <= 1e-9) continue; // a ray parallel to the image plane has no point at that depth
      const t = (depth - dot(sub(s.origin, eye), forward)) / along;
      points.push(add(s.origin, scale(s.direction, t)));
    }
  }
  return { ok: true, points };
}
