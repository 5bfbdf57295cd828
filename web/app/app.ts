// Wires the app together. Data flows one way:
// pointer -> tool -> session model -> solver client (worker) -> typed arrays -> viewer.
import * as THREE from 'three';
import { buildHead } from '../head/buildHead';
import { headSdf } from '../head/headSdf';
import { packCurves } from '../model/curveSet';
import { gridForPreset } from '../model/grid';
import { History } from '../model/history';
import { ponytailCircles } from '../model/ponytailGeometry';
import { applyPreset } from '../model/presets';
import {
  addCurve,
  DEFAULT_GROWTH,
  DEFAULT_TIGHTNESS,
  deleteCurve,
  emptySession,
  findCurve,
  nextCurveId,
  type SessionState,
  type StyleCurve,
  setAvoid,
  updateCurve,
  type Viewpoint,
} from '../model/session';
import { decodeSessionLink, encodeSessionLink, parseSession } from '../model/sessionFile';
import { buildSupportingSurface, type SupportingSurface } from '../model/supportingSurface';
import { normalize, sub, type Vec3 } from '../model/vec3';
import type { GridSpec } from '../solver/protocol';
import { type SolveResult, SolverClient } from '../solver/solverClient';
import { DividingCurveTool } from '../tools/dividingCurveTool';
import type { HintResult } from '../tools/hintStroke';
import { PONYTAIL_STAGE_HINT, type PonytailDraft, PonytailTool } from '../tools/ponytailTool';
import { SelectTool } from '../tools/selectTool';
import { StreamCurveTool } from '../tools/streamCurveTool';
import type { Tool } from '../tools/tool';
import { buildCurvePanel, type CurvePanel, type CurvePatch } from '../ui/curvePanel';
import {
  buildDisplayToggles,
  DEFAULT_DISPLAY,
  type DisplayKey,
  type DisplayState,
  type DisplayToggles,
} from '../ui/displayToggles';
import { StatusLine } from '../ui/status';
import { buildToolbar, type ToolName } from '../ui/toolbar';
import { BoundingVolumeView } from '../viewer/boundingVolume';
import { ConstraintPointsView } from '../viewer/constraintPoints';
import { FieldGlyphsView } from '../viewer/fieldGlyphs';
import { createHeadMesh } from '../viewer/headMaterial';
import { HeadPicker } from '../viewer/headPicker';
import {
  buildStrandGeometry,
  createStrandMaterial,
  type StrandMaterial,
  setHairColor,
} from '../viewer/strandMaterial';
import { SupportingSurfaceView } from '../viewer/supportingSurfaceView';
import { Viewer } from '../viewer/viewer';
import { installTestApi } from './testApi';
import { parseUrlOptions } from './urlOptions';

/** Strands grown for a preview while drawing: at most this many, fewer when the view draws a
 *  sample (a slow GPU), never fewer than the minimum. */
const PREVIEW_STRANDS = 6000;
const MIN_PREVIEW_STRANDS = 800;
/** Half width of a stream curve's supporting surface, in grid steps. */
const SURFACE_HALF_WIDTH = 6;

export class App {
  readonly viewer: Viewer;
  readonly status: StatusLine;
  readonly picker: HeadPicker;
  readonly history: History<SessionState>;
  readonly client: SolverClient;
  readonly step: number;
  selectedId: string | null = null;
  private tool: Tool;
  private readonly tools: Record<ToolName, Tool>;
  private readonly ponytailTool: PonytailTool;
  private readonly toolbar;
  private readonly panel: CurvePanel;
  /** Construction lines of the ponytail being built. */
  private toolGuides: Vec3[][] = [];
  private surfaceCache: { curve: StyleCurve; surface: SupportingSurface } | null = null;
  /** An "Avoid scalp" request is being answered. */
  private avoiding = false;
  private shownStrands: SolveResult['strands'] | null = null;
  private strandMaterial: StrandMaterial | null = null;
  private lastMessage = '';

