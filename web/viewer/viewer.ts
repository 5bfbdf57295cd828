// The three.js view: head, hair strands, style curves, the stroke being drawn. Renders on demand.
// While the user interacts (orbit, a stroke, hair still settling) the hair is drawn at a level of
// detail that keeps frames near INTERACTIVE_FRAME_MS on this GPU: a prefix of the strands, which
// buildStrandGeometry orders as an even sample. The budget comes from measured frame times, so a
// fast GPU always draws everything; a software rasteriser draws a sparse sample while things move,
// and the whole head of hair once they stop. When the view settles and the whole hair is more
// than an interactive frame can draw, the settled view is first drawn at interactive detail (that
// frame is when new hair is "shown": onHairShown), and the full-detail frame follows a frame
// later, so nothing waiting for the hair waits for it (a 30K-strand frame takes seconds on
// SwiftShader).
// Style curves, the draft stroke, guides and display glyphs are depth-tested against head and
// hair, and faint where hidden (overlayStyle.ts).
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { KEY_LIGHT_POSITION } from '../lighting/keyLight';
import type { Vec3 } from '../model/vec3';
import { DEFAULT_CAMERA } from './defaultCamera';
import {
  drawableStamp,
  type FrameMode,
  type FramePlan,
  FrameSlots,
  type HairKey,
  type LayerKey,
  OverlayWait,
  planFrame,
  sameLayer,
  viewKey,
} from './frameCache';
import {
  curveRgb,
  HIDDEN_OPACITY,
  OVERLAY_ORDER,
  OVERLAY_RGB,
  overlayPolyline,
  SELECTED_HIDDEN_OPACITY,
} from './overlayStyle';
import { type CameraView, easeInOut, interpolateView, orbitRotateSpeed } from './viewMath';

export interface CurveView {
  id: string;
  /** Session curve type ('stream' | 'dividing' | 'ponytail'): chooses the colour (stream when
   *  absent). */
  type?: string;
  points: readonly Vec3[];
}

/** Interactive frames aim at this, and are slow past SLOW_FRAME_MS: frames are presented on
 *  vsync (16.7 ms), so a frame that needs more than two (33 ms) runs at 20 per second or less,
 *  and previews while drawing cannot be shown faster than frames are. On a software rasteriser
 *  the page's main thread waits for each frame's pixels, so a preview's answer waits behind the
 *  frame before it: a lighter frame (a sparser sample of the preview's strands) lets more
 *  previews through. */
const INTERACTIVE_FRAME_MS = 20;
const SLOW_FRAME_MS = 36;
const FAST_FRAME_MS = 15;
/** While a stroke's preview is on its way, frames that would redraw only the overlays (the stroke
 *  line) wait for it this long at most, on a software rasteriser (frameCache.ts OverlayWait: a
 *  frame there holds the page's main thread for 25-35 ms). */
const OVERLAY_WAIT_MS = 50;
/** Resolution of interactive frames that stay slow with little hair, relative to the display. */
const INTERACTIVE_RESOLUTION = 0.5;
/** Index entries (2 per segment) an interactive frame may always draw: ~270 strands of the
 *  final hair's lines; fewer entries when MIN_HAIR_STRANDS strands need fewer (a stroke's
 *  previews are drawn with every other point: the same strands for half the entries). */
const MIN_HAIR_BUDGET = 30_000;
const MIN_HAIR_STRANDS = 270;
/** Hair budget before any frame was measured on a software rasteriser (a first look of 6,000
 *  strands drawn whole took ~1 s there). */
const SOFTWARE_INITIAL_BUDGET = 2 * MIN_HAIR_BUDGET;
/** Frames between a settled view drawn at interactive detail and its full-detail frame: the
 *  former is presented (with whatever the page changed meanwhile) before the latter's GPU work. */
const FULL_DETAIL_DELAY_FRAMES = 1;
/** Duration of resetView's animation. */
const RESET_VIEW_MS = 450;

export { type FrameMode, frameDetail } from './frameCache';

