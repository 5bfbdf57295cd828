// The scalp: the hair-bearing part of the cranium (method S1.1), described as a region of
// directions seen from the scalp-parameterisation centre. Spherical angles as in S5.1: θ from +y
// (0 = top of the head), φ = 0 toward +z (the face), φ = 90° toward +x (the head's left); the
// direction is (sinθ sinφ, cosθ, sinθ cosφ). The hairline is θ_max(|φ|): a direction is scalp
// when θ < θ_max(|φ|).
import type { TriangleSoup } from './head';
import { triangleNormal } from './triangleNormal';

const DEG = Math.PI / 180;

// Hairline control points (|φ| in degrees, θ_max in degrees), symmetric left/right: forehead,
// temples (a little recessed), sideburn in front of the ear, over the ear, behind the ear, nape.
const HAIRLINE: ReadonlyArray<readonly [number, number]> = [
  [0, 57],
  [20, 58],
  [40, 64],
  [55, 72],
  [66, 84],
  [73, 97],
  [79, 96],
  [84, 80],
  [98, 74],
  [112, 78],
  [128, 92],
  [150, 108],
  [168, 115],
  [180, 116],
];

// The hairline of sessions with finished edges (`finish`): it keeps the front and the temples,
// wraps the ear about a centimetre above it, drops behind the ear to the level of the lobe and
// meets the nape lower, where short cuts and up-styles show skin rather than an undercut. The
// ear itself is cut out by the built-in head (buildHead.ts), which knows where it is.
const NATURAL_HAIRLINE: ReadonlyArray<readonly [number, number]> = [
  [0, 57],
  [20, 58],
  [40, 64],
  [55, 72],
  [66, 86],
  [73, 100],
  [79, 99],
  [85, 86],
  [92, 82],
  [102, 83],
  [112, 92],
  [122, 110],
  [135, 121],
  [155, 124],
  [180, 124],
];

// The natural hairline with the nape where it is on a person (sessions with `nape`): past the
// ear it goes on down the upper neck, about 3.5 cm below the skull's base at the back, instead of
// stopping there (fresh eyes, rounds 19 and 21: a ponytail, a bun or a slicked-back style read as
// "cut at ear level" from behind, the hair ending in a line where the head meets the neck).
const LOW_NAPE_HAIRLINE: ReadonlyArray<readonly [number, number]> = [
  ...NATURAL_HAIRLINE.filter(([phi]) => phi < 112),
  [112, 94],
  [122, 116],
  [135, 133],
  [155, 140],
  [180, 142],
];

/** Which hairline a scalp region follows: the classic one (every session before `finish`), the
 *  natural one, or the natural one with a low nape (`nape`). */
export type Hairline = 'classic' | 'natural' | 'lowNape';

const HAIRLINES: Record<Hairline, ReadonlyArray<readonly [number, number]>> = {
  classic: HAIRLINE,
  natural: NATURAL_HAIRLINE,
  lowNape: LOW_NAPE_HAIRLINE,
};

/** The hairline a session's built-in head starts from: the classic one without finished edges,
 *  else the natural one, with a low nape in sessions with `nape`. */
export function sessionHairline(s: { finish?: boolean; nape?: boolean }): Hairline {
  return !s.finish ? 'classic' : s.nape ? 'lowNape' : 'natural';
}

/** θ_max (radians) of the hairline at azimuth φ (radians, any range). */
export function hairlineTheta(phi: number, hairline: Hairline = 'classic'): number {
  const line = HAIRLINES[hairline];
  let a = Math.abs(Math.atan2(Math.sin(phi), Math.cos(phi))) / DEG; // |φ| in [0, 180]
  if (a > 180) a = 180;
  for (let i = 1; i < line.length; i++) {
    const [p1, t1] = line[i];
    if (a <= p1) {
      const [p0, t0] = line[i - 1];
      const u = (a - p0) / (p1 - p0);
      const s = u * u * (3 - 2 * u); // smoothstep between control points
      return (t0 + (t1 - t0) * s) * DEG;
    }
  }
  return line[line.length - 1][1] * DEG;
}

/** True when the direction at spherical angles (θ, φ) (radians) lies in the scalp region. */
export function isScalpDirection(
  theta: number,
  phi: number,
  hairline: Hairline = 'classic',
): boolean {
  return theta < hairlineTheta(phi, hairline);
}

/** Spherical angles (θ, φ) in radians of the vector (x, y, z) (not necessarily unit). */
export function directionAngles(x: number, y: number, z: number): [number, number] {
  const r = Math.sqrt(x * x + y * y + z * z);
  if (r === 0) return [0, 0];
  return [Math.acos(Math.max(-1, Math.min(1, y / r))), Math.atan2(x, z)];
}

/** True when the point (world units) seen from `center` lies in a scalp direction. */
export function isScalpPoint(
  x: number,
  y: number,
  z: number,
  center: readonly [number, number, number] = [0, 0, 0],
): boolean {
  const [theta, phi] = directionAngles(x - center[0], y - center[1], z - center[2]);
  return isScalpDirection(theta, phi);
}

/** Mark triangles (1 = scalp) whose centroid lies in a scalp direction from `center` and whose
 *  outward normal faces away from the centre (so inner folds are never scalp). */
export function markScalpTriangles(
  mesh: TriangleSoup,
  center: readonly [number, number, number] = [0, 0, 0],
  hairline: Hairline = 'classic',
): Uint8Array {
  const { positions: P, indices: I } = mesh;
  const triangles = I.length / 3;
  const scalp = new Uint8Array(triangles);
  const n = new Float64Array(3);
  for (let t = 0; t < triangles; t++) {
    const a = 3 * I[3 * t];
    const b = 3 * I[3 * t + 1];
    const c = 3 * I[3 * t + 2];
    const cx = (P[a] + P[b] + P[c]) / 3 - center[0];
    const cy = (P[a + 1] + P[b + 1] + P[c + 1]) / 3 - center[1];
    const cz = (P[a + 2] + P[b + 2] + P[c + 2]) / 3 - center[2];
    const [theta, phi] = directionAngles(cx, cy, cz);
    if (!isScalpDirection(theta, phi, hairline)) continue;
    // face normal (unnormalised) · radial direction
    triangleNormal(P, a, b, c, n);
    if (n[0] * cx + n[1] * cy + n[2] * cz > 0) scalp[t] = 1;
  }
  return scalp;
}

/** Scalp of a user-loaded head (method S1.1): triangles whose centroid lies on the side of the
 *  plane that `planeNormal` points to. The normal need not be unit. */
export function scalpFromPlane(
  mesh: TriangleSoup,
  planePoint: readonly [number, number, number],
  planeNormal: readonly [number, number, number],
): Uint8Array {
  const { positions: P, indices: I } = mesh;
  const triangles = I.length / 3;
  const scalp = new Uint8Array(triangles);
  const [px, py, pz] = planePoint;
  const [nx, ny, nz] = planeNormal;
  for (let t = 0; t < triangles; t++) {
    const a = 3 * I[3 * t];
    const b = 3 * I[3 * t + 1];
    const c = 3 * I[3 * t + 2];
    const cx = (P[a] + P[b] + P[c]) / 3 - px;
    const cy = (P[a + 1] + P[b + 1] + P[c + 1]) / 3 - py;
    const cz = (P[a + 2] + P[b + 2] + P[c + 2]) / 3 - pz;
    if (cx * nx + cy * ny + cz * nz > 0) scalp[t] = 1;
  }
  return scalp;
}
