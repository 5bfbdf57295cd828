// The motions the hair can play (HairSim, solver-cpp/src/hair_sim.hpp): their names in the UI,
// the command line and the worker protocol, and the numbers shared by the app's player and the
// motion export.

export const MOTIONS = ['settle', 'head-turn', 'nod', 'wind'] as const;
export type MotionName = (typeof MOTIONS)[number];

/** The UI's label of each motion. */
export const MOTION_LABELS: Record<MotionName, string> = {
  settle: 'Settle',
  'head-turn': 'Head turn',
  nod: 'Nod',
  wind: 'Wind',
};

/** Frames per second of the simulation (one step per frame) and of the motion export. */
export const MOTION_FRAME_RATE = 24;
/** Frames of a motion export when none are asked for (2 s). */
export const MOTION_DEFAULT_FRAMES = 48;
/** At most this many frames in a motion export (60 s). */
export const MOTION_MAX_FRAMES = 1440;
/** Strands simulated as guides at most; the others follow them. */
export const MOTION_MAX_GUIDES = 3000;
/** The point the head (and bust) turns about: the top of the neck, in world units (10 cm). */
export const MOTION_PIVOT: readonly [number, number, number] = [0, -1.0, -0.15];

/** The Wind motion's wind: where it comes from (degrees about the vertical axis: 0 the face's
 *  side, 90 the head's left, 180 behind, 270 its right) and its mean speed (m/s; gusts add and
 *  take up to half of it). */
export interface WindSettings {
  fromDeg: number;
  speed: number;
}
export const DEFAULT_WIND: WindSettings = { fromDeg: 0, speed: 3 };
/** The wind speeds the Motion controls offer (m/s). */
export const WIND_SPEED_RANGE = { min: 0, max: 30, step: 0.5 };
/** The directions the Motion controls offer, by name. */
export const WIND_FROM: readonly { label: string; deg: number }[] = [
  { label: 'from the front', deg: 0 },
  { label: 'from the left', deg: 90 },
  { label: 'from behind', deg: 180 },
  { label: 'from the right', deg: 270 },
];

/** Why `w` is no wind the simulation takes, or null. */
export function windProblem(w: WindSettings): string | null {
  if (!Number.isFinite(w.fromDeg)) return 'the wind direction must be a number of degrees';
  if (!(w.speed >= WIND_SPEED_RANGE.min && w.speed <= WIND_SPEED_RANGE.max))
    return `the wind speed must be ${WIND_SPEED_RANGE.min} to ${WIND_SPEED_RANGE.max} m/s`;
  return null;
}

/** The C++ enum's value (SimMotion). */
export function motionCode(m: MotionName): number {
  return MOTIONS.indexOf(m);
}

export function isMotionName(s: string): s is MotionName {
  return (MOTIONS as readonly string[]).includes(s);
}

/** One frame of a motion: its guides (guideFollowers.ts GuideBinding's layout: 3 * (guide * G +
 *  point) + axis; the strands are placed on them by placeFollowers, or the strand shader) and the
 *  head's rigid pose, pose[0..8] its rotation row-major and pose[9..11] its translation
 *  (world = R * groom + t). */
export interface MotionFrame {
  frame: number;
  guides: Float32Array;
  pose: Float32Array;
}
