// The supporting surface of the selected stream curve (method S4.3, S6.2; the paper's Fig. 3a/b),
// as a translucent two-sided mesh. The surface itself is web/model/supportingSurface.ts; the
// caller chooses the curve, its viewpoint and the mode.
import * as THREE from 'three';
import type { SupportingSurface } from '../model/supportingSurface';
import { replaceGeometry, translucentSurface } from './displayMaterials';

/** Mesh geometry of a surface (its own triangles, no copies of the data's layout). */
export function surfaceGeometry(s: SupportingSurface): THREE.BufferGeometry {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(s.positions, 3));
  g.setIndex(new THREE.BufferAttribute(s.indices, 1));
  return g;
}

/** The surface display: one THREE.Mesh, rebuilt by update(). */
export class SupportingSurfaceView {
  readonly object = new THREE.Mesh(new THREE.BufferGeometry(), translucentSurface());
  /** Triangles drawn. */
  triangles = 0;

  constructor() {
    this.object.name = 'supporting-surface';
    this.object.renderOrder = 5; // after the opaque head and hair: it is transparent
    this.object.visible = false;
  }

  update(surface: SupportingSurface | null): void {
    this.triangles = surface ? surface.indices.length / 3 : 0;
    replaceGeometry(
      this.object,
      surface && this.triangles > 0 ? surfaceGeometry(surface) : new THREE.BufferGeometry(),
    );
    this.object.visible = this.triangles > 0;
  }
}
