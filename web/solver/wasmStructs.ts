// The wasm boundary's shared facts: the binding's status codes and the C structs that cross it,
// each declared here once and mirrored by one struct in wasm-build/binding.cpp.
// Every binding call (wasm-build/binding.cpp) returns a status: 0, or the code of a
// SolverErrorKind with its message in hs_last_error(). Inputs and outputs that are more than a
// handle and an array cross as C structs whose layout is declared here once (structLayout) and
// mirrored by one struct in the binding (static_assert on its size, offsets checked at load).
import type { SolverErrorKind } from './protocol';

/** Status codes of the binding (binding.cpp HsStatus has the same values). */
export const SOLVER_STATUS = {
  ok: 0,
  invalid_input: 1, // malformed input: sizes, ranges, layout, an unknown name
  non_finite: 2, // a NaN or infinity in the input
  over_memory_cap: 3, // the grid or its factor would not fit the memory cap
  not_ready: 4, // called before what it needs (no grid, no scalp, not solved since the edit)
  internal: 5, // a numerical failure or anything else
} as const satisfies Record<SolverErrorKind | 'ok', number>;

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
