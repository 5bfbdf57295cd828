// The composition root. Data flows one way:
//   pointer → tool (tools.ts) → editor (commands, and the stroke being drawn) → solver bridge →
//   worker → result → hair / overlay / status presenters → viewer.
// Everything that reacts to an edit subscribes to the editor, and everything that shows view
// state to the view store; this file only builds the parts and connects them.
import { Editor } from '../editor/editor';
import { Head } from '../head/head';
import { indexedDbHeadStore } from '../head/headStore';
import { gridForPreset } from '../model/grid';
import { applyPreset } from '../model/presets';
import { DEFAULT_GROWTH, emptySession, sessionGrid } from '../model/session';
import { indexedDbPictureStore } from '../reference/pictureStore';
import { PONYTAIL_STAGE_HINT } from '../tools/ponytailTool';
import type { DetailPanel } from '../ui/detailPanel';
import { buildDisplayToggles } from '../ui/displayToggles';
import { buildHeadPanel, type HeadPanel } from '../ui/headPanel';
import { buildHelpOverlay, type HelpOverlay } from '../ui/helpOverlay';
import { buildMotionControls } from '../ui/motionControls';
import { buildReferencePanel, type ReferencePanel } from '../ui/referencePanel';
import { StatusLine } from '../ui/status';
import { buildToolbar } from '../ui/toolbar';
import { buildViewControl } from '../ui/viewControl';
import { createBodyMesh } from '../viewer/bodyMaterial';
import { HairView } from '../viewer/hairView';
import { createHeadMesh } from '../viewer/headMaterial';
import { highestPoint, lowestPoint, viewLabel } from '../viewer/namedViews';
import { ReferencePlanes } from '../viewer/referencePlanes';
import { TieBandView } from '../viewer/tieBandView';
import { Viewer } from '../viewer/viewer';
import { buildActions, NAMED_VIEWS } from './actions';
import { ActiveTool } from './activeTool';
import {
  buildHairPanel,
  buildSelectedCurvePanel,
  closeOverlay,
  openStartingLink,
  showSolverResults,
} from './appWiring';
import { wireCardsView } from './cardsPresenter';
import { editActions } from './editActions';
import { type ExportWiring, wireExport } from './exportActions';
import { HairPresenter } from './hairPresenter';
import { HeadController } from './headController';
import { bindInput } from './input';
import { loadMirrorSetting, saveMirrorSetting } from './localSettings';
import { MotionPlayer } from './motionPlayer';
import { OverlayPresenter } from './overlayPresenter';
import { bindPageControls } from './pageControls';
import { loadQualitySetting, QualityControl } from './quality';
import { ReferenceController } from './referenceController';
import { SectionTintPresenter } from './sectionTintPresenter';
import { LinkWriter, openSessionFileOutcome } from './sessionIO';
import { SolverBridge } from './solverBridge';
import { StatusPresenter } from './statusPresenter';
import { styleGallery } from './styleGallery';
import { installTestApi } from './testApi';
import { TieAndPartingReporter } from './tieAndPartingReporter';
import { TieBandPresenter } from './tieBandPresenter';
import { createTools } from './tools';
import { parseUrlOptions } from './urlOptions';
import { ViewStore } from './viewState';

