// The reader's rules for a style curve (and for hair detail, which a curve may carry): its
// kind's fields, its scalar parameters (curveParams.ts CURVE_PARAMS), its geometry.
import {
  type CurveKindName,
  type CurveParamValues,
  curveParamNames,
  curveParamSpecs,
} from './curveParams';
import {
  DETAIL_BLOCKS,
  DETAIL_PARAMS,
  type DetailParamSpec,
  type HairDetail,
  LENGTH_JITTER,
} from './detail';
import type { PonytailCircle } from './ponytailGeometry';
import { POSITION_SCALE, toGridInt } from './quantize';
import { fail } from './readFailure';
import {
  array,
  bool,
  CURVE_HI,
  CURVE_LO,
  int,
  num,
  polyline,
  position,
  record,
  unit,
  unitFast,
  viewpoint,
} from './readValues';
import type { StyleCurve } from './session';
import { SESSION_LIMITS as L } from './sessionLimits';
import type { Plain, PlainRecord } from './sessionMigrations';
import type { Vec3 } from './vec3';

/** A curve kind's scalar parameters (curveParams.ts CURVE_PARAMS): each finite and within its
 *  range; a curve saved without one (made before it existed) gets its default. */
function scalars<K extends CurveKindName>(
  o: PlainRecord,
  kind: K,
  path: string,
): CurveParamValues<K> {
  const out: Record<string, number> = {};
  for (const spec of curveParamSpecs(kind))
    out[spec.name] =
      o[spec.name] === undefined
        ? spec.default
        : num(o[spec.name], `${path}.${spec.name}`, spec.min, spec.max);
  return out as CurveParamValues<K>;
}

/** A curve's fields besides its kind's scalar parameters (curveFields adds those). */
const CURVE_FIELDS = {
  stream: ['id', 'type', 'points', 'extend', 'viewpoint', 'surfaceMode', 'detail', 'mirror'],
  dividing: ['id', 'type', 'points', 'normals', 'viewpoint', 'detail', 'mirror'],
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
  ],
  braid: ['id', 'type', 'points', 'extend', 'viewpoint', 'detail', 'mirror'],
  bun: ['id', 'type', 'points', 'extend', 'viewpoint', 'detail', 'mirror'],
} as const satisfies Record<CurveKindName, readonly string[]>;

/** Every field a curve of kind `k` may have (its scalar parameters as the table has them now). */
const curveFields = (k: CurveKindName): string[] => [...CURVE_FIELDS[k], ...curveParamNames(k)];

/** A detail object: blocks of DETAIL_PARAMS (each key required, within its range) and
 *  lengthJitter; absent = none. */
export function detail(v: Plain | undefined, path: string): { detail?: HairDetail } {
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

export function curve(v: Plain, path: string): StyleCurve {
  if (typeof v !== 'object' || v === null || Array.isArray(v)) fail(path, 'must be an object');
  const type = v.type;
  if (
    type !== 'stream' &&
    type !== 'dividing' &&
    type !== 'ponytail' &&
    type !== 'braid' &&
    type !== 'bun'
  )
    fail(`${path}.type`, 'must be "stream", "dividing", "ponytail", "braid" or "bun"');
  const o = record(v, path, curveFields(type));
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
    case 'braid':
    case 'bun': {
      const extend = bool(o.extend, `${path}.extend`);
      const vp = viewpoint(o.viewpoint, `${path}.viewpoint`);
      const common = {
        id,
        points,
        extend,
        viewpoint: vp,
        ...detail(o.detail, `${path}.detail`),
        ...mirrorOf(o.mirror, `${path}.mirror`),
      };
      return type === 'braid'
        ? { ...common, type, ...scalars(o, 'braid', path) }
        : { ...common, type, ...scalars(o, 'bun', path) };
    }
  }
}
