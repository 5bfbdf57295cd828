// Shows the scalp's sections while a tie tool (Ponytail, Braid, Bun) is active and the session
// has sections on: the head is tinted by section (viewer/sectionTint.ts) from the hair shown,
// the sections are drawn over the hair too (half transparent: the scalp is under the hair), and
// the head gets its own colours back when another tool is chosen or the style curves are hidden
// (key 1, for clean pictures: the tint over the hair read as a shaved scalp to a new user).

import type * as THREE from 'three';
import type { Editor, ToolName } from '../editor/editor';
import type { HeadMeshArrays } from '../viewer/headMaterial';
import { sectionsOverHair, tintHeadSections } from '../viewer/sectionTint';
import type { Viewer } from '../viewer/viewer';
import type { HairPresenter } from './hairPresenter';
import { TIE_TOOL_KINDS } from './tieTools';

const TIE_TOOLS: readonly ToolName[] = ['ponytail', ...TIE_TOOL_KINDS];

export class SectionTintPresenter {
  private shownFor: unknown = null;
  /** Scalp vertices tinted now (0: the head shows its own colours). */
  tinted = 0;
  /** The sections drawn over the hair while a tie tool is active. */
  private overHair: THREE.Mesh<THREE.BufferGeometry, THREE.MeshBasicMaterial> | null = null;

  /** Triangles of the sections shown over the hair now (0: none). */
  get overHairTriangles(): number {
    return this.overHair ? this.overHair.geometry.getAttribute('position').count / 3 : 0;
  }

  private showOverHair(
    mesh: THREE.Mesh<THREE.BufferGeometry, THREE.MeshBasicMaterial> | null,
  ): void {
    if (this.overHair) {
      this.d.viewer.showDisplay(this.overHair, false);
      this.overHair.geometry.dispose();
      this.overHair.material.dispose();
    }
    this.overHair = mesh;
    if (mesh) this.d.viewer.showDisplay(mesh, true);
  }

  constructor(
    private readonly d: {
      editor: Editor;
      viewer: Viewer;
      headMesh: import('three').Mesh;
      head: () => HeadMeshArrays;
      hair: HairPresenter;
      /** Whether the style curves are shown (the Curves display toggle). */
      curvesShown: () => boolean;
    },
  ) {
    d.editor.listen(() => this.update());
  }

  /** Call when the hair shown or the head changed. */
  update(): void {
    const { editor, hair } = this.d;
    const on = TIE_TOOLS.includes(editor.tool) && !!editor.session.sections && this.d.curvesShown();
    const strands = on ? hair.strands : null;
    const key = on ? (strands ?? 'none') : null;
    if (key === this.shownFor) return;
    // leaving a tie tool: the head's own colours, once
    if (!on && this.tinted === 0) {
      this.shownFor = null;
      return;
    }
    this.shownFor = key;
    const { tinted, sections } = tintHeadSections(this.d.headMesh, this.d.head(), strands);
    this.tinted = tinted;
    this.showOverHair(on && sections ? sectionsOverHair(this.d.head(), sections) : null);
    this.d.viewer.invalidateFrameCache();
  }
}
