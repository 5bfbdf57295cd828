// The one strict reader for a session from outside: a shared link (sessionLink.ts), a file, the
// session an export carries, replaceSession, the command line.
//
// The reader (parseSession) never trusts its input and never throws:
//  1. A first pass copies the input as plain JSON data (copyPlain): only own enumerable data
//     properties of plain objects and arrays, within a depth, node and per-field size budget;
//     a getter, a Proxy trap that throws, a cycle, a BigInt, a function, a class instance, a
//     sparse array or an oversized array is refused with the path where it was found. Nothing
//     of the caller's is read twice or after this pass.
//  2. An older session is migrated to the current version (sessionMigrations.ts).
//  3. The copy is read against the session's rules (SESSION_LIMITS), field by field; the first
//     problem gives `{ok: false, error: '<path>: <what>'}`, e.g.
//     `session.curves[2].points[5]: must be within the bounding volume (±25)`.
// What it accepts it returns as a fresh value in a canonical form (fixed key order, defaults
// spelled out, -0 written as 0), so reading its JSON again gives the same value and the same
// session always gives the same bytes. Keys it does not know are refused (naming the key),
// except the top-level `camera` and `selected` that "Save" and the test hook write beside the
// session, and `headFile`: those are not part of the session and are left out of the value.
//
// A session on a loaded head (head: {kind: 'mesh', hash, …}) names the head by the SHA-256 of its
// file. A session file ("Save", writeSessionFile) embeds that file beside the session:
//   "headFile": {"name": "head.obj", "hash": "<64 hex>", "encoding": "deflate-base64",
//                "data": "<base64 of the raw deflate of the file's bytes>"}
// readSessionFile reads it back, inflating with a cap (MAX_HEAD_FILE_BYTES) and checking that the
// bytes' SHA-256 is the hash the session's head names. A file without it reads fine: the app
// finds the head by its hash in the browser's store or asks for it.

import {
  CURVE_PARAMS,
  type CurveKindName,
  type CurveParamSpec,
  type CurveParamValues,
  type GrowthParams,
} from '../solver/protocol';
import { deflateRaw, fromBase64, inflateCapped, sha256Hex, toBase64 } from './bytes';
import {
  DETAIL_BLOCKS,
  DETAIL_PARAMS,
  type DetailParamSpec,
  type HairDetail,
  LENGTH_JITTER,
} from './detail';
import { BOX_MAX, BOX_MIN, type GridPreset, isGridPreset } from './grid';
import type { MirrorPlane } from './mirror';
import type { PonytailCircle } from './ponytailGeometry';
import { POSITION_SCALE, toGridInt, unitNormal } from './quantize';
import {
  DEFAULT_GROWTH,
  HEAD_FORMATS,
  type HeadRef,
  type HeadTurn,
  type ScalpStroke,
  type SessionState,
  type StyleCurve,
  type Viewpoint,
} from './session';
import { migrateSession, type Plain, type PlainRecord, SESSION_VERSION } from './sessionMigrations';
import type { Vec3 } from './vec3';

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
  maxSegments: 2000,
  /** growth.maxStrands (0 = no cap). */
  maxStrands: 1_000_000,
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
  /** Characters in any string (but headFile.data: maxHeadFileData); nesting depth and values of
   *  the whole input. */
  maxString: 1024,
  maxDepth: 10,
  maxNodes: 2_500_000,
} as const;
const L = SESSION_LIMITS;
/** MAX_HEAD_FILE_BYTES, as the reader's limits name it. */
export const MAX_HEAD_FILE_BYTES = L.maxHeadFileBytes;
/** Characters of headFile.data: the base64 of a deflate stream of at most maxHeadFileBytes
 *  (stored blocks add 5 bytes per 64 KiB to incompressible data). */
const MAX_HEAD_FILE_DATA = 4 * Math.ceil((L.maxHeadFileBytes * 1.001 + 1024) / 3);

const DEFAULT_HAIR_COLOR = '#5a3825';

class ParseError extends Error {}

/** ParseErrors this module threw (a WeakSet: asking it runs no trap of a thrown Proxy). */
const OURS = new WeakSet<object>();
const isOurs = (e: unknown): e is ParseError => typeof e === 'object' && e !== null && OURS.has(e);

function fail(path: string, what: string): never {
  const e = new ParseError(`${path}: ${what}`);
  OURS.add(e);
  throw e;
}

// ---- first pass: a plain copy of the input ---------------------------------------------------

/** Array size caps by the key holding the array (the session's big arrays); other arrays hold
 *  at most SMALL_ARRAY items (vectors, a viewpoint). The reader checks each size exactly. */
