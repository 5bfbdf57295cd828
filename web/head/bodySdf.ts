// The built-in bust below the head, which long hair rests on: neck, shoulders, the top of the
// chest and of the back, as a signed distance function (negative inside) in the head's frame
// (world units ≈ 10 cm, y up, the face toward +z). Adult proportions: shoulders about 40 cm
// across (acromion to acromion plus the deltoids), the neck meeting the trapezius about 7 cm
// below the chin, the chest about 20 cm deep, cut flat 25 cm below the chin. It is a mesh of
// its own beside the head (buildBody.ts): its neck rises inside the head's neck, so the head,
// its scalp and its roots are the head alone.
import { sdEllipsoid, smin } from './headSdf';

/** The bust's flat bottom: 25 cm below the chin (y ≈ -1.31). */
export const BODY_BOTTOM = -3.85;
/** The top of its neck, hidden inside the head's neck. */
export const BODY_NECK_TOP = -1.55;
/** Half the shoulders' width, deltoids included (40 cm across). */
export const BODY_HALF_WIDTH = 2.0;

/** Distance to the segment a→b with radius ra at a and rb at b. */
function capsule(
  p: readonly [number, number, number],
  a: readonly [number, number, number],
  b: readonly [number, number, number],
  ra: number,
  rb: number,
): number {
  const e = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const w = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
  const t = Math.max(
    0,
    Math.min(
      1,
      (w[0] * e[0] + w[1] * e[1] + w[2] * e[2]) / (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]),
    ),
  );
  return Math.hypot(w[0] - e[0] * t, w[1] - e[1] * t, w[2] - e[2] * t) - (ra + (rb - ra) * t);
}

/** Signed distance of the bust (negative inside). */
export function bodySdf(x: number, y: number, z: number): number {
  const ax = Math.abs(x);
  const p: [number, number, number] = [ax, y, z];
  // the neck: the head's elliptic neck a little thinner, so it stays inside it where both are
  const nx = ax / 0.49;
  const nz = (z + 0.22) / 0.51;
  const neck = (Math.sqrt(nx * nx + nz * nz) - 1) * 0.49;
  // trapezius: from the side of the neck down to the acromion
  const trapezius = capsule(p, [0.4, -2.15, -0.36], [1.55, -2.55, -0.32], 0.26, 0.34);
  // deltoid: the round of the shoulder
  const deltoid = sdEllipsoid(ax - 1.58, y + 2.82, z + 0.26, 0.42, 0.55, 0.46);
  // the chest and the upper back: one rounded block, a little deeper in front (the pectorals)
  const torso = sdEllipsoid(x, y + 3.45, z + 0.28, 1.52, 1.2, 0.95);
  const pecs = sdEllipsoid(ax - 0.62, y + 2.9, z - 0.2, 0.62, 0.42, 0.36);
  let d = smin(torso, trapezius, 0.45);
  d = smin(d, deltoid, 0.35);
  d = smin(d, pecs, 0.3);
  d = smin(d, neck, 0.3);
  // cut flat at the bottom and at the neck's top (inside the head)
  return Math.max(d, BODY_BOTTOM - y, y - BODY_NECK_TOP);
}
