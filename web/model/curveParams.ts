// The scalar parameters of each style-curve kind: one table that the session reader, the
// quantiser, the share link, the curve panel, the editor and the solver packing all read
// (solver/protocol.ts CurveSet.params carries them to solver-cpp, which reads them at the
// indices of solver-cpp/src/curve_params.hpp).

/** The kinds that are a stroke and their scalar parameters, nothing else of their own (braid,
 *  bun: kinds/tie.ts defines them all from that); a new one here is typed through the model. */
export const PLAIN_TIE_KINDS = ['braid', 'bun'] as const;
export type PlainTieKind = (typeof PLAIN_TIE_KINDS)[number];

/** One scalar parameter of a curve kind: the session field `name` (StyleCurve[name], in the
 *  unit below), packed in table order at the start of the curve's CurveSet.params block and read
 *  by solver-cpp at the index named in solver-cpp/src/curve_params.hpp. The session reader
 *  accepts [min, max] (a saved curve without the field gets `default`); the editor and share
 *  links keep it on a grid of `quantum` (quantize.ts); the curve panel offers `view` (in degrees
 *  when unit is 'rad', in centimetres when it is 'cm'). */
export interface CurveParamSpec {
  readonly name: string;
  readonly label: string; // curve panel label, without the unit
  /** 'cm': a length in world units (1 = 10 cm), shown in centimetres (× 10); 'per 10 cm': a
   *  count per world unit, shown as it is; 'choice': a whole number naming one of `choices`. */
  readonly unit: 'grid steps' | 'rad' | 'cm' | 'per 10 cm' | 'choice' | '';
  /** unit 'choice': the name of each whole value from 0, shown as a drop-down. */
  readonly choices?: readonly string[];
  readonly default: number;
  readonly min: number; // accepted range, session units
  readonly max: number;
  /** The step of its grid, session units (a power of ten: links store value / quantum as an
   *  integer). Fixed once shipped: links hold the integers. */
  readonly quantum: number;
  readonly view: { readonly min: number; readonly max: number; readonly step: number };
}

/** A tie's (ponytail, braid, bun) last row: 1 gathers every strand of its scalp section
 *  (solver-cpp/src/scalp_sections.hpp), 0 the hair that reaches it. */
const GATHER_SECTION = {
  name: 'section',
  label: 'Gather',
  unit: 'choice',
  choices: ['nearby hair only', 'whole section'],
  default: 1,
  min: 0,
  max: 1,
  quantum: 1,
  view: { min: 0, max: 1, step: 1 },
} as const;

/** The scalar parameters of each curve kind, in pack order; the kinds' order is their code
 *  (CurveKind: solver-cpp/src/curve_set.hpp CurveKindCode, share links), so a new kind comes last (solver-cpp/src/curve_params.hpp
 *  has the same order). Adding one: a row at the end of its kind (links store the rows in this
 *  order, so never insert or reorder), its index in curve_params.hpp, and the C++ that reads it. */
