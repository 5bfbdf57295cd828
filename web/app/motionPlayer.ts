// Plays a motion over the hair on screen: the worker simulates the guides (protocol.ts
// motionStart / motionStep / motionStop) and binds every strand to one (motionBound, once); each
// frame it sends is the guides and the head's pose, which go to the strand shader (HairView.follow
// and followFrame: every strand placed on its guide on the GPU, all of them drawn) and move the
// head and body meshes. Frames are asked for one at a time, at most 24 per second of wall time,
// PIPELINE requests ahead so the worker steps the next frame while this thread draws the current
// one: every frame of the motion is drawn (where drawing takes longer than a 24th of a second the
// motion plays slower than in life, as an animation package's playback without frame dropping
// does; skipping frames to keep time drew 4 a second of the 16 the motion advanced at 30K); a
// frame's guide array goes back to the worker for a later frame (transferred both ways). Where the hair shown cannot follow (the Cards
// view) each frame's strands are placed on the CPU (guideFollowers.ts) and drawn rebuilt. The
// geometry's points are never written: Stop shows the groom again bit for bit; an edit that
// changes the hair, or new hair from the solver, stops the motion first.
import * as THREE from 'three';
import type { Editor } from '../editor/editor';
import {
  type FollowerAttributes,
  followerAttributes,
  type GuideBinding,
  placeFollowers,
} from '../model/guideFollowers';
import type { StrandArrays } from '../model/hairArrays';
import {
  DEFAULT_WIND,
  MOTION_FRAME_RATE,
  MOTION_LABELS,
  type MotionName,
  type WindSettings,
} from '../model/motion';
import { changesHair } from '../model/sessionSchema';
import type { SolveResult, SolverClient } from '../solver/solverClient';
import type { HairView } from '../viewer/hairView';
import type { Viewer } from '../viewer/viewer';

/** Requests the worker may be working on at once. */
const PIPELINE = 2;

export interface MotionPlayerDeps {
  client: SolverClient;
  editor: Editor;
  viewer: Viewer;
  hairView: HairView;
  /** The result whose hair is on screen (HairPresenter.shownResult). */
  shown: () => SolveResult | null;
  /** What the head's pose moves: the head and body meshes (the body may be absent) and the
   *  overlays on the head (style curves, displays, guides), so curves stay on the hair. */
  meshes: () => (THREE.Object3D | undefined)[];
  say: (message: string) => void;
  /** The status line's element: data-motion (the motion playing, or ''), data-motion-frame. */
  statusElement: HTMLElement;
  changed: () => void;
}

export class MotionPlayer {
  private motion: MotionName | null = null;
  /** This play's id (protocol motionStart.play): messages of plays before are dropped. */
  private playId = 0;
  private base: SolveResult | null = null;
  /** This play's binding (null until the worker sent it), and whether the hair shown follows
   *  it on the GPU (else each frame is placed here and drawn rebuilt). */
  private bound: {
    binding: GuideBinding;
    /** Of every point (the drawn points' when every point is drawn; else made when asked). */
    attrs: FollowerAttributes | null;
    gpu: boolean;
  } | null = null;
  /** Every how many points this play draws each strand (motionStart.pointStride). */
  private stride = 1;
  /** The last frame drawn: its guides and pose, and its strands once placed on the CPU. */
  private last: { guides: Float32Array; pose: Float32Array; strands: StrandArrays | null } | null =
    null;
  private startTime = 0;
  private frameNo = 0;
  /** Requests sent and not yet answered, and when each was sent (oldest first). */
  private sent: number[] = [];
  /** The frame the last request sent will answer with. */
  private requested = 0;
  /** Frame arrays drawn and replaced, to give back to the worker with the next request. */
  private spare: Float32Array[] = [];
  private timer: ReturnType<typeof setTimeout> | null = null;
  private saved = new Map<THREE.Object3D, THREE.Matrix4>();
  /** Frames drawn and when the first was drawn (frames per second while playing). */
  private drawnCount = 0;
  private firstDrawn = 0;
  /** The last frame's wait for the worker and its geometry update on this thread (ms), and the
   *  frames of this play drawn by rebuilding the geometry. */
  readonly times = { workerMs: 0, stepMs: 0, buildMs: 0, rebuilds: 0 };

