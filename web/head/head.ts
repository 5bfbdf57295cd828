// The head, as every part of the app sees it: one triangle mesh with its scalp mask, a BVH for
// rays and closest points, signed distance and outward normals, and the bounding box. Tools
// (stroke sampling), the model (presets, dividing-curve normals), the solver (its scalp mesh),
// the viewer and the test hooks all use this one type. A user-loaded head will be one too.
//
// Normals have one definition: the mesh's area-weighted vertex normals interpolated at the
// closest surface point (the same as the solver's scalp avoidance, solver-cpp/src/
// scalp_avoidance.cpp). The signed distance is exact where the head has an analytic one (the
// built-in head's SDF); otherwise the distance to the mesh, negative where the normal at the
// closest point faces away.

import * as THREE from 'three';
import { MeshBVH } from 'three-mesh-bvh';
import type { ScalpMesh } from '../model/hairArrays';
import { sphericalDirection, type Vec3 } from '../model/vec3';
import { type BodyMesh, bodyArrays, builtinBody } from './buildBody';
import { buildHead } from './buildHead';
import { headSdf } from './headSdf';
import { triangleNormal } from './triangleNormal';

/** The head's triangles and what is known per vertex and per triangle. */
/** The centroid of triangle t. */
function centroid(P: ArrayLike<number>, I: ArrayLike<number>, t: number): Vec3 {
  const a = 3 * I[3 * t];
  const b = 3 * I[3 * t + 1];
  const c = 3 * I[3 * t + 2];
  return [
    (P[a] + P[b] + P[c]) / 3,
    (P[a + 1] + P[b + 1] + P[c + 1]) / 3,
    (P[a + 2] + P[b + 2] + P[c + 2]) / 3,
  ];
}

/** A scalp triangle whose normal leans away from a ray by at most this (the cosine) still counts
 *  as seen by it, edge-on at the outline (scalpPointNearRay). */
const EDGE_ON = 0.15;

export interface HeadMesh {
  positions: Float32Array; // positions[3 * vertex + axis], world units
  normals: Float32Array; // normals[3 * vertex + axis], unit, outward (area-weighted)
  indices: Uint32Array; // indices[3 * triangle + corner], counter-clockwise seen from outside
  scalp: Uint8Array; // scalp[triangle] = 1 on the hair-bearing region
  /** The built-in head's scalp with the natural hairline (scalpRegion.ts), which sessions with
   *  finished edges (`finish`) start from; absent on a loaded head. */
  naturalScalp?: Uint8Array;
  /** The same with a low nape (scalpRegion.ts), which sessions with `nape` start from; absent on
   *  a loaded head. */
  lowNapeScalp?: Uint8Array;
  parts?: Uint8Array; // parts[vertex]: a HeadPart value (skin, eye, lips), for colouring
  center: Vec3; // origin of the scalp parameterisation (S5.1)
  /** A loaded head's own texture coordinates, per corner: cornerUvs[6 * triangle + 2 * corner
   *  + k], v up (OBJ's and USD's convention); absent when its file has none. */
  cornerUvs?: Float32Array;
  bounds: { min: Vec3; max: Vec3 };
}

/** Just the triangles (what mesh-only algorithms need). */
export type TriangleSoup = Pick<HeadMesh, 'positions' | 'indices'>;

export interface HeadHit {
  point: Vec3;
  distance: number; // along the ray
  triangle: number;
  scalp: boolean;
}

export class Head {
  /** Geometry the BVH indexes (also what the viewer draws). */
  readonly geometry: THREE.BufferGeometry;
  readonly bvh: MeshBVH;

