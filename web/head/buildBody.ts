// The built-in bust (bodySdf.ts) as one closed triangle mesh, the way the head is built
// (buildHead.ts): surface nets over its box, smoothed vertex normals. A mesh of its own beside
// the head: the viewer draws it in its own material, the solver keeps hair out of it (hair
// slides over it), the exports that carry the head carry it too.

import type { BodyArrays } from '../model/hairArrays';
import type { Vec3 } from '../model/vec3';
import { BODY_BOTTOM, BODY_HALF_WIDTH, BODY_NECK_TOP, bodySdf } from './bodySdf';
import { polygoniseClosed, vertexNormals } from './buildHead';

export interface BodyMesh {
  positions: Float32Array; // positions[3 * vertex + axis], world units
  normals: Float32Array; // unit, outward
  indices: Uint32Array; // counter-clockwise seen from outside
  bounds: { min: Vec3; max: Vec3 };
}

// Its box, with a margin round the surface.
const BOX_MIN: [number, number, number] = [-BODY_HALF_WIDTH - 0.2, BODY_BOTTOM - 0.1, -1.45];
const BOX_MAX: [number, number, number] = [BODY_HALF_WIDTH + 0.2, BODY_NECK_TOP + 0.1, 1.0];

/** The bust at `resolution` cells per world unit (default 16: about 2 cm² a triangle pair). */
export function buildBody(resolution = 16): BodyMesh {
  const { positions, indices } = polygoniseClosed(
    bodySdf,
    BOX_MIN,
    BOX_MAX,
    resolution,
    'buildBody',
  );
  const min: Vec3 = [Infinity, Infinity, Infinity];
  const max: Vec3 = [-Infinity, -Infinity, -Infinity];
  for (let v = 0; v < positions.length; v += 3)
    for (let a = 0; a < 3; a++) {
      min[a] = Math.min(min[a], positions[v + a]);
      max[a] = Math.max(max[a], positions[v + a]);
    }
  return { positions, normals: vertexNormals(positions, indices), indices, bounds: { min, max } };
}

let cached: BodyMesh | null = null;
/** The built-in bust, built once. */
export function builtinBody(): BodyMesh {
  cached ??= buildBody();
  return cached;
}

/** A copy of the bust's triangles, as the solver takes them (hairArrays.ts ScalpMesh.body). */
export function bodyArrays(m: BodyMesh): BodyArrays {
  return { positions: m.positions.slice(), indices: m.indices.slice() };
}
