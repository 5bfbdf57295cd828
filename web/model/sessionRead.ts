// The one strict reader for a session from outside: a shared link (sessionLink.ts), a file
// (sessionFile.ts), the session an export carries, replaceSession, the command line.
//
// The reader (parseSession) never trusts its input and never throws:
//  1. A first pass copies the input as plain JSON data (plainCopy.ts).
//  2. An older session is migrated to the current version (sessionMigrations.ts).
//  3. The copy is read against the session's rules (sessionLimits.ts SESSION_LIMITS), field by
//     field, in the order of sessionSchema.ts SESSION_FIELDS; the first problem gives
//     `{ok: false, error: '<path>: <what>'}`, e.g.
//     `session.curves[2].points[5]: must be within the bounding volume (±25)`.
// What it accepts it returns as a fresh value in a canonical form (fixed key order, defaults
// spelled out, -0 written as 0), so reading its JSON again gives the same value and the same
// session always gives the same bytes. Keys it does not know are refused (naming the key),
// except the top-level `camera` and `selected` that "Save" and the test hook write beside the
// session, and `headFile`: those are not part of the session and are left out of the value.

import { type GridPreset, isGridPreset } from './grid';
import { POSITION_SCALE, toGridInt } from './gridNumbers';
import type { GrowthParams } from './growthParams';
import { DEFAULT_GROWTH, GROWTH_FIELDS, GROWTH_KEYS, rootSamples } from './growthParams';
import type { MirrorPlane } from './mirror';
import { plainCopy } from './plainCopy';
import { unitNormal } from './quantize';
import { curve, detail } from './readCurve';
import { fail, failed, refuse } from './readFailure';
import { readBandColor, readHairLook } from './readHairLook';
import { references } from './readReference';
import {
  array,
  bool,
  CURVE_HI,
  CURVE_LO,
  fileName,
  inside,
  int,
  num,
  position,
  record,
  sha256Of,
  unit,
} from './readValues';
import {
  DEFAULT_HAIR_COLOR,
  HEAD_FORMATS,
  type HeadRef,
  type HeadTurn,
  type ScalpStroke,
  type SessionState,
  type StyleCurve,
} from './session';
import { SESSION_LIMITS as L, type Parsed } from './sessionLimits';
import { migrateSession, type Plain, type PlainRecord, SESSION_VERSION } from './sessionMigrations';
import { SESSION_FIELD_NAMES, SETTING_NAMES, settingSpec } from './sessionSchema';
import type { Vec3 } from './vec3';

/** growth: each field within its range (growthParams.ts GROWTH_FIELDS); integers where counts
 *  and seeds are meant; a field left out (sessions made before it) takes its default. */
function growth(v: Plain | undefined, path: string): GrowthParams {
  if (v === undefined) return { ...DEFAULT_GROWTH };
  const o = record(v, path, GROWTH_KEYS);
  const g = {} as GrowthParams;
  for (const key of GROWTH_KEYS) {
    const r = GROWTH_FIELDS[key];
    g[key] =
      o[key] === undefined
        ? r.default
        : 'integer' in r && r.integer
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

/** Written beside the session by "Save" (camera, headFile, pictureFiles) and the test hook (camera,
 *  selected); the reader leaves them out of the session (app/sessionIO.ts reads the saved
 *  camera, readSessionFile the head file). */
const SIDE_FIELDS = ['camera', 'selected', 'headFile', 'pictureFiles'];

function curves(v: Plain | undefined, path: string): StyleCurve[] {
  const cs = array(v, path, 'curves');
  if (cs.length > L.maxCurves) fail(path, `has more than ${L.maxCurves} curves (the cap)`);
  const out: StyleCurve[] = [];
  const ids = new Set<string>();
  for (let i = 0; i < cs.length; i++) {
    const c = curve(cs[i], `${path}[${i}]`);
    if (ids.has(c.id))
      fail(`${path}[${i}].id`, `"${c.id}" is used by an earlier curve (ids must be unique)`);
    ids.add(c.id);
    out.push(c);
  }
  // mirrored twins name each other and are of one kind
  const byId = new Map(out.map((c) => [c.id, c]));
  out.forEach((c, i) => {
    if (c.mirror === undefined) return;
    const twin = byId.get(c.mirror);
    if (!twin || twin === c || twin.mirror !== c.id || twin.type !== c.type)
      fail(
        `${path}[${i}].mirror`,
        `"${c.mirror}" must be another ${c.type} curve of the session whose mirror is "${c.id}"`,
      );
  });
  return out;
}

/** A setting of sessionSchema.ts SESSION_SETTINGS: a flag (written only when true) or a number
 *  within its range (written only when it is not the default); absent = the default. */
function setting(k: SettingName, v: Plain | undefined, path: string): Record<string, unknown> {
  if (v === undefined) return {};
  const spec = settingSpec(k);
  if (spec.type === 'flag') return bool(v, path) ? { [k]: true } : {};
  const x = spec.integer ? int(v, path, spec.min, spec.max) : num(v, path, spec.min, spec.max);
  return x === spec.default ? {} : { [k]: x };
}
type SettingName = (typeof SETTING_NAMES)[number];

/** The reader of each field of the session that is not a setting (sessionSchema.ts
 *  SESSION_FIELDS), giving the field(s) as the session holds them ({} for an absent optional
 *  field). */
const FIELD_READERS: Readonly<
  Record<string, (v: Plain | undefined, path: string) => Record<string, unknown>>
> = {
  version: () => ({ version: SESSION_VERSION }),
  head: (v, path) => ({ head: head(v, path) }),
  grid: (v, path) => {
    if (v !== undefined && (typeof v !== 'string' || !isGridPreset(v)))
      fail(path, 'must be 25k, 50k, 100k or 250k');
    return { grid: (v ?? '25k') as GridPreset };
  },
  curves: (v, path) => ({ curves: curves(v, path) }),
  growth: (v, path) => ({ growth: growth(v, path) }),
  hairColor: (v, path) => {
    const hairColor = v ?? DEFAULT_HAIR_COLOR;
    if (typeof hairColor !== 'string' || !/^#[0-9a-fA-F]{6}$/.test(hairColor))
      fail(path, 'must be a colour like #5a3825');
    return { hairColor };
  },
  hairLook: readHairLook,
  bandColor: readBandColor,
  detail,
  scalpPaint,
  symmetry,
  references,
};

// every field of the schema is read, by its reader or as a setting
for (const k of SESSION_FIELD_NAMES)
  if (!Object.hasOwn(FIELD_READERS, k) === !(SETTING_NAMES as string[]).includes(k))
    throw new Error(`sessionRead.ts: session field ${k} needs exactly one reader`);

function session(o: PlainRecord): SessionState {
  record(o, 'session', [...SESSION_FIELD_NAMES, ...SIDE_FIELDS]);
  const out: Record<string, unknown> = {};
  for (const k of SESSION_FIELD_NAMES) {
    const path = `session.${k}`;
    const read = Object.hasOwn(FIELD_READERS, k)
      ? FIELD_READERS[k](o[k], path)
      : setting(k as SettingName, o[k], path);
    Object.assign(out, read);
  }
  return out as unknown as SessionState;
}

/** The plain copy of the input and the session it holds (throws ParseError, or what a hostile
 *  input threw). */
export function readInput(v: unknown): { top: PlainRecord; session: SessionState } {
  const copy = plainCopy(v);
  if (typeof copy !== 'object' || copy === null || Array.isArray(copy))
    fail('session', 'must be an object');
  const migrated = migrateSession(copy);
  if (!migrated.ok) refuse(migrated.error);
  return { top: copy, session: session(migrated.value) };
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
