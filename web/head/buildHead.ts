// The built-in head (method S1.1): the signed distance function of headSdf.ts polygonised by
// surface nets into one closed, consistently oriented triangle mesh, with smoothed normals and a
// scalp flag per triangle. World units ≈ 10 cm; y up; the face looks toward +z; +x is the head's
// left; the scalp-parameterisation centre is the origin.

import type { HeadMesh } from './head';
import { earDistance, HeadPart, headPartAt, headSdf } from './headSdf';
import { markScalpTriangles } from './scalpRegion';
import { sampleField, surfaceNets, type TriangleMesh } from './surfaceNets';
import { triangleNormal } from './triangleNormal';

export interface BuildHeadOptions {
  /** Grid cells per world unit (10 cm) of the polygonisation; default 24 (≈ 30K triangles). */
  resolution?: number;
}

export { HeadPart };

// Sampling box: the head lies inside with a margin so that the surface never touches the border.
const BOX_MIN: [number, number, number] = [-1.05, -2.75, -1.2];
const BOX_MAX: [number, number, number] = [1.05, 1.15, 1.5];

// How far (world units) the natural hairline stays from the ear.
const EAR_MARGIN = 0.08;

export function buildHead(options: BuildHeadOptions = {}): HeadMesh {
  const resolution = options.resolution ?? 24;
  if (!(resolution >= 4 && resolution <= 200)) throw new Error(`bad resolution ${resolution}`);
  const mesh = polygoniseClosed(headSdf, BOX_MIN, BOX_MAX, resolution, 'buildHead');
  const { positions, indices } = mesh;
  const normals = vertexNormals(positions, indices);
  const vertices = positions.length / 3;
  const parts = new Uint8Array(vertices);
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  for (let v = 0; v < vertices; v++) {
    const x = positions[3 * v];
    const y = positions[3 * v + 1];
    const z = positions[3 * v + 2];
    parts[v] = headPartAt(x, y, z);
    if (x < min[0]) min[0] = x;
    if (y < min[1]) min[1] = y;
    if (z < min[2]) min[2] = z;
    if (x > max[0]) max[0] = x;
    if (y > max[1]) max[1] = y;
    if (z > max[2]) max[2] = z;
  }
  const center: [number, number, number] = [0, 0, 0];
  const scalp = markScalpTriangles(mesh, center);
  // the natural hairlines wrap the ear: the ear and a few millimetres round it stay bare
  const aroundTheEar = (hairline: 'natural' | 'lowNape') => {
    const marked = markScalpTriangles(mesh, center, hairline);
    for (let t = 0; t < marked.length; t++) {
      if (!marked[t] || scalp[t]) continue;
      const c = [0, 1, 2].map(
        (a) =>
          (positions[3 * indices[3 * t] + a] +
            positions[3 * indices[3 * t + 1] + a] +
            positions[3 * indices[3 * t + 2] + a]) /
          3,
      );
      if (earDistance(c[0], c[1], c[2]) < EAR_MARGIN) marked[t] = 0;
    }
    return marked;
  };
  const naturalScalp = aroundTheEar('natural');
  const lowNapeScalp = aroundTheEar('lowNape');
  return {
    positions,
    normals,
    indices,
    scalp,
    naturalScalp,
    lowNapeScalp,
    parts,
    center,
    bounds: { min, max },
  };
}

/** One closed, consistently oriented surface of `sdf` in the box [lo, hi] (the surface inside it
 *  with a margin) by surface nets at `resolution` cells per world unit. A grid vertex pattern
 *  can, rarely, give a non-manifold edge (four quads around one dual edge at a saddle): then the
 *  grid is shifted by a fraction of a step and the field polygonised again. */
export function polygoniseClosed(
  sdf: (x: number, y: number, z: number) => number,
  lo: readonly [number, number, number],
  hi: readonly [number, number, number],
  resolution: number,
  who: string,
): TriangleMesh {
  const step = 1 / resolution;
  for (let attempt = 0; attempt < 6; attempt++) {
    const shift = attempt === 0 ? 0 : (0.173 * attempt) % 1;
    const origin: [number, number, number] = [
      lo[0] - step * shift,
      lo[1] - step * ((shift * 1.7) % 1),
      lo[2] - step * ((shift * 2.3) % 1),
    ];
    const dims: [number, number, number] = [0, 1, 2].map(
      (a) => Math.ceil((hi[a] - origin[a]) / step) + 1,
    ) as [number, number, number];
    const candidate = surfaceNets(sampleField(sdf, dims, origin, step, 1.5));
    if (isClosedSphere(candidate)) return candidate;
  }
  throw new Error(`${who}: polygonisation is not a closed manifold`);
}

/** Area-weighted vertex normals, normalised. */
export function vertexNormals(positions: Float32Array, indices: Uint32Array): Float32Array {
  const n = new Float32Array(positions.length);
  const face = new Float64Array(3);
  for (let t = 0; t < indices.length; t += 3) {
    const a = 3 * indices[t];
    const b = 3 * indices[t + 1];
    const c = 3 * indices[t + 2];
    triangleNormal(positions, a, b, c, face);
    for (const v of [a, b, c]) {
      n[v] += face[0];
      n[v + 1] += face[1];
      n[v + 2] += face[2];
    }
  }
  for (let v = 0; v < n.length; v += 3) {
    const l = Math.hypot(n[v], n[v + 1], n[v + 2]) || 1;
    n[v] /= l;
    n[v + 1] /= l;
    n[v + 2] /= l;
  }
  return n;
}

/** True when every edge is used by exactly two triangles, once in each direction, and the
 *  Euler characteristic V − E + F is 2 (one closed surface of genus 0, no pinched vertices). */
export function isClosedSphere(mesh: TriangleMesh): boolean {
  const { positions, indices } = mesh;
  const vertices = positions.length / 3;
  const triangles = indices.length / 3;
  // outgoing directed edges per vertex, compressed rows: targets[first[a] .. first[a + 1])
  const first = new Uint32Array(vertices + 1);
  for (let t = 0; t < indices.length; t++) first[indices[t] + 1]++;
  for (let v = 0; v < vertices; v++) first[v + 1] += first[v];
  const fill = first.slice(0, vertices);
  const targets = new Uint32Array(indices.length);
  for (let t = 0; t < indices.length; t += 3) {
    for (let e = 0; e < 3; e++) {
      const a = indices[t + e];
      const b = indices[t + ((e + 1) % 3)];
      if (a === b) return false;
      targets[fill[a]++] = b;
    }
  }
  // each directed edge a→b once, and its twin b→a present
  for (let a = 0; a < vertices; a++) {
    for (let i = first[a]; i < first[a + 1]; i++) {
      const b = targets[i];
      for (let j = i + 1; j < first[a + 1]; j++) if (targets[j] === b) return false;
      let twin = false;
      for (let j = first[b]; j < first[b + 1] && !twin; j++) twin = targets[j] === a;
      if (!twin) return false;
    }
  }
  const edges = indices.length / 2;
  return vertices - edges + triangles === 2;
}
