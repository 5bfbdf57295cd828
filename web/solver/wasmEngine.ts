// SolverEngine over the wasm module (wasm-build/binding.cpp). Inputs are copied into wasm
// memory for the duration of a call and described to the binding by one C struct per call,
// written by writeStruct from its protocol.ts layout; results are copied out into fresh typed
// arrays of the protocol.ts layouts, so they can be transferred and outlive the next call.
// Every binding call returns a status; a failure throws SolverError with its kind.
import createHairSolver, {
  type HairSolverModule,
  type HairSolverModuleOptions,
} from '../generated/hairsolver.mjs';
import { type IterateProgress, type SolverEngine, SolverError } from './engine';
import {
  AVOID_INPUT,
  BOUNDARY_STRUCTS,
  CONSTRAINT_LIST,
  type ConstraintArrays,
  CURVE_SET_HEADER,
  type CurveSet,
  DETAIL_GROUP_STRIDE,
  type DetailArrays,
  type FieldArrays,
  GRID_INPUT,
  GROWTH_INPUT,
  type GridSpec,
  type GrowthParams,
  ITERATE_PROGRESS,
  SCALP_INPUT,
  type ScalpMesh,
  type SolverName,
  type SolveStats,
  STATS_OUTPUT,
  type StrandArrays,
  type StructLayout,
  solverErrorKind,
} from './protocol';

export interface LoadOptions {
  /** The .wasm bytes (Node: read from web/generated/hairsolver.wasm, or hairsolver-mt.wasm with
   *  `threaded`). */
  wasmBinary?: Uint8Array;
  /** Browser: where the module's files live, e.g. `() => wasmUrl` from `...hairsolver.wasm?url`
   *  (the threaded module also asks for its `hairsolver-mt.worker.js`). */
  locateFile?: (file: string) => string;
  /** Load the threaded module (hairsolver-mt.mjs, -pthread) instead of the single-threaded one. */
  threaded?: ThreadedModule;
  /** Why the single-threaded module is used (the status tooltip says it), e.g. "not cross-origin
   *  isolated". */
  singleReason?: string;
}

/** A module factory: the default export of hairsolver.mjs or hairsolver-mt.mjs. */
export type ModuleFactory = (options: HairSolverModuleOptions) => Promise<HairSolverModule>;

/** The threaded module and how to run it. */
export interface ThreadedModule {
  /** hairsolver-mt.mjs's default export (loaded by the caller: vite must not bundle it). */
  create: ModuleFactory;
  /** The URL of hairsolver-mt.mjs: every pthread worker imports it. */
  scriptUrl: string;
  /** Threads of the solver's parallel loops, the caller included (the module's pthread pool
   *  holds threads - 1 workers). */
  threads: number;
}

/** Threads for this machine: its logical cores, at most 4 (and at least 1). */
export function chooseThreads(hardwareConcurrency: number | undefined): number {
  const n = Math.floor(hardwareConcurrency ?? 1);
  return Number.isFinite(n) ? Math.max(1, Math.min(4, n)) : 1;
}

/** Stats of the raw solver API. */
export interface RawSolveStats {
  method: string;
  iterations: number;
  residual: number;
  constraints: number;
  added: number;
  removed: number;
  changed: number;
  setupMs: number;
  solveMs: number;
}

/** Progress of a long raw solve (iterative solvers). */
export interface RawSolveProgress {
  iterations: number;
  /** Estimated relative field error (Infinity while the solver has no estimate yet). */
  errorEstimate: number;
  relResidual: number;
}

/** The solver's memory estimate for a grid and the cap setGrid checks it against (bytes). */
export interface MemoryEstimate {
  needsBytes: number;
  capBytes: number;
}

/** Binding calls beyond wasm-build/hairsolver.d.mts (estimate and progress plumbing). */
type EstimateModule = HairSolverModule & {
  _hs_raw_estimate(h: number, nx: number, ny: number, nz: number, out: number): number;
  _hs_raw_set_progress(h: number, intervalMs: number): number;
  hsOnProgress?: (iterations: number, errorEstimate: number, relResidual: number) => boolean;
};

