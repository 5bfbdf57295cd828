// The reader's checks of single values on the plain copy (plainCopy.ts): objects with known
// keys, numbers in ranges, positions in the bounding volume, unit vectors, polylines,
// viewpoints, file names and hashes. Each refuses with a message naming the value's path.
import { BOX_MAX, BOX_MIN } from './grid';
import { POSITION_SCALE, toGridInt } from './gridNumbers';
import { fail, keyStep } from './readFailure';
import type { Viewpoint } from './session';
import { SESSION_LIMITS as L } from './sessionLimits';
import type { Plain, PlainRecord } from './sessionMigrations';
import type { Vec3 } from './vec3';

const BOX_LO = (m: number): Vec3 => [BOX_MIN[0] - m, BOX_MIN[1] - m, BOX_MIN[2] - m];
const BOX_HI = (m: number): Vec3 => [BOX_MAX[0] + m, BOX_MAX[1] + m, BOX_MAX[2] + m];
export const CURVE_LO = BOX_LO(L.curveMargin);
export const CURVE_HI = BOX_HI(L.curveMargin);
export const VIEW_LO = BOX_LO(L.viewMargin);
export const VIEW_HI = BOX_HI(L.viewMargin);

export function record(v: Plain | undefined, path: string, known: readonly string[]): PlainRecord {
  if (typeof v !== 'object' || v === null || Array.isArray(v)) fail(path, 'must be an object');
  for (const k in v)
    if (!known.includes(k)) fail(`${path}${keyStep(k)}`, 'is not a field hairsketch knows');
  return v;
}

export function array(v: Plain | undefined, path: string, what: string): Plain[] {
  if (!Array.isArray(v)) fail(path, `must be an array of ${what}`);
  return v;
}

export function num(v: Plain | undefined, path: string, min = -Infinity, max = Infinity): number {
  if (typeof v !== 'number' || !Number.isFinite(v)) fail(path, 'must be a finite number');
  if (v < min || v > max) fail(path, `must be between ${min} and ${max}`);
  return v;
}

export function int(v: Plain | undefined, path: string, min: number, max: number): number {
  const n = num(v, path, min, max);
  if (!Number.isInteger(n)) fail(path, `must be a whole number (between ${min} and ${max})`);
  return n;
}

export function bool(v: Plain | undefined, path: string): boolean {
  if (typeof v !== 'boolean') fail(path, 'must be true or false');
  return v;
}

export function vec3(v: Plain | undefined, path: string): Vec3 {
  if (!Array.isArray(v) || v.length !== 3) fail(path, 'must be [x, y, z]');
  return [num(v[0], `${path}[0]`), num(v[1], `${path}[1]`), num(v[2], `${path}[2]`)];
}

/** A position within the box grown by `margin` on every side. */
export function position(
  v: Plain | undefined,
  path: string,
  lo: Vec3,
  hi: Vec3,
  margin: number,
): Vec3 {
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
export function unitFast(v: Plain | undefined): Vec3 | null {
  if (!Array.isArray(v) || v.length !== 3) return null;
  const [x, y, z] = v;
  if (typeof x !== 'number' || typeof y !== 'number' || typeof z !== 'number') return null;
  return Math.abs(Math.hypot(x, y, z) - 1) <= L.unitTolerance ? [x, y, z] : null;
}

export function unit(v: Plain | undefined, path: string): Vec3 {
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
export function sameOnGrid(a: Vec3, b: Vec3): boolean {
  for (let k = 0; k < 3; k++)
    if (toGridInt(a[k], POSITION_SCALE) !== toGridInt(b[k], POSITION_SCALE)) return false;
  return true;
}

/** A finite [x, y, z] within lo..hi (the fast path: no message strings unless it fails). */
export function inside(v: Plain | undefined, lo: Vec3, hi: Vec3): v is [number, number, number] {
  if (!Array.isArray(v) || v.length !== 3) return false;
  for (let k = 0; k < 3; k++) {
    const x = v[k];
    // NaN fails both comparisons; ±Infinity is outside every box
    if (typeof x !== 'number' || !(x >= lo[k] && x <= hi[k])) return false;
  }
  return true;
}

/** A polyline of curve geometry: 2..maxPoints points in the volume, consecutive ones distinct. */
export function polyline(v: Plain | undefined, path: string): Vec3[] {
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

export function viewpoint(v: Plain | undefined, path: string): Viewpoint {
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

/** A file name as the user's system gave it: 1 to maxHeadName characters, no control
 *  characters (it is shown on one line), well-formed Unicode. */
export function fileName(v: Plain | undefined, path: string): string {
  if (typeof v !== 'string' || v.length === 0 || v.length > L.maxHeadName)
    fail(path, `must be a file name (1 to ${L.maxHeadName} characters)`);
  // biome-ignore lint/suspicious/noControlCharactersInRegex: refusing them is the point
  if (/[\u0000-\u001f\u007f]/.test(v)) fail(path, 'must be a file name without control characters');
  // a lone surrogate would not survive UTF-8 (a link's encoding of the name)
  if (/[\ud800-\udbff](?![\udc00-\udfff])|(?<![\ud800-\udbff])[\udc00-\udfff]/.test(v))
    fail(path, 'must be a file name in well-formed Unicode (a lone surrogate)');
  return v;
}

export function sha256Of(v: Plain | undefined, path: string): string {
  if (typeof v !== 'string' || !/^[0-9a-f]{64}$/.test(v))
    fail(path, 'must be a SHA-256 as 64 lowercase hex digits');
  return v;
}
