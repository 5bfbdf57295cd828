// Plays a motion over the hair on screen: the worker simulates (protocol.ts motionStart /
// motionStep / motionStop), each frame it sends is drawn as the hair and moves the head and body
// meshes by the head's pose. Frames are asked for at 24 per second of wall time (several at once
// when drawing falls behind, at most MAX_CATCH_UP), PIPELINE requests ahead so the worker steps
// the next frame while this thread draws the current one. A frame with the strands' layout moves
// the shown geometry's points (HairView.showPositions) instead of rebuilding it, and its array
// goes back to the worker for a later frame (transferred both ways). Stop shows the groom's
// result again, the very arrays it was (bit for bit); an edit that changes the hair, or new hair
// from the solver, stops the motion first.
import * as THREE from 'three';
import type { Editor } from '../editor/editor';
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

const MAX_CATCH_UP = 4;
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
  private base: SolveResult | null = null;
  private drawnStrands: StrandArrays | null = null;
  private startTime = 0;
  private frameNo = 0;
  /** Requests sent and not yet answered, and when each was sent (oldest first). */
  private sent: number[] = [];
  /** The frame the last request sent will answer with. */
  private requested = 0;
  /** Waiting for frame 0 of this play (frames of a motion stopped before are dropped). */
  private starting = false;
  /** Frame arrays drawn and replaced, to give back to the worker with the next request. */
  private spare: Float32Array[] = [];
  private timer: ReturnType<typeof setTimeout> | null = null;
  private saved = new Map<THREE.Object3D, THREE.Matrix4>();
  /** Frames drawn and when the first was drawn (frames per second while playing). */
  private drawnCount = 0;
  private firstDrawn = 0;
  /** The last frame's wait for the worker and its geometry update on this thread (ms), and the
   *  frames of this play drawn by rebuilding the geometry. */
  readonly times = { workerMs: 0, buildMs: 0, rebuilds: 0 };

  constructor(private readonly d: MotionPlayerDeps) {
    d.client.onMotion = (msg) => {
      if (!this.motion) return;
      if (msg.type === 'motionError') {
        this.stop();
        d.say(`Motion stopped: ${msg.message}`);
        return;
      }
      if (this.starting && msg.frame !== 0) return; // a frame of the motion played before
      this.starting = false;
      this.draw(msg.frame, msg.points, msg.pose);
    };
    d.editor.listen((c) => {
      if (this.motion && c.sessionChanged && changesHair(c.previous, c.session)) this.stop();
    });
  }

  get playing(): MotionName | null {
    return this.motion;
  }

  /** What is drawn while playing (null when stopped: the groom's result is drawn). */
  get drawn(): StrandArrays | null {
    return this.motion ? this.drawnStrands : null;
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
    const sent = this.d.client.motion({
      type: 'motionStart',
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
    this.base = base;
    this.drawnStrands = base.strands;
    this.frameNo = 0;
    this.drawnCount = 0;
    this.times.rebuilds = 0;
    this.startTime = performance.now();
    this.sent = [this.startTime];
    this.requested = 0;
    this.starting = true;
    this.spare = [];
    // drawn at interactive detail while it moves, in full once it stops
    this.d.viewer.hold('motion', true);
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
    this.d.viewer.hold('motion', false);
    for (const [m, matrix] of this.saved) {
      m.matrix.copy(matrix);
      m.matrixAutoUpdate = true;
      m.matrixWorldNeedsUpdate = true;
    }
    this.saved.clear();
    this.d.viewer.invalidateFrameCache();
    const base = this.base;
    this.base = null;
    this.drawnStrands = null;
    this.sent = [];
    this.spare = [];
    // the groom again, as it was shown (the same arrays); hair newer than it is already shown
    if (base && this.d.shown() === base)
      this.d.hairView.show(base.strands, base.lighting, undefined, true, base.attributes ?? null);
    this.setStatus();
    this.d.say('Motion stopped: the groom is back');
    this.d.viewer.requestRender();
    this.d.changed();
  }

  private draw(frame: number, points: Float32Array, pose: Float32Array): void {
    const base = this.base;
    if (!base) return;
    if (this.d.shown() !== base) {
      // new hair from the solver: it is shown, the motion over the old hair ends
      this.base = null;
      this.stop();
      return;
    }
    this.frameNo = frame;
    const b0 = performance.now();
    this.times.workerMs = b0 - (this.sent.shift() ?? b0);
    const strands: StrandArrays = { ...base.strands, points };
    const before = this.drawnStrands?.points;
    this.drawnStrands = strands;
    // the first frame is built in full (the groom's own arrays are never written), later ones
    // move its points
    if (this.drawnCount === 0 || !this.d.hairView.showPositions(strands)) {
      this.d.hairView.show(strands, base.lighting, undefined, false, null);
      this.times.rebuilds++;
    }
    // the frame drawn before is no longer viewed by the geometry (lines took the new array,
    // strips copied it): the worker fills it again
    if (before && before !== base.strands.points && before !== points) this.spare.push(before);
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

  /** Keeps PIPELINE requests in flight: each asks for the frames due by now (wall time at 24
   *  per second; at least the next one, so it is ready when due), or waits until one is. */
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
      const frames = Math.min(MAX_CATCH_UP, Math.max(1, due - this.requested));
      this.requested += frames;
      this.sent.push(performance.now());
      const recycle = this.spare;
      this.spare = [];
      this.d.client.motion({
        type: 'motionStep',
        frames,
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