  constructor() {
    const opts = parseUrlOptions(window.location.search);
    this.status = new StatusLine(
      document.getElementById('status') as HTMLElement,
      document.getElementById('hint') as HTMLElement,
    );
    this.status.set('loading', 'Building the head…');
    this.viewer = new Viewer(document.getElementById('viewport') as HTMLCanvasElement);

    const head = buildHead();
    const headMesh = createHeadMesh(head);
    this.viewer.addHead(headMesh);
    this.picker = new HeadPicker(headMesh.geometry, head);

    const grid = gridForPreset(opts.grid);
    this.step = grid.step;
    const growth = { ...DEFAULT_GROWTH, maxStrands: opts.maxStrands };
    const session = applyPreset(emptySession(opts.grid, growth), opts.preset, {
      headPoint: (t, p) => this.picker.scalpPoint(t, p)?.point ?? null,
      normalAt: headNormal,
      center: head.center,
      step: grid.step,
      viewpoint: this.viewer.cameraState(),
    });
    this.history = new History(session);

    const sample = (x: number, y: number) => {
      const ray = this.viewer.rayAt(x, y);
      const hit = this.picker.first(ray);
      return {
        origin: [ray.origin.x, ray.origin.y, ray.origin.z] as Vec3,
        direction: [ray.direction.x, ray.direction.y, ray.direction.z] as Vec3,
        scalpHit: hit?.scalp ? hit.point : null,
        headDistance: hit ? hit.distance : null,
      };
    };
    this.ponytailTool = new PonytailTool({
      sample,
      eye: () => this.viewer.eye(),
      forward: () => this.viewer.viewForward(),
      step: () => this.step,
      showDraft: (pts) => this.viewer.setDraft(pts),
      showGuides: (lines) => {
        this.toolGuides = lines.map((l) => l.slice());
        this.syncGuides();
      },
      commit: (p) => this.commitPonytail(p),
      notify: (m) => this.notify(m),
      stageChanged: (stage) => {
        if (this.tool === this.ponytailTool) this.status.hint(PONYTAIL_STAGE_HINT[stage]);
        this.notify(PONYTAIL_STAGE_HINT[stage]);
      },
    });
    this.tools = {
      dividing: new DividingCurveTool({
        sample,
        step: () => this.step,
        selected: () => {
          const c = findCurve(this.history.current, this.selectedId);
          return c?.type === 'dividing' ? c : null;
        },
        normalsAt: (pts) => pts.map(headNormal),
        showDraft: (pts) => this.viewer.setDraft(pts),
        commit: (points, normals) => this.commitDividing(points, normals),
        setTilt: (end, alpha, side) => this.setTilt(end, alpha, side),
        notify: (m) => this.notify(m),
      }),
      ponytail: this.ponytailTool,
      stream: new StreamCurveTool({
        sample,
        hintTarget: () => this.hintTarget(),
        applyHint: (r) => this.applyHint(r),
        eye: () => this.viewer.eye(),
        forward: () => this.viewer.viewForward(),
        step: () => this.step,
        showDraft: (pts) => this.viewer.setDraft(pts),
        commit: (points) => this.commitStreamCurve(points),
        preview: (points) => this.previewStroke(points),
        notify: (m) => this.notify(m),
      }),
      select: new SelectTool({
        // hidden curves (Curves display off) cannot be picked
        curves: () => (this.display.curves ? this.history.current.curves : []),
        toScreen: (p) => this.viewer.worldToScreen(p),
        select: (id) => this.select(id),
      }),
    };
    this.tool = this.tools.select;

    this.toolbar = buildToolbar(document.getElementById('toolbar') as HTMLElement, {
      tool: (name) => this.setTool(name),
      undo: () => this.undo(),
      redo: () => this.redo(),
      deleteSelected: () => this.deleteSelected(),
      hairColor: (css) => this.setHairColor(css),
      avoidScalp: () => void this.avoidScalp(),
      setViewpoint: () => this.setViewpoint(),
      surfaceMode: () => this.toggleSurfaceMode(),
      share: () => void this.shareLink(),
      saveFile: () => this.saveFile(),
      openFile: (f) => void this.openFile(f),
    });
    this.panel = buildCurvePanel(document.getElementById('stage') as HTMLElement, (id, patch) =>
      this.patchCurve(id, patch),
    );
    this.toolbar.setHairColor(session.hairColor);
    this.initDisplays(document.getElementById('toolbar') as HTMLElement, grid);
    this.bindInput();
    this.viewer.onFrame(() => this.tool.update());
    this.viewer.onRendered = () => {
      if (!this.unstamped) return;
      this.hairLog.push({ ...this.unstamped, time: performance.now() });
      if (this.hairLog.length > 1000) this.hairLog.shift();
      this.unstamped = null;
    };

    this.status.set('loading', 'Loading the solver…');
    this.client = new SolverClient(
      () => new Worker(new URL('../solver/worker.ts', import.meta.url), { type: 'module' }),
      { type: 'init', grid, omega: 100, solver: opts.solver, scalp: scalpMessage(head) },
      {
        onBusy: (phase, fraction) => {
          if (phase === 'loading') this.status.set('loading', 'Loading the solver…');
          else if (!this.previewing)
            this.status.set(
              'solving',
              `${phase === 'growing' ? 'Growing hair' : 'Solving the field'}… ${Math.round(fraction * 100)}%`,
            );
        },
        onResult: (r, final) => this.showResult(r, final),
        onError: (m) =>
          this.status.set(
            'error',
            `Error: ${m}${/over the cap/.test(m) ? ' — the exact solver does not fit this grid; use ?solver=fast' : ''}`,
          ),
        onIdle: () => this.showReady(),
      },
    );
    this.setTool(opts.preset === 'empty' ? 'stream' : 'select');
    this.syncSession();
    void this.openLink(window.location.hash);
    if (opts.warnings.length) this.notify(`URL: ${opts.warnings.join('; ')}`);
    installTestApi(this);
  }

