// The bounds the session reader enforces on whatever comes in (docs/session-format.md lists
// them), and the reader's answer type.

import { POSITION_SCALE } from './gridNumbers';
import { MAX_SEGMENTS, MAX_STRANDS } from './growthParams';

/** A reader's answer: the value, or the first problem as one line naming its field. */
export type Parsed<T> = { ok: true; value: T } | { ok: false; error: string };

/** Every bound the reader enforces (docs/session-format.md, "Whatever comes in", lists them). */
export const SESSION_LIMITS = {
  /** Style curves per session. */
  maxCurves: 200,
  /** Points per polyline (a curve's points, a cross-section, a profile); circles per ponytail. */
  maxPoints: 5000,
  /** Points of all polylines, normals and circles of a session together. */
  maxSessionPoints: 100_000,
  /** Scalp-avoidance constraints of a version 1 session (read, then dropped by its migration). */
  maxAvoid: 200_000,
  /** |avoid target component|: the app writes 0.3-long vectors; curve targets are at most 1. */
  maxAvoidTarget: 10,
  /** Curve geometry (points, cross-sections, profiles, circle centres) lies within the box
   *  (grid.ts BOX_MIN..BOX_MAX) grown by this many world units on every side. Strokes are not
   *  clipped to the box: off the head they are drawn on the depth plane of the scalp, up to the
   *  edge of the screen, and at the widest view the app allows (OrbitControls.maxDistance 25,
   *  35° field of view) a 21:9 screen spans about ±8 units vertically and ±18 horizontally
   *  around the orbit target. 25 units keeps every such stroke, while coordinates like 1e3 or
   *  1e6 are refused. */
  curveMargin: 25,
  /** A curve's viewpoint (camera position and orbit target) lies within the box grown by this
   *  many units: a curve starts on the visible scalp, within the camera's far plane (100 units),
   *  and the orbit target is at most 25 units from the camera. */
  viewMargin: 125,
  /** Points that must differ (consecutive points of a polyline, a viewpoint's position and
   *  target) differ on this grid (quantize.ts positions: 1e-4 world units), so they stay apart
   *  when the editor or a link quantises them; the app's curves are resampled at half a grid
   *  step or more (≥ 0.027). */
  positionStep: 1 / POSITION_SCALE,
  /** |n| of a unit vector (dividing normals, ponytail axes) is within this of 1. */
  unitTolerance: 1e-3,
  /** Ponytail circle radius: at least half a position step (not 0 once quantised) and at most
   *  this (world units). */
  maxRadius: 100,
  /** growth.maxSegments (per strand). */
  maxSegments: MAX_SEGMENTS,
  /** growth.maxStrands (0 = no cap). */
  maxStrands: MAX_STRANDS,
  /** Root directions sampled: ceil(180 / thetaStepDeg) · ceil(360 / phiStepDeg). */
  maxRootSamples: 4_000_000,
  /** Scalp brush strokes per session, and their points together (a stroke has at least one). */
  maxStrokes: 4096,
  maxStrokePoints: 100_000,
  /** Scalp brush radius: greater than 0 (at least half a position step) and at most this (world
   *  units: 20 cm). */
  maxBrushRadius: 2,
  /** |symmetry.offset|: the mirror plane passes within this of the origin (world units, 1 m). */
  maxPlaneOffset: 10,
  /** Characters of a head's file name; quarter turns of a loaded head. */
  maxHeadName: 255,
  maxTurns: 64,
  /** Bytes of a head file a session file embeds, after inflating (refused past it while
   *  inflating). */
  maxHeadFileBytes: 256 * 1024 * 1024,
  /** Reference pictures per session; pixels of one picture (50 megapixels); bytes of one
   *  picture file (a session file embeds each once). */
  maxReferences: 8,
  maxPicturePixels: 50_000_000,
  maxPictureFileBytes: 64 * 1024 * 1024,
  /** Characters in any string (but headFile.data: maxHeadFileData); nesting depth and values of
   *  the whole input. */
  maxString: 1024,
  maxDepth: 10,
  maxNodes: 2_500_000,
} as const;
const L = SESSION_LIMITS;
/** MAX_HEAD_FILE_BYTES, as the reader's limits name it. */
export const MAX_HEAD_FILE_BYTES = L.maxHeadFileBytes;
/** Characters of pictureFiles[i].data: the base64 of a picture file of at most
 *  maxPictureFileBytes. */
export const MAX_PICTURE_FILE_DATA = 4 * Math.ceil(L.maxPictureFileBytes / 3);
/** Characters of headFile.data: the base64 of a deflate stream of at most maxHeadFileBytes
 *  (stored blocks add 5 bytes per 64 KiB to incompressible data). */
export const MAX_HEAD_FILE_DATA = 4 * Math.ceil((L.maxHeadFileBytes * 1.001 + 1024) / 3);
