// npm run bench:tails — the cost of laying braids, buns and round tails in the growth step (the
// same wasm under Node): each preset grown from scratch on the 25k grid at every root (~30K
// strands), printing the growth time (roots, strands through the field, the tails' capture and
// layout, keeping points outside the head); the preset without its braid and bun curves is
// grown too: the difference is what the tails cost.
// Writes bench-results/tails.{json,md}.
//   npx tsx scripts/bench-tails.ts [strands]     (default: every root)

import { readFileSync } from 'node:fs';
import { presetSession } from '../web/cli/presetSession';
import { growSessionHair } from '../web/export/growSession';
import { Head } from '../web/head/head';
import { gridForSession } from '../web/model/grid';
import { hangLength, type SessionState } from '../web/model/session';
import { loadSolverEngine } from '../web/solver/wasmEngine';
import { writeBenchResults } from './benchResults.mjs';

const wasmBinary = new Uint8Array(readFileSync('web/generated/hairsolver.wasm'));
const head = Head.builtin();
const strandCap = Number(process.argv[2] ?? 0);
const TAIL_KINDS = new Set(['braid', 'bun']);

async function growMs(
  session: SessionState,
): Promise<{ ms: number[]; strands: number; points: number }> {
  const grid = gridForSession(session.grid, session.curves, undefined, hangLength(session));
  const ms: number[] = [];
  let strands = 0;
  let points = 0;
  for (let run = 0; run < 3; run++) {
    const engine = await loadSolverEngine({ wasmBinary });
    const hair = growSessionHair(engine, session, head.scalpMesh(), { grid, solver: 'fast' });
    engine.dispose();
    ms.push(hair.growMs);
    strands = hair.strands.strandStart.length - 1;
    points = hair.strands.points.length / 3;
  }
  return { ms, strands, points };
}

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

async function main(): Promise<void> {
  const lines = [
    '| preset | strands | points | growth ms (median of 3) | without its braids/buns ms | tails cost ms |',
    '| --- | --- | --- | --- | --- | --- |',
  ];
  for (const l of lines) console.log(l);
  const results = [];
  for (const name of ['braid', 'bun', 'pigtail-braids'] as const) {
    const session = presetSession(name, head, '25k', strandCap);
    const withTails = await growMs(session);
    const plain = await growMs({
      ...session,
      curves: session.curves.filter((c) => !TAIL_KINDS.has(c.type)),
    });
    const a = median(withTails.ms);
    const b = median(plain.ms);
    const line = `| ${name} | ${withTails.strands} | ${withTails.points} | ${a.toFixed(0)} | ${b.toFixed(0)} | ${(a - b).toFixed(0)} |`;
    console.log(line);
    lines.push(line);
    results.push({
      preset: name,
      ...withTails,
      medianMs: a,
      withoutTailsMs: plain.ms,
      medianWithoutMs: b,
    });
  }
  writeBenchResults('tails', {
    title: 'Braids and buns: their cost in the growth step',
    script: 'scripts/bench-tails.ts',
    command: 'npm run bench:tails',
    measures:
      'Each preset grown from scratch (wasm under Node, fast solver, 25k grid, every root unless ' +
      'capped): growth time measured in wasm (median of 3 runs on fresh engines), and the same ' +
      'session without its braid and bun curves (the field differs too, so the difference is ' +
      'the tails plus a different field walk).',
    config: { grid: '25k', solver: 'fast', strandCap, runs: 3 },
    results,
    table: lines.join('\n'),
  });
}

void main();