/** The raw solver: an explicit grid (indices only) + constraint list -> field. */
export interface RawSolver {
  /** Memory estimate for a grid of these dims (no allocation) and the current cap. */
  estimate(dims: [number, number, number]): MemoryEstimate;
  /** During solve(), fn is called at most every intervalMs with the progress; returning false
   *  stops the solve (solve() then throws). intervalMs <= 0 removes it. */
  onProgress(intervalMs: number, fn?: (p: RawSolveProgress) => boolean): void;
  /** Once per solver. Grid point (i, j, k) has index i + nx * (j + ny * k). */
  setGrid(dims: [number, number, number], omega: number): void;
  /** index[c] = grid point, target[3 * c + axis] = its target. Duplicates are averaged. */
  setConstraints(index: Int32Array, target: Float64Array): void;
  solve(): void;
  /** field[3 * p + axis], a copy. */
  field(): Float64Array;
  stats(): RawSolveStats;
  dispose(): void;
}

/** Which module an engine runs on, for the status tooltip: "threads: 2" or
 *  "single-threaded: <why>". */
const moduleLabels = new WeakMap<HairSolverModule, string>();

/** The module's label (see moduleLabels). */
export function moduleLabel(mod: HairSolverModule): string {
  return moduleLabels.get(mod) ?? 'single-threaded';
}

async function instantiate(opts: LoadOptions): Promise<HairSolverModule> {
  const locateFile = opts.locateFile;
  const t = opts.threaded;
  const threads = t ? Math.max(1, Math.floor(t.threads)) : 1;
  const options: HairSolverModuleOptions = {
    ...(opts.wasmBinary ? { wasmBinary: opts.wasmBinary } : {}),
    ...(locateFile ? { locateFile: (file: string) => locateFile(file) } : {}),
    ...(t ? { mainScriptUrlOrBlob: t.scriptUrl, hsPoolSize: Math.max(1, threads - 1) } : {}),
  };
  const mod = await (t ? t.create(options) : createHairSolver(options));
  if (t) liveHeapViews(mod);
  const bad = boundaryLayoutMismatches(mod);
  if (bad.length) throw new SolverError(`wasm boundary out of date: ${bad.join('; ')}`);
  const inEffect = mod._hs_set_threads(threads);
  moduleLabels.set(
    mod,
    t
      ? `threads: ${inEffect}`
      : `single-threaded${opts.singleReason ? `: ${opts.singleReason}` : ''}`,
  );
  return mod;
}

/** The threaded module's memory is shared and may grow in any thread, and emscripten renews its
 *  HEAP* views only when the calling thread grows it: these getters renew a view whenever the
 *  memory's buffer has changed, so JS never reads through a view of the old, shorter memory. */
function liveHeapViews(mod: HairSolverModule): void {
  const memory = mod.wasmMemory;
  if (!memory) throw new SolverError('threaded module: no wasmMemory');
  const kinds = {
    HEAPU8: Uint8Array,
    HEAP32: Int32Array,
    HEAPU32: Uint32Array,
    HEAPF32: Float32Array,
    HEAPF64: Float64Array,
  } as const;
  for (const [name, View] of Object.entries(kinds)) {
    let view: ArrayBufferView & { buffer: ArrayBufferLike } = new View(memory.buffer);
    Object.defineProperty(mod, name, {
      configurable: true,
      enumerable: true,
      get() {
        if (view.buffer !== memory.buffer) view = new View(memory.buffer);
        return view;
      },
      set() {}, // emscripten's own renewal: the getter renews on its own
    });
  }
}

/** Every boundary struct whose size or member offsets in the module differ from protocol.ts
 *  (empty when the binding and protocol.ts agree). */
export function boundaryLayoutMismatches(mod: HairSolverModule): string[] {
  const out: string[] = [];
  BOUNDARY_STRUCTS.forEach((layout: StructLayout<string>, id) => {
    const want = [layout.size, ...layout.names.map((n) => layout.fields[n].offset)];
    const got = withScratch(mod, 4 * want.length, (ptr) => {
      const n = mod._hs_struct_layout(id, ptr, want.length);
      return Array.from(i32(mod, ptr, n));
    });
    if (got.join() !== want.join())
      out.push(`struct ${id} (${layout.names[0]}, ...): binding [${got}], protocol.ts [${want}]`);
  });
  return out;
}