export class Viewer {
  readonly renderer: THREE.WebGLRenderer;
  readonly scene = new THREE.Scene();
  readonly camera: THREE.PerspectiveCamera;
  readonly controls: OrbitControls;
  private readonly hairGroup = new THREE.Group();
  private readonly curveGroup = new THREE.Group();
  /** Display overlays (constraints, field, box, surface): owned by their display modules. */
  private readonly displayGroup = new THREE.Group();
  private readonly guideGroup = new THREE.Group();
  private draft: THREE.Object3D | null = null;
  private hair: THREE.LineSegments | THREE.Mesh | null = null;
  private dirty = true;
  /** Overlay-only frames waiting for hair on its way (expectHair). */
  private readonly overlayWait = new OverlayWait(OVERLAY_WAIT_MS);
  /** WebGL runs on a software rasteriser (no GPU). */
  readonly software: boolean;
  /** The unmasked WebGL renderer (WEBGL_debug_renderer_info), or the masked one without it. */
  readonly rendererName: string;
  /** Reasons the view is interactive now (e.g. 'orbit', 'stroke', 'settling'). */
  private readonly holds = new Set<string>();
  /** Hair index count an interactive frame may draw (until a slow frame is seen: Infinity on a
   *  GPU, SOFTWARE_INITIAL_BUDGET on a software rasteriser). */
  private hairBudget: number;
  private lastRender: { time: number; drawn: number } | null = null;
  private lastDetail = 1;
  private frameHooks: Array<() => void> = [];
  /** Called after each rendered frame (e.g. to count displayed hair revisions). */
  onRendered: (() => void) | null = null;
  /** The settled view was drawn at interactive detail; its full-detail frame is still to come
   *  (in fullDetailWait more frames). */
  private fullDetailOwed = false;
  private fullDetailWait = 0;
  /** The hair object the last rendered frame drew (null: none yet). */
  private shownHair: THREE.Object3D | null = null;
  private readonly hairShownListeners = new Set<(hair: THREE.Object3D) => void>();
  /** User orbit speed (1 = default: ORBIT_DEGREES_PER_WIDTH across the view). */
  private orbitFactor = 1;
  /** The camera resetView returns to. */
  private homeView: CameraView = {
    position: [...DEFAULT_CAMERA.position],
    target: [...DEFAULT_CAMERA.target],
  };
  private viewAnimation: { from: CameraView; to: CameraView; start: number; ms: number } | null =
    null;
  /** The frame cache (frameCache.ts): its slots (made with the first frame) and what each holds. */
  private slots: FrameSlots | null = null;
  private staticKey: LayerKey | null = null;
  private hairKey: HairKey | null = null;
  /** Bumped by invalidateFrameCache: changes the slots' stamps cannot see (uniforms). */
  private cacheEpoch = 0;
  /** Frames are drawn through the frame cache when it is available (false: every frame is
   *  drawn whole, as before it existed; a test and benchmark switch). */
  frameCacheEnabled = true;
  /** Where the last frame started from (frameCache.ts FrameSource). */
  private lastSource: FramePlan['source'] = 'none';
  /** Frames drawn so far, by where each started from (a benchmark probe). */
  readonly frameSources: Record<FramePlan['source'], number> = { hair: 0, static: 0, none: 0 };

