// Keeps the page's controls in step with the state they show: the toolbar (pressed and enabled
// buttons, hair colour), the display toggles, the hint line, which buttons move the camera and
// the side panels. Each derives from the editor (session, selection, tool) and the view store
// (viewState.ts); nothing here holds state of its own. A stroke's samples change neither, so
// they redraw nothing.
import type { Editor } from '../editor/editor';
import type { CurvePanel } from '../ui/curvePanel';
import type { DetailPanel } from '../ui/detailPanel';
import type { DisplayToggles } from '../ui/displayToggles';
import type { StatusLine } from '../ui/status';
import type { Toolbar } from '../ui/toolbar';
import { setCameraButtons } from '../viewer/cameraButtons';
import type { Viewer } from '../viewer/viewer';
import { toolHint } from './tools';
import type { ViewStore } from './viewState';

export interface PageControls {
  editor: Editor;
  view: ViewStore;
  viewer: Viewer;
  line: StatusLine;
  toolbar: Toolbar;
  toggles: DisplayToggles;
  curvePanel: CurvePanel;
  detailPanel: DetailPanel;
  /** Shows the head panel for the current session and head. */
  showHeadPanel(): void;
}

export function bindPageControls(p: PageControls): void {
  const { editor, view } = p;
  let hint = '';
  const showTool = () => {
    setCameraButtons(p.viewer.controls, editor.tool !== 'select');
    showHint();
  };
  const showHint = () => {
    const next = toolHint(editor.tool, view.state.ponytailStage);
    if (next === hint) return;
    hint = next;
    p.line.hint(next);
  };

  editor.listen((c) => {
    if (c.cause === 'stroke') return;
    p.showHeadPanel();
    if (c.cause === 'tool') showTool();
    if (c.session.hairColor !== c.previous.hairColor) p.toolbar.setHairColor(c.session.hairColor);
    p.curvePanel.show(editor.selectedCurve);
    p.detailPanel.show(c.session, editor.selectedCurve);
    p.toolbar.refresh();
  });
  view.listen(({ state, previous }) => {
    if (state.display !== previous.display) p.toggles.set(state.display);
    if (state.ponytailStage !== previous.ponytailStage) showHint();
    p.toolbar.refresh();
  });

  p.toolbar.setHairColor(editor.session.hairColor);
  p.detailPanel.show(editor.session, editor.selectedCurve);
  showTool();
  p.toolbar.refresh();
}
