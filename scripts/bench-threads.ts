// npm run bench:threads: the threaded wasm module against the single-threaded one, same run,
// under Node (pthreads over worker_threads).
// 1. Solve: the default preset solved from scratch (fresh engine, the app's pipeline to 1e-6) on
//    each grid of BENCH_SOLVE_GRIDS (default 250k,50k; the grid fitted to the curves as in the
//    app), BENCH_SOLVE_ROUNDS alternating rounds (default 3): one JSON line per solve, then per
//    grid the medians, the iterations and the ratio single / threaded.
// 2. Growth: the default preset grown with N strands (default 100,000) on BENCH_GRID (default
//    250k), BENCH_ROUNDS alternating rounds (default 2), best of BENCH_REPEAT growths per
//    engine: one JSON line per module and the speedups (BENCH_ROUNDS=0: no growth part).
// BENCH_THREADS=N (default: min(4, logical cores)). Writes bench-results/threads.{json,md}.

import { availableParallelism } from 'node:os';
import { presetSession } from '../web/cli/presetSession';
import { growSessionHair } from '../web/export/growSession';
import { Head } from '../web/head/head';
import { type GridPreset, gridForPreset, gridForSession } from '../web/model/grid';
import { hangLength } from '../web/model/session';
import {
  singleNodeOptions,
  stopThreadWorkers,
  threadedNodeOptions,
} from '../web/solver/nodeThreads';
import { engineOver } from '../web/solver/requestRunner';
import { chooseThreads, type LoadOptions, loadWasmEngine } from '../web/solver/wasmEngine';
import { writeBenchResults } from './benchResults.mjs';

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
  const core = await loadWasmEngine(load);
  const engine = engineOver(core);
  const hair = growSessionHair(engine, session, head.scalpMesh(), {
    grid,
    solver: 'fast',
    maxStrands: strands,
  });
  // growth again on the converged field, best of `repeat`
  let growMs = hair.growMs;
  for (let r = 1; r < repeat; r++) {
    const t = performance.now();
    core.grow({ ...session.growth, maxStrands: strands });
    growMs = Math.min(growMs, performance.now() - t);
  }
  const out = {
    module: core.moduleLabel(),
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

const median = (v: number[]) => {
  const s = [...v].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

/** Solve only (maxStrands 1: the growth is negligible), from a fresh engine. */
async function solveOnce(load: LoadOptions, gridName: GridPreset) {
  const s = presetSession('default', head, gridName, 0);
  const core = await loadWasmEngine(load);
  const engine = engineOver(core);
  try {
    const hair = growSessionHair(engine, s, head.scalpMesh(), {
      grid: gridForSession(gridName, s.curves, undefined, hangLength(s)),
      solver: 'fast',
      maxStrands: 1,
    });
    return { module: core.moduleLabel(), solveMs: hair.solveMs, iterations: hair.iterations };
  } finally {
    engine.dispose();
  }
}

const threadedLoad = await threadedNodeOptions(threads);
const solveGrids = (process.env.BENCH_SOLVE_GRIDS ?? '250k,50k').split(',') as GridPreset[];
const solveRounds = Number(process.env.BENCH_SOLVE_ROUNDS ?? 3);
const solveSummary = [];
for (const g of solveGrids.filter((x) => x)) {
  const ms = { single: [] as number[], threaded: [] as number[] };
  const its = { single: 0, threaded: 0 };
  for (let r = 0; r < solveRounds; r++)
    for (const [label, load] of [
      ['single', singleNodeOptions()],
      ['threaded', threadedLoad],
    ] as const) {
      const o = await solveOnce(load, g);
      ms[label].push(o.solveMs);
      its[label] = o.iterations;
      console.log(JSON.stringify({ solve: g, label, ...o, solveMs: Math.round(o.solveMs) }));
    }
  const single = median(ms.single);
  const threadedMs = median(ms.threaded);
  const line = {
    grid: g,
    threads,
    rounds: solveRounds,
    singleMedianMs: Math.round(single),
    threadedMedianMs: Math.round(threadedMs),
    iterations: its,
    ratio: +(single / threadedMs).toFixed(2),
  };
  solveSummary.push(line);
  console.log(JSON.stringify({ solveMedians: line }));
}

// Alternating rounds, best of each (other load on the machine hits both alike).
const rounds = Number(process.env.BENCH_ROUNDS ?? 2);
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
const table = [
  '| part | grid | single-threaded ms | threaded ms | single / threaded | iterations (single / threaded) |',
  '| --- | --- | --- | --- | --- | --- |',
];
for (const l of solveSummary)
  table.push(
    `| solve (median of ${l.rounds}) | ${l.grid} | ${l.singleMedianMs} | ${l.threadedMedianMs} | ${l.ratio} | ${l.iterations.single} / ${l.iterations.threaded} |`,
  );
const growth =
  rounds > 0
    ? {
        threads,
        best,
        solveSpeedup: +(best.single.solveMs / best.threaded.solveMs).toFixed(2),
        growSpeedup: +(best.single.growMs / best.threaded.growMs).toFixed(2),
      }
    : null;
if (growth)
  table.push(
    `| growth of ${strands.toLocaleString('en-US')} strands (best of ${rounds} × ${repeat}) | ${gridName} | ${Math.round(best.single.growMs)} | ${Math.round(best.threaded.growMs)} | ${growth.growSpeedup} | |`,
  );
console.log(table.join('\n'));
writeBenchResults('threads', {
  title: 'Threads: the threaded wasm module against the single-threaded one',
  script: 'scripts/bench-threads.ts',
  command: 'npm run bench:threads',
  measures:
    `Both wasm modules under Node in the same run, the threaded one with ${threads} threads. ` +
    "Solve: the default preset solved from scratch (fresh engine, the app's pipeline to 1e-6) on " +
    'each grid, alternating rounds, medians. Growth: the default preset grown with many strands ' +
    '(roots every 0.55° above 30,000), best of the rounds and repeats.',
  config: {
    threads,
    solveGrids,
    solveRounds,
    growthGrid: gridName,
    strands,
    rounds,
    repeat,
  },
  results: { solve: solveSummary, growth },
  table: table.join('\n'),
});
await stopThreadWorkers();
