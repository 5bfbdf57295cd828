// Head.nearestScalpPoint (web/head/head.ts), which lets a stroke pressed just off the scalp start
// on it: checked against the head's own closest point and scalp flags.
import { describe, expect, it } from 'vitest';
import { Head } from '../../web/head/head';

const head = Head.builtin();

describe('Head.nearestScalpPoint', () => {
  it('finds the scalp within reach of a point just off it, nothing far from it', () => {
    // the forehead below the front hairline: straight in front of the head, a little low
    const brow = head.raycast([0, 0.35, 4], [0, 0, -1]);
    expect(brow).not.toBeNull();
    if (!brow) return;
    expect(brow.scalp).toBe(false);
    const q = head.nearestScalpPoint(brow.point, 0.3);
    expect(q).not.toBeNull();
    if (!q) return;
    const c = head.closest(q);
    expect(c.distance).toBeLessThan(1e-3);
    expect(head.mesh.scalp[c.triangle]).toBe(1);
    expect(
      Math.hypot(q[0] - brow.point[0], q[1] - brow.point[1], q[2] - brow.point[2]),
    ).toBeLessThan(0.3);
    // the chin is far from every scalp point
    const chin = head.raycast([0, -1.2, 4], [0, 0, -1]);
    if (chin) expect(head.nearestScalpPoint(chin.point, 0.2)).toBeNull();
  });
});