/** Copies a typed array into fresh wasm memory; returns the pointer (free it). */
function copyIn(mod: HairSolverModule, arr: ArrayBufferView): number {
  const bytes = new Uint8Array(arr.buffer, arr.byteOffset, arr.byteLength);
  const ptr = mod._malloc(Math.max(8, bytes.byteLength));
  if (ptr === 0)
    throw new SolverError(
      `out of wasm memory: no room for ${(bytes.byteLength / 2 ** 20).toFixed(1)} MB of input (the module holds ${(mod.HEAPU8.length / 2 ** 20).toFixed(0)} MB)`,
      'over_memory_cap',
    );
  mod.HEAPU8.set(bytes, ptr);
  return ptr;
}

function copyInString(mod: HairSolverModule, s: string): number {
  const bytes = new TextEncoder().encode(s);
  const z = new Uint8Array(bytes.length + 1);
  z.set(bytes);
  return copyIn(mod, z);
}

/** Runs fn with the given arrays copied into wasm memory, then frees them. */
function withInputs<T>(
  mod: HairSolverModule,
  inputs: ArrayBufferView[],
  fn: (ptrs: number[]) => T,
): T {
  const ptrs: number[] = [];
  try {
    for (const a of inputs) ptrs.push(copyIn(mod, a));
    return fn(ptrs);
  } finally {
    for (const p of ptrs) mod._free(p);
  }
}

/** Throws SolverError (with the kind of the status code) unless status is 0. */
function check(mod: HairSolverModule, status: number): void {
  if (status !== 0)
    throw new SolverError(mod.UTF8ToString(mod._hs_last_error()), solverErrorKind(status));
}

/** Runs fn with `bytes` of zeroed scratch wasm memory, then frees it. */
function withScratch<T>(mod: HairSolverModule, bytes: number, fn: (ptr: number) => T): T {
  const ptr = mod._malloc(Math.max(8, bytes));
  if (ptr === 0) throw new SolverError('out of wasm memory', 'over_memory_cap');
  try {
    mod.HEAPU8.fill(0, ptr, ptr + bytes);
    return fn(ptr);
  } finally {
    mod._free(ptr);
  }
}

/** The one writer of every input struct: `values` into wasm memory at ptr, each member where
 *  its protocol.ts layout puts it. */
function writeStruct<F extends string>(
  mod: HairSolverModule,
  layout: StructLayout<F>,
  ptr: number,
  values: Readonly<Record<F, number>>,
): void {
  for (const name of layout.names) {
    const { offset, type } = layout.fields[name];
    const at = ptr + offset;
    const v = values[name];
    if (type === 'f64') mod.HEAPF64[at >> 3] = v;
    else if (type === 'i32') mod.HEAP32[at >> 2] = v;
    else if (type === 'u32' || type === 'ptr') mod.HEAPU32[at >> 2] = v;
    else throw new SolverError(`struct member ${name}: ${type} is output only`);
  }
}

/** Reads an output struct at ptr by its protocol.ts layout (char32 members as strings). */
function readStruct<F extends string>(
  mod: HairSolverModule,
  layout: StructLayout<F>,
  ptr: number,
): Record<F, number | string> {
  const out = {} as Record<F, number | string>;
  for (const name of layout.names) {
    const { offset, type } = layout.fields[name];
    const at = ptr + offset;
    if (type === 'f64') out[name] = mod.HEAPF64[at >> 3];
    else if (type === 'i32') out[name] = mod.HEAP32[at >> 2];
    else if (type === 'u32' || type === 'ptr') out[name] = mod.HEAPU32[at >> 2];
    else out[name] = mod.UTF8ToString(at);
  }
  return out;
}

