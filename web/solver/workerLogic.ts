// The worker's logic as plain functions over a SolverEngine, so the same code runs in the
// browser worker and under Node tests with the real wasm module.
import type { SolverEngine } from './engine';
import type { FromWorker, ToWorker } from './protocol';

export type Post = (msg: FromWorker) => void;

export interface WorkerState {
  engine: SolverEngine;
  initialised: boolean;
}

const now = (): number => (typeof performance !== 'undefined' ? performance.now() : Date.now());

const errorMessage = (e: unknown): string => (e instanceof Error ? e.message : String(e));

export function handleMessage(state: WorkerState, msg: ToWorker, post: Post): void {
  switch (msg.type) {
    case 'init': {
      try {
        state.engine.setGrid(msg.grid, msg.omega, msg.solver);
        state.engine.setScalp(msg.scalp);
        state.initialised = true;
        const n = msg.grid.dims[0] * msg.grid.dims[1] * msg.grid.dims[2];
        post({ type: 'ready', gridPoints: n, roots: 0 });
      } catch (e) {
        post({ type: 'error', id: null, message: `Solver set-up failed: ${errorMessage(e)}` });
      }
      return;
    }
    case 'solve': {
      if (!state.initialised) {
        post({ type: 'error', id: msg.id, message: 'Solver is not initialised' });
        return;
      }
      try {
        post({ type: 'progress', id: msg.id, phase: 'constraints', fraction: 0 });
        state.engine.setCurves(msg.curves);
        post({ type: 'progress', id: msg.id, phase: 'solve', fraction: 0.1 });
        state.engine.solve();
        post({ type: 'progress', id: msg.id, phase: 'grow', fraction: 0.8 });
        const t0 = now();
        const strands = state.engine.grow(msg.growth);
        const growMs = now() - t0;
        const stats = { ...state.engine.stats(), growMs };
        const result: Extract<FromWorker, { type: 'result' }> = {
          type: 'result',
          id: msg.id,
          strands,
          constraints: state.engine.constraints(),
          field: msg.wantField ? state.engine.field() : null,
          stats,
        };
        post(result);
      } catch (e) {
        post({ type: 'error', id: msg.id, message: errorMessage(e) });
      }
      return;
    }
  }
}
