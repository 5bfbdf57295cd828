// Drawing a frame in layers through the frame cache (frameCache.ts): which scene objects belong
// to which layer, what the cached layers must match, and the draw itself (a cached slot, then
// only the layers that changed), plus a test probe that compares a cached frame with a whole one.
import * as THREE from 'three';
import {
  drawableStamp,
  type FrameMode,
  type FramePlan,
  FrameSlots,
  type HairKey,
  type LayerKey,
  planFrame,
  sameLayer,
  viewKey,
} from './frameCache';
import type { DrawnHair } from './hairLevelOfDetail';
import type { WeightedBlendedHair } from './hairOit';
import { ProgressiveHair } from './progressiveHair';

type Layer = 'static' | 'hair' | 'overlay' | 'light';
type DrawnLayer = Exclude<Layer, 'light'>;
export const ALL_LAYERS: readonly DrawnLayer[] = ['static', 'hair', 'overlay'];
export type LayerKeys = { layer: LayerKey; hair: string };
/** The full-detail frame drawn in slices shows the hair drawn so far each time this much more of
 *  it (of both passes) is drawn. */
const FILL_IN_STEP = 0.15;

/** What drawing a scene's layers reads from it. */
export interface SceneLayers {
  readonly renderer: THREE.WebGLRenderer;
  readonly scene: THREE.Scene;
  readonly camera: THREE.Camera;
  /** The group that holds the hair object (its only child, or none). */
  readonly hairGroup: THREE.Group;
  /** The hair object drawn. */
  hair(): DrawnHair;
  /** Whether a child of the scene is an overlay (curves, draft, guides, displays). */
  isOverlay(o: THREE.Object3D): boolean;
}

function layerOf(s: SceneLayers, o: THREE.Object3D): Layer {
  if (o === s.hairGroup) return 'hair';
  if (s.isOverlay(o)) return 'overlay';
  return o instanceof THREE.Light ? 'light' : 'static';
}

/** Draws the scene's objects of the given layers, as renderer.render draws them (lights always
 *  stay: hiding one would change the lit materials' programs). Hair whose object carries an
 *  order-independent drawing (userData.oit, hairOit.ts), drawn whole (not a level-of-detail
 *  sample), is blended by it over the static layer, with the static objects shown as its
 *  occluders, and the overlays are drawn after it. */
export function drawLayers(s: SceneLayers, layers: ReadonlyArray<DrawnLayer>): void {
  const hidden: THREE.Object3D[] = [];
  const statics: THREE.Object3D[] = [];
  for (const c of s.scene.children) {
    const layer = layerOf(s, c);
    if (layer === 'static' && c.visible) statics.push(c);
    if (layer === 'light' || layers.includes(layer) || !c.visible) continue;
    c.visible = false;
    hidden.push(c);
  }
  const r = s.renderer;
  const autoClear = r.autoClear;
  try {
    const hair = s.hair();
    // the whole hair only: a sample drawn while the view moves is blended unsorted (cheaper, and
    // sparse enough that the order shows little)
    const whole = hair ? hair.geometry.drawRange.count >= (hair.geometry.index?.count ?? 0) : false;
    const oit =
      layers.includes('hair') && s.hairGroup.visible && hair?.visible && whole
        ? (hair.userData.oit as WeightedBlendedHair | undefined)
        : undefined;
    if (!oit || !hair) {
      r.render(s.scene, s.camera);
      return;
    }
    const above = s.scene.children.filter((c) => c.visible && layerOf(s, c) !== 'static');
    const overlays = above.filter((c) => layerOf(s, c) === 'overlay');
    for (const c of above) if (!(c instanceof THREE.Light)) c.visible = false;
    try {
      if (layers.includes('static')) r.render(s.scene, s.camera);
      oit.draw(r, s.scene, s.camera, hair, statics);
      if (overlays.length > 0) {
        const under = statics.filter((c) => c.visible);
        for (const c of under) c.visible = false;
        for (const c of overlays) c.visible = true;
        r.autoClear = false;
        r.render(s.scene, s.camera);
        for (const c of under) c.visible = true;
      }
    } finally {
      for (const c of above) c.visible = true;
    }
  } finally {
    r.autoClear = autoClear;
    for (const c of hidden) c.visible = true;
  }
}

