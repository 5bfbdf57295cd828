// The composition root. Data flows one way:
//   pointer → tool (tools.ts) → editor command (editor/) → solver bridge → worker → result →
//   hair / overlay / status presenters → viewer.
// Everything that reacts to an edit subscribes to the editor; this file only builds the parts
// and connects them.
import { Editor, type ToolName } from '../editor/editor';
import { Head } from '../head/head';
import { indexedDbHeadStore } from '../head/headStore';
import { gridForPreset, gridForSession } from '../model/grid';
import { applyPreset } from '../model/presets';
import { DEFAULT_GROWTH, emptySession, hangLength } from '../model/session';
import { buildCurvePanel } from '../ui/curvePanel';
import { buildDetailPanel, type DetailPanel } from '../ui/detailPanel';
import { buildDisplayToggles } from '../ui/displayToggles';
import { buildHeadPanel, type HeadPanel } from '../ui/headPanel';
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
import { HeadController } from './headController';
import { bindInput } from './input';
import { OverlayPresenter } from './overlayPresenter';
import { QualityControl } from './quality';
import { LinkWriter, openSessionFileOutcome, openSessionLinkOutcome } from './sessionIO';
import { SolverBridge } from './solverBridge';
import { StatusPresenter } from './statusPresenter';
import { installTestApi } from './testApi';
import { createTools, toolHint } from './tools';
import { parseUrlOptions } from './urlOptions';

