// The face normal of a mesh triangle, shared by vertex normals, the scalp test and root areas.

/** Writes (b − a) × (c − a), unnormalised (its length is twice the triangle's area), into `out`
 *  and returns it; a, b, c are the corners' offsets in `P` (3 × vertex index). */
export function triangleNormal(
  P: ArrayLike<number>,
  a: number,
  b: number,
  c: number,
  out: Float64Array,
): Float64Array {
  const ux = P[b] - P[a];
  const uy = P[b + 1] - P[a + 1];
  const uz = P[b + 2] - P[a + 2];
  const vx = P[c] - P[a];
  const vy = P[c + 1] - P[a + 1];
  const vz = P[c + 2] - P[a + 2];
  out[0] = uy * vz - uz * vy;
  out[1] = uz * vx - ux * vz;
  out[2] = ux * vy - uy * vx;
  return out;
}
