// The worker protocol: every message between the app and the solver worker, and the layout of
// every typed array that crosses the boundary. Arrays are flat; the comment on each field gives
// its index formula. Arrays sent by the worker are transferred (not copied).

// The session's domain (curve kinds and their parameters, growth settings, the detail layout)
// and the flat arrays a session becomes live in web/model/; this protocol carries them and
// re-exports them for the solver's side. Their layouts, in short (each field's comment in
// web/model/hairArrays.ts has its index formula):
//   GridSpec: point (i, j, k) has index p = i + nx * (j + ny * k), position origin + step * (i, j, k).
//   CurveSet: points[3 * point + axis]; curve c owns points curveStart[c] .. curveStart[c + 1] - 1
//     and params[paramStart[c] .. paramStart[c + 1] - 1]: its kind's CURVE_PARAMS scalars in
//     table order, then its kind's variable block (dividing: a normal per point, 3 numbers;
//     ponytail: the circle count, then cx, cy, cz, ax, ay, az, r per circle); extraIndex[e],
//     extraTarget[3 * e + axis].
//   DetailArrays: groups[DETAIL_GROUP_STRIDE * g + k] (model/detail.ts has k's order),
//     curveGroup[c].
//   StrandArrays: points[3 * point + axis]; strand s owns strandStart[s] .. strandStart[s + 1] - 1;
//     optional rootIds[s] (its root's sample index), tailCurves[s] (the curve whose tail laid it,
//     or -1), rootSections[s] (its root's scalp section, with sections on).
export {
  CURVE_PARAMS,
  CurveKind,
  type CurveKindName,
  type CurveParamSpec,
  type CurveParamValues,
} from '../model/curveParams';
export { DETAIL_GROUP_STRIDE } from '../model/detail';
export type { GrowthParams } from '../model/growthParams';
export {
  type CurveSet,
  type DetailArrays,
  type GridSpec,
  type HairOptions,
  type StrandArrays,
  strandCount,
} from '../model/hairArrays';

import type { GrowthParams } from '../model/growthParams';
import type { CurveSet, GridSpec, HairOptions, StrandArrays } from '../model/hairArrays';

/** The head as the solver needs it: triangles with a scalp flag (method S1.1). */
export interface ScalpMesh {
  positions: Float32Array; // positions[3 * vertex + axis]
  indices: Uint32Array; // indices[3 * triangle + corner]
  scalp: Uint8Array; // scalp[triangle] = 1 when the triangle is part of the scalp
  center: [number, number, number]; // origin of the spherical root parameterisation (S5.1)
}

/** Lighting precomputed for a hair revision towards the fixed key light
 *  (web/lighting/hairLighting.ts, web/lighting/keyLight.ts KEY_LIGHT_DIRECTION). */
export interface HairLightingArrays {
  /** 2 per strand point (StrandArrays point order): strand[2 * point] = transmittance towards
   *  the light through hair and head, strand[2 * point + 1] = ambient occlusion (1 = open);
   *  both in [0, 1]. */
  strand: Float32Array;
  /** 1 per head vertex (ScalpMesh vertex order): transmittance through the hair towards the
   *  light, in [0, 1] (the hair's shadow on scalp and face). */
  head: Float32Array;
  ms: number; // time the precompute took in the worker
}

/** The solved field, one vector per grid point. */
export interface FieldArrays {
  vectors: Float32Array; // vectors[3 * p + axis], p = grid index
}

/** Display colour of a constraint (paper Figs. 2, 4, 5; solver-cpp/src/constraint_colour.hpp). */
export const ConstraintColour = { blue: 0, red: 1, purple: 2, green: 3, extra: 4 } as const;
export type ConstraintColourName = keyof typeof ConstraintColour;

/** The constraint set derived from the curves (method S2.3). */
export interface ConstraintArrays {
  index: Int32Array; // index[c] = grid point p of constraint c (sorted, unique)
  target: Float32Array; // target[3 * c + axis] = c_p
  /** colour[c]: ConstraintColour of constraint c (same order as index): 0 blue (stream-curve
   *  tangents, dividing-curve Gaussian profile, ponytail spine), 1 red (a stream curve's fading
   *  extension, the dividing-curve discontinuity), 2 purple (ponytail cross sections),
   *  3 green (ponytail centripetal ring), 4 extra (stated directly, e.g. scalp avoidance). */
  colour: Uint8Array;
}

