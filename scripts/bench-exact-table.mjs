// Formats the JSON lines of solver-cpp/bench/exact_bench into a markdown table.
// Usage: node scripts/bench-exact-table.mjs bench-results/exact-<time>.jsonl
import { readFileSync } from 'node:fs';

const rows = readFileSync(process.argv[2], 'utf8')
  .split('\n')
  .filter((l) => l.startsWith('{'))
  .map((l) => JSON.parse(l));
const keyOf = (r) => `${r.platform} ${r.N}`;
const groups = new Map();
for (const r of rows) {
  if (!groups.has(keyOf(r))) groups.set(keyOf(r), []);
  groups.get(keyOf(r)).push(r);
}
const s = (ms) => (ms >= 1000 ? `${(ms / 1000).toFixed(2)} s` : `${ms.toFixed(0)} ms`);
const out = [];
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
out.push('Edits on top of ~3000 constraints: a curve of k clustered points added, then removed.');
out.push('"edit" = factor work of the chosen method; "solve" = the 3-RHS solve after it (with one');
out.push(
  'refinement step after an update); "forced update" = the same edit with the update forced.',
);
out.push('');
out.push('| platform | grid | k | op | method | edit | solve | forced update |');
out.push('| --- | --- | --- | --- | --- | --- | --- | --- |');
for (const [, g] of groups) {
  for (const e of g.filter((r) => r.kind === 'edit')) {
    const forced = g.find((r) => r.kind === 'forced' && r.points === e.points && r.op === e.op);
    out.push(
      `| ${e.platform} | ${e.N}³ | ${e.points} | ${e.op} | ${e.method} | ${s(e.editMs)} | ${s(e.solveMs)} | ${forced ? s(forced.editMs) : '—'} |`,
    );
  }
}
const base = rows.filter((r) => r.kind === 'baseline');
if (base.length) {
  out.push('');
  out.push('Naive baseline: Eigen SimplicialLDLT (AMD), full refactorisation of the same matrix.');
  out.push('');
  out.push(
    '| platform | grid | nnz(L) | analyse | factor | solve | rel. diff to exact | peak MB |',
  );
  out.push('| --- | --- | --- | --- | --- | --- | --- | --- |');
  for (const b of base)
    out.push(
      `| ${b.platform} | ${b.N}³ | ${(b.nnzL / 1e6).toFixed(1)}M | ${s(b.analyseMs)} | ${s(b.factorMs)} | ${s(b.solveMs)} | ${b.relDiffToExact.toExponential(1)} | ${b.peakMB} |`,
    );
}
console.log(out.join('\n'));
