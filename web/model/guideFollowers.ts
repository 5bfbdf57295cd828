// Where a groom's strands go while a motion plays: only guides are simulated (HairSim,
// solver-cpp/src/strand_motion.hpp); every strand rides the guide it is bound to. This file is the
// CPU reference of that placement (the motion export, `hairsketch grow --motion`, the test API);
// the strand shader computes the same per vertex on the GPU (viewer/followerGlsl.ts), so no work
// a frame on the page grows with the strand count.
//
// A point r bound to guide g at a (in guide points, 0 .. G - 1; j = floor(a), w = a - j) keeps,
// from its groom, its offset from the guide's rest point there, o = r - lerp(A_j, A_j+1, w), and
// the guide's rest unit tangent there, t = normalize(lerp(TA_j, TA_j+1, w)) (TA: the guide's
// smoothed tangents, guideTangents). With the head's pose (R, c) and the guide now (B, TB):
//   p = lerp(B_j, B_j+1, w) + lerp(M (R o), R o, f(|o|)),   M the least rotation taking R t to
//   normalize(lerp(TB_j, TB_j+1, w)), f rising smoothly from 0 at FOLLOW_TURN_NEAR to 1 at
//   FOLLOW_TURN_FAR,
// so a point near its guide turns with the guide's direction where it is and keeps its distance
// from it (a strand beside its guide, or a tie's strand around the tail's one guide, keeps its
// segment lengths to first order), and a point far from it (hair parted the other way, long hair
// falling in front of the shoulder bound to a guide behind it) moves as the guide's point does
// without turning about it: turned, a 10 cm offset swings 10 cm for every radian the guide bends
// and stretches the strand. A strand with no guide (fewer than two points) rides the head: R r + c.
// At rest (guides at their groom, pose the identity) every point is its groom but for the rest
// tangent's rounding to bytes (the offset turned by at most about half a degree: under 0.1 mm).

import { smoothstep } from './smoothstep';

/** Offsets from the guide (world units) up to which a point turns with its guide's direction
 *  in full, and from which it does not turn at all (followerGlsl.ts uses the same). */
export const FOLLOW_TURN_NEAR = 0.15;
export const FOLLOW_TURN_FAR = 0.6;

/** The guides of a motion and how the strands are bound to them (StrandMotion's binding). */
export interface GuideBinding {
  guideCount: number;
  /** Points per guide (G). */
  guidePoints: number;
  /** The guides at rest: 3 * (guide * G + point) + axis (the groom's strands, resampled). */
  guideRest: Float32Array;
  /** Per strand: its guide, -1 for none. */
  guideOf: Int32Array;
  /** Per point: its place along its guide, in guide points (0 .. G - 1). */
  along: Float32Array;
}

/** What placing a point needs besides the guides now, per point (the strand shader's vertex
 *  attributes `follow`, `followOffset`, `followTangent`). */
export interface FollowerAttributes {
  /** 2 per point: its guide (-1: none) and its place along it (in guide points). */
  follow: Float32Array;
  /** 3 per point: the point less its guide's rest point there (the groom's frame). */
  offset: Float32Array;
  /** 3 per point: the guide's rest unit tangent there, as signed normalised bytes (v / 127). */
  tangent: Int8Array;
}

/** Each guide point's unit tangent (central differences, one-sided at the ends; +y where a guide
 *  has no length there), 3 floats a point in the layout of `guides`. */
export function guideTangents(
  guides: Float32Array,
  guidePoints: number,
  out = new Float32Array(guides.length),
): Float32Array {
  const G = guidePoints;
  const count = G > 0 ? Math.floor(guides.length / (3 * G)) : 0;
  for (let g = 0; g < count; g++) {
    const base = g * G;
    for (let j = 0; j < G; j++) {
      const a = 3 * (base + Math.max(0, j - 1));
      const b = 3 * (base + Math.min(G - 1, j + 1));
      const x = guides[b] - guides[a];
      const y = guides[b + 1] - guides[a + 1];
      const z = guides[b + 2] - guides[a + 2];
      const l = Math.sqrt(x * x + y * y + z * z);
      const o = 3 * (base + j);
      if (l > 1e-12) {
        out[o] = x / l;
        out[o + 1] = y / l;
        out[o + 2] = z / l;
      } else {
        out[o] = 0;
        out[o + 1] = 1;
        out[o + 2] = 0;
      }
    }
  }
  return out;
}

/** Signed normalised byte as WebGL reads it (v / 127, at least -1). */
export function snorm8(v: number): number {
  return Math.max(v / 127, -1);
}

/** The attributes that bind `points` (strandStart: each strand's first point, and the end) to
 *  their guides: of every point, or of the points `only` lists (ascending; the attributes then
 *  in its order). */
