// The session model: everything the user made, as plain immutable JSON-able data.

import type { CurveParamValues, PlainTieKind } from './curveParams';
import type { HairDetail } from './detail';
import type { DividingSettings } from './dividingFrames';
import { type GridPreset, gridForSession } from './grid';
import { DEFAULT_GROWTH, type GrowthParams } from './growthParams';
import type { GridSpec } from './hairArrays';
import type { HairLook } from './hairLook';
import { tieNear } from './kinds';
import type { MirrorPlane } from './mirror';
import type { PonytailCircle } from './ponytailGeometry';
import type { ReferenceImage } from './referenceImage';
import type { SessionSettings } from './sessionSchema';
import type { SurfaceMode } from './supportingSurface';
import type { Vec3 } from './vec3';

export interface Viewpoint {
  position: Vec3; // camera position when the curve was drawn
  target: Vec3; // orbit target
}

/** A stream curve (S4.1–S4.4). */
export interface StreamCurve {
  id: string;
  type: 'stream';
  points: Vec3[]; // world units, consecutive distance = grid step d
  extend: boolean; // append fading extrapolated segments (S4.1)
  viewpoint: Viewpoint;
  /** Supporting surface mode (S4.3); absent = 'ruled' (sessions made before the option). */
  surfaceMode?: SurfaceMode;
  /** Its own Volume (curveParams.ts; world units, 0 to 0.3; 0: the Hair panel's). The reader
   *  spells it out; a curve a tool makes may leave it out (0). */
  volume?: number;
  /** Detail for the strands this curve governs (nearest curve at the root), instead of the
   *  session's. */
  detail?: HairDetail;
  /** Id of its mirrored twin (model/mirror.ts), edited together with it. */
  mirror?: string;
}

/** A dividing curve (S4.5) drawn on the scalp. `normals[i]` is the scalp normal at points[i];
 *  sigma and h in grid steps, alpha0/alpha1 in radians. */
export interface DividingCurve extends DividingSettings {
  id: string;
  type: 'dividing';
  points: Vec3[];
  normals: Vec3[];
  viewpoint: Viewpoint;
  detail?: HairDetail;
  mirror?: string;
}

/** A ponytail (S4.6): `points` is the spine (edited like a stream curve); the cross-section and
 *  the two profile strokes are kept as drawn, the circles computed from them (C1 first); its
 *  scalars (the centripetal `tightness`) are its rows of CURVE_PARAMS.ponytail. */
export interface PonytailCurve extends CurveParamValues<'ponytail'> {
  id: string;
  type: 'ponytail';
  points: Vec3[];
  extend: boolean;
  viewpoint: Viewpoint; // where the spine was drawn
  crossSection: Vec3[];
  profiles: [Vec3[], Vec3[]];
  circles: PonytailCircle[];
  detail?: HairDetail;
  mirror?: string;
}

/** A tie that is a stroke and its scalar parameters (curveParams.ts PLAIN_TIE_KINDS, defined in
 *  kinds/tie.ts): a braid's `points` are the stroke from the scalp along the braid, scalp to tip
 *  (drawn like a ponytail's spine); a bun's, a loop drawn on the head where the bun sits
 *  (solver-cpp/src/braid_bun.hpp). Its scalars are those of CURVE_PARAMS[K] (lengths in world
 *  units, crossings per world unit; a bun's radius 0: the loop's size). */
export type PlainTieCurve<K extends PlainTieKind> = CurveParamValues<K> & {
  id: string;
  type: K;
  points: Vec3[];
  extend: boolean;
  viewpoint: Viewpoint;
  detail?: HairDetail;
  mirror?: string;
};
export type BraidCurve = PlainTieCurve<'braid'>;
export type BunCurve = PlainTieCurve<'bun'>;

export type StyleCurve =
  | StreamCurve
  | DividingCurve
  | PonytailCurve
  | { [K in PlainTieKind]: PlainTieCurve<K> }[PlainTieKind];
