// window.hairsketch: the hooks automated browser tests use (docs/testing.md, "Test contract").
import type { Editor } from '../editor/editor';
import { scalpCoverage, VIEW_DIRECTIONS } from '../head/hairCoverage';
import type { Head } from '../head/head';
import { contentKey } from '../model/curveSet';
import type { StrandArrays } from '../model/hairArrays';
import type { TieBand } from '../model/tieBands';
import type { Vec3 } from '../model/vec3';
import type { PonytailTool } from '../tools/ponytailTool';
import type { DisplayState } from '../ui/displayToggles';
import type { Viewer } from '../viewer/viewer';
import { BARE_SCALP_VIEWS, type BareScalpResult, bareScalp } from './bareScalp';
import type { HairPresenter, HairRevision } from './hairPresenter';
import type { OverlayPresenter } from './overlayPresenter';
import { isQualitySetting, type QualityControl } from './quality';
import { loadSession } from './sessionIO';
import type { SolverBridge } from './solverBridge';
import type { ViewStore } from './viewState';

export interface HairsketchTestApi {
  scalpToScreen(thetaDeg: number, phiDeg: number): { x: number; y: number } | null;
  worldToScreen(p: Vec3): { x: number; y: number } | null;
  session(): unknown;
  /** Resolves once nothing is left to do: no solve or growth, no frame to draw and (drawn, the
   *  default) the full-detail frame drawn; with drawn false, once the hair is there, before its
   *  full-detail frame (a software rasteriser takes seconds over it at 30K strands). */
  idle(drawn?: boolean): Promise<void>;
  hairHash(): string | null;
  /** Writes the session's link to the address bar now (it is otherwise written 400 ms after an
   *  edit) and returns the page's address with it. */
  link(): Promise<string>;
  crashWorker(): void;
  /** Kills the running export's worker as a crash would (nothing when no export runs). */
  crashExport(): void;
  /** Benchmark probes: when each hair revision reached the screen, the last pointer-up time
   *  (both performance.now()), and the solver's wasm heap size. */
  hairLog(): HairRevision[];
  lastPointerUp(): number;
  heapBytes(): number;
  /** Fraction of the hair's segments the last frame drew (1 = all; less while interacting on a
   *  slow GPU). */
  hairDetail(): number;
  /** Why the view draws hair at interactive detail (none: it draws all of it when settled). */
  viewHolds(): string[];
  /** Benchmark probe: the median time in ms of `runs` frames of the current view drawn with
   *  every strand (GPU work included). */
  frameMs(runs?: number): number;
  /** Root and tip of every displayed strand: [rx, ry, rz, tx, ty, tz] per strand, flat. */
  strandEnds(): number[];
  /** Replaces the session with a plain-JSON one from session() (an undoable edit); for
   *  comparing a session's hair against a fresh solve in another page. */
  replaceSession(session: unknown): void;
  /** The display toggles (method S6.2): which of curves, constraints, surface, field, box show. */
  display(): DisplayState;
  /** What the shown overlays draw: constraints, field glyphs, surface triangles (0 when off). */
  displayInfo(): { constraints: number; glyphs: number; surfaceTriangles: number; guides: number };
  /** Points of the grid the solver works on (the session's bounding volume, gridForSession). */
  gridPoints(): number;
  /** Rays from one side (back: travelling +z) at a 3° grid of scalp points: how many are seen
   *  from there and how many of those no displayed strand hides (within `radius`, 1 mm). */
  scalpCoverage(
    view: 'front' | 'back' | 'left' | 'right' | 'top',
    radius?: number,
  ): { points: number; bare: number; fraction: number; bareAt: [number, number][] };
  /** scalpCoverage of any region of the head: head points within θ and φ ranges (degrees; φ = 0
   *  at the front, 90 at the head's left), the scalp only or any surface (the forehead…). */
  coverage(
    view: 'front' | 'back' | 'left' | 'right' | 'top',
    opts: {
      theta: [number, number];
      phi: [number, number];
      surface?: 'scalp' | 'any';
      radius?: number;
      layers?: number;
    },
  ): { points: number; bare: number; fraction: number; bareAt: [number, number][] };
  /** The Quality setting ('auto' | 'fast' | 'high'), the drawing path active now and the
   *  unmasked WebGL renderer it was chosen from. */
  quality(): { setting: string; active: 'fast' | 'high'; renderer: string };
  /** Sets the Quality setting as the Quality button does (persisted view state). */
  setQuality(setting: 'auto' | 'fast' | 'high'): void;
  /** Benchmark probe: the lighting precompute time (ms, in the worker) of the hair shown. */
  lightingMs(): number | null;
  /** The displayed strands as plain arrays (layout of protocol.ts StrandArrays). */
  /** The hair drawn (also while a motion plays: its current frame): its points, where each
   *  strand starts, the index of the curve whose tie laid each strand (or -1), and the scalp
   *  section of each root (empty with sections off). */
  /** The motion playing (null: none), its frame, frames drawn per second since it started,
   *  and the last frame's wait for the worker and geometry build (ms). */
  motion(): {
    playing: string | null;
    frame: number;
    fps: number;
    /** Strands of the hair shown (the motion's frame while playing), and of those the strands
     *  the last frame drew (the view's level of detail: fewer while a frame cannot draw all). */
    strands: number;
    drawnStrands: number;
    workerMs: number;
    /** The worker's own time for the last frame: stepping the guides and reading them (ms). */
    stepMs: number;
    buildMs: number;
    /** Every how many points each strand is drawn while playing (1: all of them; more where a
     *  frame cannot draw them all: a software rasteriser). */
    pointStride: number;
    /** Frames of this play drawn by rebuilding the geometry (the Cards view: the strands placed
     *  on the CPU); 0 while the strand shader places them. */
    rebuilds: number;
    /** The overlays on the head (style curves, displays) are moved from their rest: they carry
     *  the head's pose. */
    overlaysPosed: boolean;
  };
  /** While a motion plays: the strand shader's placement of the last frame read back from the
   *  GPU against the CPU reference (model/guideFollowers.ts): points compared, the largest
   *  distance between the two and the largest distance a point moved from its groom (world
   *  units); null when nothing follows on the GPU. */
  checkFollowers(): { points: number; maxDifference: number; maxMoved: number } | null;
  /** strands() with each array's bytes as base64 (little-endian Float32, Uint32, Int32 and Uint8
   *  arrays in that order), for scripts that take the whole hair out of the page: a plain array
   *  of 300,000 numbers costs the driver seconds to check and parse, a string almost nothing. */
  strandsPacked(): {
    points: string;
    strandStart: string;
    tailCurves: string;
    rootSections: string;
  } | null;
  strands(): {
    points: number[];
    strandStart: number[];
    tailCurves: number[];
    rootSections: number[];
  } | null;
  /** Displayed strand segments with a point (either end or the middle) deeper than `depth`
   *  world units inside the head (Head.signedDistance: exact for the built-in head), and the
   *  deepest value. */
  segmentsInsideHead(
    depth: number,
    /** Every stride-th strand only (a loaded head's inside test is slower). */
    stride?: number,
  ): {
    inside: number;
    segments: number;
    deepest: number;
    /** Of `inside`, segments that start at the strand's root. */
    atRoot: number;
    /** Deepest root (roots sit on the polygonised head, not the exact surface). */
    deepestRoot: number;
  };
  /** The head shown: its name ('builtin' or the file name), triangles and scalp triangles, the
   *  session's head when its file is missing, and whether a head is being loaded. */
  head(): {
    name: string;
    triangles: number;
    scalpTriangles: number;
    missing: string | null;
    loading: boolean;
    /** The head's bounding box (world units). */
    bounds: { min: Vec3; max: Vec3 };
  };
  /** Of the displayed strands' roots: how many lie within `distance` of the head's surface on a
   *  scalp triangle (closest point), and how many there are. */
  rootsOnScalp(distance: number): { onScalp: number; roots: number };
  select(id: string | null): void;
  /** Which ponytail stroke the Ponytail tool expects next. */
  ponytailStage(): string;
  /** The spine of the ponytail being built (empty before its first stroke). */
  ponytailSpine(): Vec3[];
  /** Moves the camera (world position and orbit target). */
  setCamera(position: Vec3, target: Vec3): void;
  /** The view ray through client coordinates. */
  rayAt(x: number, y: number): { origin: Vec3; direction: Vec3 };
  /** The current view drawn through the frame cache (from the layer the next frame would start
   *  from, or the cached head with `from` = 'static') and drawn whole: RGBA pixels of each, rows
   *  bottom-up, base64; `source` the layer the cached image started from ('none': nothing was
   *  cached), `count` the hair index count both drew. */
  renderBoth(from?: 'static'): {
    width: number;
    height: number;
    source: string;
    count: number;
    cached: string;
    full: string;
  };
  /** Share of the view's pixels that drawing the hair's triangles in reverse order changes, with
   *  High's order-independent blending and with plain blending (viewer/blendOrderProbe.ts); null
   *  when the hair is not drawn order-independently. */
  blendOrder(): { oit: number; unsorted: number } | null;
  /** Share of the view's pixels the settled hair's depth changes (overlays under the hair drawn
   *  faint: viewer/blendOrderProbe.ts hairDepthProbe); null when the hair is not drawn
   *  order-independently. */
  hairDepth(): number | null;
  /** Turns the frame cache off (every frame drawn whole) or on; returns whether it is in use. */
  setFrameCache(on: boolean): boolean;
  /** Where the last frame started from: 'hair', 'static' or 'none' (viewer/frameCache.ts). */
  frameSource(): string;
  /** Frames drawn since the page loaded, by where each started from (benchmark probe). */
  frameSources(): { hair: number; static: number; none: number };
  /** How many times the drawing buffer's resolution changed (interactive frames on a slow
   *  renderer lower it, the settled view restores it): each change redraws the cached layers. */
  resolutionChanges(): number;
  /** Slices the last full-detail frame drawn a slice a frame took (viewer.ts
   *  renderFullInSlices; counted from the last frame drawn between them); 0 when none was. */
  fullFrameSlices(): number;
  /** Scalp vertices tinted by section (while a tie tool is active; 0 otherwise). */
  sectionsTinted(): number;
  /** Scalp triangles of the sections drawn over the hair (while a tie tool is active; 0
   *  otherwise). */
  sectionsOverHair(): number;
  /** The ties' bands shown (model/tieBands.ts) and their colour (#rrggbb; null: none shown). */
  tieBands(): { bands: TieBand[]; colour: string | null };
  /** The scalp brush's ring on the head (its radius, world units, and whether it erases), or
   *  null when none is shown. */
  brushRing(): { radius: number; erase: boolean } | null;
  /** Scalp bare where hair should be (app/bareScalp.ts) from the front, the side (+x), the back
   *  and the top, for the head and hair shown (minOpacity: its stricter cover); `ms` the time it
   *  took. */
  bareScalp(opts?: { minOpacity?: number }): BareScalpResult & { ms: number };
}

