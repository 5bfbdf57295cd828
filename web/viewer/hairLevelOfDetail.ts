// Level of detail of the hair while the view is interactive (orbit, a stroke, hair settling): a
// prefix of the strands, which buildStrandGeometry orders as an even sample, sized so frames stay
// near INTERACTIVE_FRAME_MS on this GPU. The budget comes from measured frame times, so a fast
// GPU always draws everything; a software rasteriser draws a sparse sample while things move.
import type * as THREE from 'three';

/** Interactive frames aim at this, and are slow past SLOW_FRAME_MS: frames are presented on
 *  vsync (16.7 ms), so a frame that needs more than two (33 ms) runs at 20 per second or less,
 *  and previews while drawing cannot be shown faster than frames are. On a software rasteriser
 *  the page's main thread waits for each frame's pixels, so a preview's answer waits behind the
 *  frame before it: a lighter frame (a sparser sample of the preview's strands) lets more
 *  previews through. */
const INTERACTIVE_FRAME_MS = 20;
const SLOW_FRAME_MS = 36;
const FAST_FRAME_MS = 15;
/** Resolution of interactive frames that stay slow with little hair, relative to the display. */
export const INTERACTIVE_RESOLUTION = 0.5;
/** Index entries (2 per segment) an interactive frame may always draw: ~270 strands of the
 *  final hair's lines; fewer entries when MIN_HAIR_STRANDS strands need fewer (a stroke's
 *  previews are drawn with every other point: the same strands for half the entries). */
const MIN_HAIR_BUDGET = 30_000;
const MIN_HAIR_STRANDS = 270;
/** Hair budget before any frame was measured on a software rasteriser (a first look of 6,000
 *  strands drawn whole took ~1 s there). */
const SOFTWARE_INITIAL_BUDGET = 2 * MIN_HAIR_BUDGET;

/** The hair object as the viewer draws it: its geometry's userData carries `lodCounts` (index
 *  counts of growing prefixes, the last one all of it) and `strands`. */
export type DrawnHair = THREE.LineSegments | THREE.Mesh | null;

/** A playing motion's frame may draw this many times an interactive frame's hair (about 160 ms
 *  a frame where the budget holds), every strand with every MAX_MOTION_STRIDE-th point at most. */
const MOTION_BUDGET_FACTOR = 8;
export const MAX_MOTION_STRIDE = 8;

export class HairLevelOfDetail {
  /** Hair index count an interactive frame may draw (until a slow frame is seen: Infinity on a
   *  GPU, SOFTWARE_INITIAL_BUDGET on a software rasteriser). */
  private budget: number;

  constructor(software: boolean) {
    this.budget = software ? SOFTWARE_INITIAL_BUDGET : Number.POSITIVE_INFINITY;
  }

  /** Fraction of `hair` an interactive frame draws (1 when the GPU keeps up). */
  interactiveDetail(hair: DrawnHair): number {
    const lod = hair?.geometry.userData.lodCounts as Uint32Array | undefined;
    const all = lod ? lod[lod.length - 1] : 0;
    return all > 0 ? Math.min(1, this.budget / all) : 1;
  }

  /** Every how many points a playing motion draws each strand of `hair` (every strand is drawn
   *  in every frame, with fewer points where the budget is short: 1 on a GPU). */
  motionStride(hair: DrawnHair): number {
    const lod = hair?.geometry.userData.lodCounts as Uint32Array | undefined;
    const all = lod ? lod[lod.length - 1] : 0;
    if (!Number.isFinite(this.budget) || all <= 0) return 1;
    const k = Math.ceil(all / (this.budget * MOTION_BUDGET_FACTOR));
    return Math.min(MAX_MOTION_STRIDE, Math.max(1, k));
  }

  /** Index counts of `hair`: all of it, and the prefix an interactive frame draws. */
  counts(hair: DrawnHair): { all: number; interactive: number } {
    const lod = hair?.geometry.userData.lodCounts as Uint32Array | undefined;
    if (!lod || lod.length === 0) return { all: 0, interactive: 0 }; // drawn whole, as given
    const all = lod[lod.length - 1];
    let interactive = all;
    if (this.budget < all) {
      let g = 1;
      while (g + 1 < lod.length && lod[g + 1] <= this.budget) g++;
      interactive = lod[Math.min(g, lod.length - 1)];
    }
    return { all, interactive };
  }

  /** The budget's floor for `hair`: MIN_HAIR_BUDGET, or MIN_HAIR_STRANDS of its strands when
   *  they take fewer index entries. */
  private floor(hair: DrawnHair): number {
    const lod = hair?.geometry.userData.lodCounts as Uint32Array | undefined;
    const strands = hair?.geometry.userData.strands as number | undefined;
    if (!lod || lod.length === 0 || !strands) return MIN_HAIR_BUDGET;
    return Math.min(MIN_HAIR_BUDGET, (MIN_HAIR_STRANDS * lod[lod.length - 1]) / strands);
  }

  /** Adapts the budget to a rendered frame's time, given the hair index count it drew (negative:
   *  it drew no hair, as from the cached hair layer). Returns true when interactive frames should
   *  drop to INTERACTIVE_RESOLUTION: `interactive` and still slow with the hair at its floor, so
   *  the cost is per pixel (a software rasteriser, a large screen). */
  adapt(frameMs: number, drawn: number, hair: DrawnHair, interactive: boolean): boolean {
    if (drawn < 0) return false; // the frame drew no hair (the cached hair layer)
    const floor = this.floor(hair);
    const lowerResolution =
      interactive && frameMs > SLOW_FRAME_MS && (drawn <= floor || this.budget <= floor);
    if (drawn <= 0) return lowerResolution;
    if (frameMs > SLOW_FRAME_MS) {
      // cost scales with segments drawn: aim at the interactive frame time
      // (never below a floor: part of a slow frame is not the hair's, e.g. a busy CPU)
      this.budget = Math.max(floor, (drawn * INTERACTIVE_FRAME_MS) / frameMs);
    } else if (frameMs < FAST_FRAME_MS && drawn >= this.budget * 0.5) {
      this.budget = this.budget * 1.5;
    }
    return lowerResolution;
  }
}
