// Dividing curves on the TS side (method S4.5): normals from the mesh, frames, hint tilt, packing.

import { describe, expect, it } from 'vitest';
import { vertexNormals } from '../../web/head/buildHead';
import { Head } from '../../web/head/head';
import { curveParams } from '../../web/model/curveSet';
import { dividingFrames, tiltFromHint } from '../../web/model/dividingFrames';
import type { Vec3 } from '../../web/model/vec3';

/** A Head over a small mesh (the app's one definition of scalp normals). */
function headOf(m: { positions: Float32Array; indices: Uint32Array }): Head {
  return new Head({
    ...m,
    normals: vertexNormals(m.positions, m.indices),
    scalp: new Uint8Array(m.indices.length / 3).fill(1),
    center: [0, 0, 0],
    bounds: { min: [0, 0, 0], max: [10, 10, 10] },
  });
}
const scalpNormalsAt = (
  pts: readonly Vec3[],
  m: { positions: Float32Array; indices: Uint32Array },
) => {
  const h = headOf(m);
  return pts.map((p) => h.normalAt(p));
};

// Flat "scalp": the square y = 2, x, z in [0, 10], wound counter-clockwise seen from +y.
const flat = {
  positions: new Float32Array([0, 2, 0, 0, 2, 10, 10, 2, 10, 10, 2, 0]),
  indices: new Uint32Array([0, 1, 2, 0, 2, 3]),
};
const curve: Vec3[] = Array.from({ length: 8 }, (_, i) => [5, 2, 2 + i]);

describe('dividing frames', () => {
  it('takes outward normals from the mesh (Head.normalAt)', () => {
    for (const n of scalpNormalsAt(curve, flat)) expect(n).toEqual([0, 1, 0]);
    // A sphere-ish check: a point above a tilted triangle gets the triangle's normal.
    const tilted = {
      positions: new Float32Array([0, 0, 0, 1, 1, 0, 0, 0, 1]),
      indices: new Uint32Array([0, 2, 1]),
    };
    const [n] = scalpNormalsAt([[0.3, 0.4, 0.3]], tilted);
    expect(n[0]).toBeCloseTo(-Math.SQRT1_2, 6);
    expect(n[1]).toBeCloseTo(Math.SQRT1_2, 6);
  });

  it('builds the frames of the header by hand: y normal, z tilted tangent, x = y × z', () => {
    const normals = scalpNormalsAt(curve, flat);
    const f = dividingFrames(curve, normals, 0, 0.7);
    expect(f[0]?.x).toEqual([1, 0, 0]);
    expect(f[0]?.z).toEqual([0, 0, 1]);
    const a = 0.7;
    const z7 = f[7]?.z as Vec3;
    const x7 = f[7]?.x as Vec3;
    expect(z7[0]).toBeCloseTo(Math.sin(a), 14);
    expect(z7[2]).toBeCloseTo(Math.cos(a), 14);
    expect(x7[0]).toBeCloseTo(Math.cos(a), 14);
    expect(x7[2]).toBeCloseTo(-Math.sin(a), 14);
  });

  it('turns a hint stroke beside the curve into a tilt', () => {
    const normals = scalpNormalsAt(curve, flat);
    // On the +x side near the start, heading +x and +z: x(α) = (cos α, 0, -sin α) = D at -π/4.
    const t = tiltFromHint(curve, normals, [
      [5.5, 2, 3],
      [6.5, 2, 4],
    ]);
    expect(t?.side).toBe(1);
    expect(t?.end).toBe('alpha0');
    expect(t?.alpha).toBeCloseTo(-Math.PI / 4, 12);
    // On the -x side near the end, heading -x and +z: side * D = (1, 0, -1)/√2 -> α = +π/4.
    const u = tiltFromHint(curve, normals, [
      [4.5, 2, 8.6],
      [3.5, 2, 9.6],
    ]);
    expect(u?.side).toBe(-1);
    expect(u?.end).toBe('alpha1');
    expect(u?.alpha).toBeCloseTo(Math.PI / 4, 12);
  });

  it('packs the protocol block', () => {
    const p = curveParams({
      id: 'c1',
      type: 'dividing',
      points: [
        [0, 1, 0],
        [0, 1.1, 0],
      ],
      normals: [
        [0, 1, 0],
        [0, 1, 0],
      ],
      sigma: 1,
      h: 0.5,
      alpha0: 0.1,
      alpha1: 0.2,
      viewpoint: { position: [0, 0, 7], target: [0, 0, 0] },
    });
    expect(p).toEqual([1, 0.5, 0.1, 0.2, 0, 1, 0, 0, 1, 0]);
  });
});
