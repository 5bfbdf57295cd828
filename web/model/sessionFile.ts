// Sessions as files and links: a strict reader for session JSON from outside (a shared link, a
// file, a test), and the link encoding (#s=<base64url of deflated JSON>).
// The reader never trusts its input: every field is checked, numbers must be finite, sizes are
// capped; on the first problem it answers with a message naming the field.

import {
  CURVE_PARAMS,
  type CurveKindName,
  type CurveParamSpec,
  type CurveParamValues,
  type GrowthParams,
} from '../solver/protocol';
import { isGridPreset } from './grid';
import { DEFAULT_GROWTH, type SessionState, type StyleCurve, type Viewpoint } from './session';
import type { Vec3 } from './vec3';

export type Parsed<T> = { ok: true; value: T } | { ok: false; error: string };

const MAX_CURVES = 200;
const MAX_POINTS = 5000; // per polyline
const MAX_EXTRA = 200_000;

class ParseError extends Error {}

function fail(path: string, what: string): never {
  throw new ParseError(`${path}: ${what}`);
}

function obj(v: unknown, path: string): Record<string, unknown> {
  if (typeof v !== 'object' || v === null || Array.isArray(v)) fail(path, 'must be an object');
  return v as Record<string, unknown>;
}

function num(v: unknown, path: string, min = -Infinity, max = Infinity): number {
  if (typeof v !== 'number' || !Number.isFinite(v)) fail(path, 'must be a finite number');
  if (v < min || v > max) fail(path, `must be between ${min} and ${max}`);
  return v;
}

function bool(v: unknown, path: string): boolean {
  if (typeof v !== 'boolean') fail(path, 'must be true or false');
  return v;
}

function vec3(v: unknown, path: string): Vec3 {
  if (!Array.isArray(v) || v.length !== 3) fail(path, 'must be [x, y, z]');
  return [num(v[0], `${path}[0]`), num(v[1], `${path}[1]`), num(v[2], `${path}[2]`)];
}

function polyline(v: unknown, path: string, minPoints: number): Vec3[] {
  if (!Array.isArray(v)) fail(path, 'must be an array of points');
  if (v.length < minPoints) fail(path, `needs at least ${minPoints} points`);
  if (v.length > MAX_POINTS) fail(path, `has more than ${MAX_POINTS} points`);
  return v.map((p, i) => vec3(p, `${path}[${i}]`));
}

function viewpoint(v: unknown, path: string): Viewpoint {
  const o = obj(v, path);
  return {
    position: vec3(o.position, `${path}.position`),
    target: vec3(o.target, `${path}.target`),
  };
}

/** A curve kind's scalar parameters (protocol.ts CURVE_PARAMS): each finite and within its
 *  range; a curve saved without one (made before it existed) gets its default. */
