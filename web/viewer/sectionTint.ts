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

/** Recolours `mesh` (a head made by createHeadMesh): its own colours, and with `hair` holding
 *  root sections, the scalp tinted by section. Returns the number of vertices tinted. */
export function tintHeadSections(
  mesh: THREE.Mesh,
  head: HeadMeshArrays,
  hair: Pick<StrandArrays, 'points' | 'strandStart' | 'rootSections'> | null,
): number {
  const a = mesh.geometry.getAttribute('color') as THREE.BufferAttribute | undefined;
  if (!a) return 0;
  const rgb = headVertexColors(head, DEFAULT_HEAD_COLORS, a.array as Float32Array);
  a.needsUpdate = true;
  const sections = hair?.rootSections;
  if (!hair || !sections || sections.length + 1 !== hair.strandStart.length) return 0;
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
  const tints = SECTION_TINTS.map((c) => new THREE.Color(c));
  const own = new THREE.Color();
  const { positions } = head;
  let tinted = 0;
  for (let v = 0; v < positions.length / 3; v++) {
    const x = positions[3 * v];
    const y = positions[3 * v + 1];
    const z = positions[3 * v + 2];
    const cx = Math.floor(x / REACH);
    const cy = Math.floor(y / REACH);
    const cz = Math.floor(z / REACH);
    let best = REACH * REACH;
    let section = -1;
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
              section = sections[s];
            }
          }
        }
    if (section < 0) continue;
    own.setRGB(rgb[3 * v], rgb[3 * v + 1], rgb[3 * v + 2]);
    own.lerp(tints[section % tints.length], TINT);
    rgb[3 * v] = own.r;
    rgb[3 * v + 1] = own.g;
    rgb[3 * v + 2] = own.b;
    tinted++;
  }
  return tinted;
}
