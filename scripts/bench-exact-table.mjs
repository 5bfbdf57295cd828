// Formats the JSON lines of solver-cpp/bench/exact_bench into a markdown table.
// Usage: node scripts/bench-exact-table.mjs bench-results/exact-<time>.jsonl [--json OUT.json]
// With --json, also writes one JSON document: the machine, every measurement, and the table.
import { execSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { cpus, totalmem } from 'node:os';

const input = process.argv[2];
const jsonAt = process.argv.indexOf('--json');
const jsonOut = jsonAt > 0 ? process.argv[jsonAt + 1] : undefined;

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

if (jsonOut) {
  const tryRun = (cmd) => {
    try {
      return execSync(cmd, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }).trim();
    } catch {
      return null;
    }
  };
  const doc = {
    date: new Date().toISOString(),
    source: input,
    machine: {
      cpu: cpus()[0]?.model ?? null,
      cores: cpus().length,
      memoryMB: Math.round(totalmem() / 1048576),
      node: process.version,
      emcc: tryRun('emcc --version')?.split('\n')[0] ?? null,
      cxx: tryRun('c++ --version')?.split('\n')[0] ?? null,
      commit: tryRun('git rev-parse HEAD'),
    },
    rows,
    table,
  };
  writeFileSync(jsonOut, `${JSON.stringify(doc, null, 2)}\n`);
}