interface Cap {
  cap: number;
  what: string;
  /** Its length counts toward maxSessionPoints. */
  points?: boolean;
  /** Its length counts toward maxStrokePoints. */
  strokePoints?: boolean;
  /** The cap of the arrays it holds (default: SMALL_ARRAY). */
  items?: Cap;
}
const SMALL_ARRAY = 16;
const POLYLINE: Cap = { cap: L.maxPoints, what: 'points', points: true };
const ARRAY_CAPS: Readonly<Record<string, Cap>> = {
  curves: { cap: L.maxCurves, what: 'curves' },
  points: POLYLINE,
  normals: { cap: L.maxPoints, what: 'normals', points: true },
  crossSection: POLYLINE,
  profiles: { cap: SMALL_ARRAY, what: 'profiles', items: POLYLINE },
  circles: { cap: L.maxPoints, what: 'circles', points: true },
  index: { cap: L.maxAvoid, what: 'entries' },
  target: { cap: 3 * L.maxAvoid, what: 'numbers' },
};
/** Arrays under `scalpPaint` and `head` (found by where they are, not only by their key). */
const STROKES: Cap = { cap: L.maxStrokes, what: 'strokes' };
const STROKE_POINTS: Cap = { cap: L.maxStrokePoints, what: 'points', strokePoints: true };
const TURNS: Cap = { cap: L.maxTurns, what: 'turns' };
const MAX_KEYS = 64;

/** The cap of the array held by `key` of the object at path at[0 .. depth). */
function capFor(at: readonly (string | number)[], depth: number, key: string): Cap | undefined {
  if (depth === 0 && key === 'scalpPaint') return STROKES;
  if (depth === 2 && at[0] === 'scalpPaint' && key === 'points') return STROKE_POINTS;
  if (depth === 1 && at[0] === 'head' && key === 'turns') return TURNS;
  return Object.hasOwn(ARRAY_CAPS, key) ? ARRAY_CAPS[key] : undefined;
}

/** Whether the string at path `at` is the embedded head file's data (allowed up to
 *  MAX_HEAD_FILE_DATA characters). */
const isHeadFileData = (at: readonly (string | number)[]) =>
  at.length === 2 && at[0] === 'headFile' && at[1] === 'data';

interface CopyBudget {
  nodes: number;
  points: number;
  strokePoints: number;
  /** Objects and arrays being copied (their ancestors): meeting one again is a cycle. */
  open: Set<object>;
  /** Where the copy is: keys and indices below `session` (made a string only for a message). */
  at: (string | number)[];
}

/** A key as a path step: `.name` for an identifier, else `["…"]` (JSON, cut to 40 characters). */
const keyStep = (k: string) =>
  /^[A-Za-z_$][\w$]*$/.test(k) && k.length <= 40
    ? `.${k}`
    : `[${JSON.stringify(k.length > 40 ? `${k.slice(0, 40)}…` : k)}]`;

function where(b: CopyBudget): string {
  let s = 'session';
  for (const k of b.at) s += typeof k === 'number' ? `[${k}]` : keyStep(k);
  return s;
}

/** One own property's value, read from its descriptor so no getter runs; undefined when absent
 *  (or, with `enumerable`, not enumerable: JSON.stringify leaves it out). */
function ownValue(
  o: object,
  key: string,
  b: CopyBudget,
  enumerable: boolean,
): { value: unknown } | undefined {
  const d = Reflect.getOwnPropertyDescriptor(o, key);
  if (d === undefined || (enumerable && !d.enumerable)) return undefined;
  if (!('value' in d)) fail(where(b), 'must be plain data (it is a getter or setter)');
  return d as { value: unknown };
}

function isPlainObject(o: object): boolean {
  const proto = Reflect.getPrototypeOf(o);
  // Object.prototype of this realm or of another one (a frame's), or no prototype
  return proto === null || proto === Object.prototype || Reflect.getPrototypeOf(proto) === null;
}

/** A plain copy of `v` (null-prototype records, arrays, primitives); undefined for undefined. */
function copyPlain(v: unknown, b: CopyBudget, cap?: Cap): Plain | undefined {
  if (++b.nodes > L.maxNodes)
    fail(where(b), `the input has more than ${L.maxNodes} values (the cap)`);
  switch (typeof v) {
    case 'undefined':
      return undefined;
    case 'boolean':
      return v;
    case 'number':
      return v === 0 ? 0 : v; // -0 as JSON writes it
    case 'string': {
      const max = isHeadFileData(b.at) ? MAX_HEAD_FILE_DATA : L.maxString;
      if (v.length > max) fail(where(b), `is longer than ${max} characters`);
      return v;
    }
    case 'object':
      break;
    default:
      fail(where(b), `must be JSON data, not a ${typeof v}`);
  }
  if (v === null) return null;
  const o = v as object;
  if (b.at.length >= L.maxDepth) fail(where(b), `is nested deeper than ${L.maxDepth} levels`);
  if (b.open.has(o)) fail(where(b), 'refers to itself (a cycle)');
  b.open.add(o);
  const depth = b.at.length;
  try {
    if (Array.isArray(o)) {
      const len = ownValue(o, 'length', b, false)?.value;
      if (typeof len !== 'number') fail(where(b), 'must be an array');
      const c = cap ?? { cap: SMALL_ARRAY, what: 'items' };
      if (len > c.cap) fail(where(b), `has ${len} ${c.what}, more than ${c.cap} (the cap)`);
      if (c.points) {
        b.points += len;
        if (b.points > L.maxSessionPoints)
          fail(where(b), `brings the session over ${L.maxSessionPoints} points in all (the cap)`);
      }
      if (c.strokePoints) {
        b.strokePoints += len;
        if (b.strokePoints > L.maxStrokePoints)
          fail(
            where(b),
            `brings the scalp strokes over ${L.maxStrokePoints} points in all (the cap)`,
          );
      }
      const out: Plain[] = new Array(len);
      for (let i = 0; i < len; i++) {
        b.at.push(i);
        const d = ownValue(o, String(i), b, false);
        if (d === undefined) fail(where(b), 'is missing (a hole in the array)');
        const item = copyPlain(d.value, b, c.items);
        out[i] = item === undefined ? null : item; // as JSON writes undefined in an array
        b.at.pop();
      }
      return out;
    }
    if (!isPlainObject(o)) fail(where(b), 'must be a plain object');
    const keys = Reflect.ownKeys(o);
    if (keys.length > MAX_KEYS) fail(where(b), `has more than ${MAX_KEYS} fields`);
    const out: PlainRecord = Object.create(null);
    for (const key of keys) {
      if (typeof key !== 'string') continue; // a symbol key: not JSON
      b.at.push(key);
      const d = ownValue(o, key, b, true);
      if (d !== undefined) {
        const item = copyPlain(d.value, b, capFor(b.at, depth, key));
        if (item !== undefined) out[key] = item;
      }
      b.at.pop();
    }
    return out;
  } catch (e) {
    if (isOurs(e)) throw e;
    b.at.length = depth; // the message names this value, not the item being read when it threw
    fail(where(b), 'could not be read (reading it threw)');
  } finally {
    b.open.delete(o);
  }
}

