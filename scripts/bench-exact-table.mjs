// Formats the JSON lines of solver-cpp/bench/exact_bench (and of scripts/bench-fast-vs-exact.ts)
// into markdown tables, prints them, and writes bench-results/<NAME>.{json,md} (the run's date,
// commit and machine, every measurement, the tables; NAME defaults to exact).
// Usage: node scripts/bench-exact-table.mjs build/bench/exact.jsonl [--name NAME]
import { execSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { writeBenchResults } from './benchResults.mjs';

const input = process.argv[2];
const nameAt = process.argv.indexOf('--name');
const name = nameAt > 0 ? process.argv[nameAt + 1] : 'exact';

const rows = readFileSync(input, 'utf8')
  .split('\n')
  .filter((l) => l.startsWith('{'))
  .map((l) => JSON.parse(l));
const keyOf = (r) => `${r.platform} ${r.N}`;
const groups = new Map();
// scripts/bench-fast-vs-exact.ts's lines (the CLI's fast and exact solvers) have their own table
const fastVsExact = rows.filter((r) => r.kind === 'fastVsExactSummary');
for (const r of rows.filter((x) => !String(x.kind).startsWith('fastVsExact'))) {
  if (!groups.has(keyOf(r))) groups.set(keyOf(r), []);
  groups.get(keyOf(r)).push(r);
}
const s = (ms) => (ms >= 1000 ? `${(ms / 1000).toFixed(2)} s` : `${ms.toFixed(0)} ms`);
const out = [];
out.push('Exact solver (nested dissection of the whole box, supernodal LDLᵀ), ~3000 constraints.');
out.push("peak MB: native = the process's max RSS; wasm = the size of the linear memory.");
out.push('');
out.push(
  '| platform | grid | n | nnz(L) | factor GFLOP | analyse | factor | 3-RHS solve | peak MB |',
);
out.push('| --- | --- | --- | --- | --- | --- | --- | --- | --- |');
for (const [, g] of groups) {
  const a = g.find((r) => r.kind === 'analyse');
  const f = g.find((r) => r.kind === 'factor');
  const mem = g.find((r) => r.kind === 'memory');
  const peak = mem ? mem.peakMB : '—';
  if (!a || !f) continue;
  out.push(
    `| ${a.platform} | ${a.N}³ | ${a.n} | ${(a.nnzL / 1e6).toFixed(1)}M | ${a.factorGflop.toFixed(1)} | ${s(a.ms)} | ${s(f.factorMs)} | ${s(f.solveMs)} | ${peak} |`,
  );
}
out.push('');
out.push(
  'Edits on top of those: a curve of k clustered points added, then removed. "chosen" = the',
);
out.push(
  'method the cost model picked; "solve" = the 3-RHS solve after it (with refinement after an',
);
out.push(
  'update); "update" and "refactor" = the edit with each method (the one not chosen forced).',
);
out.push('');
out.push('| platform | grid | k | op | chosen | solve | update | refactor | est. update GFLOP |');
out.push('| --- | --- | --- | --- | --- | --- | --- | --- | --- |');
for (const [, g] of groups) {
  for (const e of g.filter((r) => r.kind === 'edit')) {
    const time = (method) => {
      if (e.method === method) return `**${s(e.editMs)}**`;
      const f = g.find(
        (r) => r.kind === 'forced' && r.points === e.points && r.op === e.op && r.method === method,
      );
      return f ? s(f.editMs) : '—';
    };
    out.push(
      `| ${e.platform} | ${e.N}³ | ${e.points} | ${e.op} | ${e.method} | ${s(e.solveMs)} | ${time('update')} | ${time('refactor')} | ${e.updateGflop.toFixed(2)} |`,
    );
  }
}
const base = rows.filter((r) => r.kind === 'baseline');
if (base.length) {
  out.push('');
  out.push('Naive baseline: Eigen SimplicialLDLT (AMD), full refactorisation of the same matrix');
  out.push('(every edit costs one such factor).');
  out.push('');
  out.push(
    '| platform | grid | nnz(L) | analyse | factor | solve | rel. diff to exact | peak MB |',
  );
  out.push('| --- | --- | --- | --- | --- | --- | --- | --- |');
  for (const b of base)
    out.push(
      `| ${b.platform} | ${b.N}³ | ${(b.nnzL / 1e6).toFixed(1)}M | ${s(b.analyseMs)} | ${s(b.factorMs)} | ${s(b.solveMs)} | ${b.relDiffToExact.toExponential(1)} | ${b.peakMB}${b.ownProcess ? '' : ' (whole run)'} |`,
    );
}
const notes = rows.filter((r) => r.kind === 'note');
if (notes.length) {
  out.push('');
  for (const n of notes) out.push(`- ${n.platform} ${n.N}³: ${n.text}`);
}
if (fastVsExact.length) {
  if (groups.size === 0)
    out.length = 0; // only the fast-vs-exact part was run
  else out.push('');
  out.push(
    "`npx hairsketch solve --solver fast` against `--solver exact` (wasm, one thread) on the same edit sequences (scripts/bench-fast-vs-exact.ts: ~3000 constraints, then 100 / 300 / 1000 points added and removed; the steps' milliseconds as the CLI prints them, summed):",
  );
  out.push('');
  out.push(
    '| grid | sequences | exact | fast | fast / exact | target | wall time fast / exact | field difference |',
  );
  out.push('| --- | --- | --- | --- | --- | --- | --- | --- |');
  for (const r of fastVsExact)
    out.push(
      `| ${r.N}³ | ${r.seeds} | ${s(r.exactMs)} | ${s(r.fastMs)} | ${r.ratio.toFixed(3)} | ≤ 0.15 | ${(r.fastWallMs / r.exactWallMs).toFixed(3)} | ${r.maxFieldDiff.toExponential(1)} |`,
    );
}
const table = out.join('\n');
console.log(table);

const tryRun = (cmd) => {
  try {
    return execSync(cmd, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }).trim();
  } catch {
    return null;
  }
};
writeBenchResults(name, {
  title: "The exact solver (the paper's incremental factorisation), native and wasm",
  script: 'scripts/bench-exact.sh, scripts/bench-exact-table.mjs',
  command: 'npm run bench',
  measures:
    'Boxes of 29³ (24,389 points) and 37³ (50,653) with ~3000 constraints, natively and in wasm ' +
    'under Node (one thread): analyse, factor, 3-right-hand-side solve and peak memory; edits ' +
    "adding then removing a curve's 100, 300 and 1000 clustered points, with the method the cost " +
    "model chose and the time of both methods; Eigen's SimplicialLDLT refactorisation (AMD " +
    'ordering) as the naive baseline, in its own process; and, after a full `npm run bench`, the ' +
    'fast solver against the exact one through `hairsketch solve` (see fast-vs-exact.md).',
  config: {
    source: input,
    emcc: tryRun('emcc --version')?.split('\n')[0] ?? null,
    cxx: tryRun('c++ --version')?.split('\n')[0] ?? null,
  },
  results: rows,
  table,
});
