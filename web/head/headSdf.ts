// The built-in head as a signed distance function (negative inside), in world units (≈ 10 cm):
// y up, face toward +z, +x is the head's left, origin near the middle of the cranium.
// Built from smooth unions of ellipsoids, a tapered nose, an elliptic neck cylinder and smooth
// subtractions (eye sockets, ear conchae, mouth line). The function is an approximation of a
// true distance (ellipsoid bound of Quílez), good enough near the surface for polygonisation.

/** Approximate signed distance to an axis-aligned ellipsoid with radii (rx, ry, rz) centred at
 *  the origin, for the point (x, y, z) given relative to its centre. */
export function sdEllipsoid(
  x: number,
  y: number,
  z: number,
  rx: number,
  ry: number,
  rz: number,
): number {
  const ax = x / rx;
  const ay = y / ry;
  const az = z / rz;
  const k0 = Math.sqrt(ax * ax + ay * ay + az * az);
  const bx = ax / rx;
  const by = ay / ry;
  const bz = az / rz;
  const k1 = Math.sqrt(bx * bx + by * by + bz * bz);
  if (k1 < 1e-12) return -Math.min(rx, ry, rz);
  return (k0 * (k0 - 1)) / k1;
}

/** Polynomial smooth minimum (blend width k, world units). */
export function smin(a: number, b: number, k: number): number {
  const h = Math.max(k - Math.abs(a - b), 0) / k;
  return Math.min(a, b) - h * h * k * 0.25;
}

/** Polynomial smooth maximum (used for smooth subtraction: smax(a, -b, k)). */
export function smax(a: number, b: number, k: number): number {
  const h = Math.max(k - Math.abs(a - b), 0) / k;
  return Math.max(a, b) + h * h * k * 0.25;
}

/** Distance to a round cone: segment (ax,ay,az)→(bx,by,bz) with radius ra at a, rb at b
 *  (linear taper, adequate when |ra − rb| is small against the length). */
function sdTaperedCapsule(
  px: number,
  py: number,
  pz: number,
  ax: number,
  ay: number,
  az: number,
  bx: number,
  by: number,
  bz: number,
  ra: number,
  rb: number,
): number {
  const ex = bx - ax;
  const ey = by - ay;
  const ez = bz - az;
  const wx = px - ax;
  const wy = py - ay;
  const wz = pz - az;
  let t = (wx * ex + wy * ey + wz * ez) / (ex * ex + ey * ey + ez * ez);
  t = Math.max(0, Math.min(1, t));
  const dx = wx - ex * t;
  const dy = wy - ey * t;
  const dz = wz - ez * t;
  return Math.sqrt(dx * dx + dy * dy + dz * dz) - (ra + (rb - ra) * t);
}

// ---- feature placement (world units) -------------------------------------------------------

export const NECK_BOTTOM = -2.6;
/** Eye centres are at (±EYE_X, EYE_Y, EYE_Z) with radius EYE_R. */
export const EYE_X = 0.29;
export const EYE_Y = -0.2;
export const EYE_Z = 0.7;
export const EYE_R = 0.15;
/** Ear centres at (±EAR_X, EAR_Y, EAR_Z). */
export const EAR_X = 0.72;
export const EAR_Y = -0.25;
export const EAR_Z = -0.12;

/** Cranium, face mass, jaw, chin, cheeks and brow, without the finer features. */
function skull(x: number, y: number, z: number, ax: number): number {
  // cranium: top at y = 1.0, half-width 0.75, half-length 0.95
  let d = sdEllipsoid(x, y, z + 0.05, 0.75, 1.0, 0.95);
  // upper face (cheekbone level) and jaw
  d = smin(d, sdEllipsoid(x, y + 0.38, z - 0.27, 0.7, 0.6, 0.68), 0.25);
  d = smin(d, sdEllipsoid(x, y + 0.82, z - 0.27, 0.57, 0.5, 0.64), 0.3);
  // muzzle (the teeth's curve under the lips) and chin
  d = smin(d, sdEllipsoid(x, y + 0.74, z - 0.7, 0.3, 0.26, 0.27), 0.15);
  d = smin(d, sdEllipsoid(x, y + 1.1, z - 0.66, 0.25, 0.21, 0.24), 0.2);
  // cheeks
  d = smin(d, sdEllipsoid(ax - 0.37, y + 0.45, z - 0.58, 0.25, 0.2, 0.28), 0.16);
  // brow ridge
  d = smin(d, sdEllipsoid(x, y + 0.02, z - 0.77, 0.56, 0.13, 0.2), 0.12);
  return d;
}