/** What the layered drawing reads from the viewer's scene. */
export interface LayeredScene extends SceneLayers {
  readonly camera: THREE.PerspectiveCamera;
}

export class LayeredDrawing {
  /** Frames are drawn through the frame cache when it is available (false: every frame is
   *  drawn whole; a test and benchmark switch). */
  enabled = true;
  /** The cache's slots (made with the first frame) and what each holds. */
  private slots: FrameSlots | null = null;
  private staticKey: LayerKey | null = null;
  private hairKey: HairKey | null = null;
  /** Bumped by invalidate: changes the slots' stamps cannot see (uniforms). */
  private epoch = 0;
  /** The whole hair's frame drawn a slice a frame (progressiveHair.ts), and how much of it was
   *  last shown filling in. */
  private readonly progressive = new ProgressiveHair();
  private shownProgress = 0;

  constructor(private readonly s: LayeredScene) {}

  /** Whether frames go through the frame cache (on, and the canvas allows copies). */
  get active(): boolean {
    this.slots ??= new FrameSlots(this.s.renderer);
    return this.enabled && this.slots.available;
  }

  /** Forgets the cached layers (the caller requests a frame). */
  invalidate(): void {
    this.epoch++;
  }

  /** What the cached layers must match: the view, the static part's stamp, the hair's. */
  keys(): LayerKeys {
    const { camera, renderer, scene } = this.s;
    camera.updateMatrixWorld();
    const size = renderer.getDrawingBufferSize(new THREE.Vector2());
    const statics = scene.children.filter((c) => layerOf(this.s, c) === 'static');
    return {
      layer: {
        view: viewKey(
          camera.matrixWorld.elements,
          camera.projectionMatrix.elements,
          size.x,
          size.y,
        ),
        scene: `${this.epoch}|${drawableStamp(statics)}`,
      },
      hair: drawableStamp([this.s.hairGroup]),
    };
  }

  plan(mode: FrameMode, all: number, interactive: number, keys: LayerKeys): FramePlan {
    if (!this.active) return planFrame(mode, all, interactive, false, null);
    const cachedHair = this.hairSlotHolds(keys) ? (this.hairKey?.count ?? null) : null;
    return planFrame(mode, all, interactive, sameLayer(this.staticKey, keys.layer), cachedHair);
  }

  /** Whether the hair slot holds this view's hair (at some count). */
  private hairSlotHolds(keys: LayerKeys): boolean {
    return !!this.hairKey && sameLayer(this.hairKey, keys.layer) && this.hairKey.hair === keys.hair;
  }

  /** Whether the static slot holds the view `keys` describe. */
  staticValid(keys: LayerKeys): boolean {
    return this.active && sameLayer(this.staticKey, keys.layer);
  }

