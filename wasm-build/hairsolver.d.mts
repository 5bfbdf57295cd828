// Types of the emscripten module built by wasm-build/build.sh (copied next to the generated
// hairsolver.mjs). Pointers are byte offsets into the module's memory; functions returning an
// int status give 0 on success and 1 on failure (message: UTF8ToString(_hs_last_error())).
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

  _hs_engine_create(): number;
  _hs_engine_destroy(h: number): void;
  _hs_engine_set_grid(
    h: number, nx: number, ny: number, nz: number,
    ox: number, oy: number, oz: number, step: number, omega: number, solverName: number,
  ): number;
  _hs_engine_set_scalp(
    h: number, positions: number, vertexCount: number, indices: number, triangleCount: number,
    scalp: number, cx: number, cy: number, cz: number,
  ): number;
  _hs_engine_set_curves(
    h: number, points: number, pointCount: number, curveStart: number, curveCount: number,
    kinds: number, extend: number, params: number, paramCount: number, paramStart: number,
    extraIndex: number, extraTarget: number, extraCount: number,
  ): number;
  _hs_engine_scalp_avoidance(h: number, band: number, magnitude: number, flags: number): number;
  _hs_engine_avoid_count(h: number): number;
  _hs_engine_avoid_index(h: number): number;
  _hs_engine_avoid_target(h: number): number;
  _hs_engine_solve(h: number): number;
  _hs_engine_iterate(h: number, maxIterations: number, tolerance: number, progressOut: number): number;
  _hs_engine_grow(
    h: number, thetaStepDeg: number, phiStepDeg: number, jitter: number, seed: number,
    stepFraction: number, minMagnitude: number, maxLength: number, maxSegments: number,
    maxStrands: number,
  ): number;
  _hs_engine_strand_points(h: number): number;
  _hs_engine_strand_point_count(h: number): number;
  _hs_engine_strand_start(h: number): number;
  _hs_engine_strand_start_count(h: number): number;
  _hs_engine_root_count(h: number): number;
  _hs_engine_prepare_constraints(h: number): number;
  _hs_engine_constraint_index(h: number): number;
  _hs_engine_constraint_target(h: number): number;
  _hs_engine_constraint_colour(h: number): number;
  _hs_engine_prepare_field(h: number): number;
  _hs_engine_field(h: number): number;
  _hs_engine_stats_json(h: number): number;
  _hs_engine_grow_ms(h: number): number;

  _hs_raw_create(solverName: number): number;
  _hs_raw_destroy(h: number): void;
  _hs_raw_set_grid(h: number, nx: number, ny: number, nz: number, omega: number): number;
  _hs_raw_set_constraints(h: number, index: number, target: number, count: number): number;
  _hs_raw_solve(h: number): number;
  _hs_raw_field(h: number): number;
  _hs_raw_field_points(h: number): number;
  _hs_raw_stats_json(h: number): number;
}

export interface HairSolverModuleOptions {
  wasmBinary?: Uint8Array | ArrayBuffer;
  locateFile?: (file: string, prefix: string) => string;
}

declare function createHairSolver(options?: HairSolverModuleOptions): Promise<HairSolverModule>;
export default createHairSolver;
