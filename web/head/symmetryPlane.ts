// A loaded head's left–right symmetry plane (for Mirror): the plane that maps the head onto
// itself best. Vertices (at most SAMPLES, an even stride of the mesh) are reflected across a
// candidate plane and the cost is their mean distance to the mesh (closest point by the head's
// BVH), each capped at CAP so that an asymmetric part (a shoulder, an ear ring) cannot dominate.
// The plane is near-vertical and faces ±x after normalisation (loadHead.ts puts the face toward
// +z, up +y), so it is parameterised by its yaw (about y), roll (about z) and offset, and found
// by a pattern search from x = (mean x of the samples): each parameter is tried a step either
// way, an improvement is kept, and the steps halve when none helps.
import * as THREE from 'three';
import type { MirrorPlane } from '../model/mirror';
import type { Vec3 } from '../model/vec3';
import type { Head } from './head';

const SAMPLES = 600;
const CAP = 0.1; // world units (1 cm)
const MAX_ANGLE = (30 * Math.PI) / 180;

export interface SymmetryFit {
  plane: MirrorPlane;
  /** Mean reflected-vertex distance to the mesh (world units, capped per vertex at CAP). */
  cost: number;
  evaluations: number;
}

/** The plane's unit normal for yaw (about y) and roll (about z), both in radians; yaw = roll = 0
 *  is +x. */
export function planeNormal(yaw: number, roll: number): Vec3 {
  return [Math.cos(yaw) * Math.cos(roll), Math.sin(roll), -Math.sin(yaw) * Math.cos(roll)];
}

/** The yaw and roll of a unit normal (the inverse of planeNormal). */
export function planeAngles(normal: Vec3): { yaw: number; roll: number } {
  const roll = Math.asin(Math.max(-1, Math.min(1, normal[1])));
  const yaw = Math.atan2(-normal[2], normal[0]);
  return { yaw, roll };
}

export function fitSymmetryPlane(head: Head): SymmetryFit {
  const P = head.mesh.positions;
  const vertices = P.length / 3;
  const stride = Math.max(1, Math.floor(vertices / SAMPLES));
  const pts: Vec3[] = [];
  for (let v = 0; v < vertices; v += stride) pts.push([P[3 * v], P[3 * v + 1], P[3 * v + 2]]);
  const q = new THREE.Vector3();
  let evaluations = 0;
  const cost = (yaw: number, roll: number, offset: number): number => {
    evaluations++;
    const n = planeNormal(yaw, roll);
    let sum = 0;
    for (const p of pts) {
      const k = 2 * (n[0] * p[0] + n[1] * p[1] + n[2] * p[2] - offset);
      q.set(p[0] - k * n[0], p[1] - k * n[1], p[2] - k * n[2]);
      const hit = head.bvh.closestPointToPoint(q, undefined, 0, CAP);
      sum += hit ? Math.min(hit.distance, CAP) : CAP;
    }
    return sum / Math.max(pts.length, 1);
  };
  let x = [0, 0, pts.reduce((a, p) => a + p[0], 0) / Math.max(pts.length, 1)];
  let best = cost(x[0], x[1], x[2]);
  const steps = [(8 * Math.PI) / 180, (8 * Math.PI) / 180, 0.1];
  const minSteps = [(0.05 * Math.PI) / 180, (0.05 * Math.PI) / 180, 0.0005];
  for (let round = 0; round < 200 && steps.some((s, i) => s >= minSteps[i]); round++) {
    let improved = false;
    for (let i = 0; i < 3; i++) {
      if (steps[i] < minSteps[i]) continue;
      for (const dir of [1, -1]) {
        const y = [...x];
        y[i] += dir * steps[i];
        if (i < 2 && Math.abs(y[i]) > MAX_ANGLE) continue;
        const c = cost(y[0], y[1], y[2]);
        if (c < best) {
          best = c;
          x = y;
          improved = true;
          break;
        }
      }
    }
    if (!improved) for (let i = 0; i < 3; i++) steps[i] /= 2;
  }
  return { plane: { normal: planeNormal(x[0], x[1]), offset: x[2] }, cost: best, evaluations };
}