  /** The whole hair's frame, a slice of `slice` indices a call: returns 'wait' while the GPU
   *  still draws the last slice (nothing drawn) or when the hair drawn so far was shown, 'more' while slices remain (nothing on screen
   *  changed), 'done' when the last one was drawn and the frame
   *  composed over the cached head (and cached, with the overlays over it), or 'whole' when it
   *  cannot be sliced (no order-independent drawing, no cached head of this view): then the
   *  caller draws the frame whole. */
  drawWholeInSlices(
    all: number,
    keys: LayerKeys,
    slice: number,
  ): 'wait' | 'more' | 'done' | 'whole' {
    const { renderer: r, scene, camera, hairGroup } = this.s;
    const hair = this.s.hair();
    const oit = hair?.userData.oit as WeightedBlendedHair | undefined;
    if (!hair || !oit || !hairGroup.visible || !hair.visible || !this.staticValid(keys)) {
      this.progressive.cancel();
      return 'whole';
    }
    if (this.progressive.busy(r.getContext() as WebGL2RenderingContext)) return 'wait';
    const slots = this.slots as FrameSlots;
    const k = { key: `${keys.layer.view}|${keys.layer.scene}|${keys.hair}`, hair, oit, all };
    const statics = scene.children.filter((c) => c.visible && layerOf(this.s, c) === 'static');
    const size = r.getDrawingBufferSize(new THREE.Vector2());
    // the hair drawn so far over the sample on screen (the hair slot), each FILL_IN_STEP of the
    // drawing, in a frame of its own (with a slice, the frame waited for it): it fills in
    const sample = this.hairSlotHolds(keys);
    const p = this.progressive.running(k) ? this.progressive.progress : 0;
    if (p < this.shownProgress) this.shownProgress = 0; // another drawing began
    if (
      this.progressive.partial &&
      p >= this.shownProgress + FILL_IN_STEP &&
      sample &&
      slots.copy('hair', 'restore', size.x, size.y)
    ) {
      this.shownProgress = p;
      this.composeAndOverlays(oit);
      return 'wait';
    }
    if (!this.progressive.step(r, scene, camera, statics, k, slice)) return 'more';
    this.shownProgress = 0;
    if (!slots.copy('static', 'restore', size.x, size.y)) return 'whole';
    oit.compose(r, camera);
    if (slots.copy('hair', 'save', size.x, size.y))
      this.hairKey = { ...keys.layer, hair: keys.hair, count: all };
    this.composeAndOverlays(null);
    return 'done';
  }

  /** How much of the full-detail frame under way is drawn, 0..1 (0: none under way). */
  get slicedProgress(): number {
    return this.progressive.progress;
  }

  /** Composes `oit`'s sums over the canvas (unless null), then draws the overlays. */
  private composeAndOverlays(oit: WeightedBlendedHair | null): void {
    const r = this.s.renderer;
    if (oit) oit.compose(r, this.s.camera);
    const autoClear = r.autoClear;
    try {
      r.autoClear = false;
      drawLayers(this.s, ['overlay']);
    } finally {
      r.autoClear = autoClear;
    }
  }

  /** Draws a frame as `plan` says, into the canvas; `save`: keep the layers drawn in the cache
   *  (the hair layer only when `saveHair` too). Returns where the frame started from (a cached
   *  slot, or 'none'). */
  draw(
    plan: FramePlan,
    all: number,
    keys: LayerKeys,
    save: boolean,
    saveHair = save,
  ): FramePlan['source'] {
    const r = this.s.renderer;
    const hair = this.s.hair();
    if (hair && all > 0 && plan.source !== 'hair') hair.geometry.setDrawRange(0, plan.count);
    if (!this.active || !this.slots) {
      drawLayers(this.s, ALL_LAYERS);
      return 'none';
    }
    const slots = this.slots;
    const size = r.getDrawingBufferSize(new THREE.Vector2());
    let source = plan.source;
    if (source !== 'none' && !slots.copy(source, 'restore', size.x, size.y)) source = 'none';
    if (source === 'none' && plan.source === 'hair' && hair && all > 0)
      hair.geometry.setDrawRange(0, plan.count);
    const autoClear = r.autoClear;
    try {
      if (source === 'none') {
        r.autoClear = true;
        drawLayers(this.s, ['static']);
        if (save && slots.copy('static', 'save', size.x, size.y)) this.staticKey = keys.layer;
      }
      r.autoClear = false;
      if (source !== 'hair') {
        drawLayers(this.s, ['hair']);
        if (saveHair && slots.copy('hair', 'save', size.x, size.y))
          this.hairKey = { ...keys.layer, hair: keys.hair, count: plan.count };
      }
      drawLayers(this.s, ['overlay']);
    } finally {
      r.autoClear = autoClear;
    }
    return source;
  }
}