export function followerAttributes(
  points: Float32Array,
  strandStart: Uint32Array,
  binding: GuideBinding,
  only: Uint32Array | null = null,
): FollowerAttributes {
  const pointCount = strandStart.length > 0 ? strandStart[strandStart.length - 1] : 0;
  const n = only ? only.length : pointCount;
  const follow = new Float32Array(2 * n);
  const offset = new Float32Array(3 * n);
  const tangent = new Int8Array(3 * n);
  const G = binding.guidePoints;
  const rest = binding.guideRest;
  const restTangents = guideTangents(rest, G);
  let s = 0;
  for (let p = 0; p < n; p++) {
    const q = only ? only[p] : p; // the point; p: where its attributes go
    while (strandStart[s + 1] <= q) s++;
    const g = binding.guideOf[s];
    if (g < 0 || G < 2) {
      follow[2 * p] = -1;
      continue;
    }
    const a = binding.along[q];
    const j = Math.min(G - 2, Math.max(0, Math.floor(a)));
    const w = a - j;
    follow[2 * p] = g;
    follow[2 * p + 1] = a;
    const i0 = 3 * (g * G + j);
    const i1 = i0 + 3;
    for (let c = 0; c < 3; c++)
      offset[3 * p + c] = points[3 * q + c] - (rest[i0 + c] + w * (rest[i1 + c] - rest[i0 + c]));
    const tx = restTangents[i0] + w * (restTangents[i1] - restTangents[i0]);
    const ty = restTangents[i0 + 1] + w * (restTangents[i1 + 1] - restTangents[i0 + 1]);
    const tz = restTangents[i0 + 2] + w * (restTangents[i1 + 2] - restTangents[i0 + 2]);
    const l = Math.sqrt(tx * tx + ty * ty + tz * tz) || 1;
    tangent[3 * p] = Math.round((127 * tx) / l);
    tangent[3 * p + 1] = Math.round((127 * ty) / l);
    tangent[3 * p + 2] = Math.round((127 * tz) / l);
  }
  return { follow, offset, tangent };
}

/** v turned by the least rotation taking unit a to unit b (Rodrigues with k = a x b:
 *  v c + k x v + k (k . v) / (1 + c)), written into out[o..o+2]. */
function rotateBetween(
  ax: number,
  ay: number,
  az: number,
  bx: number,
  by: number,
  bz: number,
  vx: number,
  vy: number,
  vz: number,
  out: Float32Array,
  o: number,
): void {
  const c = ax * bx + ay * by + az * bz;
  const kx = ay * bz - az * by;
  const ky = az * bx - ax * bz;
  const kz = ax * by - ay * bx;
  const f = (kx * vx + ky * vy + kz * vz) / Math.max(1 + c, 1e-6);
  out[o] = vx * c + (ky * vz - kz * vy) + kx * f;
  out[o + 1] = vy * c + (kz * vx - kx * vz) + ky * f;
  out[o + 2] = vz * c + (kx * vy - ky * vx) + kz * f;
}

/** Every point of the strands placed on the guides now (`guides`, the layout of guideRest) with
 *  the head's pose (pose[0..8] its rotation row-major, pose[9..11] its translation): the CPU
 *  reference of the strand shader's placement. `rest`: the groom's points. */
export function placeFollowers(
  rest: Float32Array,
  attrs: FollowerAttributes,
  guides: Float32Array,
  guidePoints: number,
  pose: ArrayLike<number>,
  out = new Float32Array(rest.length),
): Float32Array {
  const G = guidePoints;
  const tangents = guideTangents(guides, G);
  const { follow, offset, tangent } = attrs;
  const n = follow.length / 2;
  const [r0, r1, r2, r3, r4, r5, r6, r7, r8, t0, t1, t2] = Array.from(pose);
  for (let p = 0; p < n; p++) {
    const g = follow[2 * p];
    if (g < 0) {
      const x = rest[3 * p];
      const y = rest[3 * p + 1];
      const z = rest[3 * p + 2];
      out[3 * p] = r0 * x + r1 * y + r2 * z + t0;
      out[3 * p + 1] = r3 * x + r4 * y + r5 * z + t1;
      out[3 * p + 2] = r6 * x + r7 * y + r8 * z + t2;
      continue;
    }
    const a = follow[2 * p + 1];
    const j = Math.min(G - 2, Math.max(0, Math.floor(a)));
    const w = a - j;
    const i0 = 3 * (g * G + j);
    const i1 = i0 + 3;
    // the guide's tangent now there, and its rest tangent turned by the head
    let bx = tangents[i0] + w * (tangents[i1] - tangents[i0]);
    let by = tangents[i0 + 1] + w * (tangents[i1 + 1] - tangents[i0 + 1]);
    let bz = tangents[i0 + 2] + w * (tangents[i1 + 2] - tangents[i0 + 2]);
    const bl = Math.sqrt(bx * bx + by * by + bz * bz) || 1;
    bx /= bl;
    by /= bl;
    bz /= bl;
    const qx = snorm8(tangent[3 * p]);
    const qy = snorm8(tangent[3 * p + 1]);
    const qz = snorm8(tangent[3 * p + 2]);
    let ax = r0 * qx + r1 * qy + r2 * qz;
    let ay = r3 * qx + r4 * qy + r5 * qz;
    let az = r6 * qx + r7 * qy + r8 * qz;
    const al = Math.sqrt(ax * ax + ay * ay + az * az) || 1;
    ax /= al;
    ay /= al;
    az /= al;
    const ox = offset[3 * p];
    const oy = offset[3 * p + 1];
    const oz = offset[3 * p + 2];
    const vx = r0 * ox + r1 * oy + r2 * oz;
    const vy = r3 * ox + r4 * oy + r5 * oz;
    const vz = r6 * ox + r7 * oy + r8 * oz;
    rotateBetween(ax, ay, az, bx, by, bz, vx, vy, vz, out, 3 * p);
    const f = smoothstep(FOLLOW_TURN_NEAR, FOLLOW_TURN_FAR, Math.sqrt(ox * ox + oy * oy + oz * oz));
    out[3 * p] += f * (vx - out[3 * p]) + guides[i0] + w * (guides[i1] - guides[i0]);
    out[3 * p + 1] +=
      f * (vy - out[3 * p + 1]) + guides[i0 + 1] + w * (guides[i1 + 1] - guides[i0 + 1]);
    out[3 * p + 2] +=
      f * (vz - out[3 * p + 2]) + guides[i0 + 2] + w * (guides[i1 + 2] - guides[i0 + 2]);
  }
  return out;
}