export function startApp(): void {
  const opts = parseUrlOptions(window.location.search);
  const byId = (id: string) => document.getElementById(id) as HTMLElement;
  const line = new StatusLine(byId('status'), byId('hint'));
  line.set('loading', 'Building the head…');
  const viewer = new Viewer(byId('viewport') as HTMLCanvasElement);
  const head = Head.builtin();
  const headMesh = createHeadMesh(head.mesh);
  viewer.addHead(headMesh);
  let headPanel: HeadPanel | null = null;
  const headStore = indexedDbHeadStore();
  // the session's head and scalp painting (bridge and status are made below; the controller
  // only calls them after a session change)
  const heads: HeadController = new HeadController(head, {
    viewer,
    headMesh,
    store: headStore,
    setSolverHead: (m) => bridge.setHead(m),
    setSolverScalpMask: (m) => bridge.setScalpMask(m),
    note: (m) => status.note(m),
    error: (m) => status.error(m),
    task: (m) => status.task(m),
    taskDone: (m, failed) => status.taskDone(m, failed),
    offerOpenHead: () => {
      if (!headPanel?.open) headPanel?.toggle();
      showHeadPanel();
      toolbar.refresh();
    },
    headChanged: () => showHeadPanel(), // the bridge re-solves on the new head itself
  });

  const grid = gridForPreset(opts.grid);
  const initial = applyPreset(
    emptySession(opts.grid, { ...DEFAULT_GROWTH, maxStrands: opts.maxStrands }),
    opts.preset,
    { head, step: grid.step, viewpoint: viewer.cameraState() },
  );
  // every preset starts with the tool a new user wants first: drawing a stream curve
  const editor = new Editor(initial, 'stream');

  const hairView = new HairView(viewer, headMesh);
  const quality = new QualityControl(hairView, viewer);
  const hair = new HairPresenter(viewer, hairView, line, initial.hairColor);
  const bridge = new SolverBridge(editor, {
    grid: gridForSession(initial.grid, initial.curves, undefined, hangLength(initial)),
    solver: opts.solver,
    scalp: head.scalpMesh(),
    headBounds: () => heads.gridBounds,
    interactiveDetail: () => viewer.interactiveDetail,
    shownStrands: () => line.strands,
  });
  const status = new StatusPresenter(line, bridge);
  const overlays = new OverlayPresenter(viewer, editor, bridge.grid);
  const links = new LinkWriter(editor);

  const tools = createTools({
    editor,
    head: () => heads.head,
    viewer,
    bridge,
    overlays,
    step: grid.step,
    previewScalp: (stroke) => heads.previewStroke(stroke),
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
    heads: headStore,
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
    openHead: () => toolbar.openHeadDialog(),
    toggleHeadPanel: () => {
      headPanel?.toggle();
      showHeadPanel();
      toolbar.refresh();
    },
    headPanelOpen: () => !!headPanel?.open,
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
    // a session whose head is not stored: HeadController says which head it needs
    openFile: (f) =>
      void openSessionFileOutcome(editor, f, headStore).then(
        (o) => o.kind === 'failed' && status.note(o.message),
      ),
    openHeadFile: (f) => heads.openHeadFile(editor, f),
  });
  toolbar.setHairColor(initial.hairColor);
  help = buildHelpOverlay(document.body, actions);
  exporting = wireExport({
    editor,
    viewer,
    bridge,
    status,
    head: () => heads.head,
    headBounds: () => heads.gridBounds,
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
  const panel = buildCurvePanel(
    byId('stage'),
    (id, patch) => editor.run({ kind: 'patchCurve', id, patch }),
    (m) => status.note(m),
  );
  detailPanel = buildDetailPanel(byId('stage'), {
    setGrowth: (patch) => editor.run({ kind: 'setGrowth', patch }),
    setDetail: (curveId, detail) => editor.run({ kind: 'setDetail', curveId, detail }),
    say: (m) => status.note(m),
  });
  detailPanel.show(editor.session, editor.selectedCurve);
  headPanel = buildHeadPanel(byId('stage'), {
    openHead: () => toolbar.openHeadDialog(),
    useBuiltin: () => heads.useBuiltin(editor),
    rotate: (axis) => {
      const m = heads.rotate(editor, axis);
      if (m) status.note(m);
    },
    setBrushRadius: (r) => {
      tools.scalpBrush.setRadius(r);
      showHeadPanel();
    },
    setPlane: (plane) => editor.run({ kind: 'setSymmetry', plane }),
    fitPlane: () => heads.fitPlane(editor),
    say: (m) => status.note(m),
  });
  function showHeadPanel(): void {
    headPanel?.show({
      session: editor.session,
      label: heads.label(editor.session),
      missing: heads.missing ? heads.missing.name : null,
      brushRadius: tools.scalpBrush.radius,
    });
  }

  const applyTool = (name: ToolName) => {
    tool.onCancel();
    tool = tools.byName[name];
    setCameraButtons(viewer.controls, name !== 'select');
    line.hint(toolHint(name, tools.ponytail));
  };
  editor.listen((c) => {
    heads.sessionChanged(c.session);
    showHeadPanel();
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
      // a preview answered: the pointer's newest samples go out as the next one now, not at
      // the next frame (frames are slow on a software rasteriser; the worker would wait)
      if (bridge.previewing) queueMicrotask(() => tool.update());
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
    void openSessionLinkOutcome(editor, window.location.hash, headStore).then((o) => {
      if (o.kind === 'failed') status.error(o.message);
      else links.markLinked(editor.session);
    });
  else links.schedule(); // the address bar carries the session from the start
  if (opts.warnings.length) status.note(`URL: ${opts.warnings.join('; ')}`);

  installTestApi({
    editor,
    head: () => heads.head,
    headInfo: () => ({
      name: editor.session.head === 'builtin' ? 'builtin' : editor.session.head.name,
      missing: heads.missing ? heads.missing.name : null,
      loading: heads.busy,
    }),
    viewer,
    bridge,
    hair,
    overlays,
    ponytail: tools.ponytail,
    busy: () =>
      heads.busy ||
      viewer.viewAnimating ||
      !!exporting?.busy() ||
      bridge.pending ||
      hair.awaitingFrame ||
      (tool.state !== 'idle' && tool.state !== 'pressed'),
    lastPointerUp: () => lastPointerUp,
    quality,
    exporter: exporting.exporter,
  });
}
