// A hair tie's band (tieBands.ts) as triangles: a ring round the tail, its cross-section an
// ellipse BAND_THICKNESS across (radially) and BAND_WIDTH along the axis, its inner edge on the
// band's radius so it rests on the hair. One mesh for the viewer and every export that takes
// meshes, so they show the same band.
import type { TieBand } from './tieBands';
import { normalize, type Vec3 } from './vec3';

/** Radial thickness of the band, world units (3 mm each side of its middle: 6 mm). */
export const BAND_THICKNESS = 0.03;
/** Half its width along the tail, world units (8 mm wide). */
export const BAND_HALF_WIDTH = 0.04;
/** Quads round the tail and round the cross-section. */
const AROUND = 48;
const TUBE = 12;

export interface BandMesh {
  positions: Float32Array; // positions[3 * vertex + axis]
  normals: Float32Array; // unit, outward from the ring's surface
  indices: Uint32Array; // counter-clockwise seen from outside
}

const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];

/** Two unit vectors square to `axis` and to each other (a frame for the ring). */
function frame(axis: Vec3): [Vec3, Vec3] {
  const helper: Vec3 = Math.abs(axis[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0];
  const u = normalize(cross(helper, axis));
  return [u, cross(axis, u)];
}

/** The bands as one mesh (empty arrays without bands). */
export function bandMesh(bands: readonly TieBand[]): BandMesh {
  const perBand = AROUND * TUBE;
  const positions = new Float32Array(3 * perBand * bands.length);
  const normals = new Float32Array(3 * perBand * bands.length);
  const indices = new Uint32Array(6 * perBand * bands.length);
  let v = 0;
  let t = 0;
  for (const b of bands) {
    const [u, w] = frame(b.axis);
    const a = b.axis;
    const ring = b.radius + BAND_THICKNESS; // the cross-section's middle
    const base = v;
    for (let i = 0; i < AROUND; i++) {
      const phi = (2 * Math.PI * i) / AROUND;
      // outward direction from the tail's axis
      const r: Vec3 = [0, 1, 2].map((k) => Math.cos(phi) * u[k] + Math.sin(phi) * w[k]) as Vec3;
      for (let j = 0; j < TUBE; j++) {
        const th = (2 * Math.PI * j) / TUBE;
        const radial = BAND_THICKNESS * Math.cos(th);
        const along = BAND_HALF_WIDTH * Math.sin(th);
        // the ellipse's normal: its gradient (cos/a, sin/b)
        const nr = Math.cos(th) / BAND_THICKNESS;
        const na = Math.sin(th) / BAND_HALF_WIDTH;
        const nl = Math.hypot(nr, na);
        for (let k = 0; k < 3; k++) {
          positions[3 * v + k] = b.centre[k] + (ring + radial) * r[k] + along * a[k];
          normals[3 * v + k] = (nr * r[k] + na * a[k]) / nl;
        }
        v++;
      }
    }
    for (let i = 0; i < AROUND; i++) {
      const i1 = (i + 1) % AROUND;
      for (let j = 0; j < TUBE; j++) {
        const j1 = (j + 1) % TUBE;
        const p00 = base + i * TUBE + j;
        const p10 = base + i1 * TUBE + j;
        const p01 = base + i * TUBE + j1;
        const p11 = base + i1 * TUBE + j1;
        // (∂/∂φ) × (∂/∂θ) points out of the ring: counter-clockwise from outside
        indices.set([p00, p10, p01, p10, p11, p01], t);
        t += 6;
      }
    }
  }
  return { positions, normals, indices };
}
