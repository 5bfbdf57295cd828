// Measures how round a preset's ponytails are (method S4.6), through the same pipeline as
// `hairsketch grow` (the real wasm solver). For each ponytail: the strands crossing the plane
// normal to the spine at mid-length between C1 and the spine's end (within 2.5 x the local
// circle radius of the spine), their PCA widths (2 std along each principal axis), the ratio
// minor / major, the local circle radius, and how many of their roots lie on the tail's side of
// x = 0.
//   npx tsx scripts/measure-ponytail.ts [fig1|fig8 ...] [--grid 25k|50k] [--gather N]
// --gather N puts the ponytail parameter `gather` = N into every ponytail block (after
// tightness, solver-cpp/src/ponytail_constraints.hpp) before the solver sees it; without it the
// blocks are the session's own.

import { readFileSync } from 'node:fs';
import { presetSession } from '../web/cli/presetSession';
import { growSessionHair } from '../web/export/growSession';
import { Head } from '../web/head/head';
import { type GridPreset, gridForSession } from '../web/model/grid';
import type { CurveSet, StrandArrays } from '../web/model/hairArrays';
import type { PresetName } from '../web/model/presets';
import type { PonytailCurve } from '../web/model/session';
import { hangLength } from '../web/model/session';
import { engineOver } from '../web/solver/requestRunner';
import { loadWasmEngine } from '../web/solver/wasmEngine';

type V = [number, number, number];
const sub = (a: V, b: V): V => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: V, b: V) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const len = (a: V) => Math.sqrt(dot(a, a));
const scl = (a: V, s: number): V => [a[0] * s, a[1] * s, a[2] * s];
const add = (a: V, b: V): V => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const cross = (a: V, b: V): V => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
const unit = (a: V) => scl(a, 1 / len(a));

function measure(c: PonytailCurve, s: StrandArrays, at = 0.5, window = 2.5) {
  const spine = c.points as V[];
  const c1 = c.circles[0].centre as V;
  let i1 = 0;
  spine.forEach((p, i) => {
    if (len(sub(p, c1)) < len(sub(spine[i1], c1))) i1 = i;
  });
  const acc = [0];
  for (let i = i1 + 1; i < spine.length; i++)
    acc.push(acc[acc.length - 1] + len(sub(spine[i], spine[i - 1])));
  const target = Math.max(1e-9, acc[acc.length - 1] * at);
  let j = 1;
  while (j + 1 < acc.length && acc[j] < target) j++;
  const f = (target - acc[j - 1]) / (acc[j] - acc[j - 1]);
  const a = spine[i1 + j - 1];
  const b = spine[i1 + j];
  const o = add(a, scl(sub(b, a), f));
  const n = unit(sub(b, a));
  let radius = 0;
  let best = Number.POSITIVE_INFINITY;
  for (const q of c.circles) {
    const d = len(sub(q.centre as V, o));
    if (d < best) {
      best = d;
      radius = q.radius;
    }
  }
  const u = unit(cross(cross([1, 0, 0], n), n));
  const v = cross(n, u);
  const pts: [number, number][] = [];
  let same = 0;
  const P = s.points;
  for (let k = 0; k + 1 < s.strandStart.length; k++) {
    for (let q = s.strandStart[k]; q + 1 < s.strandStart[k + 1]; q++) {
      const p0: V = [P[3 * q], P[3 * q + 1], P[3 * q + 2]];
      const p1: V = [P[3 * q + 3], P[3 * q + 4], P[3 * q + 5]];
      const d0 = dot(sub(p0, o), n);
      const d1 = dot(sub(p1, o), n);
      if (d0 > 0 === d1 > 0 || d0 === d1) continue;
      const x = sub(add(p0, scl(sub(p1, p0), d0 / (d0 - d1))), o);
      if (len(x) > window * radius) continue;
      pts.push([dot(x, u), dot(x, v)]);
      if (P[3 * s.strandStart[k]] > 0 === o[0] > 0) same++;
      break;
    }
  }
  if (process.env.MAP) {
    const N = 24;
    const cells = new Array(N * N).fill(0);
    for (const [x, y] of pts) {
      const i = Math.floor(((x / radius + 3) / 6) * N);
      const j = Math.floor(((y / radius + 3) / 6) * N);
      if (i >= 0 && i < N && j >= 0 && j < N) cells[j * N + i]++;
    }
    const sym = (k: number) => (k === 0 ? '.' : k < 5 ? ':' : k < 20 ? 'o' : k < 80 ? 'O' : '#');
    console.log(
      `  u (across) = ${u.map((x) => x.toFixed(2))}, v (down the page) = ${v.map((x) => x.toFixed(2))}, +-3 r`,
    );
    for (let j = 0; j < N; j++)
      console.log(
        `  |${cells
          .slice(j * N, j * N + N)
          .map(sym)
          .join('')}|`,
      );
  }
  const m = pts.length;
  const mx = pts.reduce((t, p) => t + p[0], 0) / m;
  const my = pts.reduce((t, p) => t + p[1], 0) / m;
  let sxx = 0;
  let syy = 0;
  let sxy = 0;
  for (const [x, y] of pts) {
    sxx += (x - mx) ** 2 / m;
    syy += (y - my) ** 2 / m;
    sxy += ((x - mx) * (y - my)) / m;
  }
  const tr = (sxx + syy) / 2;
  const disc = Math.sqrt(((sxx - syy) / 2) ** 2 + sxy ** 2);
  const major = 2 * Math.sqrt(tr + disc);
  const minor = 2 * Math.sqrt(Math.max(0, tr - disc));
  return {
    strands: m,
    major: +major.toFixed(3),
    minor: +minor.toFixed(3),
    ratio: +(minor / major).toFixed(2),
    radius: +radius.toFixed(3),
    centroidOff: +Math.hypot(mx, my).toFixed(3),
    sameSide: same,
    centre: o.map((x) => +x.toFixed(2)),
    // of the strands rooted on the tail's side with at least 2 points
    sideStrands: (() => {
      let k = 0;
      for (let q = 0; q + 1 < s.strandStart.length; q++)
        if (s.strandStart[q + 1] - s.strandStart[q] > 1 && P[3 * s.strandStart[q]] > 0 === o[0] > 0)
          k++;
      return k;
    })(),
  };
}