/** Writes an input struct, calls the binding with its pointer and checks the status. */
function callWith<F extends string>(
  mod: HairSolverModule,
  layout: StructLayout<F>,
  values: Readonly<Record<F, number>>,
  call: (structPtr: number) => number,
): void {
  withScratch(mod, layout.size, (ptr) => {
    writeStruct(mod, layout, ptr, values);
    check(mod, call(ptr));
  });
}

/** Calls the binding with an output struct and reads it (after checking the status). */
function callOut<F extends string>(
  mod: HairSolverModule,
  layout: StructLayout<F>,
  call: (structPtr: number) => number,
): Record<F, number | string> {
  return withScratch(mod, layout.size, (ptr) => {
    check(mod, call(ptr));
    return readStruct(mod, layout, ptr);
  });
}

const num = (v: number | string): number => (typeof v === 'number' ? v : Number.NaN);

function toRawStats(
  o: Record<(typeof STATS_OUTPUT.names)[number], number | string>,
): RawSolveStats {
  return {
    method: String(o.method),
    iterations: num(o.iterations),
    residual: num(o.residual),
    constraints: num(o.constraints),
    added: num(o.added),
    removed: num(o.removed),
    changed: num(o.changed),
    setupMs: num(o.setupMs),
    solveMs: num(o.solveMs),
  };
}

// Typed-array copies out of wasm memory (views are re-read: memory may have grown).
const f32 = (mod: HairSolverModule, ptr: number, n: number): Float32Array =>
  n === 0 ? new Float32Array(0) : mod.HEAPF32.slice(ptr >> 2, (ptr >> 2) + n);
const f64 = (mod: HairSolverModule, ptr: number, n: number): Float64Array =>
  n === 0 ? new Float64Array(0) : mod.HEAPF64.slice(ptr >> 3, (ptr >> 3) + n);
const u32 = (mod: HairSolverModule, ptr: number, n: number): Uint32Array =>
  n === 0 ? new Uint32Array(0) : mod.HEAPU32.slice(ptr >> 2, (ptr >> 2) + n);
const i32 = (mod: HairSolverModule, ptr: number, n: number): Int32Array =>
  n === 0 ? new Int32Array(0) : mod.HEAP32.slice(ptr >> 2, (ptr >> 2) + n);

class WasmEngine implements SolverEngine {
  private handle: number;

  constructor(private readonly mod: HairSolverModule) {
    this.handle = mod._hs_engine_create();
  }

  private h(): number {
    if (this.handle === 0) throw new SolverError('engine is disposed', 'not_ready');
    return this.handle;
  }

  setGrid(grid: GridSpec, omega: number, solver: SolverName): void {
    const h = this.h();
    const m = this.mod;
    const name = copyInString(m, solver);
    try {
      const [nx, ny, nz] = grid.dims;
      const [originX, originY, originZ] = grid.origin;
      callWith(
        m,
        GRID_INPUT,
        { originX, originY, originZ, step: grid.step, omega, nx, ny, nz, solver: name },
        (p) => m._hs_engine_set_grid(h, p),
      );
    } finally {
      m._free(name);
    }
  }

  setScalp(mesh: ScalpMesh): void {
    const h = this.h();
    const m = this.mod;
    const nt = Math.floor(mesh.indices.length / 3);
    if (mesh.scalp.length !== nt || mesh.indices.length !== 3 * nt || mesh.positions.length % 3)
      throw new SolverError(
        'scalp: array lengths do not match (3 per vertex, 3 per triangle)',
        'invalid_input',
      );
    withInputs(m, [mesh.positions, mesh.indices, mesh.scalp], ([positions, indices, scalp]) => {
      const [centerX, centerY, centerZ] = mesh.center;
      callWith(
        m,
        SCALP_INPUT,
        {
          centerX,
          centerY,
          centerZ,
          positions,
          vertexCount: mesh.positions.length / 3,
          indices,
          triangleCount: nt,
          scalp,
        },
        (p) => m._hs_engine_set_scalp(h, p),
      );
    });
  }

