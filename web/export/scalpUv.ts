// The scalp's UV layout: Lambert's azimuthal equal-area projection of the direction from the
// head's centre (the scalp parameterisation's origin, S5.1), centred on the crown (+y). The
// scalp is a cap round the crown, so the layout has no seam on it and keeps areas (a texture's
// density is the same everywhere on the scalp); the whole sphere of directions but the point
// straight down maps into the unit square:
//   rho = sin(theta / 2) = sqrt((1 - d.y) / 2)   (theta the angle from +y, d the unit direction)
//   u = 0.5 + 0.5 rho h.x,  v = 0.5 + 0.5 rho h.z  (h = (d.x, d.z) / |(d.x, d.z)|)
// so u grows towards the head's left (+x) and v towards the face (+z); the crown is (0.5, 0.5).
// The built-in head's mesh carries this layout as its UVs; a root's UV is the layout at its
// root, whatever head it grows on.

/** UV of the point (x, y, z) relative to the centre (cx, cy, cz), written to out[at], out[at+1]. */
export function scalpUvAt(
  x: number,
  y: number,
  z: number,
  center: readonly [number, number, number],
  out: Float32Array,
  at: number,
): void {
  const dx = x - center[0];
  const dy = y - center[1];
  const dz = z - center[2];
  const len = Math.sqrt(dx * dx + dy * dy + dz * dz);
  if (!(len > 0)) {
    out[at] = 0.5;
    out[at + 1] = 0.5;
    return;
  }
  const rho = Math.sqrt(Math.max(0, Math.min(1, (1 - dy / len) / 2)));
  const h = Math.hypot(dx, dz);
  const hx = h > 0 ? dx / h : 0;
  const hz = h > 0 ? dz / h : 0;
  out[at] = Math.min(1, Math.max(0, 0.5 + 0.5 * rho * hx));
  out[at + 1] = Math.min(1, Math.max(0, 0.5 + 0.5 * rho * hz));
}

/** The layout's UV of every vertex: uv[2 * vertex + k]. */
export function scalpUvs(
  positions: Float32Array,
  center: readonly [number, number, number],
): Float32Array {
  const n = positions.length / 3;
  const uv = new Float32Array(2 * n);
  for (let v = 0; v < n; v++)
    scalpUvAt(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], center, uv, 2 * v);
  return uv;
}