export type SolverName = 'cg' | 'fast' | 'exact' | 'auto';

export interface SolveStats {
  method: string;
  iterations: number;
  errorEstimate: number; // estimated relative field error of what was grown (0 = exact)
  constraints: number;
  added: number;
  removed: number;
  changed: number;
  setupMs: number;
  solveMs: number;
  growMs: number;
  heapBytes: number; // wasm heap size after the job
  /** The wasm module that solved: "threads: N" or "single-threaded: <why>" (status tooltip). */
  module?: string;
}

// ---- messages -------------------------------------------------------------------------------

export type ToWorker =
  | {
      type: 'init';
      grid: GridSpec;
      omega: number;
      solver: SolverName;
      scalp: ScalpMesh;
    }
  | {
      /** A new scalp on the same head (the scalp brush): solves after it grow their roots over
       *  it; the head's distance grid, the grid and the field stay. Refused (an 'error' with id
       *  null, the previous scalp kept) when its length is not the head's triangle count. */
      type: 'scalpMask';
      scalp: Uint8Array; // scalp[triangle] = 1 on the scalp; length = triangles of init's head
    }
  | {
      /** The solver moves to another grid (the session's bounding volume changed): the engine
       *  is set up on it in place (no new worker; the head, its scalp and its distance grid
       *  stay), the job running is dropped, and the field is zero until the next solve. A grid
       *  the engine refuses (the memory cap) is reported as an 'error' with id null. */
      type: 'grid';
      grid: GridSpec;
    }
  | {
      type: 'solve';
      id: number; // increases per request; results carry it back
      curves: CurveSet;
      growth: GrowthParams;
      options: HairOptions;
      wantField: boolean;
      /** 'preview': a few iterations and a light growth, for live feedback while drawing;
       *  'full': a quick first look, then iterate to convergence and grow the final hair. */
      mode: 'preview' | 'full';
      /** Strand cap of the light growths (a preview, a full solve's first look); growth.maxStrands
       *  still applies when smaller. 0 = no cap of its own. Chosen by the app (what it can draw
       *  while the pen moves). */
      lightMaxStrands: number;
    };

export type FromWorker =
  | { type: 'ready'; gridPoints: number; roots: number }
  | { type: 'progress'; id: number; phase: 'constraints' | 'solve' | 'grow'; fraction: number }
  | {
      type: 'result';
      id: number;
      /** The grown strands; a preview's with every other point and the tip of each
       *  (model/strandSubsample.ts everyOtherPoint), lighting per those points. */
      strands: StrandArrays;
      constraints: ConstraintArrays;
      field: FieldArrays | null;
      /** Self-shadowing, occlusion and the hair's shadow on the head; absent or null when the
       *  worker computed none. */
      lighting?: HairLightingArrays | null;
      stats: SolveStats;
      /** True for the converged field's hair; false for a preview or a first look. */
      final: boolean;
      /** The final hair's vertex attributes for the view, built in the worker with `lighting`
       *  (viewer/strandAttributes.ts lineAttributes), so the page does not stall building them;
       *  absent or null for previews and first looks (the page builds those). */
      attributes?: StrandVertexArrays | null;
      /** The field is converged: true with `final`, and for the light growth of the converged
       *  field posted before the full hair (final false); absent or false otherwise. */
      converged?: boolean;
    }
  | { type: 'error'; id: number | null; message: string; kind: SolverErrorKind };

/** Transfer list for a result message: every array buffer it carries. */
export function resultTransferables(msg: Extract<FromWorker, { type: 'result' }>): ArrayBuffer[] {
  const list: ArrayBuffer[] = [
    msg.strands.points.buffer as ArrayBuffer,
    msg.strands.strandStart.buffer as ArrayBuffer,
    msg.constraints.index.buffer as ArrayBuffer,
    msg.constraints.target.buffer as ArrayBuffer,
    msg.constraints.colour.buffer as ArrayBuffer,
  ];
  if (msg.field) list.push(msg.field.vectors.buffer as ArrayBuffer);
  if (msg.lighting)
    list.push(msg.lighting.strand.buffer as ArrayBuffer, msg.lighting.head.buffer as ArrayBuffer);
  const a = msg.attributes;
  if (a)
    for (const v of [a.tangent, a.along, a.random, a.light, a.box, a.index, a.lodCounts])
      if (!list.includes(v.buffer as ArrayBuffer)) list.push(v.buffer as ArrayBuffer);
  return list;
}

