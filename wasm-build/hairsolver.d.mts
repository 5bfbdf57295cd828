// Types of the emscripten module built by wasm-build/build.sh (copied next to the generated
// hairsolver.mjs). Pointers are byte offsets into the module's memory. Functions returning a
// status give 0 on success, else a protocol.ts SOLVER_STATUS code (the kind of failure), with the
// message at UTF8ToString(_hs_last_error()). Struct arguments (`*In`, `*Out`) point to C structs
// laid out as the protocol.ts layouts named on each.
export interface HairSolverModule {
  HEAPU8: Uint8Array;
  HEAP32: Int32Array;
  HEAPU32: Uint32Array;
  HEAPF32: Float32Array;
  HEAPF64: Float64Array;
  UTF8ToString(ptr: number): string;
  _malloc(bytes: number): number;
  _free(ptr: number): void;
  _hs_last_error(): number;
  /** Writes sizeof and the member offsets of BOUNDARY_STRUCTS[id] to out; returns the count. */
  _hs_struct_layout(id: number, out: number, max: number): number;
  /** Threads of the solver's parallel loops (caller included); returns the count in effect
   *  (always 1 in the single-threaded module). */
  _hs_set_threads(n: number): number;
  /** The module's memory (shared in the threaded module). */
  wasmMemory?: WebAssembly.Memory;

  _hs_engine_create(): number;
  _hs_engine_destroy(h: number): void;
  _hs_engine_set_grid(h: number, gridIn: number): number; // GRID_INPUT
  _hs_engine_set_scalp(h: number, scalpIn: number): number; // SCALP_INPUT
  /** scalp: uint8[triangleCount], 1 on the scalp (the head of the last set_scalp). */
  _hs_engine_set_scalp_mask(h: number, scalp: number, triangleCount: number): number;
  /** positions: float32[3 * vertexCount], indices: uint32[3 * triangleCount]; 0 triangles
   *  clears the body. */
  _hs_engine_set_body(
    h: number,
    positions: number,
    vertexCount: number,
    indices: number,
    triangleCount: number,
  ): number;
  /** out: float64[5] = sampler ms, distance ms, head bytes, distance cells, bytes in use. */
  _hs_engine_head_stats(h: number, out: number): number;
  _hs_engine_set_curves(h: number, curveSetIn: number): number; // CURVE_SET_HEADER
  _hs_engine_set_detail(
    h: number,
    groups: number, // float64[11 * groupCount] (protocol.ts DetailArrays)
    groupCount: number,
    curveGroup: number, // int32[curveCount]
    curveCount: number,
  ): number;
  _hs_engine_scalp_avoidance(h: number, avoidIn: number): number; // AVOID_INPUT
  _hs_engine_avoid_count(h: number): number;
  _hs_engine_avoid_index(h: number): number;
  _hs_engine_avoid_target(h: number): number;
  _hs_engine_solve(h: number): number;
  _hs_engine_iterate(
    h: number,
    maxIterations: number,
    tolerance: number,
    progressOut: number, // ITERATE_PROGRESS
  ): number;
  _hs_engine_forget_warm_start(h: number): number; // 1: the next iterate starts from zero
  _hs_engine_defer_preconditioner_update(h: number): void;
  _hs_engine_set_fall(h: number, on: number): number;
  _hs_engine_set_settings(h: number, values: number, count: number): number;
  _hs_engine_grow(h: number, growthIn: number): number; // GROWTH_INPUT
  _hs_engine_strand_points(h: number): number;
  _hs_engine_strand_point_count(h: number): number;
  _hs_engine_strand_start(h: number): number;
  _hs_engine_strand_start_count(h: number): number;
  _hs_engine_root_count(h: number): number;
  _hs_engine_strand_root_ids(h: number): number; // uint32 per strand
  _hs_engine_strand_root_id_count(h: number): number;
  _hs_engine_strand_tail_curves(h: number): number; // int32 per strand
  _hs_engine_strand_tail_curve_count(h: number): number;
  _hs_engine_tie_frames(h: number): number; // 8 float32 per tie
  _hs_engine_tie_frame_count(h: number): number;
  _hs_engine_strand_sections(h: number): number; // uint8 per strand
  _hs_engine_strand_section_count(h: number): number;
  _hs_engine_prepare_constraints(h: number): number;
  _hs_engine_constraint_index(h: number): number;
  _hs_engine_constraint_target(h: number): number;
  _hs_engine_constraint_colour(h: number): number;
  _hs_engine_prepare_field(h: number): number;
  _hs_engine_field(h: number): number;
  _hs_engine_stats(h: number, statsOut: number): number; // STATS_OUTPUT

  _hs_raw_create(solverName: number, handleOut: number): number; // handleOut: a 4-byte slot
  _hs_raw_destroy(h: number): void;
  _hs_raw_set_grid(h: number, gridIn: number): number; // GRID_INPUT (dims and omega)
  _hs_raw_set_constraints(h: number, listIn: number): number; // CONSTRAINT_LIST
  _hs_raw_solve(h: number): number;
  _hs_raw_field(h: number): number;
  _hs_raw_field_points(h: number): number;
  _hs_raw_stats(h: number, statsOut: number): number; // STATS_OUTPUT

  /** A groom in motion over engine h's head (binding.cpp hs_sim_create has the layouts);
   *  handleOut: a 4-byte slot. */
  _hs_sim_create(
    h: number,
    points: number,
    pointCount: number,
    strandStart: number,
    strandCount: number,
    tails: number,
    pivot: number,
    motion: number,
    seed: number,
    maxGuides: number,
    useBody: number,
    windFromDeg: number,
    windSpeed: number,
    handleOut: number,
  ): number;
  _hs_sim_destroy(s: number): void;
  _hs_sim_step(s: number): void;
  _hs_sim_guides(s: number): number; // float32[3 * guideCount * guidePoints], strand-major
  _hs_sim_guide_rest(s: number): number; // the same at rest
  _hs_sim_guide_points(s: number): number;
  _hs_sim_guide_of(s: number): number; // int32[strandCount], -1: none
  _hs_sim_along(s: number): number; // float32[pointCount], in guide points
  _hs_sim_pose(s: number, out: number): void; // out float32[12]: rotation row-major, translation
  _hs_sim_frame(s: number): number;
  _hs_sim_guide_count(s: number): number;
}

export interface HairSolverModuleOptions {
  wasmBinary?: Uint8Array | ArrayBuffer;
  locateFile?: (file: string, prefix: string) => string;
  /** Threaded module (hairsolver-mt.mjs): the URL its pthread workers import, and their count. */
  mainScriptUrlOrBlob?: string;
  hsPoolSize?: number;
}

declare function createHairSolver(options?: HairSolverModuleOptions): Promise<HairSolverModule>;
export default createHairSolver;