// ---- second pass: the session's rules, on the plain copy ---------------------------------------

const BOX_LO = (m: number): Vec3 => [BOX_MIN[0] - m, BOX_MIN[1] - m, BOX_MIN[2] - m];
const BOX_HI = (m: number): Vec3 => [BOX_MAX[0] + m, BOX_MAX[1] + m, BOX_MAX[2] + m];
const CURVE_LO = BOX_LO(L.curveMargin);
const CURVE_HI = BOX_HI(L.curveMargin);
const VIEW_LO = BOX_LO(L.viewMargin);
const VIEW_HI = BOX_HI(L.viewMargin);

function record(v: Plain | undefined, path: string, known: readonly string[]): PlainRecord {
  if (typeof v !== 'object' || v === null || Array.isArray(v)) fail(path, 'must be an object');
  for (const k in v)
    if (!known.includes(k)) fail(`${path}${keyStep(k)}`, 'is not a field hairsketch knows');
  return v;
}

function array(v: Plain | undefined, path: string, what: string): Plain[] {
  if (!Array.isArray(v)) fail(path, `must be an array of ${what}`);
  return v;
}

function num(v: Plain | undefined, path: string, min = -Infinity, max = Infinity): number {
  if (typeof v !== 'number' || !Number.isFinite(v)) fail(path, 'must be a finite number');
  if (v < min || v > max) fail(path, `must be between ${min} and ${max}`);
  return v;
}

function int(v: Plain | undefined, path: string, min: number, max: number): number {
  const n = num(v, path, min, max);
  if (!Number.isInteger(n)) fail(path, `must be a whole number (between ${min} and ${max})`);
  return n;
}

function bool(v: Plain | undefined, path: string): boolean {
  if (typeof v !== 'boolean') fail(path, 'must be true or false');
  return v;
}

function vec3(v: Plain | undefined, path: string): Vec3 {
  if (!Array.isArray(v) || v.length !== 3) fail(path, 'must be [x, y, z]');
  return [num(v[0], `${path}[0]`), num(v[1], `${path}[1]`), num(v[2], `${path}[2]`)];
}

/** A position within the box grown by `margin` on every side. */
function position(v: Plain | undefined, path: string, lo: Vec3, hi: Vec3, margin: number): Vec3 {
  const p = vec3(v, path);
  for (let a = 0; a < 3; a++)
    if (p[a] < lo[a] || p[a] > hi[a])
      fail(
        path,
        `must be within the bounding volume (±${margin}): ${'xyz'[a]} from ${+lo[a].toFixed(4)} to ${+hi[a].toFixed(4)}`,
      );
  return p;
}

/** [x, y, z] when `v` is a unit vector within the tolerance, else null (no strings made). */
function unitFast(v: Plain | undefined): Vec3 | null {
  if (!Array.isArray(v) || v.length !== 3) return null;
  const [x, y, z] = v;
  if (typeof x !== 'number' || typeof y !== 'number' || typeof z !== 'number') return null;
  return Math.abs(Math.hypot(x, y, z) - 1) <= L.unitTolerance ? [x, y, z] : null;
}

function unit(v: Plain | undefined, path: string): Vec3 {
  const n = vec3(v, path);
  const len = Math.hypot(n[0], n[1], n[2]);
  if (!(Math.abs(len - 1) <= L.unitTolerance))
    fail(
      path,
      `must be a unit vector (its length is ${+len.toPrecision(6)}, must be 1 ± ${L.unitTolerance})`,
    );
  return n;
}

/** Whether two positions are the same point on the position grid (quantize.ts). */
function sameOnGrid(a: Vec3, b: Vec3): boolean {
  for (let k = 0; k < 3; k++)
    if (toGridInt(a[k], POSITION_SCALE) !== toGridInt(b[k], POSITION_SCALE)) return false;
  return true;
}

