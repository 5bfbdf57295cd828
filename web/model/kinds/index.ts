// The table of style-curve kinds (curveKind.ts): the generic model code looks a curve's kind up
// here instead of branching on its name.
import type { CurveKindName } from '../curveParams';
import type { StyleCurve } from '../session';
import type { Vec3 } from '../vec3';
import type { CurveKindDef } from './curveKind';
import { DIVIDING } from './dividing';
import { PONYTAIL } from './ponytail';
import { STREAM } from './stream';
import { PLAIN_TIES } from './tie';

// each kind typed for its own curves; looked up for any curve (its methods take that curve)
const KINDS: { readonly [K in CurveKindName]: CurveKindDef<K> } = {
  stream: STREAM,
  dividing: DIVIDING,
  ponytail: PONYTAIL,
  ...PLAIN_TIES,
};

/** The kinds drawn as one stroke (a tool's stroke, a preview being drawn), by name. */
export const STROKE_KINDS = { stream: STREAM, ponytail: PONYTAIL, ...PLAIN_TIES } as const;
export type StrokeKindName = keyof typeof STROKE_KINDS;

/** The definition of a kind by name (null for a name that is none). */
export function kindDef(name: unknown): CurveKindDef | null {
  return typeof name === 'string' && Object.hasOwn(KINDS, name)
    ? (KINDS[name as CurveKindName] as unknown as CurveKindDef)
    : null;
}

/** The definition of curve `c`'s kind. */
export function defOf(c: StyleCurve): CurveKindDef {
  return KINDS[c.type] as unknown as CurveKindDef;
}

/** The fields every curve has besides its kind's own and its scalar parameters. */
export const COMMON_CURVE_FIELDS = ['id', 'type', 'points', 'viewpoint', 'detail', 'mirror'];

/** Whether curve `c` has "Extend past the end" on. */
export function extendsPastEnd(c: StyleCurve): boolean {
  return defOf(c).extends && (c as { extend?: boolean }).extend === true;
}

/** The points a stream stroke's end must come near to run into tie `c`; null when `c` is no tie. */
export function tieNear(c: StyleCurve): readonly Vec3[] | null {
  return defOf(c).tieNear?.(c) ?? null;
}
