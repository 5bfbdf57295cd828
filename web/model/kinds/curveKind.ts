// What the model knows of one kind of style curve, in one place: each kind's module (stream.ts,
// dividing.ts, ponytail.ts; tie.ts for braids and buns) defines one CurveKindDef, and index.ts
// lists them in a table that the generic code (the reader, the quantiser, the solver packing, mirroring and
// share links) loops over instead of branching on a kind's name. A kind's scalar parameters
// are its rows of curveParams.ts CURVE_PARAMS; its fields, read rules and blocks are here.
//
// Adding a kind: a plain tie (its stroke and its scalars, as a braid) is a name in
// curveParams.ts PLAIN_TIE_KINDS, its rows in CURVE_PARAMS and a row in tie.ts PLAIN_TIES; a kind
// with fields of its own also has its curve type in session.ts, a module here and a row in
// index.ts. Then its C++ constraints and its tool (docs/session-format.md, worked example).
import type { CurveKindName } from '../curveParams';
import type { Reader, Writer } from '../linkBytes';
import type { StyleCurve, Viewpoint } from '../session';
import type { PlainRecord } from '../sessionMigrations';
import type { SurfaceMode } from '../supportingSurface';
import type { Vec3 } from '../vec3';

/** The curve of kind K. */
export type CurveOf<K extends CurveKindName> = Extract<StyleCurve, { type: K }>;

/** What the strict reader hands a kind: the fields every curve has, already read and checked,
 *  and the kind's scalar parameters (each present, within its range). */
export interface ReadBase {
  /** The curve's record, its keys checked against the kind's fields. */
  o: PlainRecord;
  /** Where the curve is in the session, for error messages (`curves[3]`). */
  path: string;
  id: string;
  points: Vec3[];
  /** The curve's viewpoint, read (every kind has one). */
  viewpoint: () => Viewpoint;
  /** Its scalar parameters (curveParams.ts), by name. */
  scalars: Record<string, number>;
  /** Its `detail` and `mirror`, each spread only when present. */
  common: Record<string, unknown>;
}

/** A field patch of a quantised curve: `set(key, was, now)` records `now` when it differs. */
export type SetField = (key: string, was: unknown, now: unknown) => void;

/** The grid helpers the quantiser lends a kind (quantize.ts). */
export interface QuantizeKit {
  positions(p: Vec3[]): Vec3[];
  directions(p: Vec3[]): Vec3[];
  mapSame<T>(list: readonly T[], f: (t: T) => T): T[];
  qv(v: Vec3, scale: number): Vec3;
  quantize(x: number, scale: number): number;
}

export interface CurveKindDef<K extends CurveKindName = CurveKindName> {
  readonly name: K;
  /** Its fields besides id, type, points, viewpoint, detail, mirror and its scalar parameters;
   *  each has a place in a share link's layout. */
  readonly fields: readonly string[];
  /** What it does to the hair: `flow` (the hair follows it and, unless it extends, ends where it
   *  ends), `parting` (the hair parts along it), `tie` (it gathers hair into a tail). */
  readonly role: 'flow' | 'parting' | 'tie';
  /** Its supporting surface's mode (S4.3: hint strokes are lifted onto it); null when it lies on
   *  the head (a parting, a bun's loop) and has none. */
  surface(c: CurveOf<K>): SurfaceMode | null;
  /** Whether it has "Extend past the end" (`extend`). */
  readonly extends: boolean;
  /** A tie (it gathers hair: a stream stroke ending near it runs on into it) has this: the
   *  points a stroke's end must come near to run into it. */
  tieNear?(c: CurveOf<K>): readonly Vec3[];
  /** A kind drawn as one stroke (stream, braid, bun) has this: its new curve (without an id)
   *  from the stroke's points, the camera it was drawn from and "Extend past the end"; its
   *  scalar parameters at their defaults. */
  fromStroke?(points: Vec3[], viewpoint: Viewpoint, extend: boolean): Omit<CurveOf<K>, 'id'>;
  /** A kind with more to it than its stroke has this: `c` with its stroke (a hint stroke's edit)
   *  now `points`, the rest following; null when the edit would leave it broken. Without it the
   *  points are simply replaced. */
  respine?(c: CurveOf<K>, points: Vec3[]): CurveOf<K> | null;
  /** Construction lines shown while it is selected (a ponytail's circles), if any. */
  guides?(c: CurveOf<K>): { centre: Vec3; axis: Vec3; radius: number }[];
  /** The strict reader: the whole curve, keys in the order a session file has always had. */
  read(b: ReadBase): CurveOf<K>;
  /** Quantise its own fields (the generic quantiser does points, viewpoint and scalars). */
  quantize(c: CurveOf<K>, set: SetField, kit: QuantizeKit): void;
  /** Its own fields reflected (`flip` a point, `flipDir` a direction); the generic mirror
   *  reflects points and viewpoint and keeps the rest. */
  mirror(c: CurveOf<K>, flip: (p: Vec3) => Vec3, flipDir: (v: Vec3) => Vec3): Partial<CurveOf<K>>;
  /** Its parameter block for the solver (hairArrays.ts CurveSet.params) from its scalars in
   *  table order; `gather`: the session's natural fall (a ponytail gathers into a round tail). */
  solverParams(c: CurveOf<K>, scalars: number[], gather: boolean): number[];
  /** Share links: the 2-bit mode of its flags byte (bits 3-4; -1 when its value has no code and
   *  goes to the link's JSON tail), its blocks after the points, and reading them back. */
  linkMode(c: CurveOf<K>): number;
  writeLink(w: Writer, c: CurveOf<K>, extra: Record<string, unknown>): void;
  readLink(r: Reader, c: Record<string, unknown>, mode: number): void;
}

/** A kind drawn as one stroke: it has fromStroke. */
export type StrokeKindDef<K extends CurveKindName> = CurveKindDef<K> &
  Required<Pick<CurveKindDef<K>, 'fromStroke'>>;
