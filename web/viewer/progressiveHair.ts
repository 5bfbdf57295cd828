// The whole hair's order-independent drawing (hairOit.ts) spread over several animation frames:
// on a software rasteriser one frame of 30K strands holds the page for seconds (every edit, undo
// and orbit ended in a freeze). Each frame runs one slice of the hair's index range through the
// current pass (the front pass over every slice, then the sums), into the drawing's own targets,
// so nothing on screen changes until the last slice; the caller then composes the sums over the
// head in one frame. The sums and the front pass's minimum do not depend on the order the
// strands are drawn in, so the sliced frame is the one-pass frame.
import type * as THREE from 'three';
import type { WeightedBlendedHair } from './hairOit';

/** A slice boundary falls on a multiple of this many indices (a line segment's 2 and a
 *  triangle's 3). */
const SLICE_ALIGN = 6;
/** Slices the GPU may have to draw at once. */
const SLICES_IN_FLIGHT = 1;

export interface ProgressiveKey {
  /** What the frame shows (the layer keys: view, static part, hair). */
  key: string;
  hair: THREE.Mesh | THREE.LineSegments;
  oit: WeightedBlendedHair;
  /** Index count of the whole hair. */
  all: number;
}

export class ProgressiveHair {
  private job:
    | (ProgressiveKey & { phase: 'front' | 'sums'; next: number; generation: number })
    | null = null;
  /** Signalled as the GPU has drawn each slice in flight: at most SLICES_IN_FLIGHT are (one:
   *  two in flight froze the page longer and were no faster), so slices never queue up (a
   *  frame would wait for all of them). */
  private fences: WebGLSync[] = [];

  /** Forgets the drawing under way. */
  cancel(): void {
    this.job = null;
  }

  /** Whether the GPU still draws as many slices as may be in flight. */
  busy(gl: WebGL2RenderingContext): boolean {
    while (this.fences.length > 0) {
      const f = this.fences[0];
      if (gl.getSyncParameter(f, gl.SYNC_STATUS) !== gl.SIGNALED) break;
      gl.deleteSync(f);
      this.fences.shift();
    }
    return this.fences.length >= SLICES_IN_FLIGHT;
  }

  /** Whether the sums of the drawing under way hold some of the hair (its second pass has
   *  begun): composed now, they show the hair drawn so far (its index order is an even sample). */
  get partial(): boolean {
    return this.job?.phase === 'sums' && this.job.next > 0;
  }

  /** How much of the drawing under way is done, 0..1 (each pass half). */
  get progress(): number {
    const j = this.job;
    if (!j || j.all <= 0) return 0;
    return (j.phase === 'sums' ? 0.5 : 0) + (0.5 * j.next) / j.all;
  }

  /** Whether a drawing of `k` is under way (some slices drawn). */
  running(k: ProgressiveKey): boolean {
    return this.job !== null && this.matches(k);
  }

  private matches(k: ProgressiveKey): boolean {
    const j = this.job;
    return (
      j !== null &&
      j.key === k.key &&
      j.hair === k.hair &&
      j.oit === k.oit &&
      j.all === k.all &&
      j.generation === k.oit.generation
    );
  }

  /** Draws the next `slice` indices (at least one aligned slice) of the whole hair `k` describes
   *  into the drawing's targets, starting it (or again, when what it draws changed or another
   *  drawing used the targets). Returns true when every pass is done: the caller composes
   *  (WeightedBlendedHair.compose) and the drawing is forgotten. The hair's draw range is left
   *  at the whole hair. */
  step(
    renderer: THREE.WebGLRenderer,
    scene: THREE.Scene,
    camera: THREE.Camera,
    occluders: readonly THREE.Object3D[],
    k: ProgressiveKey,
    slice: number,
  ): boolean {
    const { hair, oit, all } = k;
    if (!this.matches(k)) {
      oit.begin(renderer, camera, hair);
      this.job = { ...k, phase: 'front', next: 0, generation: oit.generation };
    }
    const job = this.job as NonNullable<typeof this.job>;
    const count = Math.max(SLICE_ALIGN, Math.ceil(slice / SLICE_ALIGN) * SLICE_ALIGN);
    const end = Math.min(all, job.next + count);
    hair.geometry.setDrawRange(job.next, end - job.next);
    hair.geometry.userData.sliceOfWhole = true; // drawn as wide as in the whole (strandWidth.ts)
    try {
      if (job.phase === 'front') oit.front(renderer, camera, hair);
      else oit.sums(renderer, camera, hair);
    } finally {
      hair.geometry.setDrawRange(0, all);
      delete hair.geometry.userData.sliceOfWhole;
    }
    job.next = end;
    const gl = renderer.getContext() as WebGL2RenderingContext;
    const fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    if (fence) this.fences.push(fence);
    gl.flush();
    if (end < all) return false;
    if (job.phase === 'front') {
      oit.beginSums(renderer, scene, camera, occluders);
      job.phase = 'sums';
      job.next = 0;
      return false;
    }
    this.job = null;
    return true;
  }
}

/** The full-detail frame is drawn in slices that keep frames about this far apart (ms). */
const FULL_SLICE_MS = 160;
/** The first full-detail frame draws its hair in this many slices; none in more than
 *  FULL_MAX_SLICES. */
const FULL_FIRST_SLICES = 20;
const FULL_MAX_SLICES = 400;

/** How many indices each slice draws: the first, the size the last full-detail frame's slices
 *  came to, else a twentieth of the hair; then sized by how long the GPU took to draw the one
 *  before (a slice is drawn only once the GPU has drawn the last one), so frames come about
 *  FULL_SLICE_MS apart. Counts the slices a frame took. */
export class SliceSizer {
  private count = 0;
  private lastAt: number | null = null;
  private drawn = 0;
  /** Slices the last full-detail frame drawn in slices took (since the last frame between). */
  lastFrameSlices = 0;

  /** The size of a slice drawn at `now`, of a hair of `all` indices. */
  next(now: number, all: number): number {
    let count = this.count > 0 ? this.count : all / FULL_FIRST_SLICES;
    if (this.lastAt !== null)
      count *= Math.min(2, Math.max(0.5, FULL_SLICE_MS / Math.max(now - this.lastAt, 1)));
    return Math.round(Math.min(all, Math.max(all / FULL_MAX_SLICES, count)));
  }

  /** A slice of `count` was asked for at `now`: 'more' (slices remain), 'done' (the frame's
   *  last) or 'whole' (the frame is drawn whole instead). */
  drew(now: number, count: number, step: 'more' | 'done' | 'whole'): void {
    this.count = count;
    if (this.lastAt === null) this.drawn = 0;
    this.drawn++;
    this.lastAt = step === 'more' ? now : null;
    if (step === 'done') this.lastFrameSlices = this.drawn;
  }

  /** Another frame was drawn: the time since the last slice says nothing of the next's cost. */
  interrupt(): void {
    this.lastAt = null;
  }
}
