// A motion for export: the full hair grown (growSession.ts) played on the same engine, frame by
// frame, the strands placed on the guides as the app's strand shader places them
// (model/guideFollowers.ts placeFollowers). The app's export worker and `hairsketch grow --motion` both call simulateMotion, so the
// same session, motion and frame count give the same .usda bytes in both.
import { followerAttributes, placeFollowers } from '../model/guideFollowers';
import type { StrandArrays } from '../model/hairArrays';
import {
  DEFAULT_WIND,
  isMotionName,
  MOTION_FRAME_RATE,
  MOTION_MAX_FRAMES,
  MOTIONS,
  type MotionName,
  type WindSettings,
  windProblem,
} from '../model/motion';
import type { SessionState } from '../model/session';
import { type SolverEngine, SolverError } from '../solver/engine';
import type { ExportInput } from './types';

/** Why `frames` is not a frame count for a motion export, or null when it is one. */
export function motionFramesProblem(frames: number): string | null {
  if (!Number.isInteger(frames) || frames < 1)
    return `frames must be a positive whole number, got ${frames}`;
  if (frames > MOTION_MAX_FRAMES)
    return `frames must be at most ${MOTION_MAX_FRAMES} (${MOTION_MAX_FRAMES / MOTION_FRAME_RATE} s at ${MOTION_FRAME_RATE} fps), got ${frames}`;
  return null;
}

/** Why `name` is not a motion, or null when it is one. */
export function motionNameProblem(name: string): string | null {
  return isMotionName(name) ? null : `unknown motion "${name}": one of ${MOTIONS.join(', ')}`;
}

/** Plays `motion` over `strands` (grown on `engine`, whose head and body it collides with) for
 *  `frames` frames at 24 fps, frame 0 being the groom itself: the seed is the session's, the
 *  body is used when the session's bust is on; `wind`: the Wind motion's direction and speed. */
export function simulateMotion(
  engine: SolverEngine,
  strands: StrandArrays,
  session: SessionState,
  motion: MotionName,
  frames: number,
  wind: WindSettings = DEFAULT_WIND,
): NonNullable<ExportInput['motion']> {
  const problem = motionFramesProblem(frames) ?? motionNameProblem(motion) ?? windProblem(wind);
  if (problem) throw new SolverError(problem, 'invalid_input');
  const run = engine.startMotion(strands, {
    motion,
    seed: session.growth.seed,
    body: !!session.bust,
    wind,
  });
  try {
    const out: NonNullable<ExportInput['motion']> = {
      frames: [],
      poses: [],
      frameRate: MOTION_FRAME_RATE,
    };
    const attrs = followerAttributes(strands.points, strands.strandStart, run.binding);
    for (let f = 0; f < frames; f++) {
      const frame = run.step();
      out.frames.push(
        f === 0
          ? strands.points
          : placeFollowers(
              strands.points,
              attrs,
              frame.guides,
              run.binding.guidePoints,
              frame.pose,
            ),
      );
      out.poses.push(frame.pose);
    }
    return out;
  } finally {
    run.dispose();
  }
}
