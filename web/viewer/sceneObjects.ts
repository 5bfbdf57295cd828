// Small helpers for the viewer's own scene objects: freeing them, and the bar that marks where a
// stroke's hair ends.
import * as THREE from 'three';
import type { Vec3 } from '../model/vec3';

/** Removes and frees every child of `group`. */
export function clearGroup(group: THREE.Group): void {
  for (const child of [...group.children]) {
    group.remove(child);
    disposeObject(child);
  }
}

/** Frees an object's geometry (once, also when shared with its hidden-pass twin); materials are
 *  the owner's (shared, reused across objects). */
export function disposeObject(o: THREE.Object3D): void {
  const done = new Set<THREE.BufferGeometry>();
  o.traverse((x) => {
    const g = (x as THREE.Mesh).geometry;
    if (g && !done.has(g)) {
      done.add(g);
      g.dispose();
    }
  });
}

/** Half-length (world units: 1.5 cm) of the bar that marks where a stroke's hair ends. */
const END_BAR_HALF = 0.15;

/** A short bar across the stroke's last point, square to its last segment and to the view
 *  (null when they are parallel). */
export function endBar(points: readonly Vec3[], forward: Vec3): Vec3[] | null {
  const a = points[points.length - 2];
  const b = points[points.length - 1];
  const t = new THREE.Vector3(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  const across = t.cross(new THREE.Vector3(...forward));
  if (!(across.length() > 1e-9)) return null;
  across.setLength(END_BAR_HALF);
  return [
    [b[0] - across.x, b[1] - across.y, b[2] - across.z],
    [b[0] + across.x, b[1] + across.y, b[2] + across.z],
  ];
}
