// Test and benchmark probes of how the viewer draws (window.hairsketch: web/app/testApi.ts): the
// frame cache's switch, a frame drawn through the frame cache against the same frame drawn whole,
// where the last frames started from, and the blend-order and hair-depth probes
// (blendOrderProbe.ts). Each that draws leaves a normal frame to follow. Kept beside viewer.ts,
// which schedules and draws the frames users see.
import * as THREE from 'three';
import { blendOrderProbe, hairDepthProbe } from './blendOrderProbe';
import type { FrameMode, FramePlan } from './frameCache';
import { ALL_LAYERS, drawLayers, type LayeredDrawing, type LayeredScene } from './layeredDrawing';
import type { SliceSizer } from './progressiveHair';

/** What the probes read from the viewer. */
export interface ProbedView {
  readonly layers: LayeredDrawing;
  readonly scene: LayeredScene;
  readonly slices: SliceSizer;
  /** The hair's full and interactive index counts (hairLevelOfDetail.ts counts). */
  counts(): { all: number; interactive: number };
  /** The mode the next frame is drawn in. */
  mode(): FrameMode;
  /** Where the last frame started from. */
  lastSource(): FramePlan['source'];
  requestRender(): void;
}

export class ViewerProbes {
  constructor(private readonly v: ProbedView) {}

  /** Frames are drawn through the frame cache when it is available (false: every frame is
   *  drawn whole; a test and benchmark switch). Requests a frame. */
  set frameCacheEnabled(on: boolean) {
    this.v.layers.enabled = on;
    this.v.requestRender();
  }

  get frameCacheEnabled(): boolean {
    return this.v.layers.enabled;
  }

  /** Whether frames go through the frame cache (on, and the canvas allows copies). */
  get frameCacheActive(): boolean {
    return this.v.layers.active;
  }

  /** Where the last frame started from: 'hair' (only overlays drawn), 'static' (hair and
   *  overlays drawn over the cached head) or 'none' (drawn whole). */
  get lastFrameSource(): FramePlan['source'] {
    return this.v.lastSource();
  }

  /** Slices the last full-detail frame drawn in slices took (0: none was). */
  get lastFullFrameSlices(): number {
    return this.v.slices.lastFrameSlices;
  }

  /** The current view drawn through the frame cache (starting from the slot the next frame would
   *  use, or from the static slot with `from` = 'static') and drawn whole in one pass, both with
   *  the same hair detail; RGBA pixels of the drawing buffer, rows bottom-up. Caches nothing. */
  compareFrames(from?: 'static'): {
    width: number;
    height: number;
    source: FramePlan['source'];
    count: number;
    cached: Uint8Array;
    full: Uint8Array;
  } {
    const { layers, scene } = this.v;
    const { all, interactive } = this.v.counts();
    const keys = layers.keys();
    let plan = layers.plan(this.v.mode(), all, interactive, keys);
    if (from === 'static' && plan.source === 'hair')
      plan = { ...plan, source: layers.staticValid(keys) ? 'static' : 'none' };
    const size = scene.renderer.getDrawingBufferSize(new THREE.Vector2());
    const gl = scene.renderer.getContext();
    const read = (): Uint8Array => {
      const px = new Uint8Array(4 * size.x * size.y);
      gl.readPixels(0, 0, size.x, size.y, gl.RGBA, gl.UNSIGNED_BYTE, px);
      return px;
    };
    const source = layers.draw(plan, all, keys, false);
    const cached = read();
    const hair = scene.hair();
    if (hair && all > 0) hair.geometry.setDrawRange(0, plan.count);
    drawLayers(scene, ALL_LAYERS);
    const full = read();
    this.v.requestRender();
    return { width: size.x, height: size.y, source, count: plan.count, cached, full };
  }

  /** blendOrderProbe.ts on the view. */
  blendOrder(): { oit: number; unsorted: number } | null {
    const r = blendOrderProbe(this.v.scene);
    this.v.requestRender();
    return r;
  }

  /** hairDepthProbe (blendOrderProbe.ts) on the view. */
  hairDepth(): number | null {
    const r = hairDepthProbe(this.v.scene);
    this.v.requestRender();
    return r;
  }
}
