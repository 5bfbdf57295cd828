// Reference pictures: photos the user traces over, shown behind the head facing the camera of
// the view each was placed in. They are part of the session (undoable, saved, linked) but do not
// affect the hair. A session names each picture by the SHA-256 of its file, as it names a loaded
// head: the bytes travel beside the session in a saved file and stay in the browser's store.
import type { Vec3 } from './vec3';

/** The views a picture can face, as the screenshots name them (scripts/screenshots.ts): the
 *  front (+z), the side (+x: the head's left, on the viewer's right from the front) and the
 *  back (-z). */
export const REFERENCE_VIEWS = ['front', 'side', 'back'] as const;
export type ReferenceView = (typeof REFERENCE_VIEWS)[number];

/** The picture file formats the app opens. */
export const PICTURE_FORMATS = ['png', 'jpeg', 'webp'] as const;
export type PictureFormat = (typeof PICTURE_FORMATS)[number];

/** One placed picture. Sizes and offsets are in world units (1 unit = 10 cm). */
export interface ReferenceImage {
  /** The file's name as opened, ≤ 255 characters. */
  name: string;
  /** SHA-256 of the file's bytes, 64 lowercase hex digits. */
  hash: string;
  format: PictureFormat;
  /** The picture's size in pixels (its aspect ratio sizes the plane). */
  width: number;
  height: number;
  view: ReferenceView;
  /** 0 (invisible) to 1 (opaque). */
  opacity: number;
  /** The picture's height in world units. */
  scale: number;
  /** The picture's centre moved right and up in its own plane, world units. */
  offset: [number, number];
  /** Hidden ("Hide" in the panel); absent = shown. */
  hidden?: true;
}

/** The ranges the reader accepts and the panel offers, and each value's grid. */
export const REFERENCE_RANGES = {
  opacity: { min: 0, max: 1, quantum: 1e-3, default: 0.6 },
  scale: { min: 0.1, max: 20, quantum: 1e-4, default: 3.2 },
  offset: { min: -10, max: 10, quantum: 1e-4, default: 0 },
} as const;

/** The direction from the head towards the camera of each view. */
export const VIEW_DIRECTIONS: Record<ReferenceView, Vec3> = {
  front: [0, 0, 1],
  side: [1, 0, 0],
  back: [0, 0, -1],
};

/** The point a picture's plane passes through before its offset: the orbit target of the
 *  default camera (defaultCamera.ts), about the middle of the head. */
export const REFERENCE_CENTRE: Vec3 = [0, -0.55, 0];

/** The named view nearest to looking from `toCamera` (the direction from the head to the
 *  camera): the one with the largest dot product; a camera on the -x side is nearest the side
 *  view too (its picture then faces away, and is faint, until the camera comes round). */
export function nearestView(toCamera: Vec3): ReferenceView {
  const [x, , z] = toCamera;
  if (Math.abs(x) > Math.abs(z)) return 'side';
  return z >= 0 ? 'front' : 'back';
}

/** How visible a picture facing `view` is from a camera in direction `toCamera` (unit vector):
 *  1 within 15° of the view, fading to 0 at 40° and beyond. */
export function viewFade(view: ReferenceView, toCamera: Vec3): number {
  const d = VIEW_DIRECTIONS[view];
  const c = d[0] * toCamera[0] + d[1] * toCamera[1] + d[2] * toCamera[2];
  const lo = Math.cos((40 * Math.PI) / 180);
  const hi = Math.cos((15 * Math.PI) / 180);
  const t = Math.min(1, Math.max(0, (c - lo) / (hi - lo)));
  return t * t * (3 - 2 * t);
}

/** A new picture placed for `view` with the default opacity, size and offset. */
export function newReference(
  file: { name: string; hash: string; format: PictureFormat; width: number; height: number },
  view: ReferenceView,
): ReferenceImage {
  const R = REFERENCE_RANGES;
  return {
    ...file,
    view,
    opacity: R.opacity.default,
    scale: R.scale.default,
    offset: [R.offset.default, R.offset.default],
  };
}