/** A finite [x, y, z] within lo..hi (the fast path: no message strings unless it fails). */
function inside(v: Plain | undefined, lo: Vec3, hi: Vec3): v is [number, number, number] {
  if (!Array.isArray(v) || v.length !== 3) return false;
  for (let k = 0; k < 3; k++) {
    const x = v[k];
    // NaN fails both comparisons; ±Infinity is outside every box
    if (typeof x !== 'number' || !(x >= lo[k] && x <= hi[k])) return false;
  }
  return true;
}

/** A polyline of curve geometry: 2..maxPoints points in the volume, consecutive ones distinct. */
function polyline(v: Plain | undefined, path: string): Vec3[] {
  const a = array(v, path, 'points');
  if (a.length < 2) fail(path, 'needs at least 2 points');
  if (a.length > L.maxPoints) fail(path, `has more than ${L.maxPoints} points (the cap)`);
  const out: Vec3[] = new Array(a.length);
  for (let i = 0; i < a.length; i++) {
    const q = a[i];
    const p: Vec3 = inside(q, CURVE_LO, CURVE_HI)
      ? [q[0], q[1], q[2]]
      : position(q, `${path}[${i}]`, CURVE_LO, CURVE_HI, L.curveMargin);
    if (i > 0 && sameOnGrid(p, out[i - 1]))
      fail(
        `${path}[${i}]`,
        `repeats the point before it (consecutive points must differ on the ${L.positionStep} grid)`,
      );
    out[i] = p;
  }
  return out;
}

function viewpoint(v: Plain | undefined, path: string): Viewpoint {
  const o = record(v, path, ['position', 'target']);
  const p = position(o.position, `${path}.position`, VIEW_LO, VIEW_HI, L.viewMargin);
  const t = position(o.target, `${path}.target`, VIEW_LO, VIEW_HI, L.viewMargin);
  if (sameOnGrid(p, t))
    fail(
      path,
      `position and target must differ (on the ${L.positionStep} grid): no view direction`,
    );
  return { position: p, target: t };
}

/** A curve kind's scalar parameters (protocol.ts CURVE_PARAMS): each finite and within its
 *  range; a curve saved without one (made before it existed) gets its default. */
function scalars<K extends CurveKindName>(
  o: PlainRecord,
  kind: K,
  path: string,
): CurveParamValues<K> {
  const out: Record<string, number> = {};
  for (const spec of CURVE_PARAMS[kind] as readonly CurveParamSpec[])
    out[spec.name] =
      o[spec.name] === undefined
        ? spec.default
        : num(o[spec.name], `${path}.${spec.name}`, spec.min, spec.max);
  return out as CurveParamValues<K>;
}

const paramNames = (k: CurveKindName): string[] =>
  (CURVE_PARAMS[k] as readonly CurveParamSpec[]).map((p) => p.name);
const CURVE_FIELDS = {
  stream: [
    'id',
    'type',
    'points',
    'extend',
    'viewpoint',
    'surfaceMode',
    'detail',
    'mirror',
    ...paramNames('stream'),
  ],
  dividing: [
    'id',
    'type',
    'points',
    'normals',
    'viewpoint',
    'detail',
    'mirror',
    ...paramNames('dividing'),
  ],
  ponytail: [
    'id',
    'type',
    'points',
    'extend',
    'viewpoint',
    'crossSection',
    'profiles',
    'circles',
    'detail',
    'mirror',
    ...paramNames('ponytail'),
  ],
} as const satisfies Record<CurveKindName, readonly string[]>;

/** A detail object: blocks of DETAIL_PARAMS (each key required, within its range) and
 *  lengthJitter; absent = none. */
function detail(v: Plain | undefined, path: string): { detail?: HairDetail } {
  if (v === undefined) return {};
  const o = record(v, path, [...DETAIL_BLOCKS, 'lengthJitter']);
  const out: HairDetail = {};
  for (const b of DETAIL_BLOCKS) {
    if (o[b] === undefined) continue;
    const specs = DETAIL_PARAMS[b] as readonly DetailParamSpec[];
    const q = record(
      o[b],
      `${path}.${b}`,
      specs.map((p) => p.key),
    );
    const block: Record<string, number> = {};
    for (const p of specs) block[p.key] = num(q[p.key], `${path}.${b}.${p.key}`, p.min, p.max);
    (out as Record<string, unknown>)[b] = block;
  }
  if (o.lengthJitter !== undefined)
    out.lengthJitter = num(
      o.lengthJitter,
      `${path}.lengthJitter`,
      LENGTH_JITTER.min,
      LENGTH_JITTER.max,
    );
  return { detail: out };
}

/** A curve's `mirror`: the id of its twin (checked against the session's curves later). */
function mirrorOf(v: Plain | undefined, path: string): { mirror?: string } {
  if (v === undefined) return {};
  if (typeof v !== 'string' || !/^[A-Za-z0-9_~-]{1,32}$/.test(v))
    fail(path, "must be another curve's id");
  return { mirror: v };
}

