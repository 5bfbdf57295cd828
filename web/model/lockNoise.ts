// Seeded noise of a strand's root: values shared by strands rooted close together (locks), and
// the integer hash both it and the strands' own random values come from.

/** Lattice spacing of lockNoise, world units (1.2 cm: about a clump's width, detail.ts). */
export const LOCK_CELL = 0.12;

/** Smooth value noise of a root position in [0, 1] (a lattice of seeded values LOCK_CELL apart,
 *  interpolated with smoothstep and stretched to about a uniform spread): strands rooted within
 *  a lock's width of each other get nearly the same value, so the strand shader's highlight tilt
 *  (viewer/strandShaders.ts) turns whole locks together: the key light's highlight breaks into locks,
 *  as it does on a head of hair, instead of averaging over strands into one smooth band. */
export function lockNoise(x: number, y: number, z: number, seed = 0): number {
  const fx = x / LOCK_CELL;
  const fy = y / LOCK_CELL;
  const fz = z / LOCK_CELL;
  const ix = Math.floor(fx);
  const iy = Math.floor(fy);
  const iz = Math.floor(fz);
  const ex = fx - ix;
  const ey = fy - iy;
  const ez = fz - iz;
  const tx = ex * ex * (3 - 2 * ex);
  const ty = ey * ey * (3 - 2 * ey);
  const tz = ez * ez * (3 - 2 * ez);
  // the 8 corners in the order c = dx + 2 dy + 4 dz, unrolled (this runs per strand for every
  // preview): corner c's value hash32(hx ^ hy ^ hz ^ seed), weighted by the product of its axes'
  // weights
  const hx0 = Math.imul(ix, 73856093);
  const hx1 = Math.imul(ix + 1, 73856093);
  const hy0 = Math.imul(iy, 19349663);
  const hy1 = Math.imul(iy + 1, 19349663);
  const hz0 = Math.imul(iz, 83492791) ^ seed;
  const hz1 = Math.imul(iz + 1, 83492791) ^ seed;
  const ux = 1 - tx;
  const uy = 1 - ty;
  const uz = 1 - tz;
  const q = 1 / 4294967296;
  let v = 0;
  v += ux * uy * uz * (hash32(hx0 ^ hy0 ^ hz0) * q);
  v += tx * uy * uz * (hash32(hx1 ^ hy0 ^ hz0) * q);
  v += ux * ty * uz * (hash32(hx0 ^ hy1 ^ hz0) * q);
  v += tx * ty * uz * (hash32(hx1 ^ hy1 ^ hz0) * q);
  v += ux * uy * tz * (hash32(hx0 ^ hy0 ^ hz1) * q);
  v += tx * uy * tz * (hash32(hx1 ^ hy0 ^ hz1) * q);
  v += ux * ty * tz * (hash32(hx0 ^ hy1 ^ hz1) * q);
  v += tx * ty * tz * (hash32(hx1 ^ hy1 ^ hz1) * q);
  // interpolated values gather about the middle (standard deviation ~0.17 against a uniform's
  // 0.29): stretched back to about a uniform's spread
  return Math.min(1, Math.max(0, 0.5 + 1.7 * (v - 0.5)));
}

/** 32-bit integer hash (lowbias32, Chris Wellons). */
export function hash32(x: number): number {
  let h = x >>> 0;
  h ^= h >>> 16;
  h = Math.imul(h, 0x7feb352d);
  h ^= h >>> 15;
  h = Math.imul(h, 0x846ca68b);
  h ^= h >>> 16;
  return h >>> 0;
}
