// The ties' bands on screen (model/tieBands.ts, model/tieBandMesh.ts): one opaque mesh in the
// band colour, part of the scene's solid objects, so the hair blended over it (hairOit.ts) is
// hidden behind it as behind the head. Replaced with each hair shown; hidden while there are no
// bands (no ties, no hair).
import * as THREE from 'three';
import { bandMesh } from '../model/tieBandMesh';
import type { TieBand } from '../model/tieBands';
import type { Viewer } from './viewer';

export class TieBandView {
  private readonly mesh: THREE.Mesh<THREE.BufferGeometry, THREE.MeshStandardMaterial>;
  private bands: readonly TieBand[] = [];

  constructor(private readonly viewer: Viewer) {
    // an elastic: matte with a soft sheen
    const material = new THREE.MeshStandardMaterial({ roughness: 0.55, metalness: 0 });
    this.mesh = new THREE.Mesh(new THREE.BufferGeometry(), material);
    this.mesh.name = 'tie-bands';
    this.mesh.visible = false;
    viewer.addSolid(this.mesh);
  }

  /** The bands' mesh: a motion moves it with the head (a tail is gathered at the head). */
  get object(): THREE.Object3D {
    return this.mesh;
  }

  /** The bands shown. */
  get shown(): readonly TieBand[] {
    return this.bands;
  }

  /** Their colour (#rrggbb), null while none is shown. */
  get colour(): string | null {
    return this.mesh.visible ? `#${this.mesh.material.color.getHexString()}` : null;
  }

  /** Shows `bands` in `colour` (#rrggbb), none when empty. */
  show(bands: readonly TieBand[], colour: string): void {
    const m = this.mesh;
    const colourChanged = `#${m.material.color.getHexString()}` !== colour.toLowerCase();
    // the same bands again (every result measures them anew; most sessions have none): the
    // geometry stays, so the frame cache's head layer stays valid (a new geometry redraws the
    // whole view, ~70 ms at 1280x800 on a software rasteriser, before the new hair can show)
    const same = sameBands(bands, this.bands);
    if (same && !colourChanged) return;
    if (colourChanged) m.material.color.set(colour);
    if (!same) {
      this.bands = bands;
      const { positions, normals, indices } = bandMesh(bands);
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(positions, 3));
      g.setAttribute('normal', new THREE.BufferAttribute(normals, 3));
      g.setIndex(new THREE.BufferAttribute(indices, 1));
      m.geometry.dispose();
      m.geometry = g;
    }
    m.visible = bands.length > 0;
    this.viewer.requestRender();
  }
}

/** Whether two band lists are equal, value for value. */
function sameBands(a: readonly TieBand[], b: readonly TieBand[]): boolean {
  if (a === b) return true;
  if (a.length !== b.length) return false;
  return a.every((x, i) => {
    const y = b[i];
    return (
      x.curve === y.curve &&
      x.radius === y.radius &&
      x.centre.every((v, k) => v === y.centre[k]) &&
      x.axis.every((v, k) => v === y.axis[k])
    );
  });
}
