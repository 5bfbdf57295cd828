// The head's look: skin shading (MeshStandardMaterial) with per-vertex colours, where the scalp
// (HeadMesh.scalp) is tinted so the hair-bearing region is visibly marked, eyes are white with
// an iris, and lips are reddened. The hair's shadow: a per-vertex `hairShadow` attribute
// (transmittance through the hair towards the key light, from the worker's lighting precompute,
// 1 = unshadowed) scales the key light (the scene's first directional light); High reads the
// deep opacity maps instead (hairShadowReceiver.ts).
import * as THREE from 'three';
import type { HeadMesh } from '../head/head';
import { EYE_R, EYE_X, EYE_Y, EYE_Z, HeadPart } from '../head/headSdf';
import { patchHairShadowReceiver } from './hairShadowReceiver';

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

/** Per-vertex colours (linear RGB): a vertex blends skin and scalp by the fraction of its
 *  triangles on the scalp; eyes and lips by part. */
export function headVertexColors(
  head: HeadMeshArrays,
  colors: HeadColors = DEFAULT_HEAD_COLORS,
  out?: Float32Array,
): Float32Array {
  const { positions } = head;
  const vertices = positions.length / 3;
  const { scalpCount, triCount } = scalpCounts(head);
  const skin = new THREE.Color(colors.skin);
  const scalpColor = new THREE.Color(colors.scalp);
  const lips = new THREE.Color(colors.lips);
  const white = new THREE.Color(colors.eyeWhite);
  const iris = new THREE.Color(colors.iris);
  const pupil = new THREE.Color(colors.pupil);
  const rgb = out && out.length === 3 * vertices ? out : new Float32Array(3 * vertices);
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
  return rgb;
}

/** Per vertex: how many of its triangles there are, and how many are scalp. */
function scalpCounts(head: HeadMeshArrays): { scalpCount: Uint16Array; triCount: Uint16Array } {
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
  return { scalpCount, triCount };
}

/** Indexed geometry with `position`, `normal` and `color` (linear RGB, headVertexColors). */
export function createHeadGeometry(
  head: HeadMeshArrays,
  colors: HeadColors = DEFAULT_HEAD_COLORS,
): THREE.BufferGeometry {
  const { positions, indices } = head;
  const vertices = positions.length / 3;
  const rgb = headVertexColors(head, colors);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(rgb, 3));
  geometry.setIndex(new THREE.BufferAttribute(indices, 1));
  geometry.setAttribute(
    'hairShadow',
    new THREE.BufferAttribute(new Float32Array(vertices).fill(1), 1),
  );
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
  material.onBeforeCompile = (shader) => {
    shader.vertexShader = shader.vertexShader
      .replace(
        '#include <common>',
        '#include <common>\nattribute float hairShadow;\nvarying float vHairShadow;',
      )
      .replace('#include <begin_vertex>', '#include <begin_vertex>\nvHairShadow = hairShadow;');
    shader.fragmentShader = shader.fragmentShader.replace(
      '#include <common>',
      '#include <common>\nvarying float vHairShadow;',
    );
    // the key light is the scene's first directional light (viewer.ts adds it first)
    patchHairShadowReceiver(shader, { perVertex: 'vHairShadow', inMap: true });
  };
  return material;
}

/** Sets the hair's shadow on a head made by createHeadMesh: one transmittance per vertex
 *  (protocol.ts HairLightingArrays.head); ignored when the count does not match. */
export function setHeadHairShadow(mesh: THREE.Mesh, transmittance: Float32Array): void {
  const a = mesh.geometry.getAttribute('hairShadow') as THREE.BufferAttribute | undefined;
  if (!a || a.count !== transmittance.length) return;
  (a.array as Float32Array).set(transmittance);
  a.needsUpdate = true;
}

/** The head as a ready-to-add mesh (geometry views the head's arrays, not copied). */
export function createHeadMesh(head: HeadMeshArrays): THREE.Mesh {
  const mesh = new THREE.Mesh(createHeadGeometry(head), createHeadMaterial());
  mesh.name = 'head';
  return mesh;
}

/** Shows another head on a mesh made by createHeadMesh (a loaded head): new geometry, the same
 *  object and material (the hair view keeps its reference for the hair's shadow). */
export function setHeadGeometry(mesh: THREE.Mesh, head: HeadMeshArrays): void {
  const old = mesh.geometry;
  mesh.geometry = createHeadGeometry(head);
  old.dispose();
}

/** Recolours the head after its scalp mask changed (the scalp brush). */
export function recolorHeadScalp(mesh: THREE.Mesh, head: HeadMeshArrays): void {
  const a = mesh.geometry.getAttribute('color') as THREE.BufferAttribute | undefined;
  if (!a) return;
  headVertexColors(head, DEFAULT_HEAD_COLORS, a.array as Float32Array);
  a.needsUpdate = true;
  delete mesh.geometry.userData.scalpCounts;
}

/** Sets `triangles`' scalp flags to `value` in `head.scalp` and recolours only their vertices
 *  (the scalp brush while it is dragged: a million-triangle head is not recoloured per move).
 *  Returns how many flags changed. Skin vertices only (eyes and lips keep their colour). */
export function paintHeadTriangles(
  mesh: THREE.Mesh,
  head: HeadMeshArrays,
  triangles: Iterable<number>,
  value: 0 | 1,
  colors: HeadColors = DEFAULT_HEAD_COLORS,
): number {
  const a = mesh.geometry.getAttribute('color') as THREE.BufferAttribute | undefined;
  if (!a) return 0;
  const g = mesh.geometry;
  g.userData.scalpCounts ??= scalpCounts(head);
  const { scalpCount, triCount } = g.userData.scalpCounts as ReturnType<typeof scalpCounts>;
  const rgb = a.array as Float32Array;
  const skin = new THREE.Color(colors.skin);
  const scalpColor = new THREE.Color(colors.scalp);
  const c = new THREE.Color();
  let changed = 0;
  for (const t of triangles) {
    if (head.scalp[t] === value) continue;
    head.scalp[t] = value;
    changed++;
    for (let k = 0; k < 3; k++) {
      const v = head.indices[3 * t + k];
      scalpCount[v] += value ? 1 : -1;
      if (head.parts && head.parts[v] !== HeadPart.skin) continue;
      c.copy(skin).lerp(scalpColor, triCount[v] ? scalpCount[v] / triCount[v] : 0);
      rgb[3 * v] = c.r;
      rgb[3 * v + 1] = c.g;
      rgb[3 * v + 2] = c.b;
    }
  }
  if (changed) a.needsUpdate = true;
  return changed;
}
