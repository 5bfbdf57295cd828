// Inside test and signed distance for a mesh that may have holes, separate parts (eyes, teeth)
// and parts that overlap: each of several rays from the point counts its crossings with their
// sign (+1 leaving through a triangle's front, -1 entering), i.e. the winding number along that
// ray; the ray says "inside" when that count is not zero (for one closed part this is ray
// parity; overlapping closed parts add up instead of cancelling). The majority of the rays
// decides, so a ray escaping through a hole, or grazing an edge, is outvoted.
import * as THREE from 'three';
import type { MeshBVH } from 'three-mesh-bvh';
import type { Vec3 } from '../model/vec3';

// Seven fixed, well-spread directions, none along an axis or a diagonal (a generated or
// grid-aligned mesh has edges there).
const RAY_DIRECTIONS: ReadonlyArray<THREE.Vector3> = [
  [0.5431, 0.7172, 0.4367],
  [-0.6137, 0.2711, 0.7415],
  [0.1822, -0.8711, 0.4561],
  [-0.7719, -0.3351, -0.5403],
  [0.8253, -0.1372, -0.5477],
  [-0.1436, 0.6392, -0.7555],
  [0.3113, 0.1741, -0.9342],
].map(([x, y, z]) => new THREE.Vector3(x, y, z).normalize());

const VOTES_NEEDED = 4; // majority of 7

export interface MeshInside {
  /** True when `p` is inside the mesh (majority of 7 rays). */
  inside(p: Vec3): boolean;
  /** Distance to the closest surface point, negative inside; with `maxDistance`, points
   *  farther than that from the surface give ±maxDistance (much faster far from it). */
  signedDistance(p: Vec3, maxDistance?: number): number;
}

export function meshInside(bvh: MeshBVH, bounds: { min: Vec3; max: Vec3 }): MeshInside {
  const ray = new THREE.Ray();
  const target = new THREE.Vector3();
  const result = { point: new THREE.Vector3(), distance: 0, faceIndex: 0 };
  const outsideBox = (p: Vec3) =>
    p[0] < bounds.min[0] ||
    p[1] < bounds.min[1] ||
    p[2] < bounds.min[2] ||
    p[0] > bounds.max[0] ||
    p[1] > bounds.max[1] ||
    p[2] > bounds.max[2];

  const inside = (p: Vec3): boolean => {
    if (outsideBox(p)) return false;
    let yes = 0;
    let no = 0;
    for (const d of RAY_DIRECTIONS) {
      ray.origin.set(p[0], p[1], p[2]);
      ray.direction.copy(d);
      const hits = bvh.raycast(ray, THREE.DoubleSide);
      let winding = 0;
      for (const h of hits) {
        const n = h.face?.normal;
        if (!n) continue;
        winding += n.dot(d) > 0 ? 1 : -1;
      }
      if (winding !== 0) yes++;
      else no++;
      if (yes >= VOTES_NEEDED) return true;
      if (no >= VOTES_NEEDED) return false;
    }
    return yes > no;
  };

  // The previous query bounds this one (d(p) ≤ d(q) + |p − q|): consecutive queries on a grid
  // or along a strand prune the BVH with that bound and stay exact.
  const last: Vec3 = [Number.NaN, Number.NaN, Number.NaN];
  let lastDistance = Infinity;
  const signedDistance = (p: Vec3, maxDistance = Infinity): number => {
    target.set(p[0], p[1], p[2]);
    const bound =
      (lastDistance + Math.hypot(p[0] - last[0], p[1] - last[1], p[2] - last[2])) * (1 + 1e-6) +
      1e-9;
    const limit = Math.min(maxDistance, Number.isFinite(bound) ? bound : Infinity);
    let r = bvh.closestPointToPoint(target, result, 0, limit);
    if (!r && limit < maxDistance) r = bvh.closestPointToPoint(target, result, 0, maxDistance);
    const d = r ? r.distance : maxDistance;
    if (!Number.isFinite(d)) return Infinity; // no triangles
    last[0] = p[0];
    last[1] = p[1];
    last[2] = p[2];
    lastDistance = d;
    if (d === 0) return 0;
    return inside(p) ? -d : d;
  };

  return { inside, signedDistance };
}