function curve(v: Plain, path: string): StyleCurve {
  if (typeof v !== 'object' || v === null || Array.isArray(v)) fail(path, 'must be an object');
  const type = v.type;
  if (type !== 'stream' && type !== 'dividing' && type !== 'ponytail')
    fail(`${path}.type`, 'must be "stream", "dividing" or "ponytail"');
  const o = record(v, path, CURVE_FIELDS[type]);
  if (typeof o.id !== 'string' || !/^[A-Za-z0-9_~-]{1,32}$/.test(o.id))
    fail(`${path}.id`, 'must be a short identifier (1 to 32 of A-Z a-z 0-9 _ ~ -)');
  const id = o.id;
  const points = polyline(o.points, `${path}.points`);
  switch (type) {
    case 'stream': {
      const extend = bool(o.extend, `${path}.extend`);
      const vp = viewpoint(o.viewpoint, `${path}.viewpoint`);
      const mode = o.surfaceMode;
      if (mode !== undefined && mode !== 'ruled' && mode !== 'strip')
        fail(`${path}.surfaceMode`, 'must be "ruled" or "strip"');
      return {
        id,
        type,
        points,
        extend,
        viewpoint: vp,
        ...(mode === undefined ? {} : { surfaceMode: mode }),
        ...scalars(o, 'stream', path),
        ...detail(o.detail, `${path}.detail`),
        ...mirrorOf(o.mirror, `${path}.mirror`),
      };
    }
    case 'dividing': {
      const n = array(o.normals, `${path}.normals`, 'normals');
      if (n.length !== points.length)
        fail(
          `${path}.normals`,
          `must have one normal per point (${points.length}), has ${n.length}`,
        );
      const normals = n.map((x, i) => unitFast(x) ?? unit(x, `${path}.normals[${i}]`));
      const vp = viewpoint(o.viewpoint, `${path}.viewpoint`);
      return {
        id,
        type,
        points,
        normals,
        viewpoint: vp,
        ...scalars(o, 'dividing', path),
        ...detail(o.detail, `${path}.detail`),
        ...mirrorOf(o.mirror, `${path}.mirror`),
      };
    }
    case 'ponytail': {
      const extend = bool(o.extend, `${path}.extend`);
      const vp = viewpoint(o.viewpoint, `${path}.viewpoint`);
      const crossSection = polyline(o.crossSection, `${path}.crossSection`);
      const pr = array(o.profiles, `${path}.profiles`, 'profile strokes');
      if (pr.length !== 2)
        fail(`${path}.profiles`, `must hold two profile strokes, has ${pr.length}`);
      const profiles: [Vec3[], Vec3[]] = [
        polyline(pr[0], `${path}.profiles[0]`),
        polyline(pr[1], `${path}.profiles[1]`),
      ];
      const cs = array(o.circles, `${path}.circles`, 'circles');
      if (cs.length < 1) fail(`${path}.circles`, 'needs at least 1 circle');
      if (cs.length > points.length)
        fail(
          `${path}.circles`,
          `has ${cs.length} circles, more than its ${points.length} spine points (the cap)`,
        );
      const circles: PonytailCircle[] = [];
      for (let i = 0; i < cs.length; i++) {
        const at = `${path}.circles[${i}]`;
        const q = record(cs[i], at, ['centre', 'axis', 'radius', 'spineIndex']);
        const centre = position(q.centre, `${at}.centre`, CURVE_LO, CURVE_HI, L.curveMargin);
        const axis = unit(q.axis, `${at}.axis`);
        const radius = num(q.radius, `${at}.radius`, 0, L.maxRadius);
        if (toGridInt(radius, POSITION_SCALE) === 0)
          fail(
            `${at}.radius`,
            `must be greater than 0 (at least ${L.positionStep / 2}, at most ${L.maxRadius})`,
          );
        const spineIndex = int(q.spineIndex, `${at}.spineIndex`, 0, points.length - 1);
        if (i > 0 && spineIndex <= circles[i - 1].spineIndex)
          fail(
            `${at}.spineIndex`,
            "must be greater than the previous circle's (C1 first, in spine order)",
          );
        circles.push({ centre, axis, radius, spineIndex });
      }
      return {
        id,
        type,
        points,
        extend,
        viewpoint: vp,
        crossSection,
        profiles,
        circles,
        ...scalars(o, 'ponytail', path),
        ...detail(o.detail, `${path}.detail`),
        ...mirrorOf(o.mirror, `${path}.mirror`),
      };
    }
  }
}

/** growth: each field within its range; integers where counts and seeds are meant; a field
 *  left out (sessions made before it) takes its default. */
const GROWTH_RULES: Record<keyof GrowthParams, { min: number; max: number; integer?: boolean }> = {
  thetaStepDeg: { min: 0.1, max: 30 },
  phiStepDeg: { min: 0.1, max: 30 },
  jitter: { min: 0, max: 1 },
  seed: { min: 0, max: 2 ** 32 - 1, integer: true },
  stepFraction: { min: 0.05, max: 4 },
  minMagnitude: { min: 0, max: 1 },
  maxLength: { min: 0.01, max: 100 },
  maxSegments: { min: 1, max: L.maxSegments, integer: true },
  maxStrands: { min: 0, max: L.maxStrands, integer: true },
};
const GROWTH_KEYS = Object.keys(DEFAULT_GROWTH) as (keyof GrowthParams)[];

/** Root directions the engine samples for these steps (solver-cpp scalp_roots.cpp). */
export function rootSamples(thetaStepDeg: number, phiStepDeg: number): number {
  const nT = Math.max(1, Math.ceil(180 / thetaStepDeg - 1e-9));
  const nP = Math.max(1, Math.ceil(360 / phiStepDeg - 1e-9));
  return nT * nP;
}

