// The reader's rules for a style curve (and for hair detail, which a curve may carry): its
// kind's fields (kinds/), its scalar parameters (curveParams.ts CURVE_PARAMS), its geometry.
import {
  CURVE_KINDS,
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
import { COMMON_CURVE_FIELDS, kindDef } from './kinds';
import { fail } from './readFailure';
import { num, polyline, record, viewpoint } from './readValues';
import type { StyleCurve } from './session';
import type { Plain, PlainRecord } from './sessionMigrations';

// "stream", "dividing", … or "bun"
const KIND_NAMES = CURVE_KINDS.map((k) => `"${k}"`)
  .join(', ')
  .replace(/, ([^,]*)$/, ' or $1');

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

/** A style curve: its kind (kinds/index.ts) reads its own fields; the fields every curve has
 *  (id, points, viewpoint, detail, mirror) and its scalar parameters are read here. */
export function curve(v: Plain, path: string): StyleCurve {
  if (typeof v !== 'object' || v === null || Array.isArray(v)) fail(path, 'must be an object');
  const def = kindDef(v.type);
  if (!def) fail(`${path}.type`, `must be ${KIND_NAMES}`);
  const o = record(v, path, [...COMMON_CURVE_FIELDS, ...def.fields, ...curveParamNames(def.name)]);
  if (typeof o.id !== 'string' || !/^[A-Za-z0-9_~-]{1,32}$/.test(o.id))
    fail(`${path}.id`, 'must be a short identifier (1 to 32 of A-Z a-z 0-9 _ ~ -)');
  const id = o.id;
  const points = polyline(o.points, `${path}.points`);
  return def.read({
    o,
    path,
    id,
    points,
    viewpoint: () => viewpoint(o.viewpoint, `${path}.viewpoint`),
    scalars: scalars(o, def.name, path),
    common: { ...detail(o.detail, `${path}.detail`), ...mirrorOf(o.mirror, `${path}.mirror`) },
  });
}
