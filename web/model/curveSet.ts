// Packs the session's curves into the flat CurveSet layout (hairArrays.ts): each curve's
// parameter block is its kind's scalars from curveParams.ts CURVE_PARAMS (by name, in table
// order, the table's default for a curve without the field), as its kind (kinds/) packs them.
// Also the session's solve options, and the key that tells solve requests apart.
import { CURVE_PARAMS, CurveKind } from './curveParams';
import { DETAIL_GROUP_STRIDE, packDetailGroup } from './detail';
import type { GrowthParams } from './growthParams';
import type { CurveSet, HairOptions } from './hairArrays';
import { defOf, extendsPastEnd } from './kinds';
import type { SessionState, StyleCurve } from './session';
import { type SessionSettings, settingValues } from './sessionSchema';

/** Constraints stated directly (hairArrays.ts CurveSet.extraIndex / extraTarget). */
export interface ExtraConstraints {
  index: ArrayLike<number>;
  target: ArrayLike<number>;
}

/** The scalar parameters of a curve in CURVE_PARAMS order. */
export function curveScalars(c: StyleCurve): number[] {
  const values = c as unknown as Record<string, unknown>;
  return CURVE_PARAMS[c.type].map((spec) => {
    const v = values[spec.name];
    return typeof v === 'number' ? v : spec.default;
  });
}

/** The parameter block of a curve (hairArrays.ts CurveSet.params): its kind's (kinds/), from its
 *  scalars; `gather` (the session's natural fall) gathers a ponytail into a round tail. */
export function curveParams(c: StyleCurve, gather = false): number[] {
  return defOf(c).solverParams(c, curveScalars(c), gather);
}

/** The session's curves as the solver takes them; `fall` (the session's natural fall) gathers
 *  ponytails into round tails. */
export function packCurves(
  curves: readonly StyleCurve[],
  extras: ExtraConstraints | null = null,
  fall = false,
): CurveSet {
  let total = 0;
  for (const c of curves) total += c.points.length;
  const points = new Float64Array(3 * total);
  const curveStart = new Uint32Array(curves.length + 1);
  const kinds = new Uint8Array(curves.length);
  const extend = new Uint8Array(curves.length);
  const paramStart = new Uint32Array(curves.length + 1);
  const blocks = curves.map((c) => curveParams(c, fall));
  let nParams = 0;
  for (const b of blocks) nParams += b.length;
  const params = new Float64Array(nParams);
  let k = 0;
  let q = 0;
  curves.forEach((c, i) => {
    curveStart[i] = k;
    paramStart[i] = q;
    kinds[i] = CurveKind[c.type];
    extend[i] = extendsPastEnd(c) ? 1 : 0;
    for (const p of c.points) {
      points[3 * k] = p[0];
      points[3 * k + 1] = p[1];
      points[3 * k + 2] = p[2];
      k++;
    }
    params.set(blocks[i], q);
    q += blocks[i].length;
  });
  curveStart[curves.length] = k;
  paramStart[curves.length] = q;
  return {
    points,
    curveStart,
    kinds,
    extend,
    params,
    paramStart,
    extraIndex: Int32Array.from(extras?.index ?? []),
    extraTarget: Float64Array.from(extras?.target ?? []),
  };
}
/** A content key over typed arrays (FNV-1a over their bytes). */
export function contentKey(...arrays: ArrayBufferView[]): string {
  let h1 = 0x811c9dc5;
  let h2 = 0x01000193;
  for (const a of arrays) {
    const bytes = new Uint8Array(a.buffer, a.byteOffset, a.byteLength);
    for (let i = 0; i < bytes.length; i++) {
      h1 = Math.imul(h1 ^ bytes[i], 0x01000193);
      h2 = Math.imul(h2 ^ bytes[i], 0x5bd1e995);
    }
    h1 = Math.imul(h1 ^ bytes.length, 0x01000193);
  }
  return `${(h1 >>> 0).toString(16)}-${(h2 >>> 0).toString(16)}`;
}

/** The solve options of a session (hairArrays.ts HairOptions) for `curves` (the session's curves,
 *  perhaps with a stroke being drawn after them): its settings (sessionSchema.ts), and its detail:
 *  group 0 is the session's, then one group per curve with a detail of its own. */
export function packHairOptions(
  s: SessionSettings & Pick<SessionState, 'detail'>,
  curves: readonly StyleCurve[],
): HairOptions {
  const own = curves.filter((c) => c.detail !== undefined);
  const groups = new Float64Array(DETAIL_GROUP_STRIDE * (1 + own.length));
  packDetailGroup(s.detail, groups, 0);
  const curveGroup = new Int32Array(curves.length);
  let g = 0;
  curves.forEach((c, i) => {
    if (c.detail === undefined) return;
    g++;
    packDetailGroup(c.detail, groups, DETAIL_GROUP_STRIDE * g);
    curveGroup[i] = g;
  });
  return { ...settingValues(s), detail: { groups, curveGroup } };
}

const UTF8 = new TextEncoder();

/** The content key of a solve request (the result cache's key): every array of the curve set,
 *  every growth setting and every solve option, whatever fields they have (keys in sorted order,
 *  numbers and flags as f64, arrays by their bytes), so a field added to any of them is part of
 *  the key without a list to keep. */
export function hairRequestKey(
  curves: CurveSet,
  growth: GrowthParams,
  options: HairOptions,
): string {
  return structuredKey({ curves, growth, options });
}

/** The content key of named values walked whole (keys in sorted order, numbers and flags as
 *  f64, arrays by their bytes), so a field added to any of them is part of the key. */
export function structuredKey(values: Record<string, unknown>): string {
  const parts: ArrayBufferView[] = [];
  const add = (v: unknown, name: string) => {
    parts.push(UTF8.encode(name));
    if (ArrayBuffer.isView(v)) parts.push(v);
    else if (typeof v === 'number' || typeof v === 'boolean')
      parts.push(new Float64Array([Number(v)]));
    else if (typeof v === 'object' && v !== null)
      for (const k of Object.keys(v).sort()) add((v as Record<string, unknown>)[k], `${name}.${k}`);
    else parts.push(new Uint8Array([v === undefined ? 0 : 1]));
  };
  for (const k of Object.keys(values)) add(values[k], k);
  return contentKey(...parts);
}