function scalars<K extends CurveKindName>(
  o: Record<string, unknown>,
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

function curve(v: unknown, path: string): StyleCurve {
  const o = obj(v, path);
  if (typeof o.id !== 'string' || !/^[A-Za-z0-9_~-]{1,32}$/.test(o.id))
    fail(`${path}.id`, 'must be a short identifier');
  const id = o.id;
  const points = polyline(o.points, `${path}.points`, 2);
  const vp = viewpoint(o.viewpoint, `${path}.viewpoint`);
  switch (o.type) {
    case 'stream': {
      const mode = o.surfaceMode;
      if (mode !== undefined && mode !== 'ruled' && mode !== 'strip')
        fail(`${path}.surfaceMode`, 'must be "ruled" or "strip"');
      return {
        id,
        type: 'stream',
        points,
        extend: bool(o.extend, `${path}.extend`),
        viewpoint: vp,
        ...(mode ? { surfaceMode: mode } : {}),
        ...scalars(o, 'stream', path),
      };
    }
    case 'dividing': {
      const normals = polyline(o.normals, `${path}.normals`, points.length);
      if (normals.length !== points.length)
        fail(`${path}.normals`, 'must have one normal per point');
      return {
        id,
        type: 'dividing',
        points,
        normals,
        viewpoint: vp,
        ...scalars(o, 'dividing', path),
      };
    }
    case 'ponytail': {
      if (!Array.isArray(o.profiles) || o.profiles.length !== 2)
        fail(`${path}.profiles`, 'must hold two profile strokes');
      if (!Array.isArray(o.circles) || o.circles.length > MAX_POINTS)
        fail(`${path}.circles`, 'must be an array of circles');
      return {
        id,
        type: 'ponytail',
        points,
        extend: bool(o.extend, `${path}.extend`),
        viewpoint: vp,
        crossSection: polyline(o.crossSection, `${path}.crossSection`, 0),
        profiles: [
          polyline(o.profiles[0], `${path}.profiles[0]`, 0),
          polyline(o.profiles[1], `${path}.profiles[1]`, 0),
        ],
        circles: o.circles.map((c, i) => {
          const q = obj(c, `${path}.circles[${i}]`);
          return {
            centre: vec3(q.centre, `${path}.circles[${i}].centre`),
            axis: vec3(q.axis, `${path}.circles[${i}].axis`),
            radius: num(q.radius, `${path}.circles[${i}].radius`, 0, 100),
            spineIndex: num(q.spineIndex, `${path}.circles[${i}].spineIndex`, 0, MAX_POINTS),
          };
        }),
        ...scalars(o, 'ponytail', path),
      };
    }
    default:
      fail(`${path}.type`, 'must be "stream", "dividing" or "ponytail"');
  }
}

function growth(v: unknown, path: string): GrowthParams {
  const o = obj(v, path);
  const g = { ...DEFAULT_GROWTH };
  const limits: Record<keyof GrowthParams, [number, number]> = {
    thetaStepDeg: [0.1, 30],
    phiStepDeg: [0.1, 30],
    jitter: [0, 1],
    seed: [0, 2 ** 32 - 1],
    stepFraction: [0.05, 4],
    minMagnitude: [0, 1],
    maxLength: [0.01, 100],
    maxSegments: [1, 10_000],
    maxStrands: [0, 1_000_000],
  };
  for (const key of Object.keys(limits) as (keyof GrowthParams)[])
    if (o[key] !== undefined) g[key] = num(o[key], `${path}.${key}`, ...limits[key]);
  return g;
}

/** Reads a session from untrusted JSON-able data. */
export function parseSession(v: unknown): Parsed<SessionState> {
  try {
    const o = obj(v, 'session');
    if (o.version !== 1) fail('session.version', 'must be 1');
    if (o.grid !== undefined && (typeof o.grid !== 'string' || !isGridPreset(o.grid)))
      fail('session.grid', 'must be 25k, 50k, 100k or 250k');
    if (!Array.isArray(o.curves)) fail('session.curves', 'must be an array');
    if (o.curves.length > MAX_CURVES) fail('session.curves', `has more than ${MAX_CURVES} curves`);
    const curves = o.curves.map((c, i) => curve(c, `session.curves[${i}]`));
    if (new Set(curves.map((c) => c.id)).size !== curves.length)
      fail('session.curves', 'curve ids must be unique');
    const hairColor = o.hairColor ?? '#5a3825';
    if (typeof hairColor !== 'string' || !/^#[0-9a-fA-F]{6}$/.test(hairColor))
      fail('session.hairColor', 'must be a colour like #5a3825');
    let avoid: SessionState['avoid'] = null;
    if (o.avoid !== undefined && o.avoid !== null) {
      const a = obj(o.avoid, 'session.avoid');
      if (
        !Array.isArray(a.index) ||
        !Array.isArray(a.target) ||
        a.target.length !== 3 * a.index.length
      )
        fail('session.avoid', 'needs index[] and target[] with 3 numbers per index');
      if (a.index.length > MAX_EXTRA) fail('session.avoid', `has more than ${MAX_EXTRA} entries`);
      avoid = {
        index: a.index.map((x, i) => num(x, `session.avoid.index[${i}]`, 0, 2 ** 31 - 1)),
        target: a.target.map((x, i) => num(x, `session.avoid.target[${i}]`)),
      };
    }
    return {
      ok: true,
      value: {
        version: 1,
        head: 'builtin',
        grid: (o.grid as SessionState['grid'] | undefined) ?? '25k',
        curves,
        growth: o.growth === undefined ? { ...DEFAULT_GROWTH } : growth(o.growth, 'session.growth'),
        hairColor,
        avoid,
      },
    };
  } catch (e) {
    if (e instanceof ParseError) return { ok: false, error: e.message };
    throw e;
  }
}
