// Ponytail cross sections (method S4.6, paper §5 and Fig. 5) from its four sketched curves, and
// packing to the protocol's ponytail parameter block.
//
// For each spine point s_i (every `every`-th, counted from the root) with unit tangent t_i
// (central difference, root -> tip), the plane through s_i normal to t_i is intersected with
// each profile polyline (the intersection nearest s_i). Where both profiles cross the plane,
// spine point i gets a circle: centre s_i, axis t_i, radius |a_i - b_i| / 2 (half the distance
// between the profiles measured across the spine). The circles run over the spine points where
// both profiles are present, in spine order: C1 (nearest the scalp, the spine's root) first.
// The cross-section curve sets the radius scale where it is drawn: at the spine parameter j
// nearest its centroid, its radius is half its largest extent across the spine (points projected
// onto the plane normal to t_j); every radius is multiplied by r_cross / r_profiles(j), r_profiles
// being the profile radius of the circle nearest j. No cross-section curve: scale 1.
// Guards against profiles drawn loosely (a new user's, following the user guide): a profile that
// crosses a circle's plane far from the spine (near the scalp, where the spine turns up and over)
// gives that circle a radius far past its neighbours' (a band 9.8 cm wide, the tail a cone over
// the head), so each circle is at most OUTLIER times the wider of its neighbours (as the profiles
// gave them, before the scale), and no circle is wider than MAX_PONYTAIL_RADIUS (a whole head of
// hair gathered is about 6 cm across).
import { add, distance, dot, length, normalize, scale, sub, type Vec3 } from './vec3';

/** How much wider than the wider of its neighbours a circle may be. */
export const OUTLIER = 1.25;
/** The widest a ponytail circle may be (world units: 3 cm). */
export const MAX_PONYTAIL_RADIUS = 0.3;

export interface PonytailCircle {
  centre: Vec3;
  axis: Vec3; // unit, along the spine (root -> tip)
  radius: number; // world units
  spineIndex: number; // the spine point it sits on
}

export interface PonytailGeometry {
  circles: PonytailCircle[]; // C1 (nearest the scalp) first
  scale: number; // radius scale set by the cross-section curve
}

export interface PonytailOptions {
  every?: number; // a circle at every `every`-th spine point (default 1)
  /** No circle before this spine point (default 0): the band stays where the spine puts it
   *  (ponytailFromSpine.ts bandIndex), however near the scalp the profiles begin. */
  from?: number;
  /** The band's radius: the circle at the band (the first at or past `from`) keeps it, however far apart the profiles cross its
   *  plane (the band stays as tight as the hair it holds; the profiles shape the tail below it:
   *  a profile drawn from the head crosses the band's tilted plane far from the spine, and the
   *  band took the tail's width, 6 cm, lifting the hair into a tent above the head). */
  bandRadius?: number;
}

/** Unit tangents of a polyline (central differences; one-sided at the ends). */
export function polylineTangents(pts: readonly Vec3[]): Vec3[] {
  const n = pts.length;
  return pts.map((_, i) => normalize(sub(pts[Math.min(n - 1, i + 1)], pts[Math.max(0, i - 1)])));
}

/** Intersection of the polyline with the plane (point o, unit normal nrm) nearest to o. */
export function planeCrossing(poly: readonly Vec3[], o: Vec3, nrm: Vec3): Vec3 | null {
  let best: Vec3 | null = null;
  let bestD = Number.POSITIVE_INFINITY;
  for (let k = 0; k + 1 < poly.length; k++) {
    const da = dot(sub(poly[k], o), nrm);
    const db = dot(sub(poly[k + 1], o), nrm);
    if ((da > 0 && db > 0) || (da < 0 && db < 0) || da === db) continue;
    const f = da / (da - db);
    const x = add(poly[k], scale(sub(poly[k + 1], poly[k]), f));
    const d = distance(x, o);
    if (d < bestD) {
      bestD = d;
      best = x;
    }
  }
  return best;
}

/** Half the largest extent of the points across the axis (projected onto its normal plane). */
export function crossRadius(pts: readonly Vec3[], axis: Vec3): number {
  const proj = pts.map((p) => sub(p, scale(axis, dot(p, axis))));
  let m = 0;
  for (let i = 0; i < proj.length; i++)
    for (let j = i + 1; j < proj.length; j++) m = Math.max(m, distance(proj[i], proj[j]));
  return m / 2;
}

export function ponytailCircles(
  spine: readonly Vec3[],
  crossSection: readonly Vec3[],
  profileA: readonly Vec3[],
  profileB: readonly Vec3[],
  opts: PonytailOptions = {},
): PonytailGeometry {
  const every = Math.max(1, Math.floor(opts.every ?? 1));
  const tangents = polylineTangents(spine);
  const circles: PonytailCircle[] = [];
  const from = opts.from ?? 0;
  for (let i = 0; i < spine.length; i += every) {
    if (i < from) continue;
    const t = tangents[i];
    if (length(t) === 0) continue;
    const a = planeCrossing(profileA, spine[i], t);
    const b = planeCrossing(profileB, spine[i], t);
    if (!a || !b) continue;
    const r = distance(a, b) / 2;
    if (r > 0) circles.push({ centre: spine[i], axis: t, radius: r, spineIndex: i });
  }
  const drawn = circles.map((c) => c.radius);
  for (let i = 0; i < circles.length; i++) {
    const near = Math.max(drawn[i - 1] ?? 0, drawn[i + 1] ?? 0);
    if (near > 0) circles[i].radius = Math.min(drawn[i], OUTLIER * near);
  }
  let k = 1;
  if (crossSection.length >= 2 && circles.length > 0 && spine.length > 0) {
    let cx: Vec3 = [0, 0, 0];
    for (const p of crossSection) cx = add(cx, p);
    cx = scale(cx, 1 / crossSection.length);
    let j = 0;
    for (let i = 1; i < spine.length; i++)
      if (distance(spine[i], cx) < distance(spine[j], cx)) j = i;
    let nearest = circles[0];
    for (const c of circles)
      if (Math.abs(c.spineIndex - j) < Math.abs(nearest.spineIndex - j)) nearest = c;
    const rc = crossRadius(crossSection, tangents[j]);
    if (rc > 0) k = rc / nearest.radius;
  }
  for (const c of circles) c.radius = Math.min(c.radius * k, MAX_PONYTAIL_RADIUS);
  return { circles: keepBand(circles, opts.bandRadius, from, every), scale: k };
}

/** `circles` with the band's circle (the first, when it sits at the first spine point taken at or
 *  past `from`, every `every`-th) at `radius` (ponytailCircles' bandRadius; undefined or 0:
 *  as they are). */
export function keepBand(
  circles: PonytailCircle[],
  radius: number | undefined,
  from: number,
  every: number,
): PonytailCircle[] {
  if (!radius || radius <= 0 || circles.length === 0 || circles[0].spineIndex >= from + every)
    return circles;
  return [{ ...circles[0], radius }, ...circles.slice(1)];
}
