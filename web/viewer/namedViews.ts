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
/** The lowest point the views show when the bust is drawn (head/bodySdf.ts): the shoulders and
 *  the top of the chest, so the hair is seen resting on them. */
export const BUST_VIEW_FLOOR = -3.3;
const HEAD_TOP = 1.2;

/** How a framing made for the default floor grows for hair whose lowest point is at `lowest`
 *  and highest at `highest`: the picture's height grows with the hair's reach below the default
 *  floor and above the head's top (scale), and its middle moves by half of each (drop: down).
 *  Hair within the head's top frames as it always did (a big afro's top was cut off). */
function reachFraming(lowest: number, highest = HEAD_TOP): { scale: number; drop: number } {
  const floor = Number.isFinite(lowest) ? Math.min(DEFAULT_FLOOR, lowest) : DEFAULT_FLOOR;
  const top = Number.isFinite(highest) ? Math.max(HEAD_TOP, highest) : HEAD_TOP;
  return {
    scale: (top - floor) / (HEAD_TOP - DEFAULT_FLOOR),
    drop: (DEFAULT_FLOOR - floor) / 2 - (top - HEAD_TOP) / 2,
  };
}

/** Where the camera stands and looks for `view` of hair whose lowest point is at height
 *  `lowest` (world y; the head's own bottom when there is no hair). */
export function namedView(
  view: ViewName,
  lowest: number,
  highest = HEAD_TOP,
): { position: Vec3; target: Vec3 } {
  const { scale, drop } = reachFraming(lowest, highest);
  const target: Vec3 = [0, DEFAULT_CAMERA.target[1] - drop, 0];
  const position = POSITIONS[view].map(
    (v, a) => target[a] + (v - DEFAULT_CAMERA.target[a]) * scale,
  );
  return { position: position as Vec3, target };
}

/** The lowest point (world y) of the strands `points` (x, y, z per point) and of `floor` (the
 *  head's bottom, or the shoulders when the bust is shown): what the views must show. */
export function lowestPoint(points: ArrayLike<number>, floor: number): number {
  let low = floor;
  for (let i = 1; i < points.length; i += 3) if (points[i] < low) low = points[i];
  return low;
}

/** The highest point (world y) of the strands `points`, at least the head's top the framings
 *  are made for. */
export function highestPoint(points: ArrayLike<number>): number {
  let high = HEAD_TOP;
  for (let i = 1; i < points.length; i += 3) if (points[i] > high) high = points[i];
  return high;
}

/** The views the app's view control and keys give (app/actions.ts): straight at the head from
 *  the front, either side, the back and above, a little above eye level, at the starting view's
 *  distance. The person faces +z, so their left side is +x. */
export const APP_VIEW_NAMES = ['front', 'left', 'right', 'back', 'top'] as const;
export type AppViewName = (typeof APP_VIEW_NAMES)[number];

const ELEVATION = (8 * Math.PI) / 180;
const DIRECTIONS: Record<AppViewName, Vec3> = {
  front: [0, Math.sin(ELEVATION), Math.cos(ELEVATION)],
  left: [Math.cos(ELEVATION), Math.sin(ELEVATION), 0],
  right: [-Math.cos(ELEVATION), Math.sin(ELEVATION), 0],
  back: [0, Math.sin(ELEVATION), -Math.cos(ELEVATION)],
  // straight down, the face towards the bottom of the picture
  top: [0, Math.cos(0.01), Math.sin(0.01)],
};

/** How far down the app's views step out at a time, world units (15 cm). */
export const FRAMING_STEP = 1.5;

/** The floor an app view frames for hair reaching down to `lowest`: as low as the hair within
 *  the default floor; the shoulders' (BUST_VIEW_FLOOR) down to them; below them, the next of
 *  FRAMING_STEP steps under them. While a stroke lengthens the hair within a step the views keep
 *  their framing, so a place on the head stays where it was on the screen (a drawing trial: "the
 *  F, L and back views pull back and lower, so the head shifts on screen between strokes"). */
export function framingFloor(lowest: number): number {
  if (!(lowest < DEFAULT_FLOOR)) return lowest;
  if (lowest >= BUST_VIEW_FLOOR) return BUST_VIEW_FLOOR;
  return BUST_VIEW_FLOOR - FRAMING_STEP * Math.ceil((BUST_VIEW_FLOOR - lowest) / FRAMING_STEP);
}

/** An app view that frames the whole hairstyle: from `home` (the framing of the head, as at
 *  load) farther away and aimed lower as far as the hair reaches below the default floor
 *  (`lowest`, as for namedView, in steps: framingFloor), so hair down the back is in the
 *  picture. */
export function framedAppView(
  name: AppViewName,
  home: { position: Vec3; target: Vec3 },
  lowest: number,
  highest = HEAD_TOP,
): { position: Vec3; target: Vec3 } {
  const { scale, drop } = reachFraming(framingFloor(lowest), highest);
  const [p, t] = [home.position, home.target];
  const distance = Math.hypot(p[0] - t[0], p[1] - t[1], p[2] - t[2]) * scale;
  return appView(name, [t[0], t[1] - drop, t[2]], distance);
}

/** Where the camera stands for an app view, looking at `target` from `distance`. */
export function appView(
  name: AppViewName,
  target: Vec3 = DEFAULT_CAMERA.target,
  distance = startDistance(),
): { position: Vec3; target: Vec3 } {
  const d = DIRECTIONS[name];
  return {
    position: [
      target[0] + distance * d[0],
      target[1] + distance * d[1],
      target[2] + distance * d[2],
    ],
    target: [...target] as Vec3,
  };
}

function startDistance(): number {
  const p = DEFAULT_CAMERA.position;
  const t = DEFAULT_CAMERA.target;
  return Math.hypot(p[0] - t[0], p[1] - t[1], p[2] - t[2]);
}

/** What a view from `position` towards `target` is called: an app view's name when the camera
 *  looks along it (within 3°), "three-quarter front" for the starting view's direction (20° to
 *  the right of the front), else null (a free view). */
export function viewLabel(position: Vec3, target: Vec3): string | null {
  const v: Vec3 = [position[0] - target[0], position[1] - target[1], position[2] - target[2]];
  const n = Math.hypot(v[0], v[1], v[2]);
  if (!(n > 0)) return null;
  const close = (d: Vec3) => {
    const m = Math.hypot(d[0], d[1], d[2]);
    const c = (v[0] * d[0] + v[1] * d[1] + v[2] * d[2]) / (n * m);
    return c >= Math.cos((3 * Math.PI) / 180);
  };
  for (const name of APP_VIEW_NAMES) if (close(DIRECTIONS[name])) return name;
  const p = DEFAULT_CAMERA.position;
  const t = DEFAULT_CAMERA.target;
  if (close([p[0] - t[0], p[1] - t[1], p[2] - t[2]])) return 'three-quarter front';
  return null;
}