  // ---- edits -------------------------------------------------------------------------------

  /** Records an edit of the session (undoable) and re-solves. */
  private edit(next: SessionState, message: string): void {
    if (next === this.history.current) return;
    this.history.push(next);
    this.notify(message);
    this.syncSession();
  }

  private selected(): StyleCurve | null {
    return findCurve(this.history.current, this.selectedId);
  }

  /** The selected stream curve's supporting surface (cached per curve object). */
  private surfaceOf(c: StyleCurve): SupportingSurface {
    if (this.surfaceCache?.curve !== c) {
      const mode = c.type === 'stream' ? (c.surfaceMode ?? 'ruled') : 'ruled';
      this.surfaceCache = {
        curve: c,
        surface: buildSupportingSurface(
          c.points,
          c.viewpoint.position,
          mode,
          SURFACE_HALF_WIDTH * this.step,
        ),
      };
    }
    return this.surfaceCache.surface;
  }

  private hintTarget(): { points: readonly Vec3[]; surface: SupportingSurface } | null {
    const c = this.selected();
    if (!c || c.type === 'dividing' || c.points.length < 2) return null;
    return { points: c.points, surface: this.surfaceOf(c) };
  }

  private applyHint(r: HintResult): void {
    const c = this.selected();
    if (!c) return;
    if (r.op.kind === 'none') {
      this.notify(`Hint: no operation (${r.op.reason}) — nothing changed.`);
      return;
    }
    const points = r.points;
    if (c.type === 'ponytail') {
      // the circles follow the edited spine, between the profiles as drawn
      const { circles } = ponytailCircles(points, c.crossSection, c.profiles[0], c.profiles[1], {
        every: 2,
      });
      if (circles.length === 0) {
        this.notify(
          `Hint: ${r.op.kind} would leave the ponytail without circles — nothing changed.`,
        );
        return;
      }
      this.edit(
        updateCurve(this.history.current, c.id, () => ({ ...c, points, circles })),
        `Hint: ${r.op.kind} — ponytail ${c.id} spine now has ${points.length} points.`,
      );
      return;
    }
    this.edit(
      updateCurve(this.history.current, c.id, (x) => ({ ...x, points }) as StyleCurve),
      `Hint: ${r.op.kind} — ${c.id} now has ${points.length} points.`,
    );
  }

  private commitDividing(points: Vec3[], normals: Vec3[]): void {
    this.addNewCurve(
      (id, viewpoint) => ({
        id,
        type: 'dividing',
        points,
        normals,
        sigma: 1,
        h: 0.5,
        alpha0: 0,
        alpha1: 0,
        viewpoint,
      }),
      `dividing curve {id} (${points.length - 1} segments)`,
    );
  }

  private setTilt(end: 'alpha0' | 'alpha1', alpha: number, side: 1 | -1): void {
    const c = this.selected();
    if (c?.type !== 'dividing') return;
    const deg = Math.round((alpha * 180) / Math.PI);
    this.edit(
      updateCurve(this.history.current, c.id, (x) => ({ ...x, [end]: alpha }) as StyleCurve),
      `Tilt: ${end} of ${c.id} = ${deg}° (stroke on the ${side > 0 ? '+x' : '−x'} side).`,
    );
  }

  private commitPonytail(p: PonytailDraft): void {
    this.addNewCurve(
      (id, viewpoint) => ({
        id,
        type: 'ponytail',
        points: p.spine,
        extend: true,
        viewpoint,
        crossSection: p.crossSection,
        profiles: p.profiles,
        circles: p.circles,
        tightness: DEFAULT_TIGHTNESS,
      }),
      `ponytail {id} (${p.circles.length} circles)`,
    );
  }

  setViewpoint(): void {
    const c = this.selected();
    if (!c) return;
    const { position, target } = this.viewer.cameraState();
    this.edit(
      updateCurve(this.history.current, c.id, (x) => ({ ...x, viewpoint: { position, target } })),
      `Viewpoint of ${c.id} set to the current view.`,
    );
  }

  toggleSurfaceMode(): void {
    const c = this.selected();
    if (c?.type !== 'stream') return;
    const mode = (c.surfaceMode ?? 'ruled') === 'ruled' ? 'strip' : 'ruled';
    this.edit(
      updateCurve(this.history.current, c.id, (x) => ({ ...x, surfaceMode: mode }) as StyleCurve),
      `Supporting surface of ${c.id}: ${mode}.`,
    );
  }

