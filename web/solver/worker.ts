// The solver Web Worker: loads the wasm engine and answers protocol messages.
import wasmUrl from '../generated/hairsolver.wasm?url';
import { type FromWorker, resultTransferables, type ToWorker } from './protocol';
import { loadSolverEngine } from './wasmEngine';
import { handleMessage, type WorkerState } from './workerLogic';

const scope = self as unknown as {
  postMessage(msg: FromWorker, transfer?: Transferable[]): void;
  onmessage: ((ev: MessageEvent<ToWorker>) => void) | null;
};

const post = (msg: FromWorker): void => {
  if (msg.type === 'result') scope.postMessage(msg, resultTransferables(msg));
  else scope.postMessage(msg);
};

const queue: ToWorker[] = [];
let state: WorkerState | null = null;

scope.onmessage = (ev) => {
  queue.push(ev.data);
  drain();
};

function drain(): void {
  if (!state) return;
  // Messages only wait here while the module loads; of the solves waiting, only the last one
  // is worth running (the client sends one at a time after that).
  const pending = queue.splice(0);
  const lastSolve = pending.map((m) => m.type).lastIndexOf('solve');
  pending.forEach((msg, i) => {
    if (msg.type === 'solve' && i !== lastSolve) return;
    handleMessage(state as WorkerState, msg, post);
  });
}

loadSolverEngine({ locateFile: () => wasmUrl })
  .then((engine) => {
    state = { engine, initialised: false };
    drain();
  })
  .catch((e: unknown) => {
    post({ type: 'error', id: null, message: `Could not load the solver: ${String(e)}` });
  });
