// The bounding volume (method S1.2, S6.2): the grid's box, from its first to its last grid point,
// as a wireframe of 12 edges.
import * as THREE from 'three';
import type { GridSpec } from '../model/hairArrays';
import { flatGeometry } from './displayMaterials';
import { overlayLineMaterial, setOverlayGeometry, withHiddenTwin } from './overlayStyle';

const BOX_RGB = 0x59606b;

/** The 12 edges of the grid box: edges[6 * e + 3 * end + axis]. Corners are origin and
 *  origin + step · (dims - 1). */
export function gridBoxEdges(grid: GridSpec): Float32Array {
  const lo = grid.origin;
  const hi = [0, 1, 2].map((a) => grid.origin[a] + grid.step * (grid.dims[a] - 1));
  const corner = (c: number) => [0, 1, 2].map((a) => ((c >> a) & 1 ? hi[a] : lo[a]));
  const out: number[] = [];
  // corners c and c | bit along each axis bit that c lacks: 4 edges per axis
  for (let c = 0; c < 8; c++)
    for (let a = 0; a < 3; a++)
      if (!((c >> a) & 1)) out.push(...corner(c), ...corner(c | (1 << a)));
  return new Float32Array(out);
}

/** The box display: one THREE.LineSegments, rebuilt when the grid changes. */
export class BoundingVolumeView {
  // depth-tested against head and hair, faint where hidden (overlayStyle.ts)
  readonly object = withHiddenTwin(
    new THREE.LineSegments(new THREE.BufferGeometry(), overlayLineMaterial(BOX_RGB, 'visible')),
    overlayLineMaterial(BOX_RGB, 'hidden'),
  );

  constructor(grid: GridSpec) {
    this.object.name = 'box';
    this.update(grid);
  }

  update(grid: GridSpec): void {
    setOverlayGeometry(this.object, flatGeometry(gridBoxEdges(grid)));
  }
}