  private patchCurve(id: string, patch: CurvePatch): void {
    this.edit(
      updateCurve(this.history.current, id, (x) => ({ ...x, ...patch }) as StyleCurve),
      `Changed ${Object.keys(patch).join(', ')} of ${id}.`,
    );
  }

  /** S4.7: constraints near the head from the converged field of the current curves, stored in
   *  the session (undoable), then the hair is solved again with them. */
  async avoidScalp(): Promise<void> {
    if (this.avoiding) return;
    this.avoiding = true;
    this.refreshToolbar();
    this.status.set('solving', 'Avoid scalp: solving the field…');
    try {
      const r = await this.client.avoidScalp(packCurves(this.history.current.curves));
      this.history.push(
        setAvoid(this.history.current, {
          index: Array.from(r.index),
          target: Array.from(r.target),
        }),
      );
      this.notify(`Avoid scalp: ${r.index.length} constraints near the head.`);
    } catch (e) {
      this.notify(`Avoid scalp failed: ${e instanceof Error ? e.message : String(e)}`);
    } finally {
      this.avoiding = false;
      this.syncSession();
    }
  }

  /** Adds a new curve (given its id and the current view as viewpoint), selects it, re-solves. */
  private addNewCurve(make: (id: string, viewpoint: Viewpoint) => StyleCurve, what: string): void {
    const s = this.history.current;
    const id = nextCurveId(s);
    const { position, target } = this.viewer.cameraState();
    this.history.push(addCurve(s, make(id, { position, target })));
    this.selectedId = id;
    this.notify(`Added ${what.replace('{id}', id)}.`);
    this.syncSession();
  }

  private commitStreamCurve(points: Vec3[]): void {
    this.previewing = false;
    this.addNewCurve(
      (id, viewpoint) => ({ id, type: 'stream', points, extend: true, viewpoint }),
      `stream curve {id} (${points.length - 1} segments)`,
    );
  }

  /** Live preview while drawing: the session's curves plus the stroke so far, solved coarsely.
   *  At most one preview is in flight; the newest stroke state is sent when it returns. */
  private previewStroke(points: Vec3[] | null): void {
    if (points === null) {
      this.previewing = false;
      this.previewInFlight = false;
      return;
    }
    this.previewing = true;
    if (this.previewInFlight || points.length < 3) return;
    const s = this.history.current;
    const { position, target } = this.viewer.cameraState();
    const draft = {
      id: '~draft',
      type: 'stream' as const,
      points,
      extend: true,
      viewpoint: { position, target },
    };
    this.previewInFlight = true;
    // grow no more preview strands than the view can draw while the pen moves
    const shown = this.status.strands || PREVIEW_STRANDS;
    const cap = Math.round(
      Math.min(
        PREVIEW_STRANDS,
        Math.max(MIN_PREVIEW_STRANDS, shown * this.viewer.interactiveDetail),
      ),
    );
    const maxStrands = s.growth.maxStrands > 0 ? Math.min(s.growth.maxStrands, cap) : cap;
    this.client.request(
      packCurves([...s.curves, draft], s.avoid ?? null),
      { ...s.growth, maxStrands },
      'preview',
    );
  }

  /** Test hook: the session from another page's session() replaces this one (undoable). */
  replaceSession(json: unknown): void {
    const parsed = parseSession(json);
    if (!parsed.ok) throw new Error(`replaceSession: ${parsed.error}`);
    this.history.push({ ...parsed.value, grid: this.history.current.grid });
    this.selectedId = null;
    this.syncSession();
  }

  undo(): void {
    if (this.history.undo()) this.afterHistoryMove('Undone.');
  }

  redo(): void {
    if (this.history.redo()) this.afterHistoryMove('Redone.');
  }

  deleteSelected(): void {
    if (!this.selectedId) return;
    const next = deleteCurve(this.history.current, this.selectedId);
    if (next === this.history.current) return;
    this.history.push(next);
    this.notify(`Deleted curve ${this.selectedId}.`);
    this.selectedId = null;
    this.syncSession();
  }

  select(id: string | null): void {
    this.selectedId = id;
    this.syncCurvesView();
    this.refreshToolbar();
  }

  /** Which ponytail stroke comes next (test API). */
  get ponytailStage(): string {
    return this.ponytailTool.stage;
  }

  get ponytailSpine(): readonly Vec3[] {
    return this.ponytailTool.spinePoints;
  }

  setHairColor(css: string): void {
    this.history.push({ ...this.history.current, hairColor: css });
    this.applyHairColor();
    this.refreshToolbar();
    this.scheduleLinkUpdate();
  }