function growth(v: Plain | undefined, path: string): GrowthParams {
  if (v === undefined) return { ...DEFAULT_GROWTH };
  const o = record(v, path, GROWTH_KEYS);
  const g = {} as GrowthParams;
  for (const key of GROWTH_KEYS) {
    const r = GROWTH_RULES[key];
    g[key] =
      o[key] === undefined
        ? DEFAULT_GROWTH[key]
        : r.integer
          ? int(o[key], `${path}.${key}`, r.min, r.max)
          : num(o[key], `${path}.${key}`, r.min, r.max);
  }
  const roots = rootSamples(g.thetaStepDeg, g.phiStepDeg);
  if (roots > L.maxRootSamples)
    fail(
      path,
      `thetaStepDeg ${g.thetaStepDeg} and phiStepDeg ${g.phiStepDeg} sample ${roots} root directions, more than ${L.maxRootSamples} (the cap)`,
    );
  return g;
}

/** A file name as the user's system gave it: 1 to maxHeadName characters, no control
 *  characters (it is shown on one line), well-formed Unicode. */
function fileName(v: Plain | undefined, path: string): string {
  if (typeof v !== 'string' || v.length === 0 || v.length > L.maxHeadName)
    fail(path, `must be a file name (1 to ${L.maxHeadName} characters)`);
  // biome-ignore lint/suspicious/noControlCharactersInRegex: refusing them is the point
  if (/[\u0000-\u001f\u007f]/.test(v)) fail(path, 'must be a file name without control characters');
  // a lone surrogate would not survive UTF-8 (a link's encoding of the name)
  if (/[\ud800-\udbff](?![\udc00-\udfff])|(?<![\ud800-\udbff])[\udc00-\udfff]/.test(v))
    fail(path, 'must be a file name in well-formed Unicode (a lone surrogate)');
  return v;
}

function sha256Of(v: Plain | undefined, path: string): string {
  if (typeof v !== 'string' || !/^[0-9a-f]{64}$/.test(v))
    fail(path, 'must be a SHA-256 as 64 lowercase hex digits');
  return v;
}

const HEAD_FIELDS = ['kind', 'name', 'hash', 'format', 'up', 'turns'];

/** session.head: "builtin" (or absent), or a loaded head's reference. */
function head(v: Plain | undefined, path: string): 'builtin' | HeadRef {
  if (v === undefined || v === 'builtin') return 'builtin';
  if (typeof v !== 'object' || v === null || Array.isArray(v))
    fail(path, 'must be "builtin" or a head mesh ({"kind": "mesh", "name", "hash", …})');
  const o = record(v, path, HEAD_FIELDS);
  if (o.kind !== 'mesh') fail(`${path}.kind`, 'must be "mesh"');
  const name = fileName(o.name, `${path}.name`);
  const hash = sha256Of(o.hash, `${path}.hash`);
  const format = o.format;
  if (typeof format !== 'string' || !(HEAD_FORMATS as readonly string[]).includes(format))
    fail(`${path}.format`, `must be one of ${HEAD_FORMATS.map((f) => `"${f}"`).join(', ')}`);
  if (o.up !== 'y' && o.up !== 'z') fail(`${path}.up`, 'must be "y" or "z"');
  const up = o.up;
  const ts = o.turns === undefined ? [] : array(o.turns, `${path}.turns`, 'turns');
  if (ts.length > L.maxTurns) fail(`${path}.turns`, `has more than ${L.maxTurns} turns (the cap)`);
  const turns: HeadTurn[] = ts.map((t, i) => {
    const at = `${path}.turns[${i}]`;
    const q = record(t, at, ['axis', 'quarterTurns']);
    if (q.axis !== 'x' && q.axis !== 'y' && q.axis !== 'z')
      fail(`${at}.axis`, 'must be "x", "y" or "z"');
    return { axis: q.axis, quarterTurns: int(q.quarterTurns, `${at}.quarterTurns`, 0, 3) };
  });
  return { kind: 'mesh', name, hash, format: format as HeadRef['format'], up, turns };
}

/** session.scalpPaint: brush strokes in order (absent or empty = none). */
function scalpPaint(v: Plain | undefined, path: string): { scalpPaint?: ScalpStroke[] } {
  if (v === undefined) return {};
  const a = array(v, path, 'scalp strokes');
  if (a.length > L.maxStrokes) fail(path, `has more than ${L.maxStrokes} strokes (the cap)`);
  const out: ScalpStroke[] = [];
  let total = 0;
  for (let i = 0; i < a.length; i++) {
    const at = `${path}[${i}]`;
    const o = record(a[i], at, ['erase', 'radius', 'points']);
    const erase = bool(o.erase, `${at}.erase`);
    const radius = num(o.radius, `${at}.radius`, 0, L.maxBrushRadius);
    if (toGridInt(radius, POSITION_SCALE) === 0)
      fail(
        `${at}.radius`,
        `must be greater than 0 (at least ${L.positionStep / 2}, at most ${L.maxBrushRadius})`,
      );
    const ps = array(o.points, `${at}.points`, 'points');
    if (ps.length < 1) fail(`${at}.points`, 'needs at least 1 point');
    total += ps.length;
    if (total > L.maxStrokePoints)
      fail(
        `${at}.points`,
        `brings the scalp strokes over ${L.maxStrokePoints} points in all (the cap)`,
      );
    const points: Vec3[] = new Array(ps.length);
    for (let k = 0; k < ps.length; k++) {
      const q = ps[k];
      points[k] = inside(q, CURVE_LO, CURVE_HI)
        ? [q[0], q[1], q[2]]
        : position(q, `${at}.points[${k}]`, CURVE_LO, CURVE_HI, L.curveMargin);
    }
    out.push({ erase, radius, points });
  }
  return out.length > 0 ? { scalpPaint: out } : {};
}

