// The fast solver's iteration counts on the app's constraints (solver-cpp/bench/mg_bench --app):
// writes the default preset's constraint sets on each grid (BEFORE: without its last curve,
// AFTER: the whole preset; "nx ny nz" then "index tx ty tz" lines, as the engine builds them from
// the curves) and runs the native mg_bench on the edit BEFORE -> AFTER (warm start to 1e-6, then
// the history-free solve from zero to 1e-6). MG_THREADS=N runs the solver on N threads.
//   npx tsx scripts/bench-mg-app.ts [25k 50k 250k]
// MG_BUILD: the cmake build dir (default build/native; mg_bench is built there first), or
// several separated by commas (compared in one run: each grid runs every build in turn, none is
// rebuilt). The constraint files go to build/bench/mg-app/; the results to
// bench-results/mg-app.{json,md}.
import { execFileSync } from 'node:child_process';
import { mkdirSync, writeFileSync } from 'node:fs';
import { presetSession } from '../web/cli/presetSession';
import { Head } from '../web/head/head';
import { packCurves } from '../web/model/curveSet';
import { type GridPreset, gridForSession } from '../web/model/grid';
import type { GridSpec } from '../web/model/hairArrays';
import { hangLength, type SessionState } from '../web/model/session';
import { singleNodeOptions } from '../web/solver/nodeThreads';
import { loadWasmEngine } from '../web/solver/wasmEngine';
import { writeBenchResults } from './benchResults.mjs';

const builds = (process.env.MG_BUILD ?? 'build/native').split(',');
const grids = (
  process.argv.slice(2).length ? process.argv.slice(2) : ['25k', '50k', '250k']
) as GridPreset[];
const head = Head.builtin();
const dir = 'build/bench/mg-app';
mkdirSync(dir, { recursive: true });
if (builds.length === 1) {
  // npm test configures build/native without the benchmarks
  execFileSync('cmake', ['-S', 'solver-cpp', '-B', builds[0], '-DHAIRSKETCH_BENCH=ON'], {
    stdio: 'ignore',
  });
  execFileSync('cmake', ['--build', builds[0], '--target', 'mg_bench'], { stdio: 'ignore' });
}

async function write(session: SessionState, spec: GridSpec, file: string) {
  const engine = await loadWasmEngine(singleNodeOptions());
  try {
    engine.setGrid(spec, 100, 'fast');
    engine.setScalp(head.scalpMesh());
    engine.setCurves(packCurves(session.curves, null, !!session.fall));
    const c = engine.constraints();
    const lines = [spec.dims.join(' ')];
    for (let e = 0; e < c.index.length; e++)
      lines.push(`${c.index[e]} ${c.target[3 * e]} ${c.target[3 * e + 1]} ${c.target[3 * e + 2]}`);
    writeFileSync(file, `${lines.join('\n')}\n`);
  } finally {
    engine.dispose();
  }
}

const table: string[] = [];
const results: Array<{ grid: string; build: string; columns: string[]; values: string[] }> = [];
const cells = (line: string) =>
  line
    .split('|')
    .map((c) => c.trim())
    .filter((c) => c.length > 0);
for (const grid of grids) {
  const after = presetSession('default', head, grid, 0);
  const before = { ...after, curves: after.curves.slice(0, -1) };
  const [b, a] = [`${dir}/${grid}-before.txt`, `${dir}/${grid}-after.txt`];
  const spec = gridForSession(grid, after.curves, undefined, hangLength(after)); // both on the whole preset's grid
  await write(before, spec, b);
  await write(after, spec, a);
  for (const build of builds) {
    const out = execFileSync(`${build}/mg_bench`, ['--app', b, a], { encoding: 'utf8' }).split(
      '\n',
    );
    if (table.length === 0) {
      table.push(`| build ${out[0]}`, `|---${out[1]}`);
      console.log(table.join('\n'));
    }
    table.push(`| ${build} ${out[2]}`);
    console.log(table[table.length - 1]);
    results.push({ grid, build, columns: cells(out[0]), values: cells(out[2]) });
  }
}
writeBenchResults('mg-app', {
  title: "The fast solver on the app's constraints (native mg_bench --app)",
  script: 'scripts/bench-mg-app.ts',
  command: 'npx tsx scripts/bench-mg-app.ts',
  measures:
    "The default preset's constraints on each grid, without its last curve and then whole; the " +
    'native mg_bench solves the edit from one to the other warm-started to 1e-6, then the ' +
    'history-free solve from zero to 1e-6: iterations and times (see solver-cpp/bench/mg_bench.cpp ' +
    'for the columns).',
  config: { grids, builds, threads: process.env.MG_THREADS ?? null },
  results,
  table: table.join('\n'),
});