  constructor(private readonly d: MotionPlayerDeps) {
    d.client.onMotion = (msg) => {
      if (!this.motion) return;
      if (msg.type === 'motionError') {
        this.stop();
        d.say(`Motion stopped: ${msg.message}`);
        return;
      }
      if (msg.play !== this.playId) return; // of a play stopped before
      if (msg.type === 'motionBound') {
        const stride = this.stride;
        const gpu = d.hairView.follow(msg.binding, msg.attributes, stride);
        this.bound = { binding: msg.binding, attrs: stride > 1 ? null : msg.attributes, gpu };
        return;
      }
      this.times.stepMs = msg.stepMs;
      this.draw(msg.frame, msg.guides, msg.pose);
    };
    d.editor.listen((c) => {
      if (this.motion && c.sessionChanged && changesHair(c.previous, c.session)) this.stop();
    });
  }

  get playing(): MotionName | null {
    return this.motion;
  }

  /** What is drawn while playing (null when stopped: the groom's result is drawn): the strands
   *  of the last frame as guideFollowers.ts places them (the strand shader's CPU reference),
   *  placed when first asked for. */
  get drawn(): StrandArrays | null {
    if (!this.motion) return null;
    const base = this.base;
    const last = this.last;
    const bound = this.bound;
    if (!base || !last || !bound) return base?.strands ?? null;
    bound.attrs ??= followerAttributes(
      base.strands.points,
      base.strands.strandStart,
      bound.binding,
    );
    last.strands ??= {
      ...base.strands,
      points: placeFollowers(
        base.strands.points,
        bound.attrs,
        last.guides,
        bound.binding.guidePoints,
        last.pose,
      ),
    };
    return last.strands;
  }

  /** Every how many points each strand is drawn while playing (1: all of them). */
  get pointStride(): number {
    return this.motion ? this.stride : 1;
  }

  /** Test probe: the strand shader's placement of the last frame read back from the GPU
   *  (followerProbe.ts) against the CPU reference (drawn): the vertices compared, the largest
   *  distance between the two and the largest distance the reference moved a point from its
   *  groom (world units); null while nothing follows on the GPU. */
  checkFollowers(): { points: number; maxDifference: number; maxMoved: number } | null {
    const base = this.base;
    if (!this.motion || !this.bound?.gpu || !this.last || !base) return null;
    const gpu = this.d.hairView.readFollowed();
    const ref = this.drawn?.points;
    if (!gpu || !ref) return null;
    const groom = base.strands.points;
    const { placed, pointOf } = gpu;
    let maxDifference = 0;
    let maxMoved = 0;
    for (let v = 0; v < pointOf.length; v++) {
      const p = 3 * pointOf[v];
      maxDifference = Math.max(
        maxDifference,
        Math.hypot(
          placed[3 * v] - ref[p],
          placed[3 * v + 1] - ref[p + 1],
          placed[3 * v + 2] - ref[p + 2],
        ),
      );
      maxMoved = Math.max(
        maxMoved,
        Math.hypot(ref[p] - groom[p], ref[p + 1] - groom[p + 1], ref[p + 2] - groom[p + 2]),
      );
    }
    const points = pointOf.length;
    return { points, maxDifference, maxMoved };
  }

  get frame(): number {
    return this.frameNo;
  }

  /** Frames drawn per second of wall time since the first frame of this play. */
  get fps(): number {
    const s = (performance.now() - this.firstDrawn) / 1000;
    return this.drawnCount > 1 && s > 0 ? (this.drawnCount - 1) / s : 0;
  }

  play(motion: MotionName, wind: WindSettings = DEFAULT_WIND): void {
    if (this.motion) this.stop();
    const base = this.d.shown();
    if (!base || base.strands.strandStart.length < 2) {
      this.d.say('Nothing to play: there is no hair yet');
      return;
    }
    const s = this.d.editor.session;
    const play = this.playId + 1;
    const pointStride = this.d.viewer.motionPointStride();
    const sent = this.d.client.motion({
      type: 'motionStart',
      play,
      pointStride,
      motion,
      seed: s.growth.seed,
      body: !!s.bust,
      ...(motion === 'wind' ? { wind } : {}),
      strands: {
        points: base.strands.points,
        strandStart: base.strands.strandStart,
        ...(base.strands.tailCurves ? { tailCurves: base.strands.tailCurves } : {}),
      },
    });
    if (!sent) {
      this.d.say('The solver is not ready yet: play again in a moment');
      return;
    }
    this.motion = motion;
    this.playId = play;
    this.stride = pointStride;
    this.base = base;
    this.bound = null;
    this.last = null;
    this.frameNo = 0;
    this.drawnCount = 0;
    this.times.rebuilds = 0;
    this.startTime = performance.now();
    this.sent = [this.startTime];
    this.requested = 0;
    this.spare = [];
    this.setStatus();
    this.d.say(`Playing ${MOTION_LABELS[motion]}`);
    this.d.changed();
  }

