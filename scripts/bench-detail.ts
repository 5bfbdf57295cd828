// npm run bench:detail — the cost of hair detail in the growth step (the same wasm under Node):
// the default preset's session grown from scratch with each detail block alone and all together
// (the curly preset's values), and with a new session's detail (the empty preset's), printing growth time (roots, strands, detail, keeping points
// outside the head), points, and the segments or segment midpoints inside the head (exact SDF).
// Writes bench-results/detail.{json,md}.
//   npx tsx scripts/bench-detail.ts [strands]     (default: every root, 29,948)

import { readFileSync } from 'node:fs';
import { presetSession } from '../web/cli/presetSession';
import { growSessionHair } from '../web/export/growSession';
import { Head } from '../web/head/head';
import type { HairDetail } from '../web/model/detail';
import { gridForSession } from '../web/model/grid';
import { CURLY_DETAIL, NEW_SESSION_DETAIL } from '../web/model/presetDetail';
import { hangLength } from '../web/model/session';
import { loadSolverEngine } from '../web/solver/wasmEngine';
import { writeBenchResults } from './benchResults.mjs';

const wasmBinary = new Uint8Array(readFileSync('web/generated/hairsolver.wasm'));
const head = Head.builtin();
const strandCap = Number(process.argv[2] ?? 0);
// the default preset's strokes and settings without its own natural detail (each case sets one)
const { detail: _presetDetail, ...base } = presetSession('default', head, '25k', strandCap);
const grid = gridForSession(base.grid, base.curves, undefined, hangLength(base));
const cases: Array<[string, HairDetail | undefined]> = [
  ['none', undefined],
  ['curl', { curl: CURLY_DETAIL.curl }],
  ['clump', { clump: CURLY_DETAIL.clump }],
  ['frizz', { frizz: CURLY_DETAIL.frizz }],
  ['length jitter', { lengthJitter: CURLY_DETAIL.lengthJitter }],
  ['flyaway', { flyaway: NEW_SESSION_DETAIL.flyaway }],
  ['all (curly)', CURLY_DETAIL],
  ["a new session's (clump, jitter, flyaway)", NEW_SESSION_DETAIL],
];

async function main(): Promise<void> {
  const lines = [
    '| detail | strands | points | growth ms (median of 3) | segments inside |',
    '| --- | --- | --- | --- | --- |',
  ];
  const results: Array<{
    detail: string;
    strands: number;
    points: number;
    growMs: number[];
    medianGrowMs: number;
    segmentsInside: number;
  }> = [];
  for (const l of lines) console.log(l);
  for (const [name, detail] of cases) {
    const times: number[] = [];
    let strands = 0;
    let points = 0;
    let inside = 0;
    for (let run = 0; run < 3; run++) {
      const engine = await loadSolverEngine({ wasmBinary });
      const hair = growSessionHair(
        engine,
        { ...base, ...(detail ? { detail } : {}) },
        head.scalpMesh(),
        {
          grid,
          solver: 'fast',
        },
      );
      engine.dispose();
      times.push(hair.growMs);
      if (run > 0) continue;
      const P = hair.strands.points;
      const S = hair.strands.strandStart;
      for (let i = 0; i + 1 < S.length; i++)
        for (let k = S[i]; k + 1 < S[i + 1]; k++) {
          const m: [number, number, number] = [0, 1, 2].map(
            (a) => (P[3 * k + a] + P[3 * k + 3 + a]) / 2,
          ) as [number, number, number];
          const end: [number, number, number] = [P[3 * k + 3], P[3 * k + 4], P[3 * k + 5]];
          if (Math.min(head.signedDistance(m), head.signedDistance(end)) < -0.01) inside++;
        }
      strands = S.length - 1;
      points = P.length / 3;
    }
    const sorted = [...times].sort((a, b) => a - b);
    const line = `| ${name} | ${strands} | ${points} | ${sorted[1].toFixed(0)} | ${inside} |`;
    console.log(line);
    lines.push(line);
    results.push({
      detail: name,
      strands,
      points,
      growMs: times,
      medianGrowMs: sorted[1],
      segmentsInside: inside,
    });
  }
  writeBenchResults('detail', {
    title: 'Hair detail: the cost of curl, clump, frizz, flyaway and length jitter in growth',
    script: 'scripts/bench-detail.ts',
    command: 'npm run bench:detail',
    measures:
      "The default preset's session grown from scratch (wasm under Node, fast solver, 25k grid) " +
      "with each detail block alone, the curly preset's detail and a new session's (the empty " +
      "preset's: clump, length jitter, flyaway): growth " +
      'time measured in wasm (roots, strands, detail, keeping points outside the head; median of ' +
      '3 runs, each on a fresh engine), strand and point counts, and the segments whose midpoint ' +
      'or end lies more than 1 mm inside the head (exact signed distance).',
    config: { preset: 'default', grid: '25k', solver: 'fast', strandCap, runs: 3 },
    results,
    table: lines.join('\n'),
  });
}

void main();
