// The one Head type: mesh-based normals and signed distance against the built-in head's
// analytic signed distance function (an independent reference), rays against closest points.
import { describe, expect, it } from 'vitest';
import { buildHead } from '../../web/head/buildHead';
import { Head } from '../../web/head/head';
import { headSdf } from '../../web/head/headSdf';
import { dot, normalize, sphericalDirection, type Vec3 } from '../../web/model/vec3';

const builtin = Head.builtin();
/** The same mesh without the analytic SDF: what a user-loaded head gets. */
const meshOnly = new Head(buildHead(), null);

function sdfGradient(p: Vec3): Vec3 {
  const e = 1e-4;
  const [x, y, z] = p;
  return normalize([
    headSdf(x + e, y, z) - headSdf(x - e, y, z),
    headSdf(x, y + e, z) - headSdf(x, y - e, z),
    headSdf(x, y, z + e) - headSdf(x, y, z - e),
  ]);
}

describe('Head', () => {
  const scalp: Vec3[] = [];
  for (const t of [10, 30, 50])
    for (const p of [0, 60, 120, 180, 240, 300]) {
      const h = builtin.scalpPoint(t, p);
      if (h) scalp.push(h.point);
    }

  it('mesh normals on the scalp agree with the SDF gradient (within 8°)', () => {
    expect(scalp.length).toBeGreaterThan(15);
    for (const p of scalp)
      expect(dot(builtin.normalAt(p), sdfGradient(p))).toBeGreaterThan(
        Math.cos((8 * Math.PI) / 180),
      );
  });

  it('normals off the surface are those of the closest point', () => {
    for (const p of scalp.slice(0, 5)) {
      const n = builtin.normalAt(p);
      const out: Vec3 = [p[0] + 0.1 * n[0], p[1] + 0.1 * n[1], p[2] + 0.1 * n[2]];
      expect(dot(builtin.normalAt(out), n)).toBeGreaterThan(0.99);
    }
  });

  it('mesh signed distance matches the analytic one near the surface, and its sign everywhere', () => {
    // near the surface both are distances (to the polygonisation error)
    for (const p of scalp)
      for (const off of [-0.05, 0.05]) {
        const n = sdfGradient(p);
        const q: Vec3 = [p[0] + off * n[0], p[1] + off * n[1], p[2] + off * n[2]];
        expect(Math.abs(meshOnly.signedDistance(q) - headSdf(...q))).toBeLessThan(0.02);
      }
    // farther away the analytic function is only a bound on the distance (smooth unions)
    const far: Vec3[] = [
      [0, 0, 0],
      [0, 1.6, 0],
      [0.3, 0.2, 1.4],
      [-1.3, 0.1, 0.2],
      [0, -0.5, 0.3],
    ];
    for (const p of far) {
      const exact = headSdf(...p);
      const mesh = meshOnly.signedDistance(p);
      expect(Math.sign(mesh)).toBe(Math.sign(exact));
      // outside, the analytic value never exceeds the true distance
      if (exact > 0) expect(mesh).toBeGreaterThan(exact - 0.03);
    }
    expect(builtin.signedDistance([0, 0, 0])).toBe(headSdf(0, 0, 0));
  });

  it('a ray from outside hits the surface where the closest point is', () => {
    const dir = normalize([-0.2, -1, -0.1]);
    const origin: Vec3 = [0.2, 3, 0.1];
    const hit = builtin.raycast(origin, dir);
    expect(hit).not.toBeNull();
    if (!hit) return;
    expect(builtin.closest(hit.point).distance).toBeLessThan(1e-5);
    expect(hit.scalp).toBe(true);
    expect(builtin.visibleFrom(origin, hit.point)).toBe(true);
    // the far side of the head is hidden behind it
    const far = builtin.scalpPoint(90, 180);
    expect(far && builtin.visibleFrom([0, 0, 7], far.point)).toBe(false);
  });

  it('scalp points lie along their spherical direction from the centre', () => {
    const h = builtin.scalpPoint(40, 90);
    expect(h).not.toBeNull();
    if (!h) return;
    const d = normalize(h.point);
    expect(dot(d, sphericalDirection(40, 90))).toBeGreaterThan(0.9999);
  });

  it('scalpMesh copies the arrays for the worker', () => {
    const m = builtin.scalpMesh();
    expect(m.positions).not.toBe(builtin.mesh.positions);
    expect(Array.from(m.scalp)).toEqual(Array.from(builtin.mesh.scalp));
  });
});