  /** A new scalp mask (scalp[triangle] = 1) for the head of setScalp; the next grow samples
   *  roots over it. The binding refuses a length other than the head's triangle count. */
  setScalpMask(scalp: Uint8Array): void {
    const h = this.h();
    const m = this.mod;
    withInputs(m, [scalp], ([p]) => check(m, m._hs_engine_set_scalp_mask(h, p, scalp.length)));
  }

  /** Detail groups and each curve's group (protocol.ts DetailArrays), used by grow. */
  setDetail(d: DetailArrays): void {
    const h = this.h();
    const m = this.mod;
    if (d.groups.length % DETAIL_GROUP_STRIDE)
      throw new SolverError(
        `detail: groups must hold ${DETAIL_GROUP_STRIDE} numbers per group`,
        'invalid_input',
      );
    const nGroups = d.groups.length / DETAIL_GROUP_STRIDE;
    withInputs(m, [d.groups, d.curveGroup], ([groups, curveGroup]) =>
      check(m, m._hs_engine_set_detail(h, groups, nGroups, curveGroup, d.curveGroup.length)),
    );
  }

  setCurves(curves: CurveSet): void {
    const h = this.h();
    const m = this.mod;
    const nc = curves.curveStart.length - 1;
    const bad = (msg: string) => new SolverError(`curves: ${msg}`, 'invalid_input');
    if (nc < 0) throw bad('curveStart must have curves + 1 entries');
    if (curves.kinds.length !== nc || curves.extend.length !== nc || curves.points.length % 3)
      throw bad('array lengths do not match');
    if (curves.paramStart.length !== nc + 1) throw bad('paramStart must have curves + 1 entries');
    const ne = curves.extraIndex.length;
    if (curves.extraTarget.length !== 3 * ne)
      throw bad('extraTarget must have 3 entries per extraIndex');
    const c = curves;
    const arrays = [
      c.points,
      c.curveStart,
      c.kinds,
      c.extend,
      c.params,
      c.paramStart,
      c.extraIndex,
      c.extraTarget,
    ];
    withInputs(m, arrays, ([points, curveStart, kinds, extend, params, paramStart, xi, xt]) => {
      callWith(
        m,
        CURVE_SET_HEADER,
        {
          points,
          pointCount: c.points.length / 3,
          curveStart,
          curveCount: nc,
          kinds,
          extend,
          params,
          paramCount: c.params.length,
          paramStart,
          extraIndex: xi,
          extraTarget: xt,
          extraCount: ne,
        },
        (p) => m._hs_engine_set_curves(h, p),
      );
    });
  }

  /** Display colour of each constraint of constraints(), same order: 0 blue, 1 red, 2 purple,
   *  3 green, 4 explicit extra (solver-cpp/src/constraint_colour.hpp). */
  constraintColours(): Uint8Array {
    const h = this.h();
    const m = this.mod;
    const n = m._hs_engine_prepare_constraints(h);
    const ptr = m._hs_engine_constraint_colour(h);
    return n === 0 ? new Uint8Array(0) : m.HEAPU8.slice(ptr, ptr + n);
  }

  /** Scalp avoidance (SPEC S4.7) on the last solved field: constraints to store as the
   *  CurveSet's extraIndex / extraTarget (sorted by grid index, |target| = magnitude). */
  scalpAvoidance(opts: ScalpAvoidanceOptions = {}): ScalpAvoidanceResult {
    const h = this.h();
    const m = this.mod;
    callWith(
      m,
      AVOID_INPUT,
      {
        band: opts.band ?? 1.5,
        magnitude: opts.magnitude ?? 0.3,
        wholeHead: opts.wholeHead ? 1 : 0,
        insideToo: opts.insideToo ? 1 : 0,
        minField: opts.minField ?? 0,
      },
      (p) => m._hs_engine_scalp_avoidance(h, p),
    );
    const n = m._hs_engine_avoid_count(h);
    return {
      index: i32(m, m._hs_engine_avoid_index(h), n),
      target: f64(m, m._hs_engine_avoid_target(h), 3 * n),
    };
  }

  solve(): void {
    check(this.mod, this.mod._hs_engine_solve(this.h()));
  }