/** session.symmetry: the mirror plane n·p = offset; the normal within unitTolerance of unit
 *  length, made a unit vector (quantize.ts unitNormal). */
function symmetry(v: Plain | undefined, path: string): { symmetry?: MirrorPlane } {
  if (v === undefined) return {};
  const o = record(v, path, ['normal', 'offset']);
  const normal = unitNormal(unit(o.normal, `${path}.normal`));
  const offset = num(o.offset, `${path}.offset`, -L.maxPlaneOffset, L.maxPlaneOffset);
  return { symmetry: { normal, offset } };
}

const SESSION_FIELDS = [
  'version',
  'head',
  'grid',
  'curves',
  'growth',
  'hairColor',
  'avoidScalp',
  'fall',
  'detail',
  'scalpPaint',
  'symmetry',
];
/** Written beside the session by "Save" (camera, headFile) and the test hook (camera,
 *  selected); the reader leaves them out of the session (app/sessionIO.ts reads the saved
 *  camera, readSessionFile the head file). */
const SIDE_FIELDS = ['camera', 'selected', 'headFile'];

function session(o: PlainRecord): SessionState {
  record(o, 'session', [...SESSION_FIELDS, ...SIDE_FIELDS]);
  const h = head(o.head, 'session.head');
  if (o.grid !== undefined && (typeof o.grid !== 'string' || !isGridPreset(o.grid)))
    fail('session.grid', 'must be 25k, 50k, 100k or 250k');
  const grid: GridPreset = o.grid ?? '25k';
  const cs = array(o.curves, 'session.curves', 'curves');
  if (cs.length > L.maxCurves)
    fail('session.curves', `has more than ${L.maxCurves} curves (the cap)`);
  const curves: StyleCurve[] = [];
  const ids = new Set<string>();
  for (let i = 0; i < cs.length; i++) {
    const c = curve(cs[i], `session.curves[${i}]`);
    if (ids.has(c.id))
      fail(`session.curves[${i}].id`, `"${c.id}" is used by an earlier curve (ids must be unique)`);
    ids.add(c.id);
    curves.push(c);
  }
  // mirrored twins name each other and are of one kind
  const byId = new Map(curves.map((c) => [c.id, c]));
  curves.forEach((c, i) => {
    if (c.mirror === undefined) return;
    const twin = byId.get(c.mirror);
    if (!twin || twin === c || twin.mirror !== c.id || twin.type !== c.type)
      fail(
        `session.curves[${i}].mirror`,
        `"${c.mirror}" must be another ${c.type} curve of the session whose mirror is "${c.id}"`,
      );
  });
  const g = growth(o.growth, 'session.growth');
  const hairColor = o.hairColor ?? DEFAULT_HAIR_COLOR;
  if (typeof hairColor !== 'string' || !/^#[0-9a-fA-F]{6}$/.test(hairColor))
    fail('session.hairColor', 'must be a colour like #5a3825');
  const avoidScalp = o.avoidScalp === undefined ? false : bool(o.avoidScalp, 'session.avoidScalp');
  const fall = o.fall === undefined ? false : bool(o.fall, 'session.fall');
  return {
    version: SESSION_VERSION,
    head: h,
    grid,
    curves,
    growth: g,
    hairColor,
    ...(avoidScalp ? { avoidScalp } : {}),
    ...(fall ? { fall } : {}),
    ...detail(o.detail, 'session.detail'),
    ...scalpPaint(o.scalpPaint, 'session.scalpPaint'),
    ...symmetry(o.symmetry, 'session.symmetry'),
  };
}

/** The plain copy of the input and the session it holds (throws ParseError, or what a hostile
 *  input threw). */
function readInput(v: unknown): { top: PlainRecord; session: SessionState } {
  const copy = copyPlain(v, { nodes: 0, points: 0, strokePoints: 0, open: new Set(), at: [] });
  if (typeof copy !== 'object' || copy === null || Array.isArray(copy))
    fail('session', 'must be an object');
  const migrated = migrateSession(copy);
  if (!migrated.ok) {
    const e = new ParseError(migrated.error);
    OURS.add(e);
    throw e;
  }
  return { top: copy, session: session(migrated.value) };
}

function failed(e: unknown): { ok: false; error: string } {
  if (isOurs(e)) return { ok: false, error: e.message };
  return { ok: false, error: 'session: could not be read (reading it threw)' };
}

/** Reads a session from untrusted data (JSON, or any value a caller hands over); never throws.
 *  A `headFile` beside it is not read (readSessionFile reads it). */
export function parseSession(v: unknown): Parsed<SessionState> {
  try {
    return { ok: true, value: readInput(v).session };
  } catch (e) {
    return failed(e);
  }
}

// ---- session files with their head -----------------------------------------------------------

/** The encoding of headFile.data. */
export const HEAD_FILE_ENCODING = 'deflate-base64';

/** A head file carried by a session file: its name, SHA-256 and bytes. */
export interface HeadFileData {
  name: string;
  hash: string;
  bytes: ArrayBuffer;
}

/** What a session file holds: the session, and the head file when it embeds one. */
export interface SessionFileContents {
  session: SessionState;
  headFile?: HeadFileData;
}

/** The SHA-256 of bytes as 64 lowercase hex digits (the content hash that names a head). */
export const hashBytes = (bytes: ArrayBuffer | Uint8Array): Promise<string> => sha256Hex(bytes);

/** Reads a session file's data (parsed JSON, or any value): the session by the strict reader,
 *  and its `headFile` when present, inflated (refused past MAX_HEAD_FILE_BYTES) and checked
 *  against its hash and the session head's. Never throws; the first problem names its field
 *  (`session.headFile.hash: …`). A session on a loaded head without a headFile reads fine. */
export async function readSessionFile(data: unknown): Promise<Parsed<SessionFileContents>> {
  let top: PlainRecord;
  let value: SessionState;
  let embedded: { name: string; hash: string; data: string } | null;
  try {
    ({ top, session: value } = readInput(data));
    embedded = headFileRecord(top.headFile, value);
  } catch (e) {
    return failed(e);
  }
  if (!embedded) return { ok: true, value: { session: value } };
  const at = 'session.headFile';
  const deflated = fromBase64(embedded.data);
  if (!deflated) return { ok: false, error: `${at}.data: must be base64 text` };
  const inflated = await inflateCapped(deflated, L.maxHeadFileBytes);
  if (inflated === 'too large')
    return {
      ok: false,
      error: `${at}.data: inflates to more than ${L.maxHeadFileBytes / (1 << 20)} MiB (the cap)`,
    };
  if (inflated === 'damaged')
    return { ok: false, error: `${at}.data: does not inflate (damaged deflate data)` };
  const hash = await sha256Hex(inflated);
  if (hash !== embedded.hash)
    return {
      ok: false,
      error: `${at}.hash: does not match the data (the SHA-256 of the data is ${hash}): the file is damaged`,
    };
  const bytes =
    inflated.byteOffset === 0 && inflated.byteLength === inflated.buffer.byteLength
      ? (inflated.buffer as ArrayBuffer)
      : (inflated.slice().buffer as ArrayBuffer);
  return {
    ok: true,
    value: { session: value, headFile: { name: embedded.name, hash: embedded.hash, bytes } },
  };
}

/** The headFile record's fields, checked against the session's head (null when absent). */
function headFileRecord(
  v: Plain | undefined,
  s: SessionState,
): { name: string; hash: string; data: string } | null {
  if (v === undefined) return null;
  const at = 'session.headFile';
  const o = record(v, at, ['name', 'hash', 'encoding', 'data']);
  const name = fileName(o.name, `${at}.name`);
  const hash = sha256Of(o.hash, `${at}.hash`);
  if (o.encoding !== HEAD_FILE_ENCODING) fail(`${at}.encoding`, `must be "${HEAD_FILE_ENCODING}"`);
  if (typeof o.data !== 'string') fail(`${at}.data`, 'must be base64 text');
  if (s.head === 'builtin')
    fail(at, 'the session is on the built-in head (session.head), so it carries no head file');
  if (hash !== s.head.hash)
    fail(`${at}.hash`, `must be the hash of the session's head (session.head.hash ${s.head.hash})`);
  if (name !== s.head.name)
    fail(
      `${at}.name`,
      `must be the name of the session's head (session.head.name ${JSON.stringify(s.head.name)})`,
    );
  return { name, hash, data: o.data };
}

export interface WriteSessionFileOptions {
  /** The bytes of the file the session's head names (its SHA-256 must be the head's hash); left
   *  out, a session on a loaded head is written without its head. Ignored on the built-in head. */
  headBytes?: ArrayBuffer;
  /** Written beside the session as `camera` ("Save" keeps the view). */
  camera?: Viewpoint;
}

/** A session file's text (JSON): the session, the camera and, for a session on a loaded head
 *  given its bytes, the head file (`headFile`, last). Throws when the bytes are not the head's
 *  (their SHA-256 is not session.head.hash): writing them would make a file that cannot be read. */
export async function writeSessionFile(
  s: SessionState,
  options: WriteSessionFileOptions = {},
): Promise<string> {
  const out: Record<string, unknown> = { ...s };
  if (options.camera) out.camera = options.camera;
  if (s.head !== 'builtin' && options.headBytes) {
    const bytes = new Uint8Array(options.headBytes);
    const hash = await sha256Hex(bytes);
    if (hash !== s.head.hash)
      throw new Error(
        `writeSessionFile: the head bytes' SHA-256 ${hash} is not the session head's ${s.head.hash}`,
      );
    out.headFile = {
      name: s.head.name,
      hash,
      encoding: HEAD_FILE_ENCODING,
      data: toBase64(await deflateRaw(bytes)),
    };
  }
  return JSON.stringify(out);
}
