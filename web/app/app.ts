// The composition root. Data flows one way:
//   pointer → tool (tools.ts) → editor command (editor/) → solver bridge → worker → result →
//   hair / overlay / status presenters → viewer.
// Everything that reacts to an edit subscribes to the editor; this file only builds the parts
// and connects them.
import { Editor, type ToolName } from '../editor/editor';
import { Head } from '../head/head';
import { gridForPreset, gridForSession } from '../model/grid';
import { applyPreset } from '../model/presets';
import { DEFAULT_GROWTH, emptySession } from '../model/session';
import { PONYTAIL_STAGE_HINT } from '../tools/ponytailTool';
import { buildCurvePanel } from '../ui/curvePanel';
import { buildDetailPanel, type DetailPanel } from '../ui/detailPanel';
import { buildDisplayToggles } from '../ui/displayToggles';
import { buildHelpOverlay, type HelpOverlay } from '../ui/helpOverlay';
import { StatusLine } from '../ui/status';
import { buildToolbar } from '../ui/toolbar';
import { setCameraButtons } from '../viewer/cameraButtons';
import { HairView } from '../viewer/hairView';
import { createHeadMesh } from '../viewer/headMaterial';
import { Viewer } from '../viewer/viewer';
import { buildActions } from './actions';
import { editActions } from './editActions';
import { type ExportWiring, wireExport } from './exportActions';
import { HairPresenter } from './hairPresenter';
import { bindInput } from './input';
import { OverlayPresenter } from './overlayPresenter';
import { QualityControl } from './quality';
import { LinkWriter, openSessionFile, openSessionLink } from './sessionIO';
import { SolverBridge } from './solverBridge';
import { StatusPresenter } from './statusPresenter';
import { installTestApi } from './testApi';
import { createTools } from './tools';
import { parseUrlOptions } from './urlOptions';

const TOOL_HINTS: Record<Exclude<ToolName, 'ponytail'>, string> = {
  stream:
    'Drag from the scalp to draw a stream curve · a stroke starting on the selected curve cuts, extends or re-routes it · right-drag orbits · wheel zooms · ? lists shortcuts',
  dividing:
    'Drag on the scalp to draw a parting · a stroke starting beside the selected one tilts that side · right-drag orbits',
  select:
    'Click a curve to select it · drag orbits · wheel zooms · right-drag pans · ? lists shortcuts',
};

