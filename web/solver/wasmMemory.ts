// Moving data across the wasm boundary: typed arrays copied into wasm memory for one call and
// freed after it, the one struct writer and reader (by the protocol.ts layouts), status checks
// (a failure throws SolverError with its kind), and typed-array copies out of wasm memory.
import type { HairSolverModule } from '../generated/hairsolver.mjs';
import { SolverError } from './engine';
import { type StructLayout, solverErrorKind } from './wasmStructs';

/** Copies a typed array into fresh wasm memory; returns the pointer (free it). */
export function copyIn(mod: HairSolverModule, arr: ArrayBufferView): number {
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

export function copyInString(mod: HairSolverModule, s: string): number {
  const bytes = new TextEncoder().encode(s);
  const z = new Uint8Array(bytes.length + 1);
  z.set(bytes);
  return copyIn(mod, z);
}

/** Runs fn with the given arrays copied into wasm memory, then frees them. */
export function withInputs<T>(
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
export function check(mod: HairSolverModule, status: number): void {
  if (status !== 0)
    throw new SolverError(mod.UTF8ToString(mod._hs_last_error()), solverErrorKind(status));
}

/** Runs fn with `bytes` of zeroed scratch wasm memory, then frees it. */
export function withScratch<T>(mod: HairSolverModule, bytes: number, fn: (ptr: number) => T): T {
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
export function writeStruct<F extends string>(
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
export function readStruct<F extends string>(
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
export function callWith<F extends string>(
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
export function callOut<F extends string>(
  mod: HairSolverModule,
  layout: StructLayout<F>,
  call: (structPtr: number) => number,
): Record<F, number | string> {
  return withScratch(mod, layout.size, (ptr) => {
    check(mod, call(ptr));
    return readStruct(mod, layout, ptr);
  });
}

export const num = (v: number | string): number => (typeof v === 'number' ? v : Number.NaN);

// Typed-array copies out of wasm memory (views are re-read: memory may have grown).
export const f32 = (mod: HairSolverModule, ptr: number, n: number): Float32Array =>
  n === 0 ? new Float32Array(0) : mod.HEAPF32.slice(ptr >> 2, (ptr >> 2) + n);
export const f64 = (mod: HairSolverModule, ptr: number, n: number): Float64Array =>
  n === 0 ? new Float64Array(0) : mod.HEAPF64.slice(ptr >> 3, (ptr >> 3) + n);
export const u32 = (mod: HairSolverModule, ptr: number, n: number): Uint32Array =>
  n === 0 ? new Uint32Array(0) : mod.HEAPU32.slice(ptr >> 2, (ptr >> 2) + n);
export const i32 = (mod: HairSolverModule, ptr: number, n: number): Int32Array =>
  n === 0 ? new Int32Array(0) : mod.HEAP32.slice(ptr >> 2, (ptr >> 2) + n);
export const u8 = (mod: HairSolverModule, ptr: number, n: number): Uint8Array =>
  n === 0 ? new Uint8Array(0) : mod.HEAPU8.slice(ptr, ptr + n);
