// SPEC S4.2 against a sphere "scalp" (the whole sphere is scalp here), ray-traced by hand.
import { describe, expect, it } from 'vitest';
import { dot, normalize, sub, type Vec3 } from '../../web/model/vec3';
import { liftStroke, type StrokeSample } from '../../web/tools/depthRule';

const R = 1;
const eye: Vec3 = [0, 0, 5];
const forward: Vec3 = [0, 0, -1];

function sphereHit(o: Vec3, d: Vec3): Vec3 | null {
  const b = dot(o, d);
  const c = dot(o, o) - R * R;
  const disc = b * b - c;
  if (disc < 0) return null;
  const t = -b - Math.sqrt(disc);
  return [o[0] + d[0] * t, o[1] + d[1] * t, o[2] + d[2] * t];
}

// A pointer sample through the image-plane point (x, y) at z = 4 (one unit in front of the eye).
function sample(x: number, y: number): StrokeSample {
  const direction = normalize(sub([x, y, 4], eye));
  return { origin: eye, direction, scalpHit: sphereHit(eye, direction) };
}

describe('liftStroke (S4.2 depth rule)', () => {
  it('rejects a stroke that does not start on the scalp', () => {
    expect(liftStroke([sample(0.5, 0.5), sample(0, 0)], eye, forward)).toEqual({
      ok: false,
      reason: 'not-on-scalp',
    });
    expect(liftStroke([], eye, forward).ok).toBe(false);
  });

  it('keeps points on the sphere while over it, then the depth of the last scalp point', () => {
    const xs = [0, 0.05, 0.1, 0.15, 0.19, 0.25, 0.3, 0.4];
    const lifted = liftStroke(
      xs.map((x) => sample(x, 0)),
      eye,
      forward,
    );
    if (!lifted.ok) throw new Error('expected ok');
    let lastScalpDepth = Number.NaN;
    xs.forEach((x, i) => {
      const p = lifted.points[i];
      const s = sample(x, 0);
      if (s.scalpHit) {
        expect(Math.hypot(...p)).toBeCloseTo(R, 12); // on the sphere
        lastScalpDepth = dot(sub(p, eye), forward);
      } else {
        // Off the sphere: same depth as the last scalp point, and on the pointer's ray.
        expect(dot(sub(p, eye), forward)).toBeCloseTo(lastScalpDepth, 12);
        const along = normalize(sub(p, eye));
        expect(dot(along, s.direction)).toBeCloseTo(1, 12);
      }
    });
    // Hand check: the sphere's silhouette seen from z = 5 is at image x = 1/sqrt(24) ≈ 0.204,
    // so 0.19 is the last point on it and 0.25, 0.3, 0.4 are off it.
    expect(sample(0.19, 0).scalpHit).not.toBeNull();
    expect(sample(0.25, 0).scalpHit).toBeNull();
    // Point at x = 0.4 on the plane at the last scalp depth: t = depth, position x = 0.4 * depth.
    const depth = dot(sub(lifted.points[4], eye), forward);
    expect(lifted.points[7][0]).toBeCloseTo(0.4 * (depth / 1) * (1 / 1), 10);
  });
});