  constructor(
    readonly mesh: HeadMesh,
    /** Exact signed distance, where the head has one (world units, negative inside). */
    private readonly exactSdf: ((x: number, y: number, z: number) => number) | null = null,
    /** The body below it (the built-in bust; null on a loaded head, which is its own body). */
    readonly body: BodyMesh | null = null,
  ) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(mesh.positions, 3));
    g.setAttribute('normal', new THREE.BufferAttribute(mesh.normals, 3));
    g.setIndex(new THREE.BufferAttribute(mesh.indices, 1));
    this.geometry = g;
    // indirect: triangle indices stay those of the mesh (and of its scalp flags)
    this.bvh = new MeshBVH(g, { indirect: true });
  }

  /** The built-in mannequin head. */
  static builtin(): Head {
    const m = buildHead();
    return new Head(m, headSdf, builtinBody());
  }

  get center(): Vec3 {
    return this.mesh.center;
  }

  /** First hit along a ray (either side of the surface). */
  raycast(origin: Vec3, direction: Vec3): HeadHit | null {
    const ray = new THREE.Ray(new THREE.Vector3(...origin), new THREE.Vector3(...direction));
    const hit = this.bvh.raycastFirst(ray, THREE.DoubleSide);
    return hit ? this.toHit(hit) : null;
  }

  /** Outermost hit of the ray from the head's centre at spherical angles (S5.1 convention). */
  scalpPoint(thetaDeg: number, phiDeg: number): HeadHit | null {
    const dir = sphericalDirection(thetaDeg, phiDeg);
    const ray = new THREE.Ray(new THREE.Vector3(...this.center), new THREE.Vector3(...dir));
    const hits = this.bvh.raycast(ray, THREE.DoubleSide);
    if (hits.length === 0) return null;
    let far = hits[0];
    for (const h of hits) if (h.distance > far.distance) far = h;
    return this.toHit(far);
  }

  /** Whether `p` is the first thing seen from `eye` along the ray towards it. */
  visibleFrom(eye: Vec3, p: Vec3): boolean {
    const d: Vec3 = [p[0] - eye[0], p[1] - eye[1], p[2] - eye[2]];
    const len = Math.hypot(d[0], d[1], d[2]);
    if (!(len > 0)) return false;
    const hit = this.raycast(eye, [d[0] / len, d[1] / len, d[2] / len]);
    return hit !== null && Math.abs(hit.distance - len) < 1e-3 * len + 1e-4;
  }

  /** The closest surface point to `p`, its triangle and the outward normal there. */
  closest(p: Vec3): { point: Vec3; triangle: number; distance: number; normal: Vec3 } {
    const r = this.bvh.closestPointToPoint(new THREE.Vector3(...p));
    if (!r) throw new Error('the head has no triangles');
    const q: Vec3 = [r.point.x, r.point.y, r.point.z];
    return {
      point: q,
      triangle: r.faceIndex,
      distance: r.distance,
      normal: this.normalOn(r.faceIndex, q),
    };
  }

  /** The nearest point of the scalp to `p` (on the head) within `within` world units, or null:
   *  the centroid of the nearest scalp triangle, put on the surface. One pass over the
   *  triangles: for a press, not per frame. */
  nearestScalpPoint(p: Vec3, within: number): Vec3 | null {
    const { positions: P, indices: I, scalp } = this.mesh;
    let best = within * within;
    let at: Vec3 | null = null;
    for (let t = 0; t < scalp.length; t++) {
      if (!scalp[t]) continue;
      const q = centroid(P, I, t);
      const d2 = (q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2 + (q[2] - p[2]) ** 2;
      if (d2 < best) {
        best = d2;
        at = q;
      }
    }
    return at && this.closest(at).point;
  }

  /** Whether some triangle off the scalp (the face, an ear, the neck) lies within `within` of
   *  `p` (world units): `p` is that near the scalp's edge, the hairline. */
  nearScalpEdge(p: Vec3, within: number): boolean {
    const { scalp } = this.mesh;
    const at = new THREE.Vector3(...p);
    const closest = new THREE.Vector3();
    return this.bvh.shapecast({
      intersectsBounds: (box) => box.distanceToPoint(at) < within,
      intersectsTriangle: (tri, t) =>
        scalp[t] !== 1 && tri.closestPointToPoint(at, closest).distanceTo(at) < within,
    });
  }

  /** The scalp point nearest the ray from `origin` along unit `dir`, within `within` of it
   *  (perpendicular distance, world units) and on a triangle facing the ray's origin or seen
   *  edge-on (a press just beside the scalp's outline), or null. */
  scalpPointNearRay(origin: Vec3, dir: Vec3, within: number): Vec3 | null {
    const { positions: P, indices: I, scalp } = this.mesh;
    const n = new Float64Array(3);
    let best = within * within;
    let at: Vec3 | null = null;
    for (let t = 0; t < scalp.length; t++) {
      if (!scalp[t]) continue;
      triangleNormal(P, 3 * I[3 * t], 3 * I[3 * t + 1], 3 * I[3 * t + 2], n);
      const nl = Math.hypot(n[0], n[1], n[2]);
      if (!(nl > 0) || (n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2]) / nl > EDGE_ON) continue;
      const q = centroid(P, I, t);
      for (let k = 0; k < 3; k++) q[k] -= origin[k];
      const along = q[0] * dir[0] + q[1] * dir[1] + q[2] * dir[2];
      if (!(along > 0)) continue;
      const d2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] - along * along;
      if (d2 < best) {
        best = d2;
        at = [q[0] + origin[0], q[1] + origin[1], q[2] + origin[2]];
      }
    }
    return at && this.closest(at).point;
  }

  /** Outward unit normal of the head at (near) `p`: the vertex normals interpolated at the
   *  closest surface point. */
  normalAt(p: Vec3): Vec3 {
    return this.closest(p).normal;
  }

  /** Signed distance to the head surface: negative inside. */
  signedDistance(p: Vec3): number {
    if (this.exactSdf) return this.exactSdf(p[0], p[1], p[2]);
    const c = this.closest(p);
    const side =
      (p[0] - c.point[0]) * c.normal[0] +
      (p[1] - c.point[1]) * c.normal[1] +
      (p[2] - c.point[2]) * c.normal[2];
    return side < 0 ? -c.distance : c.distance;
  }

  /** The head as the solver worker needs it (copies: the worker gets its own arrays). */
  scalpMesh(): ScalpMesh {
    return {
      positions: this.mesh.positions.slice(),
      indices: this.mesh.indices.slice(),
      scalp: this.mesh.scalp.slice(),
      center: [...this.mesh.center],
      ...(this.body ? { body: bodyArrays(this.body) } : {}),
    };
  }

  private normalOn(triangle: number, q: Vec3): Vec3 {
    const { positions: P, indices: I, normals: N } = this.mesh;
    const a = I[3 * triangle];
    const b = I[3 * triangle + 1];
    const c = I[3 * triangle + 2];
    const w = barycentric(q, vertex(P, a), vertex(P, b), vertex(P, c));
    const n: Vec3 = [0, 0, 0];
    for (let axis = 0; axis < 3; axis++)
      n[axis] = w[0] * N[3 * a + axis] + w[1] * N[3 * b + axis] + w[2] * N[3 * c + axis];
    const len = Math.hypot(n[0], n[1], n[2]);
    if (len > 1e-12) return [n[0] / len, n[1] / len, n[2] / len];
    // degenerate blend: the face normal
    const f = faceNormal(vertex(P, a), vertex(P, b), vertex(P, c));
    return f;
  }

  private toHit(h: THREE.Intersection): HeadHit {
    const triangle = h.faceIndex ?? -1;
    return {
      point: [h.point.x, h.point.y, h.point.z],
      distance: h.distance,
      triangle,
      scalp: triangle >= 0 && this.mesh.scalp[triangle] === 1,
    };
  }
}

