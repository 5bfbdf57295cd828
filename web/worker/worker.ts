// The solver Web Worker: loads the wasm engine and answers protocol messages.
// Cross-origin isolated (the server sends COOP/COEP, so SharedArrayBuffer exists) it loads the
// threaded module, hairsolver-mt, which starts its own pthread workers; otherwise, or when that
// fails to load, the single-threaded module. The threaded module's files are plain assets (?url):
// vite must not bundle them (its loader and worker import each other at run time).

import wasmUrl from '../generated/hairsolver.wasm?url';
import mtScriptUrl from '../generated/hairsolver-mt.mjs?url';
import mtWasmUrl from '../generated/hairsolver-mt.wasm?url';
import mtWorkerUrl from '../generated/hairsolver-mt.worker.js?url';
import type { SolverEngine } from '../solver/engine';
import { type FromWorker, resultTransferables, type ToWorker } from '../solver/protocol';
import { chooseThreads, loadSolverEngine, type ModuleFactory } from '../solver/wasmEngine';
import { DEFAULT_SCHEDULER, WorkerLogic } from './workerLogic';

const scope = self as unknown as {
  postMessage(msg: FromWorker, transfer?: Transferable[]): void;
  onmessage: ((ev: MessageEvent<ToWorker>) => void) | null;
};

const post = (msg: FromWorker): void => {
  if (msg.type === 'result') scope.postMessage(msg, resultTransferables(msg));
  else if (msg.type === 'motionFrame')
    scope.postMessage(msg, [msg.guides.buffer as ArrayBuffer, msg.pose.buffer as ArrayBuffer]);
  else if (msg.type === 'motionBound')
    scope.postMessage(
      msg,
      [
        msg.binding.guideRest,
        msg.binding.guideOf,
        msg.binding.along,
        msg.attributes.follow,
        msg.attributes.offset,
        msg.attributes.tangent,
      ].map((a) => a.buffer as ArrayBuffer),
    );
  else scope.postMessage(msg);
};

// Yields to the worker's event loop through a message channel: unlike nested setTimeout(0),
// it is not clamped to 4 ms, and pending protocol messages run before it resumes.
const channel = new MessageChannel();
const resumers: Array<() => void> = [];
channel.port1.onmessage = () => resumers.shift()?.();
const yieldNow = (): Promise<void> =>
  new Promise((resolve) => {
    resumers.push(resolve);
    channel.port2.postMessage(null);
  });

// Messages that arrive while the module loads wait here.
const early: ToWorker[] = [];
let logic: WorkerLogic | null = null;

scope.onmessage = (ev) => {
  if (logic) void logic.handle(ev.data);
  else early.push(ev.data);
};

async function loadEngine(): Promise<SolverEngine> {
  const single = (singleReason: string) =>
    loadSolverEngine({ locateFile: () => wasmUrl, singleReason });
  if (!(self as { crossOriginIsolated?: boolean }).crossOriginIsolated)
    return single('not cross-origin isolated');
  const threads = chooseThreads(navigator.hardwareConcurrency);
  try {
    const scriptUrl = new URL(mtScriptUrl, self.location.href).href;
    const imported = (await import(/* @vite-ignore */ scriptUrl)) as { default: ModuleFactory };
    return await loadSolverEngine({
      locateFile: (file) => (file.endsWith('.worker.js') ? mtWorkerUrl : mtWasmUrl),
      threaded: { create: imported.default, scriptUrl, threads },
    });
  } catch (e) {
    console.warn('threaded solver module failed to load; single-threaded instead:', e);
    return single(`the threaded module failed to load (${String(e)})`);
  }
}

loadEngine()
  .then((engine) => {
    logic = new WorkerLogic(engine, post, { ...DEFAULT_SCHEDULER, yieldNow });
    for (const m of early.splice(0)) void logic.handle(m);
  })
  .catch((e: unknown) => {
    post({
      type: 'error',
      id: null,
      message: `Could not load the solver: ${String(e)}`,
      kind: 'internal',
    });
  });
