// npx tsx scripts/bench-root-uv.ts [triangles...] — the time the USD export's root UVs take on
// a loaded head with its own UVs (export/surfaceUv.ts: a grid of the head's triangles, then the
// closest triangle and its corner UVs per root) against the projection a head without UVs gets.
// The head is generated here: a head-sized sphere (radius 1 unit) of about 100K and 1M
// triangles with per-corner UVs; the roots are 30,000 seeded points on its upper half, 0.1 mm
// out. Printed per size (medians of BENCH_RUNS runs, default 3): groomLayout with the projection,
// with the head's UVs, the difference (the time added), and the grid build alone.
// Writes bench-results/root-uv.{json,md}.
import { groomLayout } from '../web/export/groomLayout';
import { strandsForExport } from '../web/export/strandsForExport';
import { SurfaceUvLookup, type UvSurface } from '../web/export/surfaceUv';
import { DEFAULT_GROWTH } from '../web/model/growthParams';
import { writeBenchResults } from './benchResults.mjs';

const RUNS = Math.max(1, Number(process.env.BENCH_RUNS ?? 3));
const STRANDS = 30_000;

/** A sphere of radius 1 with about `triangles` triangles (K rings of 2K quads), UVs per corner
 *  from longitude and latitude (a seam at the back). */
function sphere(triangles: number): UvSurface {
  const K = Math.max(4, Math.round(Math.sqrt(triangles / 4)));
  const S = 2 * K;
  const positions = new Float32Array(3 * (K + 1) * (S + 1));
  let v = 0;
  for (let i = 0; i <= K; i++)
    for (let j = 0; j <= S; j++) {
      const th = (Math.PI * i) / K;
      const ph = (2 * Math.PI * j) / S;
      positions[v++] = Math.sin(th) * Math.sin(ph);
      positions[v++] = Math.cos(th);
      positions[v++] = Math.sin(th) * Math.cos(ph);
    }
  const idx: number[] = [];
  const uv: number[] = [];
  const at = (i: number, j: number) => i * (S + 1) + j;
  const corner = (i: number, j: number) => {
    idx.push(at(i, j));
    uv.push(j / S, 1 - i / K);
  };
  for (let i = 0; i < K; i++)
    for (let j = 0; j < S; j++) {
      corner(i, j);
      corner(i + 1, j);
      corner(i, j + 1);
      corner(i, j + 1);
      corner(i + 1, j);
      corner(i + 1, j + 1);
    }
  return {
    positions,
    indices: Uint32Array.from(idx),
    cornerUvs: Float32Array.from(uv),
  };
}

function roots(n: number) {
  let a = 12345;
  const rand = () => {
    a = (Math.imul(a, 1664525) + 1013904223) >>> 0;
    return a / 4294967296;
  };
  const points = new Float32Array(6 * n);
  const strandStart = new Uint32Array(n + 1);
  for (let s = 0; s < n; s++) {
    const y = rand();
    const r = Math.sqrt(1 - y * y);
    const ph = 2 * Math.PI * rand();
    const d = [r * Math.sin(ph), y, r * Math.cos(ph)];
    for (let k = 0; k < 3; k++) {
      points[6 * s + k] = 1.001 * d[k];
      points[6 * s + 3 + k] = 1.5 * d[k];
    }
    strandStart[s + 1] = 2 * (s + 1);
  }
  return { points, strandStart };
}

const median = (xs: number[]) => [...xs].sort((x, y) => x - y)[Math.floor(xs.length / 2)];
const time = (f: () => void) => {
  const t0 = performance.now();
  f();
  return performance.now() - t0;
};

const sizes = process.argv.slice(2).map(Number);
const triangleCounts = sizes.length > 0 ? sizes : [100_000, 1_000_000];
const strands = strandsForExport(roots(STRANDS), {
  hairColor: '#5a3825',
  growth: DEFAULT_GROWTH,
});
const session = { curves: [], growth: DEFAULT_GROWTH };
const rows: {
  triangles: number;
  projectionMs: number;
  headUvMs: number;
  addedMs: number;
  gridMs: number;
}[] = [];
for (const n of triangleCounts) {
  const head = sphere(n);
  const proj: number[] = [];
  const own: number[] = [];
  const grid: number[] = [];
  for (let r = 0; r < RUNS; r++) {
    proj.push(time(() => groomLayout(strands, {}, session)));
    own.push(time(() => groomLayout(strands, {}, session, head)));
    grid.push(time(() => new SurfaceUvLookup(head)));
  }
  const row = {
    triangles: head.indices.length / 3,
    projectionMs: Math.round(median(proj)),
    headUvMs: Math.round(median(own)),
    addedMs: Math.round(median(own) - median(proj)),
    gridMs: Math.round(median(grid)),
  };
  rows.push(row);
  console.log(JSON.stringify(row));
}
const table = [
  '| head triangles | groom layout, projection (ms) | groom layout, head UVs (ms) | added (ms) | of which the grid (ms) |',
  '| ---: | ---: | ---: | ---: | ---: |',
  ...rows.map(
    (r) =>
      `| ${r.triangles.toLocaleString('en-US')} | ${r.projectionMs} | ${r.headUvMs} | ${r.addedMs} | ${r.gridMs} |`,
  ),
].join('\n');
console.log(table);
writeBenchResults('root-uv', {
  title: "USD root UVs from a loaded head's own UVs: time added for 30,000 strands",
  script: 'scripts/bench-root-uv.ts',
  command: 'npx tsx scripts/bench-root-uv.ts',
  measures: `groomLayout (web/export/groomLayout.ts) for ${STRANDS.toLocaleString('en-US')} two-point strands rooted 0.1 mm off a generated sphere head, with the scalp-layout projection and with the head's own corner UVs (closest triangle through a uniform grid, export/surfaceUv.ts); medians of ${RUNS} runs, ms; "added" is the difference; "grid" the lookup's build alone (part of "added").`,
  config: { strands: STRANDS, runs: RUNS, triangles: triangleCounts },
  results: rows,
  table,
});