/** The strands' vertex attributes for the view's line geometry (viewer/strandAttributes.ts
 *  builds them: the worker for the final hair, the page for lighter hair). Per point of
 *  StrandArrays (strand s owns points strandStart[s] .. strandStart[s + 1] − 1). */
export interface StrandVertexArrays {
  pointCount: number;
  tangent: Int8Array; // tangent[3 * point + axis]: unit tangent × 127 (central differences)
  along: Uint8Array; // along[point]: 0 at the root … 255 at the tip
  random: Uint8Array; // random[4 * point + k]: the strand's value, hue, length look, highlight noise × 255
  light: Uint8Array; // light[2 * point + k]: lighting.strand (transmittance, occlusion) × 255
  box: Float32Array; // min x, y, z, max x, y, z of the points; empty without points
  index: Uint32Array; // index[2 * segment + end]: point indices, strands in level-of-detail order
  lodCounts: Uint32Array; // lodCounts[g]: index entries of the first g of the 64 LOD groups
}

// ---- the wasm boundary ----------------------------------------------------------------------
// Every binding call (wasm-build/binding.cpp) returns a status: 0, or the code of a
// SolverErrorKind with its message in hs_last_error(). Inputs and outputs that are more than a
// handle and an array cross as C structs whose layout is declared here once (structLayout) and
// mirrored by one struct in the binding (static_assert on its size, offsets checked at load).

/** Status codes of the binding (binding.cpp HsStatus has the same values). */
export const SOLVER_STATUS = {
  ok: 0,
  invalid_input: 1, // malformed input: sizes, ranges, layout, an unknown name
  non_finite: 2, // a NaN or infinity in the input
  over_memory_cap: 3, // the grid or its factor would not fit the memory cap
  not_ready: 4, // called before what it needs (no grid, no scalp, not solved since the edit)
  internal: 5, // a numerical failure or anything else
} as const;

/** What went wrong in a solver call. */
export type SolverErrorKind = Exclude<keyof typeof SOLVER_STATUS, 'ok'>;

/** The kind of a non-zero status code ('internal' for a code this side does not know). */
export function solverErrorKind(code: number): SolverErrorKind {
  for (const [k, v] of Object.entries(SOLVER_STATUS))
    if (v === code && k !== 'ok') return k as SolverErrorKind;
  return 'internal';
}

/** Field types of a boundary struct (wasm32): f64; i32 / u32; ptr (a 4-byte byte offset into
 *  wasm memory); char32 (a NUL-terminated UTF-8 string of at most 31 bytes). */
export type StructFieldType = 'f64' | 'i32' | 'u32' | 'ptr' | 'char32';

export interface StructLayout<F extends string> {
  readonly names: readonly F[]; // declaration order = C member order
  readonly fields: {
    readonly [K in F]: { readonly offset: number; readonly type: StructFieldType };
  };
  readonly size: number; // sizeof the C struct
}

const FIELD_SIZE: Record<StructFieldType, number> = { f64: 8, i32: 4, u32: 4, ptr: 4, char32: 32 };
const FIELD_ALIGN: Record<StructFieldType, number> = { f64: 8, i32: 4, u32: 4, ptr: 4, char32: 1 };

/** A C struct's layout from its members in order, with C's natural alignment on wasm32. */
export function structLayout<const F extends string>(
  members: readonly (readonly [F, StructFieldType])[],
): StructLayout<F> {
  const fields = {} as Record<F, { offset: number; type: StructFieldType }>;
  let offset = 0;
  let align = 1;
  for (const [name, type] of members) {
    const a = FIELD_ALIGN[type];
    offset = Math.ceil(offset / a) * a;
    fields[name] = { offset, type };
    offset += FIELD_SIZE[type];
    align = Math.max(align, a);
  }
  return { names: members.map((m) => m[0]), fields, size: Math.ceil(offset / align) * align };
}