export type CurveType = StyleCurve['type'];

/** The head file formats a session can name (head/headFileFormats.ts reads each of them). */
export const HEAD_FORMATS = ['obj', 'gltf', 'glb', 'ply', 'stl'] as const;
export type HeadFormat = (typeof HEAD_FORMATS)[number];

/** An axis of the head's frame (a loaded head's quarter turns are about one). */
export type Axis = 'x' | 'y' | 'z';

/** A quarter turn step of a loaded head (loadHead.ts rotateLoadedHead), in the order applied. */
export interface HeadTurn {
  axis: Axis;
  /** 0..3 quarter turns, counter-clockwise looking down the axis. */
  quarterTurns: number;
}

/** A user's head mesh, named by its file's content: the normalised mesh is
 *  loadHeadFile(name, bytes, { up }) turned by each of `turns` in order (head/headStore.ts
 *  loadHeadRef), where `bytes` are the file whose SHA-256 is `hash`. The session does not hold
 *  the bytes: a session file embeds them beside it (sessionFile.ts), a link does not, and the
 *  browser keeps them by hash (head/headStore.ts). */
export interface HeadRef {
  kind: 'mesh';
  /** The file's name as opened (its extension tells the format to the loader), ≤ 255 characters. */
  name: string;
  /** SHA-256 of the file's bytes, 64 lowercase hex digits. */
  hash: string;
  format: HeadFormat;
  /** The file's up axis, as guessed or told when it was opened. */
  up: 'y' | 'z';
  turns: HeadTurn[];
}

/** A scalp brush stroke (head/scalpPaint.ts): a triangle is covered when its centroid is within
 *  `radius` (world units, in (0, 2]) of the polyline `points` (one point: a dab); `erase` removes
 *  scalp, else it adds scalp. */
export interface ScalpStroke {
  erase: boolean;
  radius: number;
  points: Vec3[];
}

/** A session (sessionSchema.ts lists its fields; the settings, avoidScalp and fall among them,
 *  come from its SESSION_SETTINGS). */
export interface SessionState extends SessionSettings {
  version: 4;
  /** The built-in mannequin head, or a user's head mesh. */
  head: 'builtin' | HeadRef;
  grid: GridPreset;
  curves: readonly StyleCurve[];
  growth: GrowthParams;
  hairColor: string; // CSS hex colour
  /** The colour model (melanin, redness, dye, grey, tips…; hairLook.ts); absent = the hair shows
   *  hairColor as it is (sessions made before it, or a colour picked in the colour box). */
  hairLook?: HairLook;
  /** The colour of the ties' bands, #rrggbb (with `ties`; absent = hairLook.ts
   *  DEFAULT_BAND_COLOR). Kept beside hairLook rather than in it: a session showing its direct
   *  colour (no hairLook, as new sessions do) still has bands to colour. */
  bandColor?: string;
  /** Curl, clump, frizz and length jitter of every strand (absent = none). */
  detail?: HairDetail;
  /** Scalp brush strokes applied in order over the head's default scalp (absent = none). */
  scalpPaint?: ScalpStroke[];
  /** The mirror plane n·p = offset (unit n); absent = x = 0 (the built-in head's). */
  symmetry?: MirrorPlane;
  /** Reference pictures shown behind the head (absent = none); they do not affect the hair. */
  references?: ReferenceImage[];
}

/** "Extend past the end" of a new stream curve or ponytail: with natural fall, off (the hair ends
 *  where the curve ends; on lets it grow on); without it, the paper's fading extension (on). */
export function newCurveExtends(s: Pick<SessionState, 'fall'>): boolean {
  return !s.fall;
}

// How near (world units: 3 cm) a stream stroke's end must come to a tie to continue into it.
const TIE_REACH = 0.3;

/** The tie (ponytail, braid or bun) a stream stroke ending at `end` runs into, if any: its end
 *  lies within 3 cm of where a ponytail or braid starts, or of a bun's loop. Such a stroke's hair
 *  goes on into the tie ("Extend past the end" on) instead of ending where the stroke ends. */
