// The solver Web Worker: loads the wasm engine and answers protocol messages.
import wasmUrl from '../generated/hairsolver.wasm?url';
import { type FromWorker, resultTransferables, type ToWorker } from './protocol';
import { loadSolverEngine } from './wasmEngine';
import { DEFAULT_SCHEDULER, WorkerLogic } from './workerLogic';

const scope = self as unknown as {
  postMessage(msg: FromWorker, transfer?: Transferable[]): void;
  onmessage: ((ev: MessageEvent<ToWorker>) => void) | null;
};

const post = (msg: FromWorker): void => {
  if (msg.type === 'result') scope.postMessage(msg, resultTransferables(msg));
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

loadSolverEngine({ locateFile: () => wasmUrl })
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