const vertex = (P: Float32Array, k: number): Vec3 => [P[3 * k], P[3 * k + 1], P[3 * k + 2]];

function faceNormal(a: Vec3, b: Vec3, c: Vec3): Vec3 {
  const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  const n: Vec3 = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
  const len = Math.hypot(n[0], n[1], n[2]) || 1;
  return [n[0] / len, n[1] / len, n[2] / len];
}

/** Barycentric weights of a point on (or near) triangle abc, clamped to the triangle. */
function barycentric(p: Vec3, a: Vec3, b: Vec3, c: Vec3): Vec3 {
  const v0 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const v1 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  const v2 = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
  const dot = (x: number[], y: number[]) => x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
  const d00 = dot(v0, v0);
  const d01 = dot(v0, v1);
  const d11 = dot(v1, v1);
  const d20 = dot(v2, v0);
  const d21 = dot(v2, v1);
  const den = d00 * d11 - d01 * d01;
  if (!(Math.abs(den) > 1e-30)) return [1, 0, 0];
  let v = (d11 * d20 - d01 * d21) / den;
  let w = (d00 * d21 - d01 * d20) / den;
  v = Math.min(1, Math.max(0, v));
  w = Math.min(1 - v, Math.max(0, w));
  return [1 - v - w, v, w];
}
