// The three.js view: head, hair strands, style curves, the stroke being drawn. Renders on demand,
// once per animation frame at most, and asks for no frames while idle. This file holds the frame
// schedule and the scene's content;
// the parts it delegates to:
//   cameraRig.ts          camera, orbit controls, reset-view animation, screen <-> world
//   hairLevelOfDetail.ts  how much of the hair an interactive frame draws (measured frame times)
//   layeredDrawing.ts     drawing a frame in layers through the frame cache (frameCache.ts)
//   overlayLayer.ts       style curves, the stroke being drawn, guides, display objects
//   viewCapture.ts        the view with every strand: PNG capture, timed frame
//   hairOit.ts            High's order-independent blending of the strips (drawLayers runs it)
//   viewerProbes.ts       test probes: frame cache against whole frames, blend order, depth
// While the user interacts (orbit, a stroke, hair still settling) the hair is drawn at the level
// of detail; a fast GPU always draws everything, a software rasteriser a sparse sample while
// things move, and the whole head of hair once they stop. When the view settles and the whole
// hair is more than an interactive frame can draw, the settled view is first drawn at interactive
// detail (that frame is when new hair is "shown": onHairShown), and the full-detail frame follows
// a frame later, so nothing waiting for the hair waits for it (a 30K-strand frame takes seconds
// on SwiftShader).
// Style curves, the draft stroke, guides and display glyphs are depth-tested against head and
// settled hair, and faint where hidden (overlayStyle.ts).
import * as THREE from 'three';
import type { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { KEY_LIGHT_POSITION } from '../lighting/keyLight';
import type { Vec3 } from '../model/vec3';
import { CameraRig } from './cameraRig';
import { DEFAULT_CAMERA } from './defaultCamera';
import { type FrameMode, type FramePlan, OverlayWait } from './frameCache';
import { HairLevelOfDetail, INTERACTIVE_RESOLUTION } from './hairLevelOfDetail';
import { LayeredDrawing, type LayeredScene } from './layeredDrawing';
import { type AppViewName, framedAppView } from './namedViews';
import { type CurveView, OverlayLayer } from './overlayLayer';
import { SliceSizer } from './progressiveHair';
import { basePixelRatio, glRendererName, isSoftwareRenderer } from './rendererProbe';
import { disposeObject } from './sceneObjects';
import { type CaptureSource, captureImage, measureFullFrame } from './viewCapture';
import { ViewerProbes } from './viewerProbes';

/** While a stroke's preview is on its way, frames that would redraw only the overlays (the stroke
 *  line) wait for it this long at most, on a software rasteriser (frameCache.ts OverlayWait: a
 *  frame there holds the page's main thread for 25-35 ms). */
const OVERLAY_WAIT_MS = 50;
/** Frames between a settled view drawn at interactive detail and its full-detail frame: the
 *  former is presented (with whatever the page changed meanwhile) before the latter's GPU work. */
const FULL_DETAIL_DELAY_FRAMES = 1;

export { type FrameMode, frameDetail } from './frameCache';
export type { CurveView } from './overlayLayer';
export { endBar } from './sceneObjects';

export class Viewer {
  readonly renderer: THREE.WebGLRenderer;
  readonly scene = new THREE.Scene();
  readonly camera: THREE.PerspectiveCamera;
  readonly controls: OrbitControls;
  private readonly rig: CameraRig;
  private readonly hairGroup = new THREE.Group();
  private readonly overlays = new OverlayLayer(this.scene, () => this.viewForward());
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
  /** Reasons every frame draws all of the hair (a motion playing: it moves in every frame, and a
   *  sample of it looks thin), whatever holds. */
  private readonly whole = new Set<string>();
  private readonly detail: HairLevelOfDetail;
  private readonly layers: LayeredDrawing;
  /** The scene's layers as drawLayers draws them (layeredDrawing.ts). */
  private readonly sceneLayers: LayeredScene;
  private lastRender: { time: number; drawn: number } | null = null;
  private lastDetail = 1;
  private frameHooks: Array<() => void> = [];
  private captureHooks: Array<() => void> = [];
  /** Called after each rendered frame (e.g. to count displayed hair revisions). */
  onRendered: (() => void) | null = null;
  /** Also called after each rendered frame (the view control's label follows the camera). */
  readonly renderedListeners = new Set<() => void>();
  /** Called when the camera starts easing to a view (resetView, showView), before its first frame:
   *  what is on screen is about to move. */
  readonly viewMovingListeners = new Set<() => void>();
  /** The settled view was drawn at interactive detail; its full-detail frame is still to come
   *  (in fullDetailWait more frames). */
  private fullDetailOwed = false;
  private fullDetailWait = 0;
  /** The size of each slice of the full-detail frame (renderFullInSlices). */
  private readonly slices = new SliceSizer();
  /** The hair object the last rendered frame drew (null: none yet). */
  private shownHair: THREE.Object3D | null = null;
  private readonly hairShownListeners = new Set<(hair: THREE.Object3D) => void>();
  /** Where the last frame started from (frameCache.ts FrameSource). */
  private lastSource: FramePlan['source'] = 'none';
  /** Frames drawn so far, by where each started from (a benchmark probe). */
  readonly frameSources: Record<FramePlan['source'], number> = { hair: 0, static: 0, none: 0 };
  /** Drawing-buffer resolution relative to the display's (interactive frames may lower it), and
   *  how many times it changed (each change redraws the cached layers: a test probe). */
  private resolutionScale = 1;
  resolutionChanges = 0;
  /** Objects left out of captures (addBackdrop). */
  private readonly backdrops: THREE.Object3D[] = [];
  /** Test and benchmark probes of the drawing (viewerProbes.ts). */
  readonly probes: ViewerProbes;

  constructor(readonly canvas: HTMLCanvasElement) {
    // Multisampling costs ~2x per frame on a software rasteriser (SwiftShader, llvmpipe), where
    // frame time, not the solver, bounds interactivity: it is on only for a hardware GPU.
    this.rendererName = glRendererName();
    this.software = isSoftwareRenderer(this.rendererName);
    this.detail = new HairLevelOfDetail(this.software);
    this.renderer = new THREE.WebGLRenderer({
      canvas,
      antialias: !this.software,
      preserveDrawingBuffer: true,
    });
    this.renderer.setPixelRatio(basePixelRatio());
    this.renderer.setClearColor(0xe9edf2, 1);
    this.rig = new CameraRig(canvas, DEFAULT_CAMERA, this);
    this.camera = this.rig.camera;
    this.controls = this.rig.controls;
    this.sceneLayers = {
      renderer: this.renderer,
      scene: this.scene,
      camera: this.camera,
      hairGroup: this.hairGroup,
      hair: () => this.hair,
      isOverlay: (o) => this.overlays.holds(o),
    };
    this.layers = new LayeredDrawing(this.sceneLayers);
    this.probes = new ViewerProbes({
      layers: this.layers,
      scene: this.sceneLayers,
      slices: this.slices,
      counts: () => this.detail.counts(this.hair),
      mode: () => this.frameMode(),
      lastSource: () => this.lastSource,
      requestRender: () => this.requestRender(),
    });

    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x6b5d52, 1.4));
    const key = new THREE.DirectionalLight(0xffffff, 1.6);
    key.position.set(...KEY_LIGHT_POSITION); // fixed in world space: the hair's lighting is precomputed
    this.scene.add(key);
    const rim = new THREE.DirectionalLight(0xbfd4ff, 0.6);
    rim.position.set(-4, 2, -3);
    this.scene.add(rim);
    this.scene.add(this.hairGroup, ...this.overlays.groups);

    new ResizeObserver(() => this.resize()).observe(canvas);
    this.resize();
    this.scheduleFrame();
  }

  // ---- frame schedule ------------------------------------------------------------------------

  /** An animation frame is asked for and has not run yet. */
  private frameScheduled = false;

  /** Asks for an animation frame unless one is on its way. Frames run only while there is
   *  something to do (see needsFrame): an idle view asks the browser for none. */
  private scheduleFrame(): void {
    if (this.frameScheduled) return;
    this.frameScheduled = true;
    requestAnimationFrame(this.frame);
  }

  /** Whether the next animation frame has work: a frame to draw (or one waiting for hair), the
   *  full-detail frame owed, the view interactive (a stroke, an orbit, the camera animating,
   *  hair settling: the active tool's update() runs each frame), or the cost of the frame just
   *  drawn still to be measured (at the next frame). */
  private needsFrame(): boolean {
    return this.dirty || this.fullDetailOwed || this.holds.size > 0 || this.lastRender !== null;
  }

  private readonly frame = (now: number): void => {
    this.frameScheduled = false;
    // the frame after a rendered one shows what that frame cost (the browser throttles frames
    // while the GPU is behind)
    if (this.lastRender) this.adaptDetail(now - this.lastRender.time, this.lastRender.drawn);
    this.lastRender = null;
    this.rig.stepViewAnimation(now);
    for (const hook of this.frameHooks) hook();
    if (this.dirty) {
      this.dirty = !this.renderFrame(now, this.frameMode());
    } else if (this.fullDetailOwed && this.holds.size === 0 && this.fullDetailWait-- <= 0) {
      this.renderFullInSlices(now);
    }
    if (this.needsFrame()) this.scheduleFrame();
  };

  /** Draws the scene. 'interactive': the hair at interactive detail; 'settled': all of it when a
   *  frame can afford it, else interactive detail now and all of it FULL_DETAIL_DELAY_FRAMES
   *  frames later ('full'). Through the frame cache, only what changed since the cached layers
   *  were drawn is drawn again. Returns false when the frame waits for hair on its way (only
   *  overlays would be drawn, before the time expectHair allowed). */
  private renderFrame(now: number, mode: FrameMode): boolean {
    this.slices.interrupt();
    const { all, interactive } = this.detail.counts(this.hair);
    const keys = this.layers.keys();
    const plan = this.layers.plan(mode, all, interactive, keys);
    if (this.overlayWait.holds(plan, mode, now, keys.hair)) return false;
    this.fullDetailOwed = plan.fullDetailNext;
    if (plan.fullDetailNext) this.fullDetailWait = FULL_DETAIL_DELAY_FRAMES;
    this.lastDetail = all > 0 ? plan.count / all : 1;
    // a stroke's preview is not kept in the cache: the next one replaces it (OverlayWait)
    const source = this.layers.draw(plan, all, keys, true, !this.overlayWait.previewing);
    this.overlayWait.drew(source, keys.hair);
    this.lastSource = source;
    this.frameSources[source]++;
    // a frame that drew no hair says nothing about what hair costs
    this.lastRender = { time: now, drawn: source === 'hair' ? -1 : plan.count };
    this.onRendered?.();
    for (const cb of this.renderedListeners) cb();
    const hair = this.hairGroup.children[0] ?? null;
    if (hair !== this.shownHair) {
      this.shownHair = hair;
      if (hair) for (const cb of [...this.hairShownListeners]) cb(hair);
    }
    return true;
  }

  /** The full-detail frame owed, a slice of the hair a frame (layeredDrawing.ts
   *  drawWholeInSlices): the page stays responsive while a software rasteriser draws it, and
   *  any frame that must be drawn first (an orbit, new hair) comes first (slice sizes:
   *  progressiveHair.ts SliceSizer). */
  private renderFullInSlices(now: number): void {
    const { all } = this.detail.counts(this.hair);
    const keys = this.layers.keys();
    if (!this.layers.active) {
      this.renderFrame(now, 'full');
      return;
    }
    const count = this.slices.next(now, all);
    const step = this.layers.drawWholeInSlices(all, keys, count);
    if (step === 'wait') return;
    this.slices.drew(now, count, step);
    if (step === 'whole') this.renderFrame(now, 'full');
    if (step !== 'done') return;
    this.fullDetailOwed = false;
    this.lastDetail = 1;
    this.lastSource = 'static';
    this.frameSources.static++;
    this.onRendered?.();
    for (const cb of this.renderedListeners) cb();
  }

  /** New hair is on its way (a stroke's preview was asked for): on a software rasteriser, frames
   *  that would only redraw the overlays wait for it, up to OVERLAY_WAIT_MS from the first ask
   *  that found no wait running (so the stroke line still moves when previews are slow).
   *  expectHair(false): nothing is on its way (the stroke ended); frames no longer wait. */
  expectHair(on = true): void {
    this.overlayWait.previewing = on;
    if (!on) this.overlayWait.cancel();
    else if (this.software) this.overlayWait.expect(performance.now());
  }

  /** Forgets the cached layers: for changes the cache cannot see for itself (a uniform of the
   *  hair's or the head's material). Camera, size, the head's geometry and material versions and
   *  the hair object are checked every frame. Requests a frame. */
  invalidateFrameCache(): void {
    this.layers.invalidate();
    this.requestRender();
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

  /** Runs `hook` at the start of each animation frame the view runs (frames run while it has
   *  work: see needsFrame; requestRender asks for one). */
  onFrame(hook: () => void): void {
    this.frameHooks.push(hook);
  }

  /** Runs `hook` before a capture draws the view (captureImage): what a frame would have
   *  prepared first (the hair's deep opacity maps after a quality switch) is ready although no
   *  animation frame has run since. */
  onBeforeCapture(hook: () => void): void {
    this.captureHooks.push(hook);
  }

  requestRender(): void {
    this.dirty = true;
    this.scheduleFrame();
  }

  get renderPending(): boolean {
    return this.dirty;
  }

  /** Why the view is interactive (hair drawn at interactive detail): the reasons held. */
  get heldFor(): string[] {
    return [...this.holds];
  }

  /** Every how many points a playing motion draws each strand of the hair shown
   *  (hairLevelOfDetail.ts motionStride: 1 where frames can draw all of them). */
  motionPointStride(): number {
    return this.detail.motionStride(this.hair);
  }

  /** Every frame draws all of the hair while `reason` holds (drawWhole(reason, false) ends it). */
  drawWhole(reason: string, on: boolean): void {
    if (on) this.whole.add(reason);
    else this.whole.delete(reason);
    // on a software rasteriser a frame of every strand costs by the pixels its lines cover:
    // drawn at the interactive resolution while it moves, in full once it stops
    if (this.software) this.setResolutionScale(this.whole.size > 0 ? INTERACTIVE_RESOLUTION : 1);
    this.requestRender();
  }

  private frameMode(): FrameMode {
    if (this.whole.size > 0) return 'full';
    return this.holds.size > 0 ? 'interactive' : 'settled';
  }

  /** Marks the view interactive for `reason` (or not): hair is drawn at interactive detail
   *  while any reason holds, and in full once none does. */
  hold(reason: string, on: boolean): void {
    const had = this.holds.size > 0;
    if (on) this.holds.add(reason);
    else this.holds.delete(reason);
    // a stroke let go asks for no more previews, whichever tool drew it
    if (reason === 'stroke' && !on) this.overlayWait.previewing = false;
    this.scheduleFrame();
    if (had !== this.holds.size > 0) {
      // the settled view in full resolution (a playing motion keeps its own)
      if (!on && this.whole.size === 0) this.setResolutionScale(1);
      this.requestRender();
    }
  }

  private setResolutionScale(scale: number): void {
    if (scale === this.resolutionScale) return;
    this.resolutionScale = scale;
    this.resolutionChanges++;
    this.renderer.setPixelRatio(basePixelRatio() * scale);
    this.requestRender(); // resizing the drawing buffer cleared it
  }

  // ---- level of detail -----------------------------------------------------------------------

  /** Fraction of the hair's segments the last frame drew (1 = all). */
  get hairDetail(): number {
    return this.lastDetail;
  }

  /** Fraction of the current hair an interactive frame draws (1 when the GPU keeps up). */
  get interactiveDetail(): number {
    return this.detail.interactiveDetail(this.hair);
  }

  private adaptDetail(frameMs: number, drawn: number): void {
    if (this.detail.adapt(frameMs, drawn, this.hair, this.holds.size > 0))
      this.setResolutionScale(INTERACTIVE_RESOLUTION);
  }

  // ---- camera (cameraRig.ts) -----------------------------------------------------------------

  setCamera(position: Vec3, target: Vec3): void {
    this.rig.setCamera(position, target);
  }

  /** Returns the camera to the default framing of the head (DEFAULT_CAMERA, the view at load, or
   *  the one given to setHomeView): animated over ~0.45 s unless `animate` is false. setCamera or
   *  another resetView during the animation takes over from it; orbiting or zooming during it
   *  starts from where it is going (CameraRig). */
  resetView(animate = true): void {
    this.rig.resetView(animate);
    this.viewMoving();
  }

  /** Eases the camera to a named view (namedViews.ts framedAppView) of the home framing, farther
   *  and lower as far as the hairstyle reaches below the head (`lowest`: its lowest point, world
   *  y), and above it (`highest`), as resetView eases home. */
  showView(name: AppViewName, lowest = Number.POSITIVE_INFINITY, highest?: number): void {
    const v = framedAppView(name, this.rig.home, lowest, highest);
    this.rig.easeTo(v.position, v.target);
    this.viewMoving();
  }

  private viewMoving(): void {
    if (this.rig.viewAnimating) for (const l of this.viewMovingListeners) l();
  }

  /** Sets the framing resetView returns to (default: DEFAULT_CAMERA). */
  setHomeView(position: Vec3, target: Vec3): void {
    this.rig.setHomeView(position, target);
  }

  /** Whether resetView's animation is running. */
  get viewAnimating(): boolean {
    return this.rig.viewAnimating;
  }

  /** Orbit speed relative to the default (1: a drag across the whole view turns the head
   *  ORBIT_DEGREES_PER_WIDTH = 180°; 2 turns it twice as far). Non-positive or non-finite
   *  factors count as 1. */
  setOrbitSpeed(factor: number): void {
    this.rig.setOrbitSpeed(factor);
  }

  get orbitSpeed(): number {
    return this.rig.orbitSpeed;
  }

  cameraState(): { position: Vec3; target: Vec3 } {
    return this.rig.cameraState();
  }

  /** Ray through client coordinates. */
  rayAt(clientX: number, clientY: number): THREE.Ray {
    return this.rig.rayAt(clientX, clientY);
  }

  /** Client coordinates of a world point, or null when it is behind the camera or off screen. */
  worldToScreen(p: Vec3): { x: number; y: number } | null {
    return this.rig.worldToScreen(p);
  }

  viewForward(): Vec3 {
    return this.rig.viewForward();
  }

  eye(): Vec3 {
    return this.rig.eye();
  }

  // ---- scene content -------------------------------------------------------------------------

  /** Adds an opaque object beside the head (the ties' bands): drawn with the head, in front of
   *  the hair or behind it by depth. */
  addSolid(object: THREE.Object3D): void {
    this.scene.add(object);
    this.requestRender();
  }

  addHead(mesh: THREE.Object3D): void {
    this.scene.add(mesh);
    this.requestRender();
  }

  /** Adds what is drawn behind the head (reference pictures): part of the view, left out of
   *  the PNG capture. */
  addBackdrop(object: THREE.Object3D): void {
    this.backdrops.push(object);
    this.scene.add(object);
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

  /** Shows the style curves, each in its type's colour and the selected one highlighted and
   *  drawn over the others. */
  setCurves(curves: readonly CurveView[], selectedId: string | null): void {
    this.overlays.setCurves(curves, selectedId);
    this.requestRender();
  }

  /** Shows or hides the style curves (the draft stroke is always shown). */
  /** The overlay groups that sit on the head (style curves, displays, guides): a motion moves
   *  them with it. */
  get headOverlays(): THREE.Group[] {
    return this.overlays.groups;
  }

  /** Whether it changed anything. */
  setCurvesVisible(on: boolean): boolean {
    if (!this.overlays.setCurvesVisible(on)) return false;
    this.requestRender();
    return true;
  }

  /** Adds (on) or removes a display object. The caller owns it: it is never disposed here, and
   *  calls requestRender after changing it while shown. */
  showDisplay(object: THREE.Object3D, on: boolean): void {
    if (this.overlays.showDisplay(object, on)) this.requestRender();
  }

  /** Construction lines (e.g. a ponytail's strokes and circles), in the ponytail guide colour. */
  setGuides(lines: readonly (readonly Vec3[])[]): void {
    this.overlays.setGuides(lines);
    this.requestRender();
  }

  /** The stroke being drawn (null: none), in the draft colour, over the curves. With `endsHair`
   *  a bar across its last point marks where the hair it governs will end. */
  /** The scalp brush's ring (overlayLayer.ts setBrushRing; null hides it). */
  setBrushRing(ring: { centre: Vec3; normal: Vec3; radius: number; erase: boolean } | null): void {
    if (!ring && !this.overlays.brushRing) return;
    this.overlays.setBrushRing(ring);
    this.requestRender();
  }

  /** The brush ring shown, or null. */
  get brushRing(): { radius: number; erase: boolean } | null {
    return this.overlays.brushRing;
  }

  setDraft(points: readonly Vec3[] | null, endsHair = false): void {
    this.overlays.setDraft(points, endsHair);
    this.requestRender();
  }

  // ---- the view with every strand (viewCapture.ts) -------------------------------------------

  private captureSource(): CaptureSource {
    return {
      layers: this.sceneLayers,
      canvas: this.canvas,
      software: this.software,
      hair: this.hair,
      allHair: this.detail.counts(this.hair).all,
    };
  }

  /** The current view as a PNG at `scale` × the canvas's resolution, with every strand drawn
   *  (not the level-of-detail sample), on a transparent background when asked. */
  captureImage(opts: { scale?: number; transparent?: boolean } = {}): Promise<Blob> {
    for (const hook of this.captureHooks) hook();
    const shown = this.backdrops.filter((o) => o.visible);
    for (const o of shown) o.visible = false;
    try {
      return captureImage(this.captureSource(), opts);
    } finally {
      for (const o of shown) o.visible = true;
      this.requestRender();
    }
  }

  /** Benchmark probe: draws the current view once with every strand and returns its time in
   *  ms, GPU work included. */
  measureFrame(): number {
    const ms = measureFullFrame(this.captureSource());
    this.requestRender();
    return ms;
  }

  private resize(): void {
    const w = Math.max(1, this.canvas.clientWidth);
    const h = Math.max(1, this.canvas.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.rig.applyOrbitSpeed(); // degrees per px follow the view's size
    this.requestRender();
  }
}
