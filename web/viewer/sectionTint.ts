// The scalp's sections (solver-cpp/src/scalp_sections.hpp), shown while a tie tool is active:
// each scalp vertex takes a tint of the section of the nearest strand root (the worker names
// each root's section, StrandArrays.rootSections), over the head's own colours.
import * as THREE from 'three';
import type { StrandArrays } from '../model/hairArrays';
import { DEFAULT_HEAD_COLORS, type HeadMeshArrays, headVertexColors } from './headMaterial';

/** One hue per section, cycled (sections are few: partings make them). */
const SECTION_TINTS = ['#4f9de0', '#e0914f', '#5fc27a', '#c45fc2', '#d8c84a', '#5fc2c0'];
/** How far a tinted vertex moves from its own colour towards its section's. */
const TINT = 0.55;
/** A vertex farther than this from every root (world units, 2 cm) is not scalp: no tint. */
const REACH = 0.2;

/** Each head vertex's section: that of the nearest strand root within REACH (-1: none, not
 *  scalp). Null when the hair carries no sections. */
function vertexSections(
  head: HeadMeshArrays,
  hair: Pick<StrandArrays, 'points' | 'strandStart' | 'rootSections'> | null,
): Int16Array | null {
  const sections = hair?.rootSections;
  if (!hair || !sections || sections.length + 1 !== hair.strandStart.length) return null;
  // roots binned on a grid of REACH cells
  const P = hair.points;
  const cells = new Map<string, number[]>();
  const key = (x: number, y: number, z: number) =>
    `${Math.floor(x / REACH)},${Math.floor(y / REACH)},${Math.floor(z / REACH)}`;
  for (let s = 0; s < sections.length; s++) {
    const k = 3 * hair.strandStart[s];
    const id = key(P[k], P[k + 1], P[k + 2]);
    const list = cells.get(id);
    if (list) list.push(s);
    else cells.set(id, [s]);
  }
  const { positions } = head;
  const out = new Int16Array(positions.length / 3).fill(-1);
  for (let v = 0; v < out.length; v++) {
    const x = positions[3 * v];
    const y = positions[3 * v + 1];
    const z = positions[3 * v + 2];
    const cx = Math.floor(x / REACH);
    const cy = Math.floor(y / REACH);
    const cz = Math.floor(z / REACH);
    let best = REACH * REACH;
    for (let i = -1; i <= 1; i++)
      for (let j = -1; j <= 1; j++)
        for (let l = -1; l <= 1; l++) {
          const list = cells.get(`${cx + i},${cy + j},${cz + l}`);
          if (!list) continue;
          for (const s of list) {
            const k = 3 * hair.strandStart[s];
            const d = (P[k] - x) ** 2 + (P[k + 1] - y) ** 2 + (P[k + 2] - z) ** 2;
            if (d < best) {
              best = d;
              out[v] = sections[s];
            }
          }
        }
  }
  return out;
}

/** Recolours `mesh` (a head made by createHeadMesh): its own colours, and with `hair` holding
 *  root sections, the scalp tinted by section. Returns the number of vertices tinted and each
 *  vertex's section (null: none). */
export function tintHeadSections(
  mesh: THREE.Mesh,
  head: HeadMeshArrays,
  hair: Pick<StrandArrays, 'points' | 'strandStart' | 'rootSections'> | null,
): { tinted: number; sections: Int16Array | null } {
  const a = mesh.geometry.getAttribute('color') as THREE.BufferAttribute | undefined;
  if (!a) return { tinted: 0, sections: null };
  const rgb = headVertexColors(head, DEFAULT_HEAD_COLORS, a.array as Float32Array);
  a.needsUpdate = true;
  const sections = vertexSections(head, hair);
  if (!sections) return { tinted: 0, sections: null };
  const tints = SECTION_TINTS.map((c) => new THREE.Color(c));
  const own = new THREE.Color();
  let tinted = 0;
  for (let v = 0; v < sections.length; v++) {
    const section = sections[v];
    if (section < 0) continue;
    own.setRGB(rgb[3 * v], rgb[3 * v + 1], rgb[3 * v + 2]);
    own.lerp(tints[section % tints.length], TINT);
    rgb[3 * v] = own.r;
    rgb[3 * v + 1] = own.g;
    rgb[3 * v + 2] = own.b;
    tinted++;
  }
  return { tinted, sections };
}

/** Opacity of the sections drawn over the hair. */
const OVER_HAIR_OPACITY = 0.45;

/** The scalp's sections drawn over the hair (a tie tool is active: the user must see which hair
 *  a tie will take, and hair covers the scalp): the scalp triangles facing the camera, in their
 *  section's hue, half transparent and not hidden by the hair. Null when fewer than two sections
 *  show (one section: every tie takes the same hair). */
export function sectionsOverHair(
  head: HeadMeshArrays,
  sections: Int16Array,
): THREE.Mesh<THREE.BufferGeometry, THREE.MeshBasicMaterial> | null {
  const { positions, indices } = head;
  const tints = SECTION_TINTS.map((c) => new THREE.Color(c));
  const pos: number[] = [];
  const col: number[] = [];
  const seen = new Set<number>();
  for (let t = 0; t + 2 < indices.length; t += 3) {
    const v = [indices[t], indices[t + 1], indices[t + 2]];
    const sec = sections[v[0]];
    if (sec < 0 || sections[v[1]] !== sec || sections[v[2]] !== sec) continue;
    const c = tints[sec % tints.length];
    seen.add(sec);
    for (const i of v) {
      pos.push(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
      col.push(c.r, c.g, c.b);
    }
  }
  // one section (no parting bounds one): nothing to tell apart, the hair shows as it is
  if (seen.size < 2) return null;
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(pos), 3));
  g.setAttribute('color', new THREE.BufferAttribute(new Float32Array(col), 3));
  const m = new THREE.MeshBasicMaterial({
    vertexColors: true,
    transparent: true,
    opacity: OVER_HAIR_OPACITY,
    depthTest: false,
    depthWrite: false,
    side: THREE.FrontSide,
  });
  const mesh = new THREE.Mesh(g, m);
  mesh.renderOrder = -1; // under the curves and the stroke being drawn
  return mesh;
}
