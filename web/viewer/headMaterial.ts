// The head's look: skin shading (MeshStandardMaterial) with per-vertex colours, where the scalp
// (HeadMesh.scalp) is tinted so the hair-bearing region is visibly marked, eyes are white with
// an iris, and lips are reddened. The hair's shadow: a per-vertex `hairShadow` attribute
// (transmittance through the hair towards the key light, from the worker's lighting precompute,
// 1 = unshadowed) scales the key light (the scene's first directional light); High reads the
// deep opacity maps instead (hairShadowReceiver.ts). While there is hair, a band of scalp along
// its edge takes the hair's colour (setHeadHairUnder): it stands for the fine, short hairs of a
// real hairline, too fine to grow as strands, so a hairline or an up-style's nape shows
// hair-coloured skin between the strands, not pink skin between dark bristles. Farther in (the
// crown, a parting) the scalp is skin, as it is between real hair.
import * as THREE from 'three';
import { edgeDistance } from '../head/edgeDistance';
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

/** Per vertex: the share of the scalp's tint in its colour (headVertexColors: the fraction of its
 *  triangles on the scalp; 0 on eyes and lips). */
function scalpTints(head: HeadMeshArrays, out?: Float32Array): Float32Array {
  const { scalpCount, triCount } = scalpCounts(head);
  const n = head.positions.length / 3;
  const f = out && out.length === n ? out : new Float32Array(n);
  for (let v = 0; v < n; v++) {
    const skinPart = !head.parts || head.parts[v] === HeadPart.skin;
    f[v] = skinPart && triCount[v] ? scalpCount[v] / triCount[v] : 0;
  }
  return f;
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

/** How much of the scalp's colour under hair a head takes where hair grows: the rest is the
 *  skin's (scalp skin shows a little through the roots). */
export const HAIR_UNDER_SHARE = 0.8;

/** Over this distance in from the scalp's edge (world units, 1 cm) the colour under the hair
 *  fades in: the hairline stays soft instead of a painted line. It holds to HAIR_UNDER_HOLD in
 *  and is gone by HAIR_UNDER_OUT (3.5 cm): the band of a hairline's fine hairs. */
export const HAIR_UNDER_FADE = 0.1;
export const HAIR_UNDER_HOLD = 0.25;
export const HAIR_UNDER_OUT = 0.35;
/** Farther in than that, the share it keeps: scalp seen between clumps, at a crown's whorl or along
 *  a parting reads as the hair's shade over skin, as under real hair, not as bare pink stripes
 *  (new users judging the library: "pink stripes of scalp between the clumps, like cornrows"). */
export const HAIR_UNDER_INNER = 0.6;

/** Per vertex: how far the scalp's colour under hair holds there, 0 at and outside the scalp's
 *  edge (a vertex with a triangle off the scalp, and eyes and lips) rising to 1 at HAIR_UNDER_FADE
 *  in from it, falling to HAIR_UNDER_INNER from HAIR_UNDER_HOLD to HAIR_UNDER_OUT (smoothsteps of
 *  the distance along the mesh's edges, web/head/edgeDistance.ts). */
function scalpShares(head: HeadMeshArrays, out?: Float32Array): Float32Array {
  const { scalpCount, triCount } = scalpCounts(head);
  const n = head.positions.length / 3;
  const f = out && out.length === n ? out : new Float32Array(n);
  const d = edgeDistance(
    head.positions,
    head.indices,
    (v) =>
      !(
        (!head.parts || head.parts[v] === HeadPart.skin) &&
        triCount[v] > 0 &&
        scalpCount[v] === triCount[v]
      ),
    HAIR_UNDER_OUT,
  );
  const smooth = (x: number) => {
    const c = Math.min(1, Math.max(0, x));
    return c * c * (3 - 2 * c);
  };
  for (let v = 0; v < n; v++)
    f[v] =
      smooth(d[v] / HAIR_UNDER_FADE) *
      (1 -
        (1 - HAIR_UNDER_INNER) *
          smooth((d[v] - HAIR_UNDER_HOLD) / (HAIR_UNDER_OUT - HAIR_UNDER_HOLD)));
  return f;
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
  geometry.setAttribute('scalpShare', new THREE.BufferAttribute(scalpShares(head), 1));
  geometry.setAttribute('scalpTint', new THREE.BufferAttribute(scalpTints(head), 1));
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
  // the scalp's colour under hair (linear RGB) and how much of it shows (0: no hair)
  const hairUnder = { value: new THREE.Vector4(0, 0, 0, 0) };
  material.userData.hairUnder = hairUnder;
  // skin − scalp tint (linear RGB): what a vertex's colour gains per unit of its scalpTint to be
  // skin again (headVertexColors mixes skin + tint · (scalp − skin))
  const skin = new THREE.Color(DEFAULT_HEAD_COLORS.skin);
  const scalp = new THREE.Color(DEFAULT_HEAD_COLORS.scalp);
  const scalpToSkin = {
    value: new THREE.Vector3(skin.r - scalp.r, skin.g - scalp.g, skin.b - scalp.b),
  };
  material.onBeforeCompile = (shader) => {
    shader.uniforms.hairUnder = hairUnder;
    shader.uniforms.scalpToSkin = scalpToSkin;
    shader.vertexShader = shader.vertexShader
      .replace(
        '#include <common>',
        '#include <common>\nattribute float hairShadow;\nvarying float vHairShadow;\n' +
          'attribute float scalpShare;\nvarying float vScalpShare;\n' +
          'attribute float scalpTint;\nvarying float vScalpTint;',
      )
      .replace(
        '#include <begin_vertex>',
        '#include <begin_vertex>\nvHairShadow = hairShadow;\nvScalpShare = scalpShare;\nvScalpTint = scalpTint;',
      );
    shader.fragmentShader = shader.fragmentShader
      .replace(
        '#include <common>',
        '#include <common>\nvarying float vHairShadow;\nvarying float vScalpShare;\n' +
          'varying float vScalpTint;\nuniform vec4 hairUnder;\nuniform vec3 scalpToSkin;',
      )
      .replace(
        '#include <color_fragment>',
        // with hair, the scalp's tint (which marks where hair grows on a bald head) gives way to
        // skin towards the edge, under the hairline's fine hairs: no pink line along it
        '#include <color_fragment>\n' +
          'if (hairUnder.a > 0.0) diffuseColor.rgb += vScalpTint * (1.0 - vScalpShare) * scalpToSkin;\n' +
          'diffuseColor.rgb = mix(diffuseColor.rgb, hairUnder.rgb, hairUnder.a * vScalpShare);',
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

/** The scalp under the hair takes `colour` (linear RGB, the hair's colour at its roots), or its
 *  own tint again (null: no hair). Returns whether anything changed (the frame cache's head layer
 *  must be drawn again). */
export function setHeadHairUnder(
  mesh: THREE.Mesh,
  colour: readonly [number, number, number] | null,
): boolean {
  const u = (mesh.material as THREE.Material).userData.hairUnder as
    | { value: THREE.Vector4 }
    | undefined;
  if (!u) return false;
  const v = colour
    ? new THREE.Vector4(colour[0], colour[1], colour[2], HAIR_UNDER_SHARE)
    : new THREE.Vector4(0, 0, 0, 0);
  if (u.value.equals(v)) return false;
  u.value.copy(v);
  return true;
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
  const f = mesh.geometry.getAttribute('scalpShare') as THREE.BufferAttribute | undefined;
  if (f) {
    scalpShares(head, f.array as Float32Array);
    f.needsUpdate = true;
  }
  const tint = mesh.geometry.getAttribute('scalpTint') as THREE.BufferAttribute | undefined;
  if (tint) {
    scalpTints(head, tint.array as Float32Array);
    tint.needsUpdate = true;
  }
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
  const share = g.getAttribute('scalpShare') as THREE.BufferAttribute | undefined;
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
      const f = triCount[v] ? scalpCount[v] / triCount[v] : 0;
      // the colour under hair, until the stroke's end recolours the scalp (recolorHeadScalp):
      // on where all of the vertex's triangles are scalp, off elsewhere
      if (share) (share.array as Float32Array)[v] = f === 1 ? 1 : 0;
      c.copy(skin).lerp(scalpColor, f);
      rgb[3 * v] = c.r;
      rgb[3 * v + 1] = c.g;
      rgb[3 * v + 2] = c.b;
    }
  }
  if (changed) {
    a.needsUpdate = true;
    if (share) share.needsUpdate = true;
  }
  return changed;
}
