// npm run bench:threads: the threaded wasm module against the single-threaded one, same run,
// under Node (pthreads over worker_threads): the default preset solved from scratch on a grid
// (default 250k) and grown with N strands (default 100,000). Prints one JSON line per module
// and the speedups. BENCH_GRID=25k|50k|100k|250k, BENCH_STRANDS=N, BENCH_THREADS=N (default:
// min(4, logical cores)), BENCH_REPEAT=N growths per engine, BENCH_ROUNDS=N alternating rounds
// (best of each).
import { availableParallelism } from 'node:os';
import { presetSession } from '../web/cli/presetSession';
import { growSessionHair } from '../web/export/growSession';
import { Head } from '../web/head/head';
import { type GridPreset, gridForPreset } from '../web/model/grid';
import {
  singleNodeOptions,
  stopThreadWorkers,
  threadedNodeOptions,
} from '../web/solver/nodeThreads';
import { chooseThreads, type LoadOptions, loadSolverEngine } from '../web/solver/wasmEngine';

const gridName = (process.env.BENCH_GRID ?? '250k') as GridPreset;
const strands = Number(process.env.BENCH_STRANDS ?? 100_000);
const threads = Number(process.env.BENCH_THREADS ?? chooseThreads(availableParallelism()));
const repeat = Number(process.env.BENCH_REPEAT ?? 3);
const head = Head.builtin();
const grid = gridForPreset(gridName);
// Roots every 0.55° instead of 1° for more than the preset's ~30K strands (as bench:export).
const base = presetSession('default', head, gridName, 0);
const dense = strands > 30_000;
const session = dense
  ? { ...base, growth: { ...base.growth, thetaStepDeg: 0.55, phiStepDeg: 0.55 } }
  : base;

async function run(label: string, load: LoadOptions) {
  const engine = await loadSolverEngine(load);
  const hair = growSessionHair(engine, session, head.scalpMesh(), {
    grid,
    solver: 'fast',
    maxStrands: strands,
  });
  // growth again on the converged field, best of `repeat`
  let growMs = hair.growMs;
  for (let r = 1; r < repeat; r++) {
    const t = performance.now();
    engine.grow({ ...session.growth, maxStrands: strands });
    growMs = Math.min(growMs, performance.now() - t);
  }
  const out = {
    module: engine.moduleLabel(),
    grid: gridName,
    gridPoints: grid.dims[0] * grid.dims[1] * grid.dims[2],
    strands: hair.strands.strandStart.length - 1,
    solveMs: Math.round(hair.solveMs),
    iterations: hair.iterations,
    growMs: Math.round(growMs),
  };
  engine.dispose();
  console.log(JSON.stringify({ label, ...out }));
  return out;
}

// Alternating rounds, best of each (other load on the machine hits both alike).
const rounds = Number(process.env.BENCH_ROUNDS ?? 2);
const threadedLoad = await threadedNodeOptions(threads);
const best = {
  single: { solveMs: Infinity, growMs: Infinity },
  threaded: { solveMs: Infinity, growMs: Infinity },
};
for (let r = 0; r < rounds; r++)
  for (const [label, load] of [
    ['single', singleNodeOptions()],
    ['threaded', threadedLoad],
  ] as const) {
    const o = await run(label, load);
    best[label].solveMs = Math.min(best[label].solveMs, o.solveMs);
    best[label].growMs = Math.min(best[label].growMs, o.growMs);
  }
console.log(
  JSON.stringify({
    threads,
    best,
    solveSpeedup: +(best.single.solveMs / best.threaded.solveMs).toFixed(2),
    growSpeedup: +(best.single.growMs / best.threaded.growMs).toFixed(2),
  }),
);
await stopThreadWorkers();
