// The head's look: skin shading (MeshStandardMaterial) with per-vertex colours, where the scalp
// (HeadMesh.scalp) is tinted so the hair-bearing region is visibly marked, eyes are white with
// an iris, and lips are reddened.
import * as THREE from 'three';
import type { HeadMesh } from '../head/head';
import { EYE_R, EYE_X, EYE_Y, EYE_Z, HeadPart } from '../head/headSdf';

export interface HeadColors {
  skin: THREE.ColorRepresentation;
  scalp: THREE.ColorRepresentation;
  lips: THREE.ColorRepresentation;
  eyeWhite: THREE.ColorRepresentation;
  iris: THREE.ColorRepresentation;
  pupil: THREE.ColorRepresentation;
}

export const DEFAULT_HEAD_COLORS: HeadColors = {
  skin: '#e2b59c',
  scalp: '#b88f86',
  lips: '#bf6f6a',
  eyeWhite: '#eeeae4',
  iris: '#4f6b7a',
  pupil: '#141414',
};

/** What the geometry needs from a head (web/head/head.ts HeadMesh; parts are optional: a
 *  user-loaded head is all skin). */
export type HeadMeshArrays = Pick<
  HeadMesh,
  'positions' | 'indices' | 'scalp' | 'normals' | 'parts'
>;

/** Indexed geometry with `position`, `normal` and `color` (linear RGB). A vertex's colour blends
 *  skin and scalp by the fraction of its triangles on the scalp. */
export function createHeadGeometry(
  head: HeadMeshArrays,
  colors: HeadColors = DEFAULT_HEAD_COLORS,
): THREE.BufferGeometry {
  const { positions, indices, scalp } = head;
  const vertices = positions.length / 3;
  const scalpCount = new Uint16Array(vertices);
  const triCount = new Uint16Array(vertices);
  for (let t = 0; t < scalp.length; t++) {
    for (let c = 0; c < 3; c++) {
      const v = indices[3 * t + c];
      triCount[v]++;
      if (scalp[t]) scalpCount[v]++;
    }
  }
  const skin = new THREE.Color(colors.skin);
  const scalpColor = new THREE.Color(colors.scalp);
  const lips = new THREE.Color(colors.lips);
  const white = new THREE.Color(colors.eyeWhite);
  const iris = new THREE.Color(colors.iris);
  const pupil = new THREE.Color(colors.pupil);
  const rgb = new Float32Array(3 * vertices);
  const c = new THREE.Color();
  for (let v = 0; v < vertices; v++) {
    const part = head.parts ? head.parts[v] : HeadPart.skin;
    if (part === HeadPart.eye) {
      const x = positions[3 * v];
      const dx = Math.abs(x) - EYE_X;
      const dy = positions[3 * v + 1] - EYE_Y;
      const dz = positions[3 * v + 2] - EYE_Z;
      const cos = dz / (Math.hypot(dx, dy, dz) || EYE_R);
      if (cos > 0.985) c.copy(pupil);
      else if (cos > 0.93) c.copy(iris);
      else c.copy(white);
    } else if (part === HeadPart.lips) {
      c.copy(lips);
    } else {
      const f = triCount[v] ? scalpCount[v] / triCount[v] : 0;
      c.copy(skin).lerp(scalpColor, f);
    }
    rgb[3 * v] = c.r;
    rgb[3 * v + 1] = c.g;
    rgb[3 * v + 2] = c.b;
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(rgb, 3));
  geometry.setIndex(new THREE.BufferAttribute(indices, 1));
  if (head.normals) geometry.setAttribute('normal', new THREE.BufferAttribute(head.normals, 3));
  else geometry.computeVertexNormals();
  geometry.computeBoundingBox();
  geometry.computeBoundingSphere();
  return geometry;
}

/** Skin material reading the vertex colours of createHeadGeometry. */
export function createHeadMaterial(): THREE.MeshStandardMaterial {
  const material = new THREE.MeshStandardMaterial({
    vertexColors: true,
    roughness: 0.62,
    metalness: 0,
  });
  material.name = 'HeadSkin';
  return material;
}

/** The head as a ready-to-add mesh (geometry views the head's arrays, not copied). */
export function createHeadMesh(head: HeadMeshArrays): THREE.Mesh {
  const mesh = new THREE.Mesh(createHeadGeometry(head), createHeadMaterial());
  mesh.name = 'head';
  return mesh;
}
