// The displayed hair: strand arrays from the solver become one LineSegments object in the
// viewer, with one shared Kajiya–Kay material (a new material would compile its shader again).
import * as THREE from 'three';
import type { StrandArrays } from '../solver/protocol';
import {
  buildStrandGeometry,
  createStrandMaterial,
  type StrandMaterial,
  setHairColor,
} from './strandMaterial';
import type { Viewer } from './viewer';

export class HairView {
  private material: StrandMaterial | null = null;
  private color = '#5a3825';

  constructor(private readonly viewer: Viewer) {}

  /** Replaces the hair on screen with `strands`; `shown` runs once a frame has drawn it. */
  show(strands: StrandArrays, shown?: () => void): void {
    const geometry = buildStrandGeometry(strands.points, strands.strandStart);
    this.material ??= createStrandMaterial({ color: this.color });
    const hair = new THREE.LineSegments(geometry, this.material);
    if (shown) {
      const off = this.viewer.onHairShown((h) => {
        if (h !== hair) return;
        off();
        shown();
      });
    }
    this.viewer.setHair(hair);
  }

  setColor(css: string): void {
    if (css === this.color) return;
    this.color = css;
    if (this.material) setHairColor(this.material, css);
    this.viewer.requestRender();
  }
}
