// Raycasting the head through a BVH (three-mesh-bvh). The BVH is built "indirect" so triangle
// indices stay those of the HeadModel and its per-triangle scalp flags.
import * as THREE from 'three';
import { MeshBVH } from 'three-mesh-bvh';
import { sphericalDirection, type Vec3 } from '../model/vec3';

export interface HeadHit {
  point: Vec3;
  distance: number;
  triangle: number;
  scalp: boolean;
}

export interface PickableHead {
  positions: Float32Array;
  indices: Uint32Array;
  scalp: Uint8Array;
  center: [number, number, number];
}

export class HeadPicker {
  readonly bvh: MeshBVH;

  constructor(
    readonly geometry: THREE.BufferGeometry,
    private readonly head: PickableHead,
  ) {
    this.bvh = new MeshBVH(geometry, { indirect: true });
  }

  /** First hit along a ray (either side of the surface). */
  first(ray: THREE.Ray): HeadHit | null {
    const hit = this.bvh.raycastFirst(ray, THREE.DoubleSide);
    return hit ? this.toHit(hit) : null;
  }

  /** Outermost hit of the ray from the head's center at spherical angles (S5.1 convention). */
  scalpPoint(thetaDeg: number, phiDeg: number): HeadHit | null {
    const c = this.head.center;
    const dir = sphericalDirection(thetaDeg, phiDeg);
    const ray = new THREE.Ray(new THREE.Vector3(...c), new THREE.Vector3(...dir));
    const hits = this.bvh.raycast(ray, THREE.DoubleSide);
    if (hits.length === 0) return null;
    let far = hits[0];
    for (const h of hits) if (h.distance > far.distance) far = h;
    return this.toHit(far);
  }

  private toHit(h: THREE.Intersection): HeadHit {
    const triangle = h.faceIndex ?? -1;
    return {
      point: [h.point.x, h.point.y, h.point.z],
      distance: h.distance,
      triangle,
      scalp: triangle >= 0 && this.head.scalp[triangle] === 1,
    };
  }
}
