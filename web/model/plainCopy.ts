// The reader's first pass: a plain copy of the input as JSON data (only own enumerable data
// properties of plain objects and arrays, within a depth, node and per-field size budget); a
// getter, a Proxy trap that throws, a cycle, a BigInt, a function, a class instance, a sparse
// array or an oversized array is refused with the path where it was found. Nothing of the
// caller's is read twice or after this pass.
import { fail, isOurs, keyStep } from './readFailure';
import { SESSION_LIMITS as L, MAX_HEAD_FILE_DATA, MAX_PICTURE_FILE_DATA } from './sessionLimits';
import type { Plain, PlainRecord } from './sessionMigrations';

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

/** Whether the string at path `at` is an embedded picture file's data (allowed up to
 *  MAX_PICTURE_FILE_DATA characters). */
const isPictureFileData = (at: readonly (string | number)[]) =>
  at.length === 3 && at[0] === 'pictureFiles' && at[2] === 'data';

interface CopyBudget {
  nodes: number;
  points: number;
  strokePoints: number;
  /** Objects and arrays being copied (their ancestors): meeting one again is a cycle. */
  open: Set<object>;
  /** Where the copy is: keys and indices below `session` (made a string only for a message). */
  at: (string | number)[];
}

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
      const max = isHeadFileData(b.at)
        ? MAX_HEAD_FILE_DATA
        : isPictureFileData(b.at)
          ? MAX_PICTURE_FILE_DATA
          : L.maxString;
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

/** The plain copy of `v` (throws a ParseError naming where it fails, or what a hostile input
 *  threw). */
export function plainCopy(v: unknown): Plain | undefined {
  return copyPlain(v, { nodes: 0, points: 0, strokePoints: 0, open: new Set(), at: [] });
}
