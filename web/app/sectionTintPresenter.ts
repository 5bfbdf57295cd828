// Shows the scalp's sections while a tie tool (Ponytail, Braid, Bun) is active and the session
// has sections on: the head is tinted by section (viewer/sectionTint.ts) from the hair shown,
// and gets its own colours back when another tool is chosen.
import type { Editor, ToolName } from '../editor/editor';
import type { HeadMeshArrays } from '../viewer/headMaterial';
import { tintHeadSections } from '../viewer/sectionTint';
import type { Viewer } from '../viewer/viewer';
import type { HairPresenter } from './hairPresenter';
import { TIE_TOOL_KINDS } from './tieTools';

const TIE_TOOLS: readonly ToolName[] = ['ponytail', ...TIE_TOOL_KINDS];

export class SectionTintPresenter {
  private shownFor: unknown = null;
  /** Scalp vertices tinted now (0: the head shows its own colours). */
  tinted = 0;

  constructor(
    private readonly d: {
      editor: Editor;
      viewer: Viewer;
      headMesh: import('three').Mesh;
      head: () => HeadMeshArrays;
      hair: HairPresenter;
    },
  ) {
    d.editor.listen(() => this.update());
  }

  /** Call when the hair shown or the head changed. */
  update(): void {
    const { editor, hair } = this.d;
    const on = TIE_TOOLS.includes(editor.tool) && !!editor.session.sections;
    const strands = on ? hair.strands : null;
    const key = on ? (strands ?? 'none') : null;
    if (key === this.shownFor) return;
    // leaving a tie tool: the head's own colours, once
    if (!on && this.tinted === 0) {
      this.shownFor = null;
      return;
    }
    this.shownFor = key;
    this.tinted = tintHeadSections(this.d.headMesh, this.d.head(), strands);
    this.d.viewer.invalidateFrameCache();
  }
}