function nose(x: number, y: number, z: number, ax: number): number {
  let d = sdTaperedCapsule(x, y, z, 0, -0.1, 0.93, 0, -0.47, 1.2, 0.065, 0.095);
  d = smin(d, sdEllipsoid(ax - 0.1, y + 0.5, z - 1.02, 0.095, 0.08, 0.1), 0.1);
  return d;
}

function lips(x: number, y: number, z: number): number {
  let d = sdEllipsoid(x, y + 0.775, z - 0.95, 0.2, 0.055, 0.085);
  d = smin(d, sdEllipsoid(x, y + 0.885, z - 0.925, 0.17, 0.06, 0.085), 0.04);
  return d;
}

function ear(y: number, z: number, ax: number): number {
  // tilt the ear back a little: rotate (y, z) by ~12°
  const ly = y - EAR_Y;
  const lz = z - EAR_Z;
  const c = 0.978;
  const s = 0.208;
  const ry = c * ly - s * lz;
  const rz = s * ly + c * lz;
  const lx = ax - EAR_X;
  let d = sdEllipsoid(lx, ry, rz, 0.11, 0.3, 0.18);
  // concha: a hollow on the outer side
  d = smax(d, -sdEllipsoid(lx - 0.13, ry + 0.04, rz - 0.02, 0.08, 0.17, 0.1), 0.04);
  return d;
}

function neck(x: number, y: number, z: number): number {
  // elliptic cylinder, slightly flaring toward the bottom, capped flat at NECK_BOTTOM
  const u = Math.min(1, Math.max(0, (-1.85 - y) / 0.75));
  const rx = 0.52 * (1 + 0.22 * u * u);
  const rz = 0.54 * (1 + 0.08 * u * u);
  const qx = x / rx;
  const qz = (z + 0.22) / rz;
  const side = (Math.sqrt(qx * qx + qz * qz) - 1) * Math.min(rx, rz);
  // the top end at y = -0.2 lies inside the cranium, hidden by the union
  return Math.max(side, NECK_BOTTOM - y, y + 0.2);
}

/** Signed distance of the built-in head (negative inside). */
export function headSdf(x: number, y: number, z: number): number {
  const ax = Math.abs(x);
  let d = skull(x, y, z, ax);
  // neck
  d = smin(d, neck(x, y, z), 0.35);
  // eye sockets: smooth subtraction, then the eyeballs
  const ex = ax - EYE_X;
  const ey = y - EYE_Y;
  if (z > 0.3 && ey > -0.5 && ey < 0.5 && ex < 0.5) {
    d = smax(d, -sdEllipsoid(ex, ey - 0.01, z - 0.9, 0.19, 0.14, 0.2), 0.1);
    const r = Math.sqrt(ex * ex + ey * ey + (z - EYE_Z) * (z - EYE_Z));
    d = smin(d, r - EYE_R, 0.04);
    // eyelids: shells slightly larger than the eyeball above and below the opening
    const lid = r - EYE_R - 0.02;
    d = smin(d, smax(lid, EYE_Y + 0.035 - y, 0.03), 0.02);
    d = smin(d, smax(lid, y - EYE_Y + 0.07, 0.03), 0.02);
  }
  // nose
  if (z > 0.5 && y > -0.8 && y < 0.2 && ax < 0.4) d = smin(d, nose(x, y, z, ax), 0.1);
  // lips and mouth line
  if (z > 0.5 && y > -1.15 && y < -0.55 && ax < 0.5) {
    d = smin(d, lips(x, y, z), 0.06);
    d = smax(d, -sdEllipsoid(x, y + 0.835, z - 1.03, 0.19, 0.016, 0.09), 0.025);
  }
  // ears
  if (ax > 0.4 && y > -0.75 && y < 0.25 && z < 0.4 && z > -0.6) d = smin(d, ear(y, z, ax), 0.1);
  return d;
}

/** Distance-like value of the ear at (x, y, z) (either side; negative inside the ear), large
 *  away from it: where the natural hairline leaves the ear bare. */
export function earDistance(x: number, y: number, z: number): number {
  return ear(y, z, Math.abs(x));
}

/** Surface part labels, for colouring (HeadModel.parts). */
export const HeadPart = { skin: 0, eye: 1, lips: 2 } as const;

/** Which part a point on (or near) the surface belongs to. */
export function headPartAt(x: number, y: number, z: number): number {
  const ax = Math.abs(x);
  const ex = ax - EYE_X;
  const ey = y - EYE_Y;
  const ez = z - EYE_Z;
  if (Math.sqrt(ex * ex + ey * ey + ez * ez) - EYE_R < 0.008) return HeadPart.eye;
  if (z > 0.5 && y > -1.15 && y < -0.55 && ax < 0.5 && lips(x, y, z) < 0.01) return HeadPart.lips;
  return HeadPart.skin;
}