/** hs_engine_set_grid, hs_raw_set_grid (origin and step unused there): GridSpec + omega + the
 *  solver's name. binding.cpp HsGridInput. */
export const GRID_INPUT = structLayout([
  ['originX', 'f64'],
  ['originY', 'f64'],
  ['originZ', 'f64'],
  ['step', 'f64'],
  ['omega', 'f64'],
  ['nx', 'i32'],
  ['ny', 'i32'],
  ['nz', 'i32'],
  ['solver', 'ptr'],
]);

/** hs_engine_set_scalp: ScalpMesh. binding.cpp HsScalpInput. */
export const SCALP_INPUT = structLayout([
  ['centerX', 'f64'],
  ['centerY', 'f64'],
  ['centerZ', 'f64'],
  ['positions', 'ptr'],
  ['vertexCount', 'u32'],
  ['indices', 'ptr'],
  ['triangleCount', 'u32'],
  ['scalp', 'ptr'],
]);

/** hs_engine_set_curves: CurveSet, each array a pointer and its count. binding.cpp
 *  HsCurveSetHeader. */
export const CURVE_SET_HEADER = structLayout([
  ['points', 'ptr'],
  ['pointCount', 'u32'],
  ['curveStart', 'ptr'],
  ['curveCount', 'u32'],
  ['kinds', 'ptr'],
  ['extend', 'ptr'],
  ['params', 'ptr'],
  ['paramCount', 'u32'],
  ['paramStart', 'ptr'],
  ['extraIndex', 'ptr'],
  ['extraTarget', 'ptr'],
  ['extraCount', 'u32'],
]);

/** hs_engine_grow: GrowthParams. binding.cpp HsGrowthInput. */
export const GROWTH_INPUT = structLayout([
  ['thetaStepDeg', 'f64'],
  ['phiStepDeg', 'f64'],
  ['jitter', 'f64'],
  ['seed', 'f64'], // a uint32, checked in the binding
  ['stepFraction', 'f64'],
  ['minMagnitude', 'f64'],
  ['maxLength', 'f64'],
  ['maxSegments', 'i32'],
  ['maxStrands', 'i32'],
]);

/** hs_engine_scalp_avoidance (S4.7). binding.cpp HsAvoidInput. */
export const AVOID_INPUT = structLayout([
  ['band', 'f64'],
  ['magnitude', 'f64'],
  ['minField', 'f64'],
  ['wholeHead', 'i32'], // 0 / 1
  ['insideToo', 'i32'], // 0 / 1
]);

/** hs_raw_set_constraints: index[c], target[3 * c + axis]. binding.cpp HsConstraintList. */
export const CONSTRAINT_LIST = structLayout([
  ['index', 'ptr'],
  ['target', 'ptr'],
  ['count', 'u32'],
]);

/** Output of hs_engine_iterate. binding.cpp HsIterateProgress. */
export const ITERATE_PROGRESS = structLayout([
  ['errorEstimate', 'f64'],
  ['iterations', 'i32'],
  ['converged', 'i32'], // 0 / 1
]);

/** Output of hs_engine_stats / hs_raw_stats: the last edit and solve. binding.cpp HsStats. */
export const STATS_OUTPUT = structLayout([
  ['residual', 'f64'], // relative residual of the last solve, where the solver tracks it
  ['setupMs', 'f64'],
  ['solveMs', 'f64'],
  ['growMs', 'f64'], // engine only: the last grow, measured in wasm
  ['iterations', 'i32'],
  ['added', 'i32'],
  ['removed', 'i32'],
  ['changed', 'i32'],
  ['constraints', 'i32'],
  ['method', 'char32'],
]);

/** Every boundary struct, by the id hs_struct_layout(id, ...) answers for (binding.cpp). */
export const BOUNDARY_STRUCTS = [
  GRID_INPUT,
  SCALP_INPUT,
  CURVE_SET_HEADER,
  GROWTH_INPUT,
  AVOID_INPUT,
  CONSTRAINT_LIST,
  ITERATE_PROGRESS,
  STATS_OUTPUT,
] as const;
