// The three.js view: head, hair strands, style curves, the stroke being drawn. Renders on demand.
// While the user interacts (orbit, a stroke, hair still settling) the hair is drawn at a level of
// detail that keeps frames near INTERACTIVE_FRAME_MS on this GPU: a prefix of the strands, which
// buildStrandGeometry orders as an even sample. The budget comes from measured frame times, so a
// fast GPU always draws everything; a software rasteriser draws a sparse sample while things move,
// and the whole head of hair once they stop.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { Vec3 } from '../model/vec3';

export interface CurveView {
  id: string;
  points: readonly Vec3[];
}

const INTERACTIVE_FRAME_MS = 40;
const SLOW_FRAME_MS = 60;
const FAST_FRAME_MS = 25;
/** Resolution of interactive frames that stay slow with little hair, relative to the display. */
const INTERACTIVE_RESOLUTION = 0.5;
/** Index entries (2 per segment) an interactive frame may always draw: ~250 strands. */
const MIN_HAIR_BUDGET = 30_000;

export const DEFAULT_CAMERA = { position: [2.6, 0.9, 7.0] as Vec3, target: [0, -0.55, 0] as Vec3 };

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
  private draft: THREE.Line | null = null;
  private hair: THREE.LineSegments | null = null;
  private dirty = true;
  /** WebGL runs on a software rasteriser (no GPU). */
  readonly software: boolean;
  /** Reasons the view is interactive now (e.g. 'orbit', 'stroke', 'settling'). */
  private readonly holds = new Set<string>();
  /** Hair index count an interactive frame may draw (Infinity until a slow frame is seen). */
  private hairBudget = Number.POSITIVE_INFINITY;
  private lastRender: { time: number; drawn: number } | null = null;
  private lastDetail = 1;
  private frameHooks: Array<() => void> = [];
  /** Called after each rendered frame (e.g. to count displayed hair revisions). */
  onRendered: (() => void) | null = null;

  constructor(readonly canvas: HTMLCanvasElement) {
    // Multisampling costs ~2x per frame on a software rasteriser (SwiftShader, llvmpipe), where
    // frame time, not the solver, bounds interactivity: it is on only for a hardware GPU.
    this.software = isSoftwareGl();
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
    this.controls.addEventListener('start', () => this.hold('orbit', true));
    this.controls.addEventListener('end', () => this.hold('orbit', false));
    this.setCamera(DEFAULT_CAMERA.position, DEFAULT_CAMERA.target);

    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x6b5d52, 1.4));
    const key = new THREE.DirectionalLight(0xffffff, 1.6);
    key.position.set(3, 5, 4);
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
      for (const hook of this.frameHooks) hook();
      if (this.dirty) {
        this.dirty = false;
        const drawn = this.applyHairDetail();
        this.renderer.render(this.scene, this.camera);
        this.lastRender = { time: now, drawn };
        this.onRendered?.();
      }
      requestAnimationFrame(loop);
    };
    requestAnimationFrame(loop);
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

  private applyHairDetail(): number {
    const lod = this.hair?.geometry.userData.lodCounts as Uint32Array | undefined;
    if (!this.hair || !lod) return 0;
    const all = lod[lod.length - 1];
    let count = all;
    if (this.holds.size > 0 && this.hairBudget < all) {
      let g = 1;
      while (g + 1 < lod.length && lod[g + 1] <= this.hairBudget) g++;
      count = lod[g];
    }
    this.hair.geometry.setDrawRange(0, count);
    this.lastDetail = all > 0 ? count / all : 1;
    return count;
  }

  private adaptBudget(frameMs: number, drawn: number): void {
    // Interactive frames still slow with the hair at its floor: the cost is per pixel (a software
    // rasteriser, a large screen), so draw them at half resolution until the view settles.
    if (
      this.holds.size > 0 &&
      frameMs > SLOW_FRAME_MS &&
      (drawn <= MIN_HAIR_BUDGET || this.hairBudget <= MIN_HAIR_BUDGET)
    )
      this.setResolutionScale(INTERACTIVE_RESOLUTION);
    if (drawn <= 0) return;
    if (frameMs > SLOW_FRAME_MS) {
      // cost scales with segments drawn: aim at the interactive frame time
      // (never below a floor: part of a slow frame is not the hair's, e.g. a busy CPU)
      this.hairBudget = Math.max(MIN_HAIR_BUDGET, (drawn * INTERACTIVE_FRAME_MS) / frameMs);
    } else if (frameMs < FAST_FRAME_MS && drawn >= this.hairBudget * 0.5) {
      this.hairBudget = this.hairBudget * 1.5;
    }
  }

  get renderPending(): boolean {
    return this.dirty;
  }

  setCamera(position: Vec3, target: Vec3): void {
    this.camera.position.set(...position);
    this.controls.target.set(...target);
    this.controls.update();
    this.requestRender();
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
    this.hair = object instanceof THREE.LineSegments ? object : null;
    this.requestRender();
  }

  setCurves(curves: readonly CurveView[], selectedId: string | null): void {
    for (const child of [...this.curveGroup.children]) {
      this.curveGroup.remove(child);
      disposeObject(child);
    }
    for (const c of curves) {
      const line = polyline(c.points, c.id === selectedId ? 0xffc400 : 0x00b7d4);
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

  /** Construction lines drawn over everything (e.g. a ponytail's strokes and circles). */
  setGuides(lines: readonly (readonly Vec3[])[]): void {
    for (const child of [...this.guideGroup.children]) {
      this.guideGroup.remove(child);
      disposeObject(child);
    }
    for (const l of lines) if (l.length >= 2) this.guideGroup.add(polyline(l, 0xb04dff));
    this.requestRender();
  }

  setDraft(points: readonly Vec3[] | null): void {
    if (this.draft) {
      this.scene.remove(this.draft);
      disposeObject(this.draft);
      this.draft = null;
    }
    if (points && points.length >= 2) {
      this.draft = polyline(points, 0x2f7bff);
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
    this.requestRender();
  }
}

function basePixelRatio(): number {
  return Math.min(window.devicePixelRatio || 1, 2);
}

/** Whether WebGL here is a software rasteriser, from the unmasked renderer string of a probe
 *  context (released at once). */
function isSoftwareGl(): boolean {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}

// Line materials are shared and never disposed: a disposed material releases its shader program,
// and compiling it again stalls on the GPU (seconds behind a software rasteriser).
const lineMaterials = new Map<number, THREE.LineBasicMaterial>();
function lineMaterial(color: number): THREE.LineBasicMaterial {
  let m = lineMaterials.get(color);
  if (!m) {
    m = new THREE.LineBasicMaterial({ color, depthTest: false, transparent: true });
    lineMaterials.set(color, m);
  }
  return m;
}

function polyline(points: readonly Vec3[], color: number): THREE.Line {
  const arr = new Float32Array(points.length * 3);
  points.forEach((p, i) => {
    arr.set(p, 3 * i);
  });
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(arr, 3));
  const line = new THREE.Line(g, lineMaterial(color));
  line.renderOrder = 10;
  return line;
}

/** Frees an object's geometry; materials are the owner's (shared, reused across objects). */
function disposeObject(o: THREE.Object3D): void {
  o.traverse((x) => {
    (x as THREE.Mesh).geometry?.dispose();
  });
}
