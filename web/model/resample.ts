// Stroke resampling at a fixed world-space step (method S4: segments of length d).
import { distance, dot, isFiniteVec, sub, type Vec3 } from './vec3';

/**
 * Walks the polyline and emits points whose consecutive distance is exactly `step` (chords, not
 * arc length), starting at the first point. The tail shorter than one step is dropped.
 * Non-finite points are skipped. Returns [] for an empty input.
 */
export function resamplePolyline(input: readonly Vec3[], step: number): Vec3[] {
  if (!(step > 0) || !Number.isFinite(step)) throw new RangeError(`step must be > 0, got ${step}`);
  const pts = input.filter(isFiniteVec);
  if (pts.length === 0) return [];
  const out: Vec3[] = [pts[0]];
  let current: Vec3 = pts[0];
  let seg = 0; // searching segment pts[seg] -> pts[seg + 1]
  while (seg < pts.length - 1) {
    const a = pts[seg];
    const b = pts[seg + 1];
    if (distance(current, b) < step) {
      seg++;
      continue;
    }
    // Solve |a + t (b - a) - current| = step for the largest t in [0, 1] (b is beyond the sphere).
    const ab = sub(b, a);
    const ac = sub(a, current);
    const qa = dot(ab, ab);
    const qb = 2 * dot(ab, ac);
    const qc = dot(ac, ac) - step * step;
    const disc = Math.max(0, qb * qb - 4 * qa * qc);
    const t = Math.min(1, Math.max(0, (-qb + Math.sqrt(disc)) / (2 * qa)));
    const p: Vec3 = [a[0] + ab[0] * t, a[1] + ab[1] * t, a[2] + ab[2] * t];
    out.push(p);
    current = p;
    // Continue on the same segment: the next point may also lie on it.
    if (t >= 1) seg++;
    else pts[seg] = p;
  }
  return out;
}

/** Total length of a polyline. */
export function polylineLength(pts: readonly Vec3[]): number {
  let l = 0;
  for (let i = 1; i < pts.length; i++) l += distance(pts[i - 1], pts[i]);
  return l;
}
