// The key light, fixed in world space (it does not follow the camera), so lighting precomputed
// per hair revision (hairLighting.ts, in the solver worker) stays valid while the view orbits.
// The viewer's key DirectionalLight, the strand shader and the precompute all use it; the fill
// comes from behind on the other side (the viewer's rim light).

const unit = (x: number, y: number, z: number): [number, number, number] => {
  const l = Math.hypot(x, y, z);
  return [x / l, y / l, z / l];
};

/** Towards the key light (above, in front, to the head's right). */
export const KEY_LIGHT_DIRECTION: readonly [number, number, number] = unit(3, 5, 4);
/** Where the viewer places its key DirectionalLight (any point along KEY_LIGHT_DIRECTION). */
export const KEY_LIGHT_POSITION: readonly [number, number, number] = [3, 5, 4];
/** Towards the fill light (behind, left, a little above: the viewer's rim light). */
export const FILL_LIGHT_DIRECTION: readonly [number, number, number] = unit(-4, 2, -3);
