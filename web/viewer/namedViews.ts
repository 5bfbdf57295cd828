// The three still views a hairstyle is shown from (front, side, back), framed so the whole
// hairstyle fits: the README's screenshots, `hairsketch render` and the embed's `?view=` use
// them. No three.js here, so the command line can use it without loading it.
import type { Vec3 } from '../model/vec3';
import { DEFAULT_CAMERA } from './defaultCamera';

export const VIEW_NAMES = ['front', 'side', 'back'] as const;
export type ViewName = (typeof VIEW_NAMES)[number];

export function isViewName(s: string): s is ViewName {
  return (VIEW_NAMES as readonly string[]).includes(s);
}

/** Camera positions for a hairstyle that fits the default bounding volume (the front one is the
 *  app's starting view), all aimed at DEFAULT_CAMERA.target. */
const POSITIONS: Record<ViewName, Vec3> = {
  front: DEFAULT_CAMERA.position,
  side: [7.4, 0.6, -0.6],
  back: [-4.2, 1.6, -5.6],
};

/** The lowest point the default framing shows whole, and the head's top: hair reaching lower is
 *  framed from farther away, aimed lower. */
const DEFAULT_FLOOR = -2.4;
const HEAD_TOP = 1.2;

/** Where the camera stands and looks for `view` of hair whose lowest point is at height
 *  `lowest` (world y; the head's own bottom when there is no hair). */
export function namedView(view: ViewName, lowest: number): { position: Vec3; target: Vec3 } {
  const floor = Number.isFinite(lowest) ? Math.min(DEFAULT_FLOOR, lowest) : DEFAULT_FLOOR;
  // the picture's height grows with the hair's reach below the default floor
  const scale = (HEAD_TOP - floor) / (HEAD_TOP - DEFAULT_FLOOR);
  const target: Vec3 = [0, DEFAULT_CAMERA.target[1] + (floor - DEFAULT_FLOOR) / 2, 0];
  const position = POSITIONS[view].map(
    (v, a) => target[a] + (v - DEFAULT_CAMERA.target[a]) * scale,
  );
  return { position: position as Vec3, target };
}
