// A loaded head's symmetry plane: the built-in head (symmetric about x = 0 by construction) moved
// by a known turn and shift must give back the moved plane; mirroring across a general plane is
// an involution that keeps points on the plane.
import { describe, expect, it } from 'vitest';
import { buildHead } from '../../web/head/buildHead';
import { Head } from '../../web/head/head';
import { fitSymmetryPlane, planeAngles, planeNormal } from '../../web/head/symmetryPlane';
import { reflectDirection, reflectPoint } from '../../web/model/mirror';
import type { Vec3 } from '../../web/model/vec3';

function movedHead(yawDeg: number, shift: Vec3): Head {
  const m = buildHead({ resolution: 16 });
  const c = Math.cos((yawDeg * Math.PI) / 180);
  const s = Math.sin((yawDeg * Math.PI) / 180);
  const P = m.positions.slice();
  const N = m.normals.slice();
  for (let v = 0; v < P.length / 3; v++) {
    const [x, y, z] = [P[3 * v], P[3 * v + 1], P[3 * v + 2]];
    // rotation about y by yaw: x' = c x + s z, z' = -s x + c z
    P[3 * v] = c * x + s * z + shift[0];
    P[3 * v + 1] = y + shift[1];
    P[3 * v + 2] = -s * x + c * z + shift[2];
    const [nx, nz] = [N[3 * v], N[3 * v + 2]];
    N[3 * v] = c * nx + s * nz;
    N[3 * v + 2] = -s * nx + c * nz;
  }
  return new Head({ ...m, positions: P, normals: N }, null);
}

describe('fitSymmetryPlane', () => {
  it('finds x = 0 on the built-in head', () => {
    const fit = fitSymmetryPlane(new Head(buildHead({ resolution: 16 }), null));
    expect(fit.plane.normal[0]).toBeGreaterThan(Math.cos((0.5 * Math.PI) / 180));
    expect(Math.abs(fit.plane.offset)).toBeLessThan(0.005);
    expect(fit.cost).toBeLessThan(0.01);
  });

  it('finds a turned and shifted head’s plane (yaw 9°, x + 0.12)', () => {
    const yaw = 9;
    const shift: Vec3 = [0.12, 0.03, -0.05];
    const fit = fitSymmetryPlane(movedHead(yaw, shift));
    // the moved plane: normal R·x̂ = (cos, 0, -sin), through the shift
    const n: Vec3 = [Math.cos((yaw * Math.PI) / 180), 0, -Math.sin((yaw * Math.PI) / 180)];
    const offset = n[0] * shift[0] + n[2] * shift[2];
    const angle = Math.acos(
      Math.min(
        1,
        fit.plane.normal[0] * n[0] + fit.plane.normal[1] * n[1] + fit.plane.normal[2] * n[2],
      ),
    );
    expect((angle * 180) / Math.PI).toBeLessThan(1);
    expect(Math.abs(fit.plane.offset - offset)).toBeLessThan(0.01);
  });
});

describe('reflection across a plane', () => {
  const plane = { normal: planeNormal(0.3, -0.1), offset: 0.2 };
  it('is an involution, keeps points on the plane and negates the normal', () => {
    const p: Vec3 = [0.4, -0.7, 1.3];
    const back = reflectPoint(reflectPoint(p, plane), plane);
    for (let a = 0; a < 3; a++) expect(back[a]).toBeCloseTo(p[a], 12);
    const on: Vec3 = plane.normal.map((x) => x * plane.offset) as Vec3;
    const r = reflectPoint(on, plane);
    for (let a = 0; a < 3; a++) expect(r[a]).toBeCloseTo(on[a], 12);
    const n = reflectDirection(plane.normal, plane);
    for (let a = 0; a < 3; a++) expect(n[a]).toBeCloseTo(-plane.normal[a], 12);
    const { yaw, roll } = planeAngles(plane.normal);
    expect(yaw).toBeCloseTo(0.3, 12);
    expect(roll).toBeCloseTo(-0.1, 12);
  });
});