export const CURVE_PARAMS = {
  /** S4.1. Its own Volume (with the shape rules: how far the hair around it stands off the head
   *  at its roots, in place of the Hair panel's Volume; 0: the Hair panel's). */
  stream: [
    {
      name: 'volume',
      label: 'Own volume',
      unit: 'cm',
      default: 0,
      min: 0,
      max: 0.3,
      quantum: 0.01,
      view: { min: 0, max: 3, step: 0.5 },
    },
  ],
  /** S4.5: the parting's Gaussian profile (sigma, h) and tilt at both ends (alpha0, alpha1). */
  dividing: [
    {
      name: 'sigma',
      label: 'σ',
      unit: 'grid steps',
      default: 1,
      min: 0.05,
      max: 20,
      quantum: 1e-4,
      view: { min: 0.25, max: 4, step: 0.05 },
    },
    {
      name: 'h',
      label: 'h',
      unit: 'grid steps',
      default: 0.5,
      min: 0,
      max: 20,
      quantum: 1e-4,
      view: { min: 0, max: 3, step: 0.05 },
    },
    {
      name: 'alpha0',
      label: 'α0',
      unit: 'rad',
      default: 0,
      min: -Math.PI,
      max: Math.PI,
      quantum: 1e-5,
      view: { min: -80, max: 80, step: 1 },
    },
    {
      name: 'alpha1',
      label: 'α1',
      unit: 'rad',
      default: 0,
      min: -Math.PI,
      max: Math.PI,
      quantum: 1e-5,
      view: { min: -80, max: 80, step: 1 },
    },
  ],
  /** S4.6: the centripetal magnitude of the green ring. */
  ponytail: [
    {
      name: 'tightness',
      label: 'Tightness',
      unit: '',
      default: 0.6,
      min: 0,
      max: 10,
      quantum: 1e-4,
      view: { min: 0, max: 1, step: 0.05 },
    },
    GATHER_SECTION,
  ],
  /** A three-strand braid (solver-cpp/src/braid_bun.hpp): its width, bundle crossings per 10 cm
   *  (all three bundles counted), tightness (how flat the bundles lie) and the loose tail's
   *  length. Lengths in world units (1 = 10 cm). */
  braid: [
    {
      name: 'width',
      label: 'Width',
      unit: 'cm',
      default: 0.5,
      min: 1e-4,
      max: 3,
      quantum: 1e-4,
      view: { min: 0.5, max: 30, step: 0.1 },
    },
    {
      name: 'crossings',
      label: 'Crossings',
      unit: 'per 10 cm',
      default: 6,
      min: 1e-4,
      max: 40,
      quantum: 1e-4,
      view: { min: 0.5, max: 40, step: 0.5 },
    },
    {
      name: 'tightness',
      label: 'Tightness',
      unit: '',
      default: 0.5,
      min: 0,
      max: 1,
      quantum: 1e-4,
      view: { min: 0, max: 1, step: 0.05 },
    },
    {
      name: 'tailLength',
      label: 'Tail length',
      unit: 'cm',
      default: 0.4,
      min: 0,
      max: 20,
      quantum: 1e-4,
      view: { min: 0, max: 200, step: 0.5 },
    },
    GATHER_SECTION,
  ],
  /** A bun (solver-cpp/src/braid_bun.hpp): its radius (0: the drawn loop's size), height and
   *  the turns each strand coils. Lengths in world units (1 = 10 cm). */
  bun: [
    {
      name: 'radius',
      label: 'Radius',
      unit: 'cm',
      default: 0,
      min: 0,
      max: 2,
      quantum: 1e-4,
      view: { min: 0, max: 20, step: 0.1 },
    },
    {
      name: 'height',
      label: 'Height',
      unit: 'cm',
      default: 0.35,
      min: 1e-4,
      max: 2,
      quantum: 1e-4,
      view: { min: 0.1, max: 20, step: 0.1 },
    },
    {
      name: 'turns',
      label: 'Turns',
      unit: '',
      default: 2.5,
      min: 1e-4,
      max: 10,
      quantum: 1e-4,
      view: { min: 0.25, max: 10, step: 0.25 },
    },
    GATHER_SECTION,
  ],
} as const satisfies Record<string, readonly CurveParamSpec[]>;

export type CurveKindName = keyof typeof CURVE_PARAMS;

/** The curve kinds in code order. */
export const CURVE_KINDS = Object.keys(CURVE_PARAMS) as CurveKindName[];

/** Style curve kinds' codes, as stored in CurveSet.kinds (hairArrays.ts): their table order. */
export const CurveKind = Object.fromEntries(CURVE_KINDS.map((k, i) => [k, i])) as {
  readonly [K in CurveKindName]: number;
};

/** The scalar parameter values of a curve kind, by name. */
export type CurveParamValues<K extends CurveKindName> = {
  [P in (typeof CURVE_PARAMS)[K][number]['name']]: number;
};

/** A kind's rows, as the plain spec type. */
export function curveParamSpecs(kind: CurveKindName): readonly CurveParamSpec[] {
  return CURVE_PARAMS[kind];
}

/** The names of a kind's scalar parameters, in table order. */
export function curveParamNames(kind: CurveKindName): string[] {
  return curveParamSpecs(kind).map((p) => p.name);
}

/** Integers per unit of a parameter's grid (1 / quantum, exact for a power of ten). */
export function quantumScale(spec: Pick<CurveParamSpec, 'quantum'>): number {
  return Math.round(1 / spec.quantum);
}

/** The scalar parameters of a new curve of kind `k`: the defaults of CURVE_PARAMS. */
export function defaultParams<K extends CurveKindName>(k: K): CurveParamValues<K> {
  const out: Record<string, number> = {};
  for (const p of CURVE_PARAMS[k]) out[p.name] = p.default;
  return out as CurveParamValues<K>;
}