  setTool(name: ToolName): void {
    this.tool.onCancel();
    this.tool = this.tools[name];
    this.toolbar.setTool(name);
    const c = this.viewer.controls;
    // Drawing takes the primary button; the camera orbits with the right button then.
    if (name !== 'select') {
      c.mouseButtons = {
        LEFT: -1 as THREE.MOUSE,
        MIDDLE: THREE.MOUSE.PAN,
        RIGHT: THREE.MOUSE.ROTATE,
      };
      c.touches = { ONE: -1 as THREE.TOUCH, TWO: THREE.TOUCH.DOLLY_ROTATE };
      this.status.hint(
        name === 'stream'
          ? 'Drag from the scalp to draw a stream curve · on the selected curve’s supporting surface a stroke cuts, extends or re-routes it · right-drag orbits · wheel zooms'
          : name === 'dividing'
            ? 'Drag on the scalp to draw a parting · a stroke starting beside the selected one tilts that side · right-drag orbits'
            : PONYTAIL_STAGE_HINT[this.ponytailTool.stage],
      );
    } else {
      c.mouseButtons = {
        LEFT: THREE.MOUSE.ROTATE,
        MIDDLE: THREE.MOUSE.DOLLY,
        RIGHT: THREE.MOUSE.PAN,
      };
      c.touches = { ONE: THREE.TOUCH.ROTATE, TWO: THREE.TOUCH.DOLLY_PAN };
      this.status.hint('Click a curve to select it · drag orbits · wheel zooms · right-drag pans');
    }
  }

  private afterHistoryMove(message: string): void {
    if (this.selectedId && !this.history.current.curves.some((c) => c.id === this.selectedId))
      this.selectedId = null;
    this.notify(message);
    this.applyHairColor();
    this.toolbar.setHairColor(this.history.current.hairColor);
    this.syncSession();
  }

  // ---- session -> solver -> view -------------------------------------------------------------

  private syncSession(): void {
    const s = this.history.current;
    this.status.counts(this.status.strands, s.curves.length);
    this.syncCurvesView();
    this.refreshToolbar();
    this.viewer.hold('settling', true); // until the final hair is shown (cached: at once)
    this.client.request(packCurves(s.curves, s.avoid ?? null), s.growth);
    this.scheduleLinkUpdate();
  }

  // ---- session links -------------------------------------------------------------------------

  private linkTimer: ReturnType<typeof setTimeout> | null = null;
  /** The session the address bar's link encodes (null: none yet). */
  private linkedSession: SessionState | null = null;

  /** Keeps the address bar's #s= link in step with the session (a reload keeps the work). */
  private scheduleLinkUpdate(): void {
    if (this.linkTimer !== null) clearTimeout(this.linkTimer);
    this.linkTimer = setTimeout(() => {
      this.linkTimer = null;
      // links need CompressionStream; without it the address bar just does not follow
      this.writeLink().catch(() => {});
    }, 400);
  }

  private async writeLink(): Promise<string> {
    const s = this.history.current;
    const url = new URL(window.location.href);
    if (this.linkedSession !== s) {
      url.hash = await encodeSessionLink(s);
      if (this.history.current !== s) return url.toString(); // superseded meanwhile
      window.history.replaceState(null, '', url);
      this.linkedSession = s;
    }
    return window.location.href;
  }

  /** "Share link": the current session's link, copied to the clipboard when allowed. */
  async shareLink(): Promise<void> {
    let href: string;
    try {
      href = await this.writeLink();
    } catch {
      this.notify('This browser cannot make session links (no CompressionStream); use Save.');
      return;
    }
    try {
      await navigator.clipboard.writeText(href);
      this.notify(`Link copied (${Math.round(href.length / 1024)} KB).`);
    } catch {
      this.notify('The link is in the address bar (the clipboard is not available here).');
    }
  }

