// The bust's look (head/buildBody.ts): a plain matte material of its own, in a tone beside the
// head's skin so the neck reads as one, without the head's scalp and face colouring; it receives
// the hair's shadow (hairShadowReceiver.ts).
import * as THREE from 'three';
import type { BodyMesh } from '../head/buildBody';
import { patchHairShadowReceiver } from './hairShadowReceiver';

/** The bust's colour (sRGB). */
export const BODY_COLOR = '#d7b29b';

/** The bust as a mesh for the scene (name 'body'), hidden until a session with `bust` shows it. */
export function createBodyMesh(body: BodyMesh): THREE.Mesh {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(body.positions, 3));
  g.setAttribute('normal', new THREE.BufferAttribute(body.normals, 3));
  g.setIndex(new THREE.BufferAttribute(body.indices, 1));
  const material = new THREE.MeshStandardMaterial({
    color: BODY_COLOR,
    roughness: 0.85,
    metalness: 0,
  });
  // the hair's shadow (High: from the deep opacity maps)
  material.onBeforeCompile = (shader) =>
    patchHairShadowReceiver(shader, { perVertex: null, inMap: false });
  const mesh = new THREE.Mesh(g, material);
  mesh.name = 'body';
  mesh.visible = false;
  return mesh;
}
