// The viewer's overlays, drawn over head and hair: the style curves, the stroke being drawn (the
// draft), construction guides and the display objects (constraints, field, box, surface). Each
// is depth-tested against head and hair and faint where hidden (overlayStyle.ts).
import * as THREE from 'three';
import type { Vec3 } from '../model/vec3';
import {
  BRUSH_RING_RGB,
  curveRgb,
  HIDDEN_OPACITY,
  OVERLAY_ORDER,
  OVERLAY_RGB,
  overlayPolyline,
  SELECTED_HIDDEN_OPACITY,
} from './overlayStyle';
import { clearGroup, disposeObject, endBar } from './sceneObjects';

export interface CurveView {
  id: string;
  /** Session curve type ('stream' | 'dividing' | 'ponytail'): chooses the colour (stream when
   *  absent). */
  type?: string;
  points: readonly Vec3[];
}

export class OverlayLayer {
  private readonly curveGroup = new THREE.Group();
  /** Display overlays (constraints, field, box, surface): owned by their display modules. */
  private readonly displayGroup = new THREE.Group();
  private readonly guideGroup = new THREE.Group();
  private draft: THREE.Object3D | null = null;
  private ring: THREE.Object3D | null = null;

  /** `scene`: where the draft goes (the groups are added by the viewer, in groups' order);
   *  `viewForward`: the view direction, for the draft's end bar. */
  constructor(
    private readonly scene: THREE.Scene,
    private readonly viewForward: () => Vec3,
  ) {}

  /** The overlay groups, in the order they are added to the scene. */
  get groups(): THREE.Group[] {
    return [this.curveGroup, this.displayGroup, this.guideGroup];
  }

  /** Whether a child of the scene is an overlay. */
  holds(o: THREE.Object3D): boolean {
    return (
      o === this.curveGroup ||
      o === this.displayGroup ||
      o === this.guideGroup ||
      o === this.draft ||
      o === this.ring
    );
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
  }

  /** Shows or hides the style curves; false when nothing changed. */
  setCurvesVisible(on: boolean): boolean {
    if (this.curveGroup.visible === on) return false;
    this.curveGroup.visible = on;
    return true;
  }

  /** Adds (on) or removes a display object (never disposed here); false when nothing changed. */
  showDisplay(object: THREE.Object3D, on: boolean): boolean {
    const shown = object.parent === this.displayGroup;
    if (on === shown) return false;
    if (on) this.displayGroup.add(object);
    else this.displayGroup.remove(object);
    return true;
  }

  /** Construction lines (e.g. a ponytail's strokes and circles), in the ponytail guide colour. */
  setGuides(lines: readonly (readonly Vec3[])[]): void {
    clearGroup(this.guideGroup);
    for (const l of lines)
      if (l.length >= 2) this.guideGroup.add(overlayPolyline(l, OVERLAY_RGB.ponytailGuide));
  }

  /** The stroke being drawn (null: none), in the draft colour, over the curves. With `endsHair`
   *  a bar across its last point marks where the hair it governs will end. */
  setDraft(points: readonly Vec3[] | null, endsHair: boolean): void {
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
  }

  /** The scalp brush's ring (null: none): a circle of the brush's radius round `centre`, square to
   *  the head's normal there, lifted 2 mm off it; blue while it paints, red while it erases. */
  setBrushRing(ring: { centre: Vec3; normal: Vec3; radius: number; erase: boolean } | null): void {
    if (this.ring) {
      this.scene.remove(this.ring);
      disposeObject(this.ring);
      this.ring = null;
    }
    if (!ring) return;
    const n = new THREE.Vector3(...ring.normal).normalize();
    const u = new THREE.Vector3(Math.abs(n.y) < 0.9 ? 0 : 1, Math.abs(n.y) < 0.9 ? 1 : 0, 0)
      .cross(n)
      .normalize();
    const v = n.clone().cross(u);
    const c = new THREE.Vector3(...ring.centre).addScaledVector(n, 0.02);
    const pts: Vec3[] = [];
    for (let i = 0; i <= 64; i++) {
      const a = (2 * Math.PI * i) / 64;
      const p = c
        .clone()
        .addScaledVector(u, ring.radius * Math.cos(a))
        .addScaledVector(v, ring.radius * Math.sin(a));
      pts.push([p.x, p.y, p.z]);
    }
    this.ring = overlayPolyline(
      pts,
      ring.erase ? BRUSH_RING_RGB.erase : BRUSH_RING_RGB.paint,
      OVERLAY_ORDER.draft,
      0.85, // seen through the hair over the scalp
    );
    this.ring.userData.brushRing = { radius: ring.radius, erase: ring.erase };
    this.scene.add(this.ring);
  }

  /** The brush ring shown (radius, mode), or null. */
  get brushRing(): { radius: number; erase: boolean } | null {
    return (this.ring?.userData.brushRing as { radius: number; erase: boolean }) ?? null;
  }
}