  /** "Save": the session (and the camera) as a JSON file download. */
  saveFile(): void {
    const json = JSON.stringify({ ...this.history.current, camera: this.viewer.cameraState() });
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([json], { type: 'application/json' }));
    a.download = 'hairstyle.hairsketch.json';
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 10_000);
    this.notify(`Saved the session (${this.history.current.curves.length} curves).`);
  }

  /** "Open": a session file replaces the session (undoable); a bad file says why, changes nothing. */
  async openFile(file: File): Promise<void> {
    if (file.size > 64 << 20) {
      this.notify(`Could not open ${file.name}: larger than 64 MB.`);
      return;
    }
    let data: unknown;
    try {
      data = JSON.parse(await file.text());
    } catch {
      this.notify(`Could not open ${file.name}: not JSON. Nothing changed.`);
      return;
    }
    const parsed = parseSession(data);
    if (!parsed.ok) {
      this.notify(`Could not open ${file.name}: ${parsed.error}. Nothing changed.`);
      return;
    }
    this.history.push({ ...parsed.value, grid: this.history.current.grid });
    this.selectedId = null;
    const cam = (data as { camera?: { position?: unknown; target?: unknown } }).camera;
    if (cam && isVec3(cam.position) && isVec3(cam.target))
      this.viewer.setCamera(cam.position, cam.target);
    this.applyHairColor();
    this.toolbar.setHairColor(this.history.current.hairColor);
    this.notify(`Opened ${file.name} (${parsed.value.curves.length} curves).`);
    this.syncSession();
  }

  /** Opens the session a link carries (#s=…); a bad link says why and keeps what is shown. */
  private async openLink(fragment: string): Promise<void> {
    if (!fragment.startsWith('#s=')) return;
    const parsed = await decodeSessionLink(fragment);
    if (!parsed.ok) {
      const message = `Could not open the link: ${parsed.error}. Showing the preset instead.`;
      this.status.set('error', message);
      this.notify(message); // stays in the status line once the preset's hair is ready
      return;
    }
    const grid = this.history.current.grid;
    this.history.reset({ ...parsed.value, grid }); // the page's ?grid wins; curves are in world units
    this.linkedSession = this.history.current;
    this.selectedId = null;
    this.applyHairColor();
    this.toolbar.setHairColor(this.history.current.hairColor);
    this.notify(`Opened a shared session (${parsed.value.curves.length} curves).`);
    this.syncSession();
  }

  private syncCurvesView(): void {
    this.viewer.setCurves(this.history.current.curves, this.selectedId);
    this.panel.show(this.selected());
    this.syncGuides();
    this.updateDisplays(); // the selected curve's surface follows edits and selection
  }

  /** The ponytail being built, else the selected ponytail's circles. */
  private syncGuides(): void {
    if (this.toolGuides.length > 0) {
      this.viewer.setGuides(this.toolGuides);
      return;
    }
    const c = this.selected();
    this.viewer.setGuides(c?.type === 'ponytail' ? c.circles.map(circlePolyline) : []);
  }

  private refreshToolbar(): void {
    const c = this.selected();
    this.toolbar.setEnabled({
      undo: this.history.canUndo,
      redo: this.history.canRedo,
      del: this.selectedId !== null,
      viewpoint: c !== null,
      surfaceMode: c?.type === 'stream',
      avoid: !this.avoiding,
    });
  }

  private showResult(r: SolveResult, final: boolean): void {
    if (this.shownStrands !== r.strands) {
      this.shownStrands = r.strands;
      const geometry = buildStrandGeometry(r.strands.points, r.strands.strandStart);
      // one material for all hair revisions: a new one would compile its shader again
      this.strandMaterial ??= createStrandMaterial({ color: this.history.current.hairColor });
      this.viewer.setHair(new THREE.LineSegments(geometry, this.strandMaterial));
      this.status.counts(r.strands.strandStart.length - 1, this.history.current.curves.length);
      this.status.bumpRevision();
      this.unstamped = {
        revision: this.status.revision,
        final,
        strands: r.strands.strandStart.length - 1,
      };
    }
    this.displayResult = r;
    this.updateDisplays();
    // hair that is still settling is drawn at interactive detail, the final hair in full
    this.viewer.hold('settling', !final);
    const st = r.stats;
    this.heapBytes = st.heapBytes;
    if (final)
      this.lastSolve = `${st.constraints} constraints, ${st.method} ${st.iterations} it. ${st.solveMs.toFixed(0)} ms, growth ${st.growMs.toFixed(0)} ms`;
    this.previewInFlight = false;
    if (!this.client.pending) this.showReady();
  }

  private lastSolve = '';
  /** When each displayed hair revision reached the screen (performance.now(), for benchmarks). */
  readonly hairLog: Array<{ revision: number; time: number; final: boolean; strands: number }> = [];
  private unstamped: { revision: number; final: boolean; strands: number } | null = null;
  lastPointerUp = 0;
  heapBytes = 0;
  /** A stroke is being drawn and previews are being solved. */
  private previewing = false;
  private previewInFlight = false;

  private showReady(): void {
    if (this.client.pending) return;
    this.viewer.hold('settling', false);
    const s = this.status;
    const extra = [this.lastMessage, this.lastSolve].filter(Boolean).join(' · ');
    s.set('ready', `Ready — ${s.strands} strands, ${s.curves} curves${extra ? ` · ${extra}` : ''}`);
  }

  private notify(message: string): void {
    this.lastMessage = message;
    if (this.status.state === 'ready') this.showReady();
  }

  private applyHairColor(): void {
    if (this.strandMaterial) setHairColor(this.strandMaterial, this.history.current.hairColor);
    this.viewer.requestRender();
  }

  // ---- display toggles (SPEC S6.2) ----------------------------------------------------------
  // What the view shows besides head and hair. View state: not in the undo history, not shared.
  // Hooks elsewhere: initDisplays (constructor), updateDisplays (syncCurvesView, showResult).

  readonly display: DisplayState = { ...DEFAULT_DISPLAY };
  private displayGrid: GridSpec | null = null;
  private displayToggles: DisplayToggles | null = null;
  /** The result whose constraints / field the overlays draw. */
  private displayResult: SolveResult | null = null;
  private readonly displayViews = {
    constraints: new ConstraintPointsView(),
    field: new FieldGlyphsView(),
    surface: new SupportingSurfaceView(),
    box: null as BoundingVolumeView | null,
  };
  /** What each overlay was last built from (rebuilt only when it changes). */
  private readonly displayDrawn = {
    constraints: null as unknown,
    field: null as unknown,
    surface: null as unknown,
    surfaceMode: '',
  };

  private initDisplays(toolbar: HTMLElement, grid: GridSpec): void {
    this.displayGrid = grid;
    this.displayViews.box = new BoundingVolumeView(grid);
    this.displayToggles = buildDisplayToggles(toolbar, this.display, (k, on) =>
      this.setDisplay(k, on),
    );
  }

  /** Turns one display on or off (the checkboxes, shortcuts 1–5 and tests call this). */
  setDisplay(key: DisplayKey, on: boolean): void {
    if (this.display[key] === on) return;
    this.display[key] = on;
    this.displayToggles?.set(this.display);
    if (key === 'field') {
      // the worker copies the field out only while it is shown
      this.client.wantField = on;
      // (while a stroke is drawn, its next preview carries the field)
      if (on && !this.displayResult?.field && !this.previewing) this.syncSession();
    }
    this.updateDisplays();
  }

  /** Rebuilds what changed of the shown overlays and adds / removes them from the view. */
  updateDisplays(): void {
    const grid = this.displayGrid;
    if (!grid) return; // called during construction, before initDisplays
    const d = this.display;
    const v = this.displayViews;
    const drawn = this.displayDrawn;
    const r = this.displayResult;
    this.viewer.setCurvesVisible(d.curves);

    let rebuilt = false;
    const constraints = d.constraints ? (r?.constraints ?? null) : null;
    if (drawn.constraints !== constraints) {
      drawn.constraints = constraints;
      v.constraints.update(constraints, grid);
      rebuilt = true;
    }
    this.viewer.showDisplay(v.constraints.object, d.constraints);

    const field = d.field ? (r?.field?.vectors ?? null) : null;
    if (drawn.field !== field) {
      drawn.field = field;
      v.field.update(field, grid);
      rebuilt = true;
    }
    this.viewer.showDisplay(v.field.object, d.field);

    const curve = d.surface
      ? (this.history.current.curves.find((c) => c.id === this.selectedId) ?? null)
      : null;
    // the surface hint strokes are lifted onto (dividing curves have none: they lie on the scalp)
    const surface = curve && curve.type !== 'dividing' ? this.surfaceOf(curve) : null;
    const mode = surface ? surface.mode : '';
    if (drawn.surface !== curve || drawn.surfaceMode !== mode) {
      drawn.surface = curve;
      drawn.surfaceMode = mode;
      v.surface.update(surface);
      rebuilt = true;
    }
    this.viewer.showDisplay(v.surface.object, d.surface);

    if (v.box) this.viewer.showDisplay(v.box.object, d.box);
    if (rebuilt) this.viewer.requestRender();
  }

  /** What the overlays draw now (test API). */
  displayInfo(): { constraints: number; glyphs: number; surfaceTriangles: number } {
    const v = this.displayViews;
    const d = this.display;
    return {
      constraints: d.constraints ? v.constraints.count : 0,
      glyphs: d.field ? v.field.count : 0,
      surfaceTriangles: d.surface ? v.surface.triangles : 0,
    };
  }

  // ---- input -------------------------------------------------------------------------------

  private bindInput(): void {
    const canvas = this.viewer.canvas;
    let captured: number | null = null;
    const ptr = (e: PointerEvent) => ({ x: e.clientX, y: e.clientY, button: e.button });
    canvas.addEventListener('pointerdown', (e) => {
      if (captured !== null) return;
      if (this.tool.onPointerDown(ptr(e))) {
        captured = e.pointerId;
        canvas.setPointerCapture(e.pointerId);
        this.viewer.hold('stroke', true);
      } else if (e.button === 0) {
        captured = e.pointerId;
      }
    });
    canvas.addEventListener('pointermove', (e) => {
      if (e.pointerId === captured) this.tool.onPointerMove(ptr(e));
    });
    const end = (e: PointerEvent, cancel: boolean) => {
      if (e.pointerId !== captured) return;
      captured = null;
      this.viewer.hold('stroke', false);
      if (cancel) this.tool.onCancel();
      else this.tool.onPointerUp(ptr(e));
    };
    canvas.addEventListener('pointerup', (e) => {
      this.lastPointerUp = performance.now();
      end(e, false);
    });
    canvas.addEventListener('pointercancel', (e) => end(e, true));
    canvas.addEventListener('contextmenu', (e) => e.preventDefault());
    window.addEventListener('keydown', (e) => {
      if (e.target instanceof HTMLInputElement) return;
      const mod = e.ctrlKey || e.metaKey;
      const key = e.key.toLowerCase();
      if (mod && key === 'z') {
        e.preventDefault();
        if (e.shiftKey) this.redo();
        else this.undo();
      } else if (mod && key === 'y') {
        e.preventDefault();
        this.redo();
      } else if (mod && key === 's') {
        e.preventDefault();
        this.saveFile();
      } else if (mod && key === 'o') {
        e.preventDefault();
        this.toolbar.openFileDialog();
      } else if (!mod && (e.key === 'Delete' || e.key === 'Backspace')) {
        this.deleteSelected();
      } else if (!mod && key === 's') {
        this.setTool('stream');
      } else if (!mod && key === 'v') {
        this.setTool('select');
      } else if (!mod && key === 'd') {
        this.setTool('dividing');
      } else if (!mod && key === 'p') {
        this.setTool('ponytail');
      } else if (!mod && key === 'm') {
        this.toggleSurfaceMode();
      } else if (e.key === 'Escape') {
        this.tool.onCancel();
        this.select(null);
      }
    });
  }

  // ---- queries (test API) ----------------------------------------------------------------------

  /** Whether a world point is the first thing the camera sees along its ray. */
  visible(p: Vec3): boolean {
    const eye = this.viewer.eye();
    const d = sub(p, eye);
    const len = Math.hypot(d[0], d[1], d[2]);
    const ray = new THREE.Ray(new THREE.Vector3(...eye), new THREE.Vector3(...d).normalize());
    const hit = this.picker.first(ray);
    return hit !== null && Math.abs(hit.distance - len) < 1e-3 * len + 1e-4;
  }

  get busy(): boolean {
    return (
      this.avoiding ||
      this.client.pending ||
      (this.tool.state !== 'idle' && this.tool.state !== 'pressed')
    );
  }

  displayedStrands(): SolveResult['strands'] | null {
    return this.shownStrands;
  }
}