declare global {
  interface Window {
    hairsketch: HairsketchTestApi;
  }
}

/** The parts of the app the hooks read. */
export interface TestApiParts {
  editor: Editor;
  /** The head shown (it changes with Open head). */
  head(): Head;
  /** What the app knows of the head: its file name, and the session's head when missing. */
  headInfo(): { name: string; missing: string | null; loading: boolean };
  viewer: Viewer;
  bridge: SolverBridge;
  hair: HairPresenter;
  overlays: OverlayPresenter;
  view: ViewStore;
  ponytail: PonytailTool;
  /** Scalp vertices tinted by section now (a tie tool is active). */
  sectionsTinted(): number;
  sectionsOverHair(): number;
  /** Writes the session's link now; the address with it. */
  link(): Promise<string>;
  /** The ties' bands on screen. */
  tieBands(): { bands: TieBand[]; colour: string | null };
  /** Work is pending (a solve, an avoidance request, a stroke being drawn). */
  busy(): boolean;
  lastPointerUp(): number;
  quality?: QualityControl;
  exporter?: { crash(): void };
  /** The motion player (app/motionPlayer.ts). */
  motion?: {
    drawn: StrandArrays | null;
    playing: string | null;
    frame: number;
    fps: number;
    times: { workerMs: number; stepMs: number; buildMs: number; rebuilds: number };
    checkFollowers(): { points: number; maxDifference: number; maxMoved: number } | null;
    readonly pointStride: number;
  };
}

