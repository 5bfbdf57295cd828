// Dev tool: times the worker's steps (setCurves, iterate slices, growth) on a grid preset under
// Node with the real wasm module, starting from the default preset plus one extra stroke.
// Usage: npx tsx scripts/profile-engine.ts [25k|50k|100k|250k] [fast|exact|cg]
import { readFileSync } from 'node:fs';
import { Head } from '../web/head/head';
import { packCurves } from '../web/model/curveSet';
import { gridForPreset, isGridPreset } from '../web/model/grid';
import { presetCurves } from '../web/model/presets';
import { DEFAULT_GROWTH } from '../web/model/session';
import type { SolverName } from '../web/solver/protocol';
import { loadWasmEngine } from '../web/solver/wasmEngine';

const gridName = process.argv[2] ?? '25k';
const solver = (process.argv[3] ?? 'fast') as SolverName;
if (!isGridPreset(gridName)) throw new Error(`unknown grid ${gridName}`);
const t = () => performance.now();
const head = Head.builtin();
const grid = gridForPreset(gridName);
const curves = presetCurves('default', {
  head,
  step: grid.step,
  viewpoint: { position: [0, 0, 6], target: [0, 0, 0] },
});
const engine = await loadWasmEngine({
  wasmBinary: new Uint8Array(readFileSync('web/generated/hairsolver.wasm')),
});
let s = t();
engine.setGrid(grid, 100, solver);
engine.setScalp({
  ...head.scalpMesh(),
});
console.log(`setGrid+setScalp ${(t() - s).toFixed(0)} ms`);
const run = (label: string, set: typeof curves) => {
  s = t();
  engine.setCurves(packCurves(set));
  const setMs = t() - s;
  s = t();
  let p = engine.iterate(4, 1e-6);
  const first = t() - s;
  s = t();
  const light = engine.grow({ ...DEFAULT_GROWTH, maxStrands: 6000 });
  const lightMs = t() - s;
  s = t();
  while (!p.converged) p = engine.iterate(4, 1e-6);
  const rest = t() - s;
  s = t();
  const full = engine.grow(DEFAULT_GROWTH);
  const fullMs = t() - s;
  console.log(
    `${label}: setCurves ${setMs.toFixed(0)} ms, 4 it ${first.toFixed(0)} ms, light growth ${lightMs.toFixed(0)} ms (${light.strandStart.length - 1}), ` +
      `rest ${rest.toFixed(0)} ms to ${p.iterations} it, full growth ${fullMs.toFixed(0)} ms (${full.strandStart.length - 1}), ${engine.stats().method}`,
  );
};
run('preset', curves);
const extra = curves[0];
run('preset+1', [
  ...curves,
  {
    ...extra,
    id: 'x',
    points: extra.points.map(([x, y, z]) => [-x, y, z + 0.05] as [number, number, number]),
  },
]);
run('preset again', curves);
for (const step of [1.0, 0.55]) {
  const g = { ...DEFAULT_GROWTH, thetaStepDeg: step, phiStepDeg: step };
  engine.grow(g); // roots sampled and cached
  const ms: number[] = [];
  const cpp: number[] = [];
  let n = 0;
  for (let r = 0; r < 5; r++) {
    s = t();
    n = engine.grow(g).strandStart.length - 1;
    ms.push(t() - s);
    cpp.push(engine.growMs());
  }
  ms.sort((a, b) => a - b);
  cpp.sort((a, b) => a - b);
  console.log(
    `growth ${n} strands (roots cached): median ${ms[2].toFixed(0)} ms of 5 (in C++ ${cpp[2].toFixed(0)} ms)`,
  );
}