  stop(): void {
    if (!this.motion) return;
    this.motion = null;
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    this.d.client.motion({ type: 'motionStop' });
    this.d.hairView.unfollow();
    for (const [m, matrix] of this.saved) {
      m.matrix.copy(matrix);
      m.matrixAutoUpdate = true;
      m.matrixWorldNeedsUpdate = true;
    }
    this.saved.clear();
    this.d.viewer.invalidateFrameCache();
    const base = this.base;
    const rebuilt = this.times.rebuilds > 0;
    this.base = null;
    this.bound = null;
    this.last = null;
    this.sent = [];
    this.spare = [];
    // the groom again, as it was shown (the same arrays) where frames were drawn rebuilt; hair
    // newer than it is already shown
    if (base && rebuilt && this.d.shown() === base)
      this.d.hairView.show(base.strands, base.lighting, undefined, true, base.attributes ?? null);
    this.setStatus();
    this.d.say('Motion stopped: the groom is back');
    this.d.viewer.requestRender();
    this.d.changed();
  }

  private draw(frame: number, guides: Float32Array, pose: Float32Array): void {
    const base = this.base;
    const bound = this.bound;
    if (!base || !bound) return;
    if (this.d.shown() !== base) {
      // new hair from the solver: it is shown, the motion over the old hair ends
      this.base = null;
      this.stop();
      return;
    }
    this.frameNo = frame;
    const b0 = performance.now();
    this.times.workerMs = b0 - (this.sent.shift() ?? b0);
    // the frame drawn before is no longer read: the worker fills its array again
    if (this.last) this.spare.push(this.last.guides);
    this.last = { guides, pose, strands: null };
    if (frame === 0 && bound.gpu) {
      // the groom itself, on screen already: the first frame drawn is the next one
      this.setStatus();
      this.schedule();
      return;
    }
    if (bound.gpu) this.d.hairView.followFrame(guides, pose);
    else {
      const strands = this.drawn as StrandArrays;
      this.d.hairView.show(strands, base.lighting, undefined, false, null);
      this.times.rebuilds++;
    }
    this.times.buildMs = performance.now() - b0;
    const m = new THREE.Matrix4().set(
      pose[0],
      pose[1],
      pose[2],
      pose[9],
      pose[3],
      pose[4],
      pose[5],
      pose[10],
      pose[6],
      pose[7],
      pose[8],
      pose[11],
      0,
      0,
      0,
      1,
    );
    for (const mesh of this.d.meshes()) {
      if (!mesh) continue;
      if (!this.saved.has(mesh)) {
        mesh.updateMatrix();
        this.saved.set(mesh, mesh.matrix.clone());
        mesh.matrixAutoUpdate = false;
      }
      mesh.matrix.multiplyMatrices(m, this.saved.get(mesh) as THREE.Matrix4);
      mesh.matrixWorldNeedsUpdate = true;
    }
    // the head is in the frame cache's static layer: it moved
    this.d.viewer.invalidateFrameCache();
    this.d.viewer.requestRender();
    if (this.drawnCount === 0) this.firstDrawn = performance.now();
    this.drawnCount++;
    this.setStatus();
    this.schedule();
  }

  /** Keeps PIPELINE requests in flight: each asks for the next frame when it is due (wall time at
   *  24 per second) or already late, else waits until it is. */
  private schedule(): void {
    while (this.motion && this.sent.length < PIPELINE && this.timer === null) {
      const due = Math.floor(((performance.now() - this.startTime) / 1000) * MOTION_FRAME_RATE);
      if (this.requested > due) {
        // a frame ahead already asked for: ask again when the last one asked is due
        const at = this.startTime + (this.requested * 1000) / MOTION_FRAME_RATE;
        this.timer = setTimeout(
          () => {
            this.timer = null;
            this.schedule();
          },
          Math.max(1, at - performance.now()),
        );
        return;
      }
      this.requested += 1;
      this.sent.push(performance.now());
      const recycle = this.spare;
      this.spare = [];
      this.d.client.motion({
        type: 'motionStep',
        frames: 1,
        ...(recycle.length > 0 ? { recycle } : {}),
      });
    }
  }

  private setStatus(): void {
    const el = this.d.statusElement;
    el.dataset.motion = this.motion ?? '';
    el.dataset.motionFrame = String(this.motion ? this.frameNo : 0);
  }
}
