// Braids and buns (solver-cpp/src/braid_bun.hpp): a stroke (a braid's spine from the scalp, a
// bun's loop where it sits) and the kind's scalar parameters, nothing else of their own.

import { defaultParams, type PlainTieKind } from '../curveParams';
import { bool } from '../readValues';
import type { SurfaceMode } from '../supportingSurface';
import type { Vec3 } from '../vec3';
import type { CurveOf, StrokeKindDef } from './curveKind';

/** A tie whose curve is its stroke and its scalars; `near`: the points a stream stroke's end must
 *  come near to run into it; `surface`: its supporting surface's mode (null: none). */
function plainTie<K extends PlainTieKind>(
  name: K,
  near: (c: CurveOf<K>) => readonly Vec3[],
  surface: SurfaceMode | null,
): StrokeKindDef<K> {
  return {
    name,
    role: 'tie',
    surface: () => surface,
    fields: ['extend'],
    extends: true,
    tieNear: near,
    fromStroke: (points, viewpoint, extend) =>
      ({ type: name, points, extend, viewpoint, ...defaultParams(name) }) as Omit<CurveOf<K>, 'id'>,
    read({ o, path, id, points, viewpoint, scalars, common }) {
      const extend = bool(o.extend, `${path}.extend`);
      const vp = viewpoint();
      return { id, points, extend, viewpoint: vp, ...common, type: name, ...scalars } as CurveOf<K>;
    },
    quantize() {},
    mirror: () => ({}),
    // exactly its scalars (solver-cpp/src/curve_params.hpp BraidParam, BunParam)
    solverParams: (_c, scalars) => scalars,
    linkMode: () => 0,
    writeLink() {},
    readLink() {},
  };
}

/** Every plain tie (curveParams.ts PLAIN_TIE_KINDS), by name. */
export const PLAIN_TIES: { readonly [K in PlainTieKind]: StrokeKindDef<K> } = {
  /** A braid: a stroke from the scalp along the braid, scalp to tip (a ruled surface, as a
   *  ponytail's spine has). */
  braid: plainTie('braid', (c) => c.points.slice(0, 1), 'ruled'),
  /** A bun: a loop drawn on the head where the bun sits (on the head: no supporting surface). */
  bun: plainTie('bun', (c) => c.points, null),
};