export function startApp(): void {
  const opts = parseUrlOptions(window.location.search);
  const byId = (id: string) => document.getElementById(id) as HTMLElement;
  const line = new StatusLine(byId('status'), byId('hint'));
  line.set('loading', 'Building the head…');
  const viewer = new Viewer(byId('viewport') as HTMLCanvasElement);
  const head = Head.builtin();
  const headMesh = createHeadMesh(head.mesh);
  viewer.addHead(headMesh);
  const bodyMesh = head.body ? createBodyMesh(head.body) : undefined;
  if (bodyMesh) viewer.addHead(bodyMesh);
  let headPanel: HeadPanel | null = null;
  const headStore = indexedDbHeadStore();
  // the session's head and scalp painting (bridge and status are made below; the controller
  // only calls them after a session change)
  const heads: HeadController = new HeadController(head, {
    viewer,
    headMesh,
    bodyMesh,
    store: headStore,
    setSolverHead: (m) => bridge.setHead(m),
    setSolverScalpMask: (m) => bridge.setScalpMask(m),
    note: (m) => status.note(m),
    error: (m) => status.error(m),
    task: (m) => status.task(m),
    taskDone: (m, failed) => status.taskDone(m, failed),
    offerOpenHead: () => {
      if (!headPanel?.open) headPanel?.toggle();
      closeOtherPanel('head');
      showHeadPanel();
      toolbar.refresh();
    },
    headChanged: () => showHeadPanel(), // the bridge re-solves on the new head itself
  });

  // reference pictures behind the head (the panel is made below; it is only shown after a change)
  const pictureStore = indexedDbPictureStore();
  const planes = new ReferencePlanes();
  viewer.addBackdrop(planes.group);
  let referencePanel: ReferencePanel | null = null;
  const references = new ReferenceController({
    planes,
    store: pictureStore,
    camera: () => viewer.cameraState(),
    redraw: () => viewer.invalidateFrameCache(),
    error: (m) => status.error(m),
    task: (m) => status.task(m),
    taskDone: (m, failed) => status.taskDone(m, failed),
    changed: () => referencePanel?.show(references.panelState()),
  });

  const grid = gridForPreset(opts.grid);
  const initial = applyPreset(
    emptySession(opts.grid, { ...DEFAULT_GROWTH, maxStrands: opts.maxStrands }),
    opts.preset,
    { head, step: grid.step, viewpoint: viewer.cameraState() },
  );
  heads.startWith(initial);
  // every preset starts with the tool a new user wants first: drawing a stream curve
  const editor = new Editor(initial, 'stream');
  const view = new ViewStore({ quality: loadQualitySetting(), mirror: loadMirrorSetting() });
  view.listen((c) => {
    if (c.state.mirror !== c.previous.mirror) saveMirrorSetting(c.state.mirror);
  });

  const hairView = new HairView(viewer, headMesh);
  const quality = new QualityControl(hairView, viewer, view);
  // the bridge hears of each edit first: a result it answers from its cache at once comes
  // before the presenters' own reaction to the edit
  const bridge = new SolverBridge(editor, {
    grid: sessionGrid(initial, undefined),
    solver: opts.solver,
    scalp: head.scalpMesh(),
    headBounds: () => heads.gridBounds,
    interactiveDetail: () => viewer.interactiveDetail,
    shownStrands: () => hair.shownStrands,
  });
  editor.listen((c) => {
    if (c.sessionChanged) heads.sessionChanged(c.session);
    if (c.sessionChanged) references.sessionChanged(c.session);
    if (c.camera) viewer.setCamera(c.camera.position, c.camera.target);
  });
  const hair = new HairPresenter(viewer, hairView, line, editor);
  const sectionTint = new SectionTintPresenter({
    editor,
    viewer,
    headMesh,
    head: () => heads.head.mesh,
    hair,
    curvesShown: () => view.state.display.curves,
  });
  view.listen((c) => {
    if (c.state.display.curves !== c.previous.display.curves) sectionTint.update();
  });
  const bandView = new TieBandView(viewer);
  const bands = new TieBandPresenter(bandView, editor);
  wireCardsView({ view, editor, hairView, statusElement: byId('status') });
  const overlays = new OverlayPresenter(viewer, editor, view, bridge.grid);
  const status = new StatusPresenter(line, bridge);
  editor.listen((c) => status.editorChanged(c));
  const reports = new TieAndPartingReporter((m) => status.note(m));
  editor.listen((c) => reports.editorChanged(c));
  const links = new LinkWriter(editor);

  const tools = createTools({
    editor,
    head: () => heads.head,
    viewer,
    step: grid.step,
    mirror: () => view.state.mirror,
    curvesShown: () => view.state.display.curves,
    showGuides: (lines) => overlays.setToolGuides(lines),
    previewScalp: (stroke, mirror) => heads.previewStroke(stroke, mirror),
    notify: (m) => status.note(m),
    ponytailStage: (stage) => {
      view.update({ ponytailStage: stage });
      // between the shaping strokes the status says which is next; after the spine made a
      // ponytail, or the profiles shaped it, it keeps what the edit did ("Added ponytail c1 and
      // its mirror c2") and the hint line says what may follow
      if (stage === 'profileA' || stage === 'profileB') status.note(PONYTAIL_STAGE_HINT[stage]);
    },
  });
  const active = new ActiveTool({
    editor,
    tools: tools.byName,
    onFrame: (hook) => viewer.onFrame(hook),
  });

  let help: HelpOverlay | null = null;
  let detailPanel: DetailPanel | null = null;
  const edits = editActions({
    editor,
    viewer,
    status,
    view,
    // the views frame the hair and as much of the bust as it reaches (not the whole bust)
    hairstyleLowest: () => lowestPoint(hair.strands?.points ?? [], heads.head.mesh.bounds.min[1]),
    hairstyleHighest: () => highestPoint(hair.strands?.points ?? []),
    cancelTool: () => active.cancel(),
    openDialog: () => toolbar.openFileDialog(),
    // a new session keeps this one's strand count
    emptySession: () =>
      applyPreset(
        emptySession(opts.grid, {
          ...DEFAULT_GROWTH,
          maxStrands: editor.session.growth.maxStrands,
        }),
        'empty',
        { head, step: grid.step, viewpoint: viewer.cameraState() },
      ),
    links,
    heads: headStore,
    pictures: pictureStore,
    refresh: () => toolbar.refresh(),
  });
  const styles = styleGallery({ editor, parent: document.body, status });
  let exporting: ExportWiring | null = null;
  const actions = buildActions({
    ...edits,
    exportMenu: () => exporting?.menu.toggle(),
    toggleHelp: () => help?.toggle(),
    toggleDetailPanel: () => {
      detailPanel?.toggle();
      closeOtherPanel('detail');
      toolbar.refresh();
    },
    detailPanelOpen: () => !!detailPanel?.open,
    openHead: () => toolbar.openHeadDialog(),
    openReference: () => toolbar.openReferenceDialog(),
    openStyles: () => styles.show(),
    toggleHeadPanel: () => {
      headPanel?.toggle();
      closeOtherPanel('head');
      showHeadPanel();
      toolbar.refresh();
    },
    headPanelOpen: () => !!headPanel?.open,
    display: (k) => view.state.display[k],
    setDisplay: (k, on) => view.setDisplay(k, on),
    qualityLabel: () => quality.label(),
    cycleQuality: () => quality.cycle(),
    toggleMotion: () => {
      if (motion.playing) motion.stop();
      else motion.play(motionControls.selected(), motionControls.wind());
    },
  });
  const toolbar = buildToolbar(byId('toolbar'), actions, {
    hairColor: (css) => editor.run({ kind: 'setHairColor', color: css }),
    // a session whose head is not stored: HeadController says which head it needs
    openFile: (f) =>
      void openSessionFileOutcome(editor, f, headStore, pictureStore).then(
        (o) => o.kind === 'failed' && status.note(o.message),
      ),
    openHeadFiles: (files) => heads.openHeadFiles(editor, files),
    openReferenceFile: (f) => references.openPickedFile(editor, f),
  });
  // the scalp brush's ring goes with the tool
  editor.listen(() => {
    if (editor.tool !== 'scalp') tools.scalpBrush.hideRing();
  });
  const views = buildViewControl(
    byId('stage'),
    actions.filter((a) => NAMED_VIEWS.some((v) => a.id === `view.${v.name}`)),
  );
  const followView = () => {
    const c = viewer.cameraState();
    views.setLabel(viewLabel(c.position, c.target));
  };
  followView();
  viewer.renderedListeners.add(followView);
  // data-detail: every strand on screen, or the sample drawn until the full-detail frame is; not
  // full while a view key's camera eases (from the key press on: a screenshot waits for it)
  viewer.renderedListeners.add(() => line.detail(viewer.hairDetail === 1 && !viewer.viewAnimating));
  viewer.viewMovingListeners.add(() => line.detail(false));
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
    cardCount: () => view.state.cardCount,
    setCardCount: (n) => view.update({ cardCount: n }),
    motion: () => motionControls.selected(),
  });
  const toggles = buildDisplayToggles(toolbar.moreElement, view.state.display, (k, on) =>
    view.setDisplay(k, on),
  );
  view.listen(({ state, previous }) => {
    const on = state.display.field;
    if (on !== previous.display.field) bridge.setWantField(on, !!overlays.shownResult?.field);
  });
  const curvePanel = buildSelectedCurvePanel(byId('stage'), editor, status);
  detailPanel = buildHairPanel(byId('stage'), editor, status);
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
  referencePanel = buildReferencePanel(
    byId('stage'),
    references.panelEvents(editor, {
      open: () => toolbar.openReferenceDialog(),
      say: (m) => status.note(m),
    }),
  );
  /** The Hair and Head panels share the view's left edge: the one just opened closes the other
   *  (both open, the Head panel covered the Hair panel's lower half: a new user's note). */
  function closeOtherPanel(opened: 'detail' | 'head'): void {
    const [mine, other] = opened === 'detail' ? [detailPanel, headPanel] : [headPanel, detailPanel];
    if (mine?.open && other?.open) other.toggle();
  }

  function showHeadPanel(): void {
    headPanel?.show({
      session: editor.session,
      label: heads.label(editor.session),
      missing: heads.missing ? heads.missing.name : null,
      brushRadius: tools.scalpBrush.radius,
    });
  }

  bindPageControls({
    editor,
    view,
    viewer,
    line,
    toolbar,
    toggles,
    curvePanel,
    detailPanel,
    showHeadPanel,
  });
  showSolverResults({ bridge, hair, sectionTint, bands, overlays, status, active, reports });
  const motion = new MotionPlayer({
    client: bridge.client,
    editor,
    viewer,
    hairView,
    shown: () => hair.shownResult,
    // the bands too: a tail is gathered at the head, so its band moves with it
    meshes: () => [headMesh, bodyMesh, bandView.object, ...viewer.headOverlays],
    say: (m) => status.note(m),
    statusElement: byId('status'),
    changed: () => motionControls.refresh(),
  });
  const motionControls = buildMotionControls(toolbar.moreElement, {
    play: (m, w) => motion.play(m, w),
    stop: () => motion.stop(),
    playing: () => motion.playing,
  });

  let lastPointerUp = 0;
  bindInput({
    viewer,
    tool: () => active.current,
    actions,
    overlayKey: (key) => closeOverlay(key, exporting, help),
    pointerUp: (t) => {
      lastPointerUp = t;
    },
  });

  overlays.syncCurves();
  line.counts(0, initial.curves.length);
  line.set('loading', 'Loading the solver…');
  bridge.sync();
  openStartingLink({ editor, status, links, headStore });
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
    view,
    ponytail: tools.ponytail,
    sectionsTinted: () => sectionTint.tinted,
    sectionsOverHair: () => sectionTint.overHairTriangles,
    link: () => links.write(),
    tieBands: () => ({ bands: [...bandView.shown], colour: bandView.colour }),
    busy: () =>
      heads.busy ||
      references.busy ||
      viewer.viewAnimating ||
      !!exporting?.busy() ||
      bridge.pending ||
      hair.awaitingFrame ||
      active.busy,
    lastPointerUp: () => lastPointerUp,
    quality,
    exporter: exporting.exporter,
    motion,
  });
}
