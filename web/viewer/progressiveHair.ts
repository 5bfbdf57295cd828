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