  constructor(readonly canvas: HTMLCanvasElement) {
    // Multisampling costs ~2x per frame on a software rasteriser (SwiftShader, llvmpipe), where
    // frame time, not the solver, bounds interactivity: it is on only for a hardware GPU.
    this.rendererName = glRendererName();
    this.software = /swiftshader|llvmpipe|softpipe|software/i.test(this.rendererName);
    this.hairBudget = this.software ? SOFTWARE_INITIAL_BUDGET : Number.POSITIVE_INFINITY;
    this.renderer = new THREE.WebGLRenderer({
      canvas,
      antialias: !this.software,
      preserveDrawingBuffer: true,
    });
    this.renderer.setPixelRatio(basePixelRatio());
    this.renderer.setClearColor(0xe9edf2, 1);
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.05, 100);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = false;
    this.controls.minDistance = 2;
    this.controls.maxDistance = 25;
    this.controls.addEventListener('change', () => this.requestRender());
    this.controls.addEventListener('start', () => {
      this.stopViewAnimation(); // the user takes the camera
      this.hold('orbit', true);
    });
    this.controls.addEventListener('end', () => this.hold('orbit', false));
    this.setCamera(DEFAULT_CAMERA.position, DEFAULT_CAMERA.target);

    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x6b5d52, 1.4));
    const key = new THREE.DirectionalLight(0xffffff, 1.6);
    key.position.set(...KEY_LIGHT_POSITION); // fixed in world space: the hair's lighting is precomputed
    this.scene.add(key);
    const rim = new THREE.DirectionalLight(0xbfd4ff, 0.6);
    rim.position.set(-4, 2, -3);
    this.scene.add(rim);
    this.scene.add(this.hairGroup, this.curveGroup, this.displayGroup, this.guideGroup);

    new ResizeObserver(() => this.resize()).observe(canvas);
    this.resize();
    const loop = (now: number) => {
      // the frame after a rendered one shows what that frame cost (the browser throttles frames
      // while the GPU is behind)
      if (this.lastRender) this.adaptBudget(now - this.lastRender.time, this.lastRender.drawn);
      this.lastRender = null;
      this.stepViewAnimation(now);
      for (const hook of this.frameHooks) hook();
      if (this.dirty) {
        this.dirty = !this.renderFrame(now, this.holds.size > 0 ? 'interactive' : 'settled');
      } else if (this.fullDetailOwed && this.holds.size === 0 && this.fullDetailWait-- <= 0) {
        this.renderFrame(now, 'full');
      }
      requestAnimationFrame(loop);
    };
    requestAnimationFrame(loop);
  }

  /** Draws the scene. 'interactive': the hair at interactive detail; 'settled': all of it when a
   *  frame can afford it, else interactive detail now and all of it FULL_DETAIL_DELAY_FRAMES
   *  frames later ('full'). Through the frame cache, only what changed since the cached layers
   *  were drawn is drawn again. Returns false when the frame waits for hair on its way (only
   *  overlays would be drawn, before the time expectHair allowed). */
  private renderFrame(now: number, mode: FrameMode): boolean {
    const { all, interactive } = this.hairCounts();
    const keys = this.layerKeys();
    const plan = this.planFor(mode, all, interactive, keys);
    if (this.overlayWait.waits(plan, mode, now)) return false;
    this.fullDetailOwed = plan.fullDetailNext;
    if (plan.fullDetailNext) this.fullDetailWait = FULL_DETAIL_DELAY_FRAMES;
    this.lastDetail = all > 0 ? plan.count / all : 1;
    const source = this.draw(plan, all, keys, true);
    this.lastSource = source;
    this.frameSources[source]++;
    // a frame that drew no hair says nothing about what hair costs
    this.lastRender = { time: now, drawn: source === 'hair' ? -1 : plan.count };
    this.onRendered?.();
    const hair = this.hairGroup.children[0] ?? null;
    if (hair !== this.shownHair) {
      this.shownHair = hair;
      if (hair) for (const cb of [...this.hairShownListeners]) cb(hair);
    }
    return true;
  }

  /** New hair is on its way (a stroke's preview was asked for): on a software rasteriser, frames
   *  that would only redraw the overlays wait for it, up to OVERLAY_WAIT_MS from the first ask
   *  that found no wait running (so the stroke line still moves when previews are slow).
   *  expectHair(false): nothing is on its way (the stroke ended); frames no longer wait. */
  expectHair(on = true): void {
    if (!on) this.overlayWait.cancel();
    else if (this.software) this.overlayWait.expect(performance.now());
  }

  /** Whether frames go through the frame cache (on, and the canvas allows copies). */
  get frameCacheActive(): boolean {
    this.slots ??= new FrameSlots(this.renderer);
    return this.frameCacheEnabled && this.slots.available;
  }

  /** Where the last frame started from: 'hair' (only overlays drawn), 'static' (hair and
   *  overlays drawn over the cached head) or 'none' (drawn whole). */
  get lastFrameSource(): FramePlan['source'] {
    return this.lastSource;
  }

  /** Forgets the cached layers: for changes the cache cannot see for itself (a uniform of the
   *  hair's or the head's material). Camera, size, the head's geometry and material versions and
   *  the hair object are checked every frame. Requests a frame. */
  invalidateFrameCache(): void {
    this.cacheEpoch++;
    this.requestRender();
  }

  /** What the cached layers must match: the view, the static part's stamp, the hair's. */
  private layerKeys(): { layer: LayerKey; hair: string } {
    this.camera.updateMatrixWorld();
    const size = this.renderer.getDrawingBufferSize(new THREE.Vector2());
    const statics = this.scene.children.filter((c) => this.layerOf(c) === 'static');
    return {
      layer: {
        view: viewKey(
          this.camera.matrixWorld.elements,
          this.camera.projectionMatrix.elements,
          size.x,
          size.y,
        ),
        scene: `${this.cacheEpoch}|${drawableStamp(statics)}`,
      },
      hair: drawableStamp([this.hairGroup]),
    };
  }

  private planFor(
    mode: FrameMode,
    all: number,
    interactive: number,
    keys: { layer: LayerKey; hair: string },
  ): FramePlan {
    if (!this.frameCacheActive) return planFrame(mode, all, interactive, false, null);
    const cachedHair =
      this.hairKey && sameLayer(this.hairKey, keys.layer) && this.hairKey.hair === keys.hair
        ? this.hairKey.count
        : null;
    return planFrame(mode, all, interactive, sameLayer(this.staticKey, keys.layer), cachedHair);
  }

  private layerOf(o: THREE.Object3D): 'static' | 'hair' | 'overlay' | 'light' {
    if (o === this.hairGroup) return 'hair';
    if (
      o === this.curveGroup ||
      o === this.displayGroup ||
      o === this.guideGroup ||
      o === this.draft
    )
      return 'overlay';
    return o instanceof THREE.Light ? 'light' : 'static';
  }

  /** Draws the scene's objects of the given layers (lights always stay: hiding one would change
   *  the lit materials' programs). */
  private renderLayers(layers: ReadonlyArray<'static' | 'hair' | 'overlay'>): void {
    const hidden: THREE.Object3D[] = [];
    for (const c of this.scene.children) {
      const layer = this.layerOf(c);
      if (layer === 'light' || layers.includes(layer) || !c.visible) continue;
      c.visible = false;
      hidden.push(c);
    }
    try {
      this.renderer.render(this.scene, this.camera);
    } finally {
      for (const c of hidden) c.visible = true;
    }
  }

  /** Draws a frame as `plan` says, into the canvas; `save`: keep the layers drawn in the cache.
   *  Returns where the frame started from (a cached slot, or 'none'). */
  private draw(
    plan: FramePlan,
    all: number,
    keys: { layer: LayerKey; hair: string },
    save: boolean,
  ): FramePlan['source'] {
    const r = this.renderer;
    if (this.hair && all > 0 && plan.source !== 'hair')
      this.hair.geometry.setDrawRange(0, plan.count);
    if (!this.frameCacheActive || !this.slots) {
      r.render(this.scene, this.camera);
      return 'none';
    }
    const slots = this.slots;
    const size = r.getDrawingBufferSize(new THREE.Vector2());
    let source = plan.source;
    if (source !== 'none' && !slots.copy(source, 'restore', size.x, size.y)) source = 'none';
    if (source === 'none' && plan.source === 'hair' && this.hair && all > 0)
      this.hair.geometry.setDrawRange(0, plan.count);
    const autoClear = r.autoClear;
    try {
      if (source === 'none') {
        r.autoClear = true;
        this.renderLayers(['static']);
        if (save && slots.copy('static', 'save', size.x, size.y)) this.staticKey = keys.layer;
      }
      r.autoClear = false;
      if (source !== 'hair') {
        this.renderLayers(['hair']);
        if (save && slots.copy('hair', 'save', size.x, size.y))
          this.hairKey = { ...keys.layer, hair: keys.hair, count: plan.count };
      }
      this.renderLayers(['overlay']);
    } finally {
      r.autoClear = autoClear;
    }
    return source;
  }

  /** Test probe: the current view drawn through the frame cache (starting from the slot the next
   *  frame would use, or from the static slot with `from` = 'static') and drawn whole in one pass,
   *  both with the same hair detail; RGBA pixels of the drawing buffer, rows bottom-up. Caches
   *  nothing; a normal frame follows. */
  compareFrames(from?: 'static'): {
    width: number;
    height: number;
    source: FramePlan['source'];
    count: number;
    cached: Uint8Array;
    full: Uint8Array;
  } {
    const { all, interactive } = this.hairCounts();
    const keys = this.layerKeys();
    let plan = this.planFor(
      this.holds.size > 0 ? 'interactive' : 'settled',
      all,
      interactive,
      keys,
    );
    if (from === 'static' && plan.source === 'hair') {
      const staticValid = this.frameCacheActive && sameLayer(this.staticKey, keys.layer);
      plan = { ...plan, source: staticValid ? 'static' : 'none' };
    }
    const size = this.renderer.getDrawingBufferSize(new THREE.Vector2());
    const gl = this.renderer.getContext();
    const read = (): Uint8Array => {
      const px = new Uint8Array(4 * size.x * size.y);
      gl.readPixels(0, 0, size.x, size.y, gl.RGBA, gl.UNSIGNED_BYTE, px);
      return px;
    };
    const source = this.draw(plan, all, keys, false);
    const cached = read();
    if (this.hair && all > 0) this.hair.geometry.setDrawRange(0, plan.count);
    this.renderer.render(this.scene, this.camera);
    const full = read();
    this.requestRender();
    return { width: size.x, height: size.y, source, count: plan.count, cached, full };
  }

  /** Calls `cb` with each hair object (as given to setHair) once the first frame that draws it
   *  has been rendered, at whatever detail; DOM changes made in `cb` are painted with that frame.
   *  Returns a function that removes the listener. */
  onHairShown(cb: (hair: THREE.Object3D) => void): () => void {
    this.hairShownListeners.add(cb);
    return () => this.hairShownListeners.delete(cb);
  }

  /** Whether `hair` (as given to setHair) has been on screen. */
  hairShown(hair: THREE.Object3D): boolean {
    return this.shownHair === hair;
  }

  /** The settled view has been drawn at interactive detail and its full-detail frame is still to
   *  come (a frame or two; that frame may take seconds on a software rasteriser). */
  get fullDetailPending(): boolean {
    return this.fullDetailOwed;
  }

  /** Runs `hook` once per animation frame, before rendering. */
  onFrame(hook: () => void): void {
    this.frameHooks.push(hook);
  }

  requestRender(): void {
    this.dirty = true;
  }

  /** Marks the view interactive for `reason` (or not): hair is drawn at interactive detail
   *  while any reason holds, and in full once none does. */
  hold(reason: string, on: boolean): void {
    const had = this.holds.size > 0;
    if (on) this.holds.add(reason);
    else this.holds.delete(reason);
    if (had !== this.holds.size > 0) {
      if (!on) this.setResolutionScale(1); // the settled view in full resolution
      this.requestRender();
    }
  }

  /** Drawing-buffer resolution relative to the display's (interactive frames may lower it). */
  private resolutionScale = 1;

  private setResolutionScale(scale: number): void {
    if (scale === this.resolutionScale) return;
    this.resolutionScale = scale;
    this.renderer.setPixelRatio(basePixelRatio() * scale);
  }

  /** Fraction of the hair's segments the last frame drew (1 = all). */
  get hairDetail(): number {
    return this.lastDetail;
  }

  /** Fraction of the current hair an interactive frame draws (1 when the GPU keeps up). */
  get interactiveDetail(): number {
    const lod = this.hair?.geometry.userData.lodCounts as Uint32Array | undefined;
    const all = lod ? lod[lod.length - 1] : 0;
    return all > 0 ? Math.min(1, this.hairBudget / all) : 1;
  }

  /** Index counts of the current hair: all of it, and the prefix an interactive frame draws. */
  private hairCounts(): { all: number; interactive: number } {
    const lod = this.hair?.geometry.userData.lodCounts as Uint32Array | undefined;
    if (!lod || lod.length === 0) return { all: 0, interactive: 0 }; // drawn whole, as given
    const all = lod[lod.length - 1];
    let interactive = all;
    if (this.hairBudget < all) {
      let g = 1;
      while (g + 1 < lod.length && lod[g + 1] <= this.hairBudget) g++;
      interactive = lod[Math.min(g, lod.length - 1)];
    }
    return { all, interactive };
  }

  /** The hair budget's floor for the current hair: MIN_HAIR_BUDGET, or MIN_HAIR_STRANDS of its
   *  strands when they take fewer index entries. */
  private minHairBudget(): number {
    const lod = this.hair?.geometry.userData.lodCounts as Uint32Array | undefined;
    const strands = this.hair?.geometry.userData.strands as number | undefined;
    if (!lod || lod.length === 0 || !strands) return MIN_HAIR_BUDGET;
    return Math.min(MIN_HAIR_BUDGET, (MIN_HAIR_STRANDS * lod[lod.length - 1]) / strands);
  }

  private adaptBudget(frameMs: number, drawn: number): void {
    if (drawn < 0) return; // the frame drew no hair (the cached hair layer)
    const floor = this.minHairBudget();
    // Interactive frames still slow with the hair at its floor: the cost is per pixel (a software
    // rasteriser, a large screen), so draw them at half resolution until the view settles.
    if (
      this.holds.size > 0 &&
      frameMs > SLOW_FRAME_MS &&
      (drawn <= floor || this.hairBudget <= floor)
    )
      this.setResolutionScale(INTERACTIVE_RESOLUTION);
    if (drawn <= 0) return;
    if (frameMs > SLOW_FRAME_MS) {
      // cost scales with segments drawn: aim at the interactive frame time
      // (never below a floor: part of a slow frame is not the hair's, e.g. a busy CPU)
      this.hairBudget = Math.max(floor, (drawn * INTERACTIVE_FRAME_MS) / frameMs);
    } else if (frameMs < FAST_FRAME_MS && drawn >= this.hairBudget * 0.5) {
      this.hairBudget = this.hairBudget * 1.5;
    }
  }

  get renderPending(): boolean {
    return this.dirty;
  }

  setCamera(position: Vec3, target: Vec3): void {
    this.stopViewAnimation();
    this.placeCamera(position, target);
  }

  private placeCamera(position: Vec3, target: Vec3): void {
    this.camera.position.set(...position);
    this.controls.target.set(...target);
    this.controls.update();
    this.requestRender();
  }

  /** Returns the camera to the default framing of the head (DEFAULT_CAMERA, the view at load, or
   *  the one given to setHomeView): animated over ~0.45 s unless `animate` is false. Orbiting,
   *  setCamera or another resetView during the animation takes over from it. */
  resetView(animate = true): void {
    const to: CameraView = {
      position: [...this.homeView.position],
      target: [...this.homeView.target],
    };
    this.stopViewAnimation();
    if (!animate) {
      this.placeCamera(to.position, to.target);
      return;
    }
    this.viewAnimation = { from: this.cameraState(), to, start: -1, ms: RESET_VIEW_MS };
    this.hold('view-animation', true); // interactive detail while the camera moves
    this.requestRender();
  }

  /** Sets the framing resetView returns to (default: DEFAULT_CAMERA). */
  setHomeView(position: Vec3, target: Vec3): void {
    this.homeView = { position: [...position], target: [...target] };
  }

  /** Whether resetView's animation is running. */
  get viewAnimating(): boolean {
    return this.viewAnimation !== null;
  }

  private stepViewAnimation(now: number): void {
    const a = this.viewAnimation;
    if (!a) return;
    if (a.start < 0) a.start = now;
    const t = a.ms > 0 ? (now - a.start) / a.ms : 1;
    const v = interpolateView(a.from, a.to, easeInOut(t));
    this.placeCamera(v.position, v.target);
    if (t >= 1) this.stopViewAnimation();
  }

  private stopViewAnimation(): void {
    if (!this.viewAnimation) return;
    this.viewAnimation = null;
    this.hold('view-animation', false);
  }

  /** Orbit speed relative to the default (1: a drag across the whole view turns the head
   *  ORBIT_DEGREES_PER_WIDTH = 180°; 2 turns it twice as far). Non-positive or non-finite
   *  factors count as 1. */
  setOrbitSpeed(factor: number): void {
    this.orbitFactor = Number.isFinite(factor) && factor > 0 ? factor : 1;
    this.applyOrbitSpeed();
  }

  get orbitSpeed(): number {
    return this.orbitFactor;
  }

  private applyOrbitSpeed(): void {
    this.controls.rotateSpeed = orbitRotateSpeed(
      this.canvas.clientWidth,
      this.canvas.clientHeight,
      this.orbitFactor,
    );
  }

  cameraState(): { position: Vec3; target: Vec3 } {
    const p = this.camera.position;
    const t = this.controls.target;
    return { position: [p.x, p.y, p.z], target: [t.x, t.y, t.z] };
  }

  addHead(mesh: THREE.Object3D): void {
    this.scene.add(mesh);
    this.requestRender();
  }

  /** Replaces the displayed hair. */
  setHair(object: THREE.Object3D | null): void {
    for (const child of [...this.hairGroup.children]) {
      this.hairGroup.remove(child);
      disposeObject(child);
    }
    if (object) this.hairGroup.add(object);
    this.hair =
      object instanceof THREE.LineSegments || object instanceof THREE.Mesh ? object : null;
    this.requestRender();
  }

  /** Shows the style curves, each in its type's colour (overlayStyle.ts OVERLAY_RGB) and the
   *  selected one highlighted and drawn over the others. */
  setCurves(curves: readonly CurveView[], selectedId: string | null): void {
    clearGroup(this.curveGroup);
    for (const c of curves) {
      if (c.points.length < 2) continue;
      const selected = c.id === selectedId;
      const line = overlayPolyline(
        c.points,
        curveRgb(c.type, selected),
        selected ? OVERLAY_ORDER.selected : OVERLAY_ORDER.visible,
        selected ? SELECTED_HIDDEN_OPACITY : HIDDEN_OPACITY,
      );
      line.userData.curveId = c.id;
      this.curveGroup.add(line);
    }
    this.requestRender();
  }

  /** Shows or hides the style curves (the draft stroke is always shown). */
  setCurvesVisible(on: boolean): void {
    if (this.curveGroup.visible === on) return;
    this.curveGroup.visible = on;
    this.requestRender();
  }

  /** Adds (on) or removes a display object. The caller owns it: it is never disposed here, and
   *  calls requestRender after changing it while shown. */
  showDisplay(object: THREE.Object3D, on: boolean): void {
    const shown = object.parent === this.displayGroup;
    if (on === shown) return;
    if (on) this.displayGroup.add(object);
    else this.displayGroup.remove(object);
    this.requestRender();
  }

  /** Construction lines (e.g. a ponytail's strokes and circles), in the ponytail guide colour. */
  setGuides(lines: readonly (readonly Vec3[])[]): void {
    clearGroup(this.guideGroup);
    for (const l of lines)
      if (l.length >= 2) this.guideGroup.add(overlayPolyline(l, OVERLAY_RGB.ponytailGuide));
    this.requestRender();
  }

  /** The stroke being drawn (null: none), in the draft colour, over the curves. With `endsHair`
   *  a bar across its last point marks where the hair it governs will end. */
  setDraft(points: readonly Vec3[] | null, endsHair = false): void {
    if (this.draft) {
      this.scene.remove(this.draft);
      disposeObject(this.draft);
      this.draft = null;
    }
    if (points && points.length >= 2) {
      const group = new THREE.Group();
      group.add(overlayPolyline(points, OVERLAY_RGB.draft, OVERLAY_ORDER.draft));
      const bar = endsHair ? endBar(points, this.viewForward()) : null;
      if (bar) group.add(overlayPolyline(bar, OVERLAY_RGB.draft, OVERLAY_ORDER.draft));
      this.draft = group;
      this.scene.add(this.draft);
    }
    this.requestRender();
  }

  /** Ray through client coordinates. */
  rayAt(clientX: number, clientY: number): THREE.Ray {
    const rect = this.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(
      ((clientX - rect.left) / rect.width) * 2 - 1,
      -((clientY - rect.top) / rect.height) * 2 + 1,
    );
    const rc = new THREE.Raycaster();
    rc.setFromCamera(ndc, this.camera);
    return rc.ray;
  }

  /** Client coordinates of a world point, or null when it is behind the camera or off screen. */
  worldToScreen(p: Vec3): { x: number; y: number } | null {
    const v = new THREE.Vector3(...p).project(this.camera);
    if (v.z < -1 || v.z > 1 || Math.abs(v.x) > 1 || Math.abs(v.y) > 1) return null;
    const rect = this.canvas.getBoundingClientRect();
    return {
      x: rect.left + ((v.x + 1) / 2) * rect.width,
      y: rect.top + ((1 - v.y) / 2) * rect.height,
    };
  }

  viewForward(): Vec3 {
    const f = new THREE.Vector3();
    this.camera.getWorldDirection(f);
    return [f.x, f.y, f.z];
  }

  /** The current view as a PNG at `scale` × the canvas's resolution, with every strand drawn
   *  (not the level-of-detail sample), on a transparent background when asked. Rendered into a
   *  half-float target and encoded to sRGB here (a render target is drawn in linear light). */
  async captureImage(opts: { scale?: number; transparent?: boolean } = {}): Promise<Blob> {
    const scale = opts.scale ?? 2;
    const ratio = basePixelRatio() * scale;
    const w = Math.max(1, Math.round(this.canvas.clientWidth * ratio));
    const h = Math.max(1, Math.round(this.canvas.clientHeight * ratio));
    const r = this.renderer;
    const half = r.extensions.has('EXT_color_buffer_float');
    const rt = new THREE.WebGLRenderTarget(w, h, {
      type: half ? THREE.HalfFloatType : THREE.UnsignedByteType,
      samples: this.software ? 0 : 4,
    });
    const clear = new THREE.Color();
    r.getClearColor(clear);
    const clearAlpha = r.getClearAlpha();
    const { all } = this.hairCounts();
    const pixels = half ? new Uint16Array(4 * w * h) : new Uint8Array(4 * w * h);
    try {
      if (this.hair && all > 0) this.hair.geometry.setDrawRange(0, all);
      if (opts.transparent) r.setClearColor(clear, 0);
      r.setRenderTarget(rt);
      r.render(this.scene, this.camera);
      r.readRenderTargetPixels(rt, 0, 0, w, h, pixels);
    } finally {
      r.setRenderTarget(null);
      r.setClearColor(clear, clearAlpha);
      rt.dispose();
      this.requestRender();
    }
    const out = new Uint8ClampedArray(4 * w * h);
    const channel = half
      ? (k: number) => THREE.DataUtils.fromHalfFloat((pixels as Uint16Array)[k])
      : (k: number) => (pixels as Uint8Array)[k] / 255;
    for (let y = 0; y < h; y++) {
      const src = (h - 1 - y) * w * 4; // rows come bottom-up
      const dst = y * w * 4;
      for (let x = 0; x < 4 * w; x += 4) {
        for (let c = 0; c < 3; c++) out[dst + x + c] = 255 * linearToSrgb(channel(src + x + c));
        out[dst + x + 3] = 255 * Math.min(1, Math.max(0, channel(src + x + 3)));
      }
    }
    const canvas = document.createElement('canvas');
    canvas.width = w;
    canvas.height = h;
    const ctx = canvas.getContext('2d');
    if (!ctx) throw new Error('this browser cannot draw images (no 2D canvas)');
    ctx.putImageData(new ImageData(out, w, h), 0, 0);
    return new Promise((resolve, reject) =>
      canvas.toBlob(
        (b) => (b ? resolve(b) : reject(new Error('PNG encoding failed'))),
        'image/png',
      ),
    );
  }

  /** Benchmark probe: draws the current view once with every strand and returns its time in
   *  ms, GPU work included (a one-pixel read before and after waits for the GPU). */
  measureFrame(): number {
    const { all } = this.hairCounts();
    const gl = this.renderer.getContext();
    const px = new Uint8Array(4);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
    const t0 = performance.now();
    if (this.hair && all > 0) this.hair.geometry.setDrawRange(0, all);
    this.renderer.render(this.scene, this.camera);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
    const ms = performance.now() - t0;
    this.requestRender();
    return ms;
  }

  eye(): Vec3 {
    const p = this.camera.position;
    return [p.x, p.y, p.z];
  }

  private resize(): void {
    const w = Math.max(1, this.canvas.clientWidth);
    const h = Math.max(1, this.canvas.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.applyOrbitSpeed(); // degrees per px follow the view's size
    this.requestRender();
  }
}

