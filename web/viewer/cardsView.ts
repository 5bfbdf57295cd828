// The Cards view's object: the hair cards the export writes (export/cardsWriter.ts, same
// clusters, geometry and atlas for the same strands, session and count), drawn as a game engine
// draws them: the colour atlas as the map, alpha-tested at 0.5 (glTF's MASK) and both sides.
import * as THREE from 'three';
import { makeHairCards } from '../export/cardsWriter';
import { strandsForExport } from '../export/strandsForExport';
import type { StrandArrays } from '../model/hairArrays';
import type { HairLook } from '../model/hairLook';
import type { SessionState } from '../model/session';

export interface CardsObject {
  object: THREE.Mesh;
  cards: number;
  triangles: number;
  ms: number;
}

/** The cards of `strands` (as the solver grew them) for `session`'s colour and seed, cut into
 *  `count` cards. The caller owns the object; its material and texture go with it (dispose()). */
export function buildCardsObject(
  strands: StrandArrays,
  session: Pick<SessionState, 'hairColor' | 'growth'> & { hairLook?: HairLook | null },
  count: number,
): CardsObject {
  const t0 = performance.now();
  const exported = strandsForExport(strands, session);
  const geometry = new THREE.BufferGeometry();
  const material = new THREE.MeshStandardMaterial({
    alphaTest: 0.5,
    side: THREE.DoubleSide,
    metalness: 0,
    roughness: 0.6,
  });
  const mesh = new THREE.Mesh(geometry, material);
  mesh.name = 'hair cards';
  if (exported.strandStart.length < 2) return { object: mesh, cards: 0, triangles: 0, ms: 0 };
  const made = makeHairCards(exported, count, session.growth.seed);
  const g = made.geometry;
  geometry.setAttribute('position', new THREE.BufferAttribute(g.positions, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(g.normals, 3));
  geometry.setAttribute('uv', new THREE.BufferAttribute(g.uvs, 2));
  geometry.setIndex(new THREE.BufferAttribute(g.indices, 1));
  geometry.computeBoundingSphere();
  // rows top to bottom with flipY off: v = 0 samples the first row, as glTF's UVs expect
  const map = new THREE.DataTexture(
    made.atlas.colour,
    made.atlas.size,
    made.atlas.size,
    THREE.RGBAFormat,
  );
  map.colorSpace = THREE.SRGBColorSpace;
  map.flipY = false;
  map.generateMipmaps = true;
  map.minFilter = THREE.LinearMipmapLinearFilter;
  map.magFilter = THREE.LinearFilter;
  map.wrapS = THREE.ClampToEdgeWrapping;
  map.wrapT = THREE.ClampToEdgeWrapping;
  map.needsUpdate = true;
  material.map = map;
  // the material and its texture are this object's own: freed with its geometry
  geometry.addEventListener('dispose', () => {
    map.dispose();
    material.dispose();
  });
  return {
    object: mesh,
    cards: made.cards,
    triangles: g.triangles,
    ms: performance.now() - t0,
  };
}
