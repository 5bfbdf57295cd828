// Materials of the display overlays drawn as surfaces (the supporting surface); the line and point
// overlays (constraints, field glyphs, bounding box) use overlayStyle.ts's two-pass depth rule.
// Each is created once, on first use, and never disposed: a disposed material releases its shader
// program, and compiling it again stalls on the GPU (seconds behind a software rasteriser).
import * as THREE from 'three';

const cache = new Map<string, THREE.Material>();

/** The material made once under `key` (created on first use, never disposed). */
export function shared<M extends THREE.Material>(key: string, make: () => M): M {
  let m = cache.get(key);
  if (!m) {
    m = make();
    cache.set(key, m);
  }
  return m as M;
}

/** Translucent, two-sided, not writing depth: the head and hair stay visible through it. */
export const translucentSurface = (): THREE.MeshBasicMaterial =>
  shared(
    'surface',
    () =>
      new THREE.MeshBasicMaterial({
        color: 0xf2b134,
        transparent: true,
        opacity: 0.28,
        side: THREE.DoubleSide,
        depthWrite: false,
      }),
  );

/** Geometry of line segments / points from flat arrays (positions[3 * vertex + axis], colours the
 *  same layout in 0..1, or none). */
export function flatGeometry(
  positions: Float32Array,
  colours?: Float32Array,
): THREE.BufferGeometry {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  if (colours) g.setAttribute('color', new THREE.BufferAttribute(colours, 3));
  return g;
}

/** Gives `object` new geometry, freeing the old one's GPU buffers (materials stay). */
export function replaceGeometry(
  object: THREE.Mesh | THREE.LineSegments | THREE.Points,
  geometry: THREE.BufferGeometry,
): void {
  const old = object.geometry;
  object.geometry = geometry;
  old.dispose();
}
