// Wires the app together. Data flows one way:
// pointer -> tool -> session model -> solver client (worker) -> typed arrays -> viewer.
import * as THREE from 'three';
import { buildHead } from '../head/buildHead';
import { packCurves } from '../model/curveSet';
import { gridForPreset } from '../model/grid';
import { History } from '../model/history';
import { applyPreset } from '../model/presets';
import {
  addCurve,
  DEFAULT_GROWTH,
  deleteCurve,
  emptySession,
  nextCurveId,
  type SessionState,
} from '../model/session';
import type { SurfaceMode } from '../model/supportingSurface';
import { buildSupportingSurface } from '../model/supportingSurface';
import { sub, type Vec3 } from '../model/vec3';
import type { GridSpec } from '../solver/protocol';
import { type SolveResult, SolverClient } from '../solver/solverClient';
import { SelectTool } from '../tools/selectTool';
import { StreamCurveTool } from '../tools/streamCurveTool';
import type { Tool } from '../tools/tool';
import {
  buildDisplayToggles,
  DEFAULT_DISPLAY,
  type DisplayKey,
  type DisplayState,
  type DisplayToggles,
} from '../ui/displayToggles';
import { StatusLine } from '../ui/status';
import { buildToolbar } from '../ui/toolbar';
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

export class App {
  readonly viewer: Viewer;
  readonly status: StatusLine;
  readonly picker: HeadPicker;
  readonly history: History<SessionState>;
  readonly client: SolverClient;
  readonly step: number;
  selectedId: string | null = null;
  private tool: Tool;
  private readonly tools: Record<'stream' | 'select', Tool>;
  private readonly toolbar;
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
      center: head.center,
      step: grid.step,
      viewpoint: this.viewer.cameraState(),
    });
    this.history = new History(session);

    this.tools = {
      stream: new StreamCurveTool({
        sample: (x, y) => {
          const ray = this.viewer.rayAt(x, y);
          const hit = this.picker.first(ray);
          return {
            origin: [ray.origin.x, ray.origin.y, ray.origin.z],
            direction: [ray.direction.x, ray.direction.y, ray.direction.z],
            scalpHit: hit?.scalp ? hit.point : null,
          };
        },
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
    });
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
    if (opts.warnings.length) this.notify(`URL: ${opts.warnings.join('; ')}`);
    installTestApi(this);
  }

  // ---- edits -------------------------------------------------------------------------------

  private commitStreamCurve(points: Vec3[]): void {
    this.previewing = false;
    const s = this.history.current;
    const id = nextCurveId(s);
    const { position, target } = this.viewer.cameraState();
    this.history.push(
      addCurve(s, { id, type: 'stream', points, extend: true, viewpoint: { position, target } }),
    );
    this.selectedId = id;
    this.notify(`Added stream curve ${id} (${points.length - 1} segments).`);
    this.syncSession();
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
    this.client.request(packCurves([...s.curves, draft]), { ...s.growth, maxStrands }, 'preview');
  }

  /** Test hook: the session from another page's session() replaces this one (undoable). */
  replaceSession(json: unknown): void {
    const j = json as Partial<SessionState>;
    if (!j || !Array.isArray(j.curves) || typeof j.growth !== 'object')
      throw new Error('replaceSession: not a session (curves and growth are required)');
    const s = this.history.current;
    this.history.push({ ...s, curves: j.curves, growth: { ...s.growth, ...j.growth } });
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

  setHairColor(css: string): void {
    this.history.push({ ...this.history.current, hairColor: css });
    this.applyHairColor();
    this.refreshToolbar();
  }

  setTool(name: 'stream' | 'select'): void {
    this.tool.onCancel();
    this.tool = this.tools[name];
    this.toolbar.setTool(name);
    const c = this.viewer.controls;
    // Drawing takes the primary button; the camera orbits with the right button then.
    if (name === 'stream') {
      c.mouseButtons = {
        LEFT: -1 as THREE.MOUSE,
        MIDDLE: THREE.MOUSE.PAN,
        RIGHT: THREE.MOUSE.ROTATE,
      };
      c.touches = { ONE: -1 as THREE.TOUCH, TWO: THREE.TOUCH.DOLLY_ROTATE };
      this.status.hint(
        'Drag from the scalp to draw a stream curve · right-drag orbits · wheel zooms · middle-drag pans',
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
    this.client.request(packCurves(s.curves), s.growth);
  }

  private syncCurvesView(): void {
    this.viewer.setCurves(this.history.current.curves, this.selectedId);
    this.updateDisplays(); // the selected curve's surface follows edits and selection
  }

  private refreshToolbar(): void {
    this.toolbar.setEnabled({
      undo: this.history.canUndo,
      redo: this.history.canRedo,
      del: this.selectedId !== null,
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
    const source = curve ? surfaceSource(curve) : null;
    const mode = source?.mode ?? '';
    if (drawn.surface !== curve || drawn.surfaceMode !== mode) {
      drawn.surface = curve;
      drawn.surfaceMode = mode;
      v.surface.update(
        source
          ? buildSupportingSurface(
              source.points,
              source.eye,
              source.mode,
              SURFACE_HALF_WIDTH_STEPS * grid.step,
            )
          : null,
      );
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
      } else if (!mod && (e.key === 'Delete' || e.key === 'Backspace')) {
        this.deleteSelected();
      } else if (!mod && key === 's') {
        this.setTool('stream');
      } else if (!mod && key === 'v') {
        this.setTool('select');
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
    return this.client.pending || (this.tool.state !== 'idle' && this.tool.state !== 'pressed');
  }

  displayedStrands(): SolveResult['strands'] | null {
    return this.shownStrands;
  }
}

/** Half width of the displayed supporting surface, in grid steps. */
const SURFACE_HALF_WIDTH_STEPS = 6;

/** What the supporting surface of a curve is built from: its points, its own viewpoint and its
 *  mode (its `surfaceMode` where the curve model stores one, else the ruled surface); null for a
 *  curve without a viewpoint (e.g. a dividing curve, drawn on the scalp) or with < 2 points. */
function surfaceSource(curve: object): { points: Vec3[]; eye: Vec3; mode: SurfaceMode } | null {
  const c = curve as {
    points?: Vec3[];
    viewpoint?: { position: Vec3 };
    surfaceMode?: unknown;
  };
  if (!c.viewpoint || !c.points || c.points.length < 2) return null;
  return {
    points: c.points,
    eye: c.viewpoint.position,
    mode: c.surfaceMode === 'strip' ? 'strip' : 'ruled',
  };
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
