// A parting drawn up to the head's outline is carried on over it: seen from above, the outline
// over the ears is the skull's widest part, 4-5 cm above the hairline, and the pointer cannot go
// past it. The user guide's half-up gesture ("from the outline above one ear round the back of
// the crown to the outline above the other") ends there; where the end fell a few millimetres
// short of the scalp-edge search (ScalpSections' kCloseReach) the parting stayed open (fresh
// eyes, twice). An end on the outline (its surface facing across the view) goes on along the
// surface, turning away from the viewer over the outline, until it leaves the scalp or has gone
// OVER_REACH; the solver's closing rule does the rest. An end a few pixels inside the outline
// (its surface up to NEAR_OUTLINE from across the view), drawn from above, is carried on too:
// a later new user's half-up parting stopped 6 px inside the outline above each
// ear and stayed open ("parts the hair"), the ends 5 cm above the scalp's edge.
import type { Head } from '../head/head';
import type { Vec3 } from '../model/vec3';

/** An end whose surface normal is this close to across the view (|n · view| below it, about 20°
 *  from the outline) lies on the outline. */
const ON_OUTLINE = 0.35;
/** An end this close to across the view (|n · view| below it, about 30° from the outline) is
 *  near it, and carried on over it as far as NEAR_REACH (the new user's ends: 0.39 and 0.42). */
const NEAR_OUTLINE = 0.5;
/** Near the outline counts only from above (the view's y below this: within about 35° of the
 *  top view), where the outline over the ears lies above the scalp's edge. From the front or the
 *  side a parting pressed near the head's side ends there on purpose (sketching.spec's, from
 *  the side towards the middle, was carried 5 cm down the side and its tilt hint missed). */
const FROM_ABOVE = -0.8;
/** How far an end is carried over the outline at most (world units, 4 cm; 5 cm from near it). */
const OVER_REACH = 0.4;
const NEAR_REACH = 0.5;

const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const unit = (a: Vec3): Vec3 | null => {
  const n = Math.hypot(a[0], a[1], a[2]);
  return n > 1e-9 ? [a[0] / n, a[1] / n, a[2] / n] : null;
};
/** v less its part along the unit normal n. */
const along = (v: Vec3, n: Vec3): Vec3 => {
  const k = dot(v, n);
  return [v[0] - k * n[0], v[1] - k * n[1], v[2] - k * n[2]];
};

/** The points past `end` (coming from `before`) over the outline seen along `view` (unit, into
 *  the screen), in steps of `step`; none when the end is not on the outline. */
function over(before: Vec3, end: Vec3, view: Vec3, head: Head, step: number): Vec3[] {
  const n0 = head.normalAt(end);
  const facing = Math.abs(dot(n0, view));
  if (facing >= (view[1] < FROM_ABOVE ? NEAR_OUTLINE : ON_OUTLINE)) return [];
  const reach = facing < ON_OUTLINE ? OVER_REACH : NEAR_REACH;
  const out: Vec3[] = [];
  let prev = before;
  let at = end;
  for (let gone = 0; gone < reach; gone += step) {
    const n = head.normalAt(at);
    // on along the stroke, turned away from the viewer (over the outline), in the surface
    const d = unit(along([at[0] - prev[0], at[1] - prev[1], at[2] - prev[2]], n));
    const v = unit(along(view, n));
    if (!d || !v) break;
    const w = unit([d[0] + v[0], d[1] + v[1], d[2] + v[2]]);
    if (!w) break;
    const c = head.closest([at[0] + step * w[0], at[1] + step * w[1], at[2] + step * w[2]]);
    out.push(c.point);
    if (!head.mesh.scalp[c.triangle]) break; // off the scalp: the edge is reached
    prev = at;
    at = c.point;
  }
  return out;
}

/** `points` (a parting on the scalp, drawn looking along `view`) with each end that lies on the
 *  outline carried on over it; `carried` says whether any was. */
export function partingOverOutline(
  points: Vec3[],
  view: Vec3,
  head: Head,
  step: number,
): { points: Vec3[]; carried: boolean } {
  const v = unit(view);
  if (!v || points.length < 2) return { points, carried: false };
  const n = points.length;
  const tail = over(points[n - 2], points[n - 1], v, head, step);
  const lead = over(points[1], points[0], v, head, step);
  if (tail.length === 0 && lead.length === 0) return { points, carried: false };
  return { points: [...lead.reverse(), ...points, ...tail], carried: true };
}
