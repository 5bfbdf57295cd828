// The viewer's camera: a perspective camera with orbit controls, the framing "Reset view" eases
// back to, the user's orbit speed, and conversions between screen and world.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { Vec3 } from '../model/vec3';
import { type CameraView, easeInOut, interpolateView, orbitRotateSpeed } from './viewMath';

/** Duration of resetView's animation. */
const RESET_VIEW_MS = 450;

/** What the camera asks of the viewer: a new frame, and an interactive hold while the user
 *  orbits ('orbit') or the camera eases home ('view-animation'). */
export interface CameraRigHost {
  requestRender(): void;
  hold(reason: string, on: boolean): void;
}

export class CameraRig {
  readonly camera: THREE.PerspectiveCamera;
  readonly controls: OrbitControls;
  /** User orbit speed (1 = default: ORBIT_DEGREES_PER_WIDTH across the view). */
  private orbitFactor = 1;
  /** The camera resetView returns to. */
  private homeView: CameraView;
  private viewAnimation: { from: CameraView; to: CameraView; start: number; ms: number } | null =
    null;

  constructor(
    private readonly canvas: HTMLCanvasElement,
    home: CameraView,
    private readonly host: CameraRigHost,
  ) {
    this.homeView = { position: [...home.position], target: [...home.target] };
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.05, 100);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = false;
    this.controls.minDistance = 2;
    this.controls.maxDistance = 25;
    // the wheel zooms towards the point under the pointer, as design tools do (fresh eyes zoomed
    // on a nape and it slid out of the view towards the middle)
    this.controls.zoomToCursor = true;
    // a wheel notch (100 px of delta) brings the camera 10 % nearer, as design tools zoom (at
    // three.js's 5 % fresh eyes needed 15 notches to frame a forehead)
    this.controls.zoomSpeed = 2;
    this.controls.addEventListener('change', () => host.requestRender());
    this.controls.addEventListener('start', () => {
      // the user takes the camera: from the view a named view key or Reset view asked for, not
      // from part way there (fresh eyes pressed F and right-dragged while the camera still eased
      // down from the top view, and orbited from above the head)
      this.finishViewAnimation();
      host.hold('orbit', true);
    });
    this.controls.addEventListener('end', () => host.hold('orbit', false));
    this.setCamera(home.position, home.target);
  }

  setCamera(position: Vec3, target: Vec3): void {
    this.stopViewAnimation();
    this.placeCamera(position, target);
  }

  private placeCamera(position: Vec3, target: Vec3): void {
    this.camera.position.set(...position);
    this.controls.target.set(...target);
    this.controls.update();
    this.host.requestRender();
  }

  /** Returns the camera to the home view (the view at load, or the one given to setHomeView):
   *  animated over ~0.45 s unless `animate` is false. setCamera or another resetView during the
   *  animation takes over from it; orbiting or zooming during it starts from where it is going. */
  resetView(animate = true): void {
    this.easeTo(this.homeView.position, this.homeView.target, animate);
  }

  /** Moves the camera to `position`, looking at `target`, eased as resetView is (a named view). */
  easeTo(position: Vec3, target: Vec3, animate = true): void {
    const to: CameraView = { position: [...position], target: [...target] };
    this.stopViewAnimation();
    if (!animate) {
      this.placeCamera(to.position, to.target);
      return;
    }
    this.viewAnimation = { from: this.cameraState(), to, start: -1, ms: RESET_VIEW_MS };
    this.host.hold('view-animation', true); // interactive detail while the camera moves
    this.host.requestRender();
  }

  /** The framing resetView returns to. */
  get home(): CameraView {
    return { position: [...this.homeView.position], target: [...this.homeView.target] };
  }

  /** Sets the framing resetView returns to. */
  setHomeView(position: Vec3, target: Vec3): void {
    this.homeView = { position: [...position], target: [...target] };
  }

  /** Whether resetView's animation is running. */
  get viewAnimating(): boolean {
    return this.viewAnimation !== null;
  }

  /** Moves the camera along resetView's animation to time `now` (once per frame). */
  stepViewAnimation(now: number): void {
    const a = this.viewAnimation;
    if (!a) return;
    if (a.start < 0) a.start = now;
    const t = a.ms > 0 ? (now - a.start) / a.ms : 1;
    const v = interpolateView(a.from, a.to, easeInOut(t));
    this.placeCamera(v.position, v.target);
    if (t >= 1) this.stopViewAnimation();
  }

  /** Puts the camera where the running animation is going, and ends it. */
  private finishViewAnimation(): void {
    const a = this.viewAnimation;
    if (!a) return;
    this.stopViewAnimation();
    this.placeCamera(a.to.position, a.to.target);
  }

  private stopViewAnimation(): void {
    if (!this.viewAnimation) return;
    this.viewAnimation = null;
    this.host.hold('view-animation', false);
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

  /** Degrees per pixel follow the view's size: call after the canvas is resized. */
  applyOrbitSpeed(): void {
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
}