  iterate(maxIterations: number, tolerance: number): IterateProgress {
    const h = this.h();
    const m = this.mod;
    const p = callOut(m, ITERATE_PROGRESS, (out) =>
      m._hs_engine_iterate(h, maxIterations, tolerance, out),
    );
    return {
      iterations: num(p.iterations),
      errorEstimate: num(p.errorEstimate),
      converged: p.converged === 1,
    };
  }

  forgetWarmStart(): boolean {
    return this.mod._hs_engine_forget_warm_start(this.h()) === 1;
  }

  deferPreconditionerUpdate(): void {
    this.mod._hs_engine_defer_preconditioner_update(this.h());
  }

  setFall(on: boolean): void {
    check(this.mod, this.mod._hs_engine_set_fall(this.h(), on ? 1 : 0));
  }

  grow(g: GrowthParams): StrandArrays {
    const h = this.h();
    const m = this.mod;
    callWith(m, GROWTH_INPUT, g, (p) => m._hs_engine_grow(h, p));
    return {
      points: f32(m, m._hs_engine_strand_points(h), 3 * m._hs_engine_strand_point_count(h)),
      strandStart: u32(m, m._hs_engine_strand_start(h), m._hs_engine_strand_start_count(h)),
    };
  }

  constraints(): Omit<ConstraintArrays, 'colour'> {
    const h = this.h();
    const m = this.mod;
    const n = m._hs_engine_prepare_constraints(h);
    return {
      index: i32(m, m._hs_engine_constraint_index(h), n),
      target: f32(m, m._hs_engine_constraint_target(h), 3 * n),
    };
  }

  field(): FieldArrays {
    const h = this.h();
    const n = this.mod._hs_engine_prepare_field(h);
    return { vectors: f32(this.mod, this.mod._hs_engine_field(h), 3 * n) };
  }

  stats(): Omit<SolveStats, 'growMs' | 'errorEstimate' | 'heapBytes'> {
    const h = this.h();
    const { residual: _, ...s } = toRawStats(
      callOut(this.mod, STATS_OUTPUT, (p) => this.mod._hs_engine_stats(h, p)),
    );
    return { ...s, module: moduleLabel(this.mod) };
  }

  /** Which module this engine runs on ("threads: 2", "single-threaded: …"). */
  moduleLabel(): string {
    return moduleLabel(this.mod);
  }

  /** Milliseconds of the last grow (roots + strands), measured in wasm. */
  growMs(): number {
    const h = this.h();
    return num(callOut(this.mod, STATS_OUTPUT, (p) => this.mod._hs_engine_stats(h, p)).growMs);
  }

  heapBytes(): number {
    return this.mod.HEAPU8.length;
  }

  /** What the last setScalp took, measured in wasm (benchmarks). */
  headStats(): HeadStats {
    const h = this.h();
    const m = this.mod;
    return withScratch(m, 40, (out) => {
      check(m, m._hs_engine_head_stats(h, out));
      const v = m.HEAPF64.slice(out >> 3, (out >> 3) + 5);
      return {
        samplerMs: v[0],
        distanceMs: v[1],
        headBytes: v[2],
        distanceCells: v[3],
        inUseBytes: v[4],
      };
    });
  }

  /** Number of roots of the last grow. */
  rootCount(): number {
    return this.mod._hs_engine_root_count(this.h());
  }

  dispose(): void {
    if (this.handle !== 0) this.mod._hs_engine_destroy(this.handle);
    this.handle = 0;
  }
}

/** What the last setScalp took (HairEngine::HeadStats). */
export interface HeadStats {
  samplerMs: number; // building the root sampler (mesh copy, bins)
  distanceMs: number; // building the head's distance grid
  headBytes: number; // what the head keeps in wasm memory (sampler + distance grid)
  distanceCells: number;
  inUseBytes: number; // bytes malloc has handed out in the module (its whole state)
}

/** Engine with extras beyond SolverEngine (timings, root count). */
export type WasmSolverEngine = SolverEngine & {
  setScalpMask(scalp: Uint8Array): void;
  headStats(): HeadStats;
  growMs(): number;
  rootCount(): number;
  scalpAvoidance(opts?: ScalpAvoidanceOptions): ScalpAvoidanceResult;
  constraintColours(): Uint8Array;
  moduleLabel(): string;
};