/** The curve set with `gather` inserted after tightness in every ponytail block. */
function withGather(cs: CurveSet, gather: number): CurveSet {
  const params: number[] = [];
  const start = [0];
  for (let c = 0; c < cs.kinds.length; c++) {
    const block = Array.from(cs.params.subarray(cs.paramStart[c], cs.paramStart[c + 1]));
    if (cs.kinds[c] === 2) block.splice(1, 0, gather);
    params.push(...block);
    start.push(params.length);
  }
  return { ...cs, params: Float64Array.from(params), paramStart: Uint32Array.from(start) };
}

async function main() {
  const argv = process.argv.slice(2);
  let grid: GridPreset = '25k';
  let gather: number | null = null;
  const names: PresetName[] = [];
  for (let i = 0; i < argv.length; i++) {
    if (argv[i] === '--grid') grid = argv[++i] as GridPreset;
    else if (argv[i] === '--gather') gather = Number(argv[++i]);
    else names.push(argv[i] as PresetName);
  }
  const head = Head.builtin();
  for (const name of names.length ? names : (['fig1', 'fig8'] as PresetName[])) {
    // twins: fig8's two ponytails alone (a ponytail behind one ear plus Mirror)
    const base = presetSession(name === ('twins' as PresetName) ? 'fig8' : name, head, grid, 0);
    const session =
      name === ('twins' as PresetName)
        ? { ...base, curves: base.curves.filter((c) => c.type === 'ponytail') }
        : base;
    const core = await loadWasmEngine({
      wasmBinary: new Uint8Array(readFileSync('web/generated/hairsolver.wasm')),
    });
    if (gather !== null) {
      const set = core.setCurves.bind(core);
      core.setCurves = (cs: CurveSet) => set(withGather(cs, gather));
    }
    const engine = engineOver(core);
    const scalp = head.scalpMesh();
    const g = gridForSession(grid, session.curves, undefined, hangLength(session));
    const hair = growSessionHair(engine, session, scalp, { grid: g, solver: 'fast' });
    const tails = session.curves.filter((c): c is PonytailCurve => c.type === 'ponytail');
    tails.forEach((c, k) => {
      for (const at of [0, 0.5])
        console.log(
          JSON.stringify({
            preset: name,
            grid,
            step: +g.step.toFixed(3),
            gather,
            tail: k,
            at,
            circles: c.circles.length,
            c1: +c.circles[0].radius.toFixed(3),
            ...measure(c, hair.strands, at),
          }),
        );
    });
    engine.dispose?.();
  }
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
