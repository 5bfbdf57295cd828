// Node only (tests, CLI, benchmarks): the threaded wasm module (hairsolver-mt.mjs) under Node.
// It is built for the web (ENVIRONMENT=web,worker) and starts its pthreads with `new Worker(url)`;
// Node has no Web Worker, so a small one over node:worker_threads stands in: it runs the module's
// classic hairsolver-mt.worker.js with `self`, `postMessage` and `onmessage` as a browser would.
// Never imported by the app (the browser has real workers).
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { Worker as NodeWorker } from 'node:worker_threads';
import type { LoadOptions, ModuleFactory } from './wasmEngine';

const generated = new URL('../generated/', import.meta.url);
const started: NodeWorker[] = [];

class WebWorkerOverNode {
  onmessage: ((e: { data: unknown }) => void) | null = null;
  onerror: ((e: unknown) => void) | null = null;
  private readonly w: NodeWorker;

  constructor(url: string | URL) {
    const file = new URL(String(url));
    const source = readFileSync(fileURLToPath(file), 'utf8');
    const boot = `
const { parentPort } = require('node:worker_threads');
globalThis.self = globalThis;
globalThis.location = { href: ${JSON.stringify(file.href)} };
globalThis.postMessage = (m, t) => parentPort.postMessage(m, t);
parentPort.on('message', (data) => { if (self.onmessage) self.onmessage({ data }); });
(0, eval)(${JSON.stringify(source)});
`;
    this.w = new NodeWorker(boot, { eval: true });
    this.w.on('message', (data) => this.onmessage?.({ data }));
    this.w.on('error', (e) => (this.onerror ? this.onerror(e) : console.error(e)));
    started.push(this.w);
  }

  postMessage(message: unknown, transfer?: Transferable[]): void {
    // biome-ignore lint/suspicious/noExplicitAny: worker_threads' transfer list type differs
    this.w.postMessage(message, transfer as any);
  }

  terminate(): void {
    void this.w.terminate();
  }
}

/** Load options for the threaded module under Node with `threads` threads (the caller included).
 *  Its pthread workers do not keep Node alive once it has loaded. */
export async function threadedNodeOptions(threads: number): Promise<LoadOptions> {
  const g = globalThis as { Worker?: unknown };
  if (!g.Worker) g.Worker = WebWorkerOverNode;
  const scriptUrl = new URL('hairsolver-mt.mjs', generated).href;
  const imported = (await import(/* @vite-ignore */ scriptUrl)) as { default: ModuleFactory };
  const create: ModuleFactory = async (options) => {
    const mod = await imported.default({
      ...options,
      locateFile: (f: string) => new URL(f, generated).href,
      // emscripten warns once that the main thread blocks: here it is Node's, where that is fine
      printErr: (s: string) => {
        if (!s.startsWith('Blocking on the main thread')) console.error(s);
      },
    } as Parameters<ModuleFactory>[0]);
    for (const w of started) w.unref();
    return mod;
  };
  return {
    wasmBinary: new Uint8Array(
      readFileSync(fileURLToPath(new URL('hairsolver-mt.wasm', generated))),
    ),
    threaded: { create, scriptUrl, threads },
  };
}

/** Ends every pthread worker started so far (the modules they served can no longer be used). */
export async function stopThreadWorkers(): Promise<void> {
  await Promise.all(started.splice(0).map((w) => w.terminate()));
}

/** The single-threaded module's load options under Node. */
export function singleNodeOptions(): LoadOptions {
  return {
    wasmBinary: new Uint8Array(readFileSync(fileURLToPath(new URL('hairsolver.wasm', generated)))),
  };
}