/** Options of scalp avoidance (SPEC S4.7). */
export interface ScalpAvoidanceOptions {
  band?: number; // grid steps from the scalp (default 1.5)
  magnitude?: number; // target length (default 0.3)
  wholeHead?: boolean; // measure against every head triangle, not only the scalp (default false)
  insideToo?: boolean; // also grid points inside the head within the band (default false)
  minField?: number; // no constraint where the field is shorter than this (default 0)
}

/** index[e] = grid point, target[3 * e + axis]: ready for CurveSet.extraIndex / extraTarget. */
export interface ScalpAvoidanceResult {
  index: Int32Array;
  target: Float64Array;
}

/** Loads a fresh wasm module and returns an engine over it. */
export async function loadSolverEngine(opts: LoadOptions = {}): Promise<WasmSolverEngine> {
  return new WasmEngine(await instantiate(opts));
}

class WasmRawSolver implements RawSolver {
  constructor(
    private readonly mod: HairSolverModule,
    private handle: number,
  ) {}

  private h(): number {
    if (this.handle === 0) throw new SolverError('solver is disposed', 'not_ready');
    return this.handle;
  }

  setGrid(dims: [number, number, number], omega: number): void {
    const h = this.h();
    const m = this.mod;
    const [nx, ny, nz] = dims;
    const unit = { originX: 0, originY: 0, originZ: 0, step: 1, solver: 0 };
    callWith(m, GRID_INPUT, { ...unit, omega, nx, ny, nz }, (p) => m._hs_raw_set_grid(h, p));
  }

  estimate(dims: [number, number, number]): MemoryEstimate {
    const h = this.h();
    const m = this.mod as EstimateModule;
    return withScratch(m, 16, (out) => {
      check(m, m._hs_raw_estimate(h, dims[0], dims[1], dims[2], out));
      return { needsBytes: m.HEAPF64[out >> 3], capBytes: m.HEAPF64[(out >> 3) + 1] };
    });
  }

  onProgress(intervalMs: number, fn?: (p: RawSolveProgress) => boolean): void {
    const m = this.mod as EstimateModule;
    m.hsOnProgress = fn
      ? (iterations, errorEstimate, relResidual) => fn({ iterations, errorEstimate, relResidual })
      : undefined;
    check(m, m._hs_raw_set_progress(this.h(), fn ? intervalMs : 0));
  }

  setConstraints(index: Int32Array, target: Float64Array): void {
    if (target.length !== 3 * index.length)
      throw new SolverError('constraints: target must have 3 entries per index', 'invalid_input');
    const h = this.h();
    const m = this.mod;
    withInputs(m, [index, target], ([i, t]) => {
      callWith(m, CONSTRAINT_LIST, { index: i, target: t, count: index.length }, (p) =>
        m._hs_raw_set_constraints(h, p),
      );
    });
  }

  solve(): void {
    check(this.mod, this.mod._hs_raw_solve(this.h()));
  }

  field(): Float64Array {
    const h = this.h();
    return f64(this.mod, this.mod._hs_raw_field(h), 3 * this.mod._hs_raw_field_points(h));
  }

  stats(): RawSolveStats {
    const h = this.h();
    return toRawStats(callOut(this.mod, STATS_OUTPUT, (p) => this.mod._hs_raw_stats(h, p)));
  }

  dispose(): void {
    if (this.handle !== 0) this.mod._hs_raw_destroy(this.handle);
    this.handle = 0;
  }
}

/** Loads a fresh wasm module and creates the named solver ('cg', ...) over it. */
export async function loadRawSolver(solver: string, opts: LoadOptions = {}): Promise<RawSolver> {
  const mod = await instantiate(opts);
  const name = copyInString(mod, solver);
  try {
    const h = withScratch(mod, 4, (out) => {
      check(mod, mod._hs_raw_create(name, out));
      return mod.HEAPU32[out >> 2];
    });
    return new WasmRawSolver(mod, h);
  } finally {
    mod._free(name);
  }
}
