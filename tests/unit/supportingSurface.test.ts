// Supporting surfaces (method S4.3): ruled quads lie in their segment's eye plane, strip lines are
// orthogonal to the segment-eye triangle, and ray hits report the right surface coordinates.
import { describe, expect, it } from 'vitest';
import {
  buildSupportingSurface,
  eyeTriangleNormal,
  intersectSupportingSurface,
} from '../../web/model/supportingSurface';
import { add, dot, length, normalize, scale, sub, type Vec3 } from '../../web/model/vec3';

const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];

// A bent 3D curve (step ~0.1) and an eye off to the side.
const curve: Vec3[] = Array.from({ length: 12 }, (_, i) => {
  const a = 0.1 * i;
  return [Math.sin(a), 0.3 * a, Math.cos(a) - 1 + 0.05 * a * a];
});
const eye: Vec3 = [0.4, 0.8, 4];

function triangles(s: ReturnType<typeof buildSupportingSurface>) {
  const P = s.positions;
  const v = (k: number): Vec3 => [P[3 * k], P[3 * k + 1], P[3 * k + 2]];
  const out: { seg: number; v: Vec3[] }[] = [];
  for (let t = 0; t < s.indices.length / 3; t++)
    out.push({
      seg: s.triangleSegment[t],
      v: [v(s.indices[3 * t]), v(s.indices[3 * t + 1]), v(s.indices[3 * t + 2])],
    });
  return out;
}

describe('ruled supporting surface', () => {
  const s = buildSupportingSurface(curve, eye, 'ruled', 0.5);
  it('puts every triangle in the plane of the eye and its segment', () => {
    const tris = triangles(s);
    expect(tris.length).toBe(2 * (curve.length - 1));
    for (const { seg, v } of tris) {
      expect(seg).toBeGreaterThanOrEqual(0);
      const n = eyeTriangleNormal(eye, curve[seg], curve[seg + 1]) as Vec3;
      // The triangle's plane contains the eye and both segment ends.
      for (const p of v) expect(Math.abs(dot(sub(p, eye), n))).toBeLessThan(1e-6);
      const tn = normalize(cross(sub(v[1], v[0]), sub(v[2], v[0])));
      expect(Math.abs(dot(tn, n))).toBeCloseTo(1, 5);
      // Each vertex lies on the view ray through one of the segment's ends.
      for (const p of v) {
        const onA = length(cross(sub(p, eye), sub(curve[seg], eye))) / length(sub(p, eye));
        const onB = length(cross(sub(p, eye), sub(curve[seg + 1], eye))) / length(sub(p, eye));
        expect(Math.min(onA, onB)).toBeLessThan(1e-5);
      }
    }
  });

  it('hits report the curve parameter and the offset along the view ray', () => {
    const c = add(curve[3], scale(sub(curve[4], curve[3]), 0.4));
    const x = add(c, scale(normalize(sub(c, eye)), 0.2)); // 0.2 behind the curve
    const cam: Vec3 = [3, 1, 1];
    const hit = intersectSupportingSurface(s, cam, normalize(sub(x, cam)));
    expect(hit).not.toBeNull();
    if (!hit) return;
    expect(length(sub(hit.point, x))).toBeLessThan(1e-5);
    expect(hit.param).toBeCloseTo(3.4, 4);
    expect(hit.nearestIndex).toBe(3);
    expect(hit.offset).toBeCloseTo(0.2, 4);
    expect(hit.distance).toBeCloseTo(0.2, 4);
  });
});

describe('strip supporting surface', () => {
  const W = 0.3;
  const s = buildSupportingSurface(curve, eye, 'strip', W);
  it('is made of lines orthogonal to each segment-eye triangle', () => {
    const tris = triangles(s);
    let quads = 0;
    for (const { seg, v } of tris) {
      if (seg < 0) continue; // wedge at a joint
      quads++;
      const a = curve[seg];
      const b = curve[seg + 1];
      const n = s.segmentNormal[seg];
      // n is orthogonal to the triangle (eye, a, b).
      expect(Math.abs(dot(n, sub(a, eye)))).toBeLessThan(1e-12);
      expect(Math.abs(dot(n, sub(b, eye)))).toBeLessThan(1e-12);
      expect(length(n)).toBeCloseTo(1, 12);
      // Every vertex is a segment end moved by ±W along n.
      for (const p of v) {
        const da = sub(p, a);
        const db = sub(p, b);
        const alongA = length(sub(da, scale(n, dot(da, n))));
        const alongB = length(sub(db, scale(n, dot(db, n))));
        expect(Math.min(alongA, alongB)).toBeLessThan(1e-6);
        expect(Math.abs(Math.abs(alongA < alongB ? dot(da, n) : dot(db, n)) - W)).toBeLessThan(
          1e-6,
        );
      }
    }
    expect(quads).toBe(2 * (curve.length - 1));
    // The bent curve's normals change, so joints get wedges.
    expect(tris.length).toBeGreaterThan(quads);
  });

  it('hits report the curve parameter and the offset along the triangle normal', () => {
    const x = add(
      add(curve[6], scale(sub(curve[7], curve[6]), 0.25)),
      scale(s.segmentNormal[6], -0.1),
    );
    const hit = intersectSupportingSurface(s, eye, normalize(sub(x, eye)));
    expect(hit).not.toBeNull();
    if (!hit) return;
    expect(length(sub(hit.point, x))).toBeLessThan(1e-5);
    expect(hit.param).toBeCloseTo(6.25, 4);
    expect(hit.offset).toBeCloseTo(-0.1, 5);
    // A ray that misses the band.
    const far = add(curve[6], scale(s.segmentNormal[6], 2));
    expect(intersectSupportingSurface(s, eye, normalize(sub(far, eye)))).toBeNull();
  });
});