/** Half width of the displayed supporting surface, in grid steps. */

/** What the supporting surface of a curve is built from: its points, its own viewpoint and its
 *  mode (its `surfaceMode` where the curve model stores one, else the ruled surface); null for a
 *  curve without a viewpoint (e.g. a dividing curve, drawn on the scalp) or with < 2 points. */
function isVec3(v: unknown): v is Vec3 {
  return Array.isArray(v) && v.length === 3 && v.every((x) => Number.isFinite(x));
}

function scalpMessage(head: {
  positions: Float32Array;
  indices: Uint32Array;
  scalp: Uint8Array;
  center: [number, number, number];
}) {
  // Copies: the worker gets its own arrays, the app keeps the head.
  return {
    positions: head.positions.slice(),
    indices: head.indices.slice(),
    scalp: head.scalp.slice(),
    center: head.center,
  };
}

/** Outward unit normal of the built-in head at (near) p: the gradient of its signed distance
 *  (central differences). Used for a dividing curve's per-point scalp normals (S4.5). */
export function headNormal(p: Vec3): Vec3 {
  const e = 1e-3;
  const [x, y, z] = p;
  return normalize([
    headSdf(x + e, y, z) - headSdf(x - e, y, z),
    headSdf(x, y + e, z) - headSdf(x, y - e, z),
    headSdf(x, y, z + e) - headSdf(x, y, z - e),
  ]);
}

/** A circle as a closed polyline (48 segments), for display. */
function circlePolyline(c: { centre: Vec3; axis: Vec3; radius: number }): Vec3[] {
  const a = normalize(c.axis);
  const ref: Vec3 = Math.abs(a[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
  const u = normalize([
    a[1] * ref[2] - a[2] * ref[1],
    a[2] * ref[0] - a[0] * ref[2],
    a[0] * ref[1] - a[1] * ref[0],
  ]);
  const v: Vec3 = [a[1] * u[2] - a[2] * u[1], a[2] * u[0] - a[0] * u[2], a[0] * u[1] - a[1] * u[0]];
  const out: Vec3[] = [];
  for (let i = 0; i <= 48; i++) {
    const t = (2 * Math.PI * i) / 48;
    const cs = Math.cos(t) * c.radius;
    const sn = Math.sin(t) * c.radius;
    out.push([
      c.centre[0] + cs * u[0] + sn * v[0],
      c.centre[1] + cs * u[1] + sn * v[1],
      c.centre[2] + cs * u[2] + sn * v[2],
    ]);
  }
  return out;
}