export function tieAtEnd(curves: readonly StyleCurve[], end: Vec3): StyleCurve | null {
  let best: StyleCurve | null = null;
  let bestD = TIE_REACH;
  for (const c of curves) {
    for (const p of tieNear(c) ?? []) {
      const d = Math.hypot(p[0] - end[0], p[1] - end[1], p[2] - end[2]);
      if (d < bestD) {
        bestD = d;
        best = c;
      }
    }
  }
  return best;
}

/** "Extend past the end" of a new stream curve: as newCurveExtends says, or on when the stroke
 *  ends at a tie (tieAtEnd). */
export function streamExtends(s: Pick<SessionState, 'fall' | 'curves'>, points: readonly Vec3[]) {
  const end = points[points.length - 1];
  return newCurveExtends(s) || (!!end && tieAtEnd(s.curves, end) !== null);
}

/** How far hair may hang below the scalp, for the bounding volume (model/grid.ts
 *  gridForSession): with natural fall, hair no curve governs grows to the maximum length; without
 *  it (the paper's method) the curves alone decide, and the volume is what it always was. */
export function hangLength(s: Pick<SessionState, 'fall' | 'growth'>): number {
  return s.fall ? s.growth.maxLength : 0;
}

export { DEFAULT_GROWTH };

/** The hair colour of a new session, and of one that names none. */
export const DEFAULT_HAIR_COLOR = '#5a3825';

export function emptySession(
  grid: GridPreset,
  growth: GrowthParams = DEFAULT_GROWTH,
): SessionState {
  return {
    version: 4,
    head: 'builtin',
    grid,
    curves: [],
    growth,
    hairColor: DEFAULT_HAIR_COLOR,
    fall: true,
    sections: true,
    finish: true,
    bust: true,
    shape: true,
    ties: true,
    hairline: true,
    curlVolume: true,
    nape: true,
    coilVolume: true,
    roundPlaits: true,
    tieVolume: true,
    compactBun: true,
    clumpAll: true,
    faceClear: true,
    locks: true,
  };
}

export function addCurve(s: SessionState, c: StyleCurve): SessionState {
  return { ...s, curves: [...s.curves, c] };
}

export function deleteCurve(s: SessionState, id: string): SessionState {
  const curves = s.curves.filter((c) => c.id !== id);
  return curves.length === s.curves.length ? s : { ...s, curves };
}

export function findCurve(s: SessionState, id: string | null): StyleCurve | null {
  return id === null ? null : (s.curves.find((c) => c.id === id) ?? null);
}

/** Replaces curve `id` by `update(curve)`; the same session when nothing changes. */
export function updateCurve(
  s: SessionState,
  id: string,
  update: (c: StyleCurve) => StyleCurve,
): SessionState {
  let changed = false;
  const curves = s.curves.map((c) => {
    if (c.id !== id) return c;
    const n = update(c);
    if (n !== c) changed = true;
    return n;
  });
  return changed ? { ...s, curves } : s;
}

/** Curve ids are unique within a session: a counter past the largest id in use. */
export function nextCurveId(s: SessionState): string {
  let max = 0;
  for (const c of s.curves) {
    const m = /^c(\d+)$/.exec(c.id);
    if (m) max = Math.max(max, Number(m[1]));
  }
  return `c${max + 1}`;
}

/** The grid a session's hair is solved on: gridForSession with its preset (or `preset`, a
 *  command line's override), its curves and how far its hair may hang. The one place the app, the
 *  exports, the embed and the command line get it. */
export function sessionGrid(
  s: Pick<SessionState, 'grid' | 'curves' | 'fall' | 'growth'>,
  headBounds: { min: Vec3; max: Vec3 } | undefined,
  preset: GridPreset = s.grid,
): GridSpec {
  return gridForSession(preset, s.curves, headBounds, hangLength(s));
}
