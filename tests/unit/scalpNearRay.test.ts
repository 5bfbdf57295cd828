// A press beside the scalp on screen starts on it (Head.scalpPointNearRay, the fallback of the
// tools' press when the scalp is not within 2 cm of what the ray hit): from the top view a press
// on an ear, or just past the head's outline beside it, was refused. Checked against the head's
// own raycast, closest point and scalp flags.
import { describe, expect, it } from 'vitest';
import { Head } from '../../web/head/head';
import type { Vec3 } from '../../web/model/vec3';

const head = Head.builtin();
const down: Vec3 = [0, -1, 0];

/** Distance from p to the ray from o along unit d. */
function fromRay(p: Vec3, o: Vec3, d: Vec3): number {
  const q: Vec3 = [p[0] - o[0], p[1] - o[1], p[2] - o[2]];
  const t = q[0] * d[0] + q[1] * d[1] + q[2] * d[2];
  return Math.hypot(q[0] - t * d[0], q[1] - t * d[1], q[2] - t * d[2]);
}

describe('scalpPointNearRay', () => {
  it('from the top, a press on an ear starts on the scalp above it, within 3 cm of the ray', () => {
    // straight down onto the right ear (its top seen from above, beyond the cranium's side)
    const o: Vec3 = [0.8, 5, -0.15];
    const hit = head.raycast(o, down);
    expect(hit).not.toBeNull();
    expect(hit?.scalp).toBe(false);
    // the fault: no scalp within the press's 2 cm of the ear
    expect(head.nearestScalpPoint(hit?.point as Vec3, 0.2)).toBeNull();
    const p = head.scalpPointNearRay(o, down, 0.3);
    expect(p).not.toBeNull();
    const at = p as Vec3;
    const near = head.closest(at);
    expect(near.distance).toBeLessThan(1e-3);
    expect(head.mesh.scalp[near.triangle]).toBe(1);
    expect(fromRay(at, o, down)).toBeLessThan(0.3);
    // on the near side of the head, seen from above or edge-on
    expect(at[0]).toBeGreaterThan(0.5);
    expect(near.normal[1]).toBeGreaterThan(-0.2);
  });

  it('finds nothing farther than its reach, nor on scalp facing away', () => {
    // 6 cm past the head's side: no scalp within 3 cm of the ray
    expect(head.scalpPointNearRay([1.4, 5, 0], down, 0.3)).toBeNull();
    // looking up from under the chin: all of the scalp faces away (or is hidden)
    expect(head.scalpPointNearRay([0, -5, 0.3], [0, 1, 0], 0.3)).toBeNull();
  });
});