export function startApp(): void {
  const opts = parseUrlOptions(window.location.search);
  const byId = (id: string) => document.getElementById(id) as HTMLElement;
  const line = new StatusLine(byId('status'), byId('hint'));
  line.set('loading', 'Building the head…');
  const viewer = new Viewer(byId('viewport') as HTMLCanvasElement);
  const head = Head.builtin();
  const headMesh = createHeadMesh(head.mesh);
  viewer.addHead(headMesh);

  const grid = gridForPreset(opts.grid);
  const initial = applyPreset(
    emptySession(opts.grid, { ...DEFAULT_GROWTH, maxStrands: opts.maxStrands }),
    opts.preset,
    { head, step: grid.step, viewpoint: viewer.cameraState() },
  );
  const editor = new Editor(initial, opts.preset === 'empty' ? 'stream' : 'select');

  const hairView = new HairView(viewer, headMesh);
  const quality = new QualityControl(hairView, viewer);
  const hair = new HairPresenter(viewer, hairView, line, initial.hairColor);
  const bridge = new SolverBridge(editor, {
    grid: gridForSession(initial.grid, initial.curves),
    solver: opts.solver,
    scalp: head.scalpMesh(),
    interactiveDetail: () => viewer.interactiveDetail,
    shownStrands: () => line.strands,
  });
  const status = new StatusPresenter(line, () => bridge.pending);
  const overlays = new OverlayPresenter(viewer, editor, bridge.grid);
  const links = new LinkWriter(editor);

  const tools = createTools({
    editor,
    head,
    viewer,
    bridge,
    overlays,
    step: grid.step,
    notify: (m) => status.note(m),
    ponytailStage: (hint) => {
      if (editor.tool === 'ponytail') line.hint(hint);
      status.note(hint);
    },
  });
  let tool = tools.byName[editor.tool];
  viewer.onFrame(() => tool.update());

  let help: HelpOverlay | null = null;
  let detailPanel: DetailPanel | null = null;
  const edits = editActions({
    editor,
    viewer,
    bridge,
    status,
    tool: () => tool,
    openDialog: () => toolbar.openFileDialog(),
    links,
    refresh: () => toolbar.refresh(),
  });
  let exporting: ExportWiring | null = null;
  const actions = buildActions({
    ...edits,
    exportMenu: () => exporting?.menu.toggle(),
    toggleHelp: () => help?.toggle(),
    toggleDetailPanel: () => {
      detailPanel?.toggle();
      toolbar.refresh();
    },
    detailPanelOpen: () => !!detailPanel?.open,
    display: (k) => overlays.display[k],
    setDisplay: (k, on) => overlays.setDisplay(k, on),
    qualityLabel: () => quality.label(),
    cycleQuality: () => {
      quality.cycle();
      toolbar.refresh();
    },
  });
  const toolbar = buildToolbar(byId('toolbar'), actions, {
    hairColor: (css) => editor.run({ kind: 'setHairColor', color: css }),
    openFile: (f) => void openSessionFile(editor, f).then((m) => m && status.note(m)),
  });
  toolbar.setHairColor(initial.hairColor);
  help = buildHelpOverlay(document.body, actions);
  exporting = wireExport({
    editor,
    viewer,
    bridge,
    status,
    head,
    solver: opts.solver,
    anchor: byId('toolbar'),
  });
  const toggles = buildDisplayToggles(toolbar.moreElement, overlays.display, (k, on) =>
    overlays.setDisplay(k, on),
  );
  overlays.onDisplayChanged = (key, on) => {
    toggles.set(overlays.display);
    if (key === 'field') bridge.setWantField(on, !!overlays.shownResult?.field);
  };
  const panel = buildCurvePanel(byId('stage'), (id, patch) =>
    editor.run({ kind: 'patchCurve', id, patch }),
  );
  detailPanel = buildDetailPanel(byId('stage'), {
    setGrowth: (patch) => editor.run({ kind: 'setGrowth', patch }),
    setDetail: (curveId, detail) => editor.run({ kind: 'setDetail', curveId, detail }),
  });
  detailPanel.show(editor.session, editor.selectedCurve);

  const applyTool = (name: ToolName) => {
    tool.onCancel();
    tool = tools.byName[name];
    setCameraButtons(viewer.controls, name !== 'select');
    line.hint(name === 'ponytail' ? PONYTAIL_STAGE_HINT[tools.ponytail.stage] : TOOL_HINTS[name]);
  };
  editor.listen((c) => {
    if (c.cause === 'tool') applyTool(c.tool);
    if (c.camera) viewer.setCamera(c.camera.position, c.camera.target);
    hair.editorChanged(c);
    overlays.editorChanged(c);
    status.editorChanged(c);
    if (c.session.hairColor !== c.previous.hairColor) toolbar.setHairColor(c.session.hairColor);
    panel.show(editor.selectedCurve);
    detailPanel?.show(c.session, editor.selectedCurve);
    toolbar.refresh();
  });
  bridge.subscribe({
    busy: (phase, fraction, previewing) => status.busy(phase, fraction, previewing),
    result: (r, final) => {
      hair.result(r, final);
      overlays.result(r);
      status.result(r, final);
    },
    error: (m, kind, restarting) => status.solverError(m, kind, restarting),
    gridChanged: (g) => overlays.setGrid(g),
    idle: () => {
      hair.idle();
      // "Ready" once the converged hair is on screen (cached or unchanged hair: at once)
      if (!hair.awaitingFrame) status.ready();
    },
  });
  hair.onFinalShown = () => status.ready();

  let lastPointerUp = 0;
  bindInput({
    viewer,
    tool: () => tool,
    actions,
    overlayKey: (key) => {
      if (key === 'escape' && exporting?.menu.open) {
        exporting.menu.close();
        return true;
      }
      if (!help?.open || (key !== 'escape' && key !== '?')) return false;
      help.close();
      return true;
    },
    pointerUp: (t) => {
      lastPointerUp = t;
    },
  });

  applyTool(editor.tool);
  overlays.syncCurves();
  toolbar.refresh();
  line.counts(0, initial.curves.length);
  line.set('loading', 'Loading the solver…');
  bridge.sync();
  if (window.location.hash.startsWith('#s='))
    void openSessionLink(editor, window.location.hash).then((m) => {
      if (m) status.error(m);
      else links.markLinked(editor.session);
    });
  else links.schedule(); // the address bar carries the session from the start
  if (opts.warnings.length) status.note(`URL: ${opts.warnings.join('; ')}`);

  installTestApi({
    editor,
    head,
    viewer,
    bridge,
    hair,
    overlays,
    ponytail: tools.ponytail,
    busy: () =>
      !!exporting?.busy() ||
      bridge.pending ||
      hair.awaitingFrame ||
      (tool.state !== 'idle' && tool.state !== 'pressed'),
    lastPointerUp: () => lastPointerUp,
    quality,
    exporter: exporting.exporter,
  });
}
