// Positions-only update of the strands on screen (a motion frame: the same strands, new points).
// The geometry buildStrandGeometry or buildStrandStripGeometry made keeps its colours, lighting,
// `along` and index; only `position` and the `tangent` derived from it (the strand material
// lights and, for strips, widens along it) are written and marked for upload, with the bounds.
// `along`'s distance from the tip (the lighter tips) is kept too: the motion holds its guides'
// segment lengths (a position-based constraint) and the other strands ride their guide, so a
// point stays about as far from its tip by arc length, and a frame costs no pass more.
import * as THREE from 'three';
import { writeTangents } from './strandAttributes';

/** Writes `points` into the hair object's geometry when it was built for strands of this layout
 *  (`strandStart`): lines (one vertex a point) or strips (two). Lines take `points` as their
 *  position array (no copy: do not change it afterwards); strips copy it. False (nothing
 *  written) for anything else, e.g. cards or another layout: the caller rebuilds. */
export function updateStrandPositions(
  object: THREE.Object3D | null,
  points: Float32Array,
  strandStart: Uint32Array,
): boolean {
  if (!(object instanceof THREE.LineSegments || object instanceof THREE.Mesh)) return false;
  const g = object.geometry as THREE.BufferGeometry;
  const pos = g.getAttribute('position');
  const tan = g.getAttribute('tangent');
  const strands = Math.max(0, strandStart.length - 1);
  const pointCount = strands > 0 ? strandStart[strands] : 0;
  if (!(pos instanceof THREE.BufferAttribute) || !(tan instanceof THREE.BufferAttribute))
    return false;
  if (g.userData.strands !== strands || 3 * pointCount > points.length) return false;
  const per = object instanceof THREE.LineSegments ? 1 : 2; // vertices per point
  if (pos.count !== per * pointCount || tan.count !== per * pointCount || pos.itemSize !== 3)
    return false;
  const tangent = tan.array as Int8Array;
  const box = writeTangents(points, strandStart, tangent, per);
  if (per === 1) {
    if (pos.array.length === points.length) pos.array = points;
    else (pos.array as Float32Array).set(points.subarray(0, 3 * pointCount));
  } else {
    const out = pos.array as Float32Array;
    for (let i = 0; i < pointCount; i++) {
      const x = points[3 * i];
      const y = points[3 * i + 1];
      const z = points[3 * i + 2];
      out[6 * i] = x;
      out[6 * i + 1] = y;
      out[6 * i + 2] = z;
      out[6 * i + 3] = x;
      out[6 * i + 4] = y;
      out[6 * i + 5] = z;
    }
  }
  pos.needsUpdate = true;
  tan.needsUpdate = true;
  if (pointCount > 0) {
    g.boundingBox ??= new THREE.Box3();
    g.boundingSphere ??= new THREE.Sphere();
    const b = g.boundingBox;
    b.min.set(box[0], box[1], box[2]);
    b.max.set(box[3], box[4], box[5]);
    const s = g.boundingSphere;
    b.getCenter(s.center);
    s.radius = 0.5 * b.min.distanceTo(b.max);
  }
  return true;
}