function linearToSrgb(v: number): number {
  const c = Math.min(1, Math.max(0, v));
  return c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055;
}

function basePixelRatio(): number {
  return Math.min(window.devicePixelRatio || 1, 2);
}

/** The unmasked renderer string of a probe context (released at once): tells a software
 *  rasteriser from a GPU. */
function glRendererName(): string {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return '';
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return name;
}

function clearGroup(group: THREE.Group): void {
  for (const child of [...group.children]) {
    group.remove(child);
    disposeObject(child);
  }
}

/** Frees an object's geometry (once, also when shared with its hidden-pass twin); materials are
 *  the owner's (shared, reused across objects). */
function disposeObject(o: THREE.Object3D): void {
  const done = new Set<THREE.BufferGeometry>();
  o.traverse((x) => {
    const g = (x as THREE.Mesh).geometry;
    if (g && !done.has(g)) {
      done.add(g);
      g.dispose();
    }
  });
}

/** Half-length (world units: 1.5 cm) of the bar that marks where a stroke's hair ends. */
const END_BAR_HALF = 0.15;

/** A short bar across the stroke's last point, square to its last segment and to the view
 *  (null when they are parallel). */
export function endBar(points: readonly Vec3[], forward: Vec3): Vec3[] | null {
  const a = points[points.length - 2];
  const b = points[points.length - 1];
  const t = new THREE.Vector3(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  const across = t.cross(new THREE.Vector3(...forward));
  if (!(across.length() > 1e-9)) return null;
  across.setLength(END_BAR_HALF);
  return [
    [b[0] - across.x, b[1] - across.y, b[2] - across.z],
    [b[0] + across.x, b[1] + across.y, b[2] + across.z],
  ];
}
