// Loading the wasm module (single-threaded or threaded), checking that its boundary structs match
// protocol.ts, and the label that says which module an engine runs on.
import createHairSolver, {
  type HairSolverModule,
  type HairSolverModuleOptions,
} from '../generated/hairsolver.mjs';
import { SolverError } from './engine';
import { i32, withScratch } from './wasmMemory';
import { BOUNDARY_STRUCTS, type StructLayout } from './wasmStructs';

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

/** Which module an engine runs on, for the status tooltip: "threads: 2" or
 *  "single-threaded: <why>". */
const moduleLabels = new WeakMap<HairSolverModule, string>();

/** The module's label (see moduleLabels). */
export function moduleLabel(mod: HairSolverModule): string {
  return moduleLabels.get(mod) ?? 'single-threaded';
}

/** Loads a fresh module as `opts` say, checks its boundary and sets its thread count. */
export async function instantiate(opts: LoadOptions): Promise<HairSolverModule> {
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