export function installTestApi(app: TestApiParts): void {
  const { editor, viewer, hair } = app;
  const head = () => app.head();
  window.hairsketch = {
    scalpToScreen(thetaDeg, phiDeg) {
      const hit = head().scalpPoint(thetaDeg, phiDeg);
      if (!hit?.scalp || !head().visibleFrom(viewer.eye(), hit.point)) return null;
      return viewer.worldToScreen(hit.point);
    },
    worldToScreen: (p) => viewer.worldToScreen(p),
    session: () =>
      JSON.parse(
        JSON.stringify({
          ...editor.session,
          camera: viewer.cameraState(),
          selected: editor.selectedId,
        }),
      ),
    idle: (drawn = true) =>
      new Promise<void>((resolve) => {
        const check = () => {
          if (!app.busy() && (!drawn || (!viewer.renderPending && !viewer.fullDetailPending)))
            resolve();
          // a timer, not an animation frame: asking for frames would keep an idle view drawing
          else setTimeout(check, 16);
        };
        check();
      }),
    hairHash() {
      const s = hair.strands;
      return s ? contentKey(s.points, s.strandStart) : null;
    },
    link: () => app.link(),
    crashWorker: () => app.bridge.crash(),
    crashExport: () => app.exporter?.crash(),
    hairLog: () => hair.log.slice(),
    lastPointerUp: () => app.lastPointerUp(),
    heapBytes: () => hair.heapBytes,
    hairDetail: () => viewer.hairDetail,
    viewHolds: () => viewer.heldFor,
    gridPoints: () => {
      const d = app.bridge.grid.dims;
      return d[0] * d[1] * d[2];
    },
    scalpCoverage: (view, radius) =>
      scalpCoverage(head(), hair.strands, { dir: VIEW_DIRECTIONS[view], radius }),
    coverage: (view, o) =>
      scalpCoverage(head(), hair.strands, {
        dir: VIEW_DIRECTIONS[view],
        radius: o.radius,
        layers: o.layers,
        region: { theta: o.theta, phi: o.phi },
        surface: o.surface,
      }),
    frameMs(runs = 5) {
      const t: number[] = [];
      for (let i = 0; i < Math.max(1, runs); i++) t.push(viewer.measureFrame());
      t.sort((x, y) => x - y);
      return t[t.length >> 1];
    },
    strandEnds() {
      const s = hair.strands;
      if (!s) return [];
      const out: number[] = [];
      for (let i = 0; i + 1 < s.strandStart.length; i++) {
        const a = s.strandStart[i];
        const b = s.strandStart[i + 1] - 1;
        for (const k of [a, b]) out.push(s.points[3 * k], s.points[3 * k + 1], s.points[3 * k + 2]);
      }
      return out;
    },
    replaceSession(session) {
      const r = loadSession(editor, session, { kind: 'test' });
      if (!r.ok) throw new Error(`replaceSession: ${r.error}`);
    },
    display: () => ({ ...app.view.state.display }),
    displayInfo: () => app.overlays.info(),
    quality: () =>
      app.quality?.info() ?? { setting: 'fast', active: 'fast', renderer: viewer.rendererName },
    setQuality: (s) => {
      if (!isQualitySetting(s)) throw new Error(`setQuality: unknown setting ${String(s)}`);
      app.quality?.set(s);
    },
    lightingMs: () => app.quality?.lightingMs() ?? null,
    motion: () => {
      const shown = app.motion?.drawn ?? hair.strands;
      const strands = shown ? shown.strandStart.length - 1 : 0;
      return {
        playing: app.motion?.playing ?? null,
        frame: app.motion?.frame ?? 0,
        fps: app.motion?.fps ?? 0,
        strands,
        drawnStrands: Math.round(viewer.hairDetail * strands),
        workerMs: app.motion?.times.workerMs ?? 0,
        stepMs: app.motion?.times.stepMs ?? 0,
        buildMs: app.motion?.times.buildMs ?? 0,
        rebuilds: app.motion?.times.rebuilds ?? 0,
        pointStride: app.motion?.playing ? app.motion.pointStride : 1,
        // at rest their matrix is the identity (1 on the diagonal: every fifth element)
        overlaysPosed: viewer.headOverlays.some((g) =>
          g.matrix.elements.some((v, i) => v !== (i % 5 === 0 ? 1 : 0)),
        ),
      };
    },
    checkFollowers: () => app.motion?.checkFollowers() ?? null,
    strandsPacked() {
      const s = app.motion?.drawn ?? hair.strands;
      return s
        ? {
            points: base64Of(s.points),
            strandStart: base64Of(s.strandStart),
            tailCurves: base64Of(s.tailCurves ?? new Int32Array()),
            rootSections: base64Of(s.rootSections ?? new Uint8Array()),
          }
        : null;
    },
    strands() {
      const s = app.motion?.drawn ?? hair.strands;
      return s
        ? {
            points: Array.from(s.points),
            strandStart: Array.from(s.strandStart),
            tailCurves: Array.from(s.tailCurves ?? []),
            rootSections: Array.from(s.rootSections ?? []),
          }
        : null;
    },
    segmentsInsideHead(depth, stride = 1) {
      const s = hair.strands;
      const h = head();
      const every = Math.max(1, Math.floor(stride));
      let inside = 0;
      let segments = 0;
      let deepest = Number.POSITIVE_INFINITY;
      let atRoot = 0;
      let deepestRoot = Number.POSITIVE_INFINITY;
      if (!s) return { inside, segments, deepest, atRoot, deepestRoot };
      const P = s.points;
      const sd = (x: number, y: number, z: number) => h.signedDistance([x, y, z]);
      const at = (k: number) => sd(P[3 * k], P[3 * k + 1], P[3 * k + 2]);
      for (let i = 0; i + 1 < s.strandStart.length; i += every) {
        deepestRoot = Math.min(deepestRoot, at(s.strandStart[i]));
        for (let k = s.strandStart[i]; k + 1 < s.strandStart[i + 1]; k++) {
          segments++;
          const mid = sd(
            (P[3 * k] + P[3 * k + 3]) / 2,
            (P[3 * k + 1] + P[3 * k + 4]) / 2,
            (P[3 * k + 2] + P[3 * k + 5]) / 2,
          );
          const d = Math.min(at(k), at(k + 1), mid);
          deepest = Math.min(deepest, d);
          if (d < -depth) {
            inside++;
            if (k === s.strandStart[i]) atRoot++;
          }
        }
      }
      return { inside, segments, deepest, atRoot, deepestRoot };
    },
    head() {
      const h = head();
      const info = app.headInfo();
      let scalpTriangles = 0;
      for (const f of h.mesh.scalp) scalpTriangles += f;
      return {
        name: info.name,
        triangles: h.mesh.indices.length / 3,
        scalpTriangles,
        missing: info.missing,
        loading: info.loading,
        bounds: { min: [...h.mesh.bounds.min], max: [...h.mesh.bounds.max] },
      };
    },
    rootsOnScalp(distance) {
      const s = hair.strands;
      const h = head();
      let onScalp = 0;
      const roots = s ? s.strandStart.length - 1 : 0;
      for (let i = 0; s && i < roots; i++) {
        const k = 3 * s.strandStart[i];
        const c = h.closest([s.points[k], s.points[k + 1], s.points[k + 2]]);
        if (c.distance <= distance && h.mesh.scalp[c.triangle] === 1) onScalp++;
      }
      return { onScalp, roots };
    },
    select: (id) => editor.select(id),
    ponytailStage: () => app.view.state.ponytailStage,
    setCamera: (position, target) => viewer.setCamera(position, target),
    rayAt(x, y) {
      const r = viewer.rayAt(x, y);
      return {
        origin: [r.origin.x, r.origin.y, r.origin.z],
        direction: [r.direction.x, r.direction.y, r.direction.z],
      };
    },
    ponytailSpine: () => app.ponytail.spinePoints.map((p) => [...p] as Vec3),
    renderBoth(from) {
      const r = viewer.probes.compareFrames(from);
      return { ...r, cached: base64(r.cached), full: base64(r.full) };
    },
    hairDepth: () => viewer.probes.hairDepth(),
    blendOrder: () => viewer.probes.blendOrder(),
    setFrameCache(on) {
      viewer.probes.frameCacheEnabled = on;
      return viewer.probes.frameCacheActive;
    },
    frameSource: () => viewer.probes.lastFrameSource,
    frameSources: () => ({ ...viewer.frameSources }),
    resolutionChanges: () => viewer.resolutionChanges,
    fullFrameSlices: () => viewer.probes.lastFullFrameSlices,
    sectionsTinted: () => app.sectionsTinted(),
    sectionsOverHair: () => app.sectionsOverHair(),
    tieBands: () => app.tieBands(),
    brushRing: () => viewer.brushRing,
    bareScalp(opts) {
      const t0 = performance.now();
      const r = bareScalp(head().mesh, hair.strands, BARE_SCALP_VIEWS, {
        minOpacity: opts?.minOpacity,
      });
      return { ...r, ms: performance.now() - t0 };
    },
  };
}

function base64(bytes: Uint8Array): string {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000)
    s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

/** A typed array's bytes as base64 (strandsPacked). */
function base64Of(a: ArrayBufferView): string {
  const bytes = new Uint8Array(a.buffer, a.byteOffset, a.byteLength);
  let bin = '';
  for (let i = 0; i < bytes.length; i += 0x8000)
    bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(bin);
}
