// npm run bench:head — loading and preparing a big head, JS and wasm under Node.
// The head is generated here: a cranium on a neck (a perturbed surface of revolution with a
// nose, in mm, Y-up, closed), written as a binary PLY of about 100K and 1M triangles and read
// back by the app's own loader (loadHead.ts: parse, weld and normalise, BVH with normals, the
// default scalp). Then the solver's side (wasm, hairsolver.wasm): setScalp builds the root
// sampler (ScalpRoots) and the head's distance grid (HeadDistance), and setScalpMask swaps the
// scalp without rebuilding either. Printed per size (medians of 3 runs, BENCH_RUNS to change):
//   JS load ms and its parts, the JS typed arrays the loaded head keeps, the JS signed distance
//   at every point of the 50k grid fitted round the head (banded at 2 grid steps, one run),
//   wasm setScalp ms (JS copy-in included) split into sampler and distance grid, setScalpMask ms,
//   wasm memory (heap growth of a fresh module, bytes the head keeps, bytes in use), and the
//   worker's lighting of one result against the head (resultLighting; 1,000 short strands, so
//   the figure is mostly the head's part: voxelising it and a march per head vertex).
// Writes bench-results/head.{json,md}.
//   npx tsx scripts/bench-head.ts [triangles...]     (default: 100000 1000000)
import { readFileSync } from 'node:fs';
import { type LoadedHead, loadHeadFile } from '../web/head/loadHead';
import { resultLighting } from '../web/lighting/resultLighting';
import { gridForSession } from '../web/model/grid';
import type { ScalpMesh } from '../web/model/hairArrays';
import { DEFAULT_GROWTH } from '../web/model/session';
import type { Vec3 } from '../web/model/vec3';
import { loadWasmEngine } from '../web/solver/wasmEngine';
import { writeBenchResults } from './benchResults.mjs';

const RUNS = Math.max(1, Number(process.env.BENCH_RUNS ?? 3));
const wasmBinary = new Uint8Array(readFileSync('web/generated/hairsolver.wasm'));

/** A closed head on a neck with 4 K² triangles (K rings of 2K vertices between two poles), in
 *  mm: cranium radius 95, neck radius 55 down to y = -175, a nose toward +z. */
function headPly(K: number): ArrayBuffer {
  const S = 2 * K;
  const thetaNeck = Math.PI - Math.asin(55 / 95);
  const yNeck = 95 * Math.cos(thetaNeck);
  const profile = (u: number): [number, number] => {
    if (u <= 0.6) {
      const th = (u / 0.6) * thetaNeck;
      return [95 * Math.sin(th), 95 * Math.cos(th)];
    }
    if (u <= 0.9) return [55, yNeck + ((u - 0.6) / 0.3) * (-175 - yNeck)];
    return [55 * (1 - (u - 0.9) / 0.1), -175];
  };
  const nv = K * S + 2;
  const pos = new Float32Array(3 * nv);
  pos.set([0, 95, 0], 0);
  for (let k = 1; k <= K; k++) {
    const u = k / (K + 1);
    const [rho, y] = profile(u);
    for (let j = 0; j < S; j++) {
      const phi = (2 * Math.PI * j) / S;
      const wobble = 1 + 0.015 * Math.sin(7 * phi) * Math.sin(5 * Math.PI * u);
      const dphi = Math.atan2(Math.sin(phi), Math.cos(phi));
      const nose = 18 * Math.exp(-((y + 20) ** 2) / 200 - dphi ** 2 / 0.02);
      const v = 1 + (k - 1) * S + j;
      pos[3 * v] = 0.85 * rho * wobble * Math.sin(phi);
      pos[3 * v + 1] = y;
      pos[3 * v + 2] = rho * wobble * Math.cos(phi) + nose;
    }
  }
  pos.set([0, -175, 0], 3 * (nv - 1));
  const tris: number[] = [];
  const ring = (k: number, j: number) => 1 + (k - 1) * S + (j % S);
  for (let j = 0; j < S; j++) tris.push(0, ring(1, j), ring(1, j + 1));
  for (let k = 1; k < K; k++)
    for (let j = 0; j < S; j++) {
      tris.push(ring(k, j), ring(k + 1, j), ring(k + 1, j + 1));
      tris.push(ring(k, j), ring(k + 1, j + 1), ring(k, j + 1));
    }
  for (let j = 0; j < S; j++) tris.push(nv - 1, ring(K, j + 1), ring(K, j));
  const nt = tris.length / 3;
  const header = new TextEncoder().encode(
    `ply\nformat binary_little_endian 1.0\nelement vertex ${nv}\nproperty float x\nproperty float y\nproperty float z\nelement face ${nt}\nproperty list uchar int vertex_indices\nend_header\n`,
  );
  const out = new ArrayBuffer(header.length + 12 * nv + 13 * nt);
  new Uint8Array(out).set(header);
  const view = new DataView(out);
  let at = header.length;
  for (let i = 0; i < 3 * nv; i++, at += 4) view.setFloat32(at, pos[i], true);
  for (let t = 0; t < nt; t++) {
    view.setUint8(at++, 3);
    for (let c = 0; c < 3; c++, at += 4) view.setInt32(at, tris[3 * t + c], true);
  }
  return out;
}

const median = (xs: number[]): number => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};
const ms = (x: number) => `${Math.round(x).toLocaleString('en-US')}`;
const mb = (bytes: number) => `${(bytes / 2 ** 20).toFixed(1)}`;
/** Bytes of the typed arrays a loaded head keeps: its mesh (positions, normals, indices, scalp)
 *  and its BVH (three-mesh-bvh's node buffers and triangle order). A GC heap delta was tried
 *  and is too noisy (0 to 150 MB for the same head). */
const headBytes = (h: LoadedHead): number => {
  const m = h.mesh;
  let b = m.positions.byteLength + m.normals.byteLength + m.indices.byteLength;
  b += m.scalp.byteLength + (m.parts?.byteLength ?? 0);
  const bvh = h.head.bvh as unknown as {
    _roots?: ArrayBuffer[];
    _indirectBuffer?: ArrayBufferView | null;
  };
  for (const r of bvh._roots ?? []) b += r.byteLength;
  return b + (bvh._indirectBuffer?.byteLength ?? 0);
};

interface Row {
  triangles: number;
  load: { total: number; parse: number; normalise: number; bvh: number; scalp: number };
  jsHeap: number;
  sdf: { ms: number; points: number };
  lighting: number;
  setScalp: { total: number; sampler: number; distance: number };
  mask: number;
  wasm: { growth: number; head: number; inUse: number; cells: number };
}

async function measure(triangles: number): Promise<Row> {
  const K = Math.round(Math.sqrt(triangles / 4));
  const ply = headPly(K);
  const loads: LoadedHead[] = [];
  const parts = { total: [], parse: [], normalise: [], bvh: [], scalp: [] } as Record<
    keyof Row['load'],
    number[]
  >;
  for (let run = 0; run < RUNS; run++) {
    loads.length = 0;
    const t0 = performance.now();
    const r = await loadHeadFile('generated-head.ply', ply.slice(0));
    const total = performance.now() - t0;
    if (!r.ok) throw new Error(r.error);
    loads.push(r.head);
    const t = r.head.timings;
    parts.total.push(total);
    parts.parse.push(t.parseMs);
    parts.normalise.push(t.normaliseMs);
    parts.bvh.push(t.bvhMs);
    parts.scalp.push(t.scalpMs);
  }
  const loaded = loads[0];
  const nt = loaded.mesh.indices.length / 3;

  // JS signed distance at every point of the 50k grid fitted round the head.
  const grid = gridForSession('50k', [], loaded.mesh.bounds, DEFAULT_GROWTH.maxLength);
  const [nx, ny, nz] = grid.dims;
  const band = 2 * grid.step;
  const s0 = performance.now();
  for (let k = 0; k < nz; k++)
    for (let j = 0; j < ny; j++)
      for (let i = 0; i < nx; i++) {
        const p: Vec3 = [
          grid.origin[0] + i * grid.step,
          grid.origin[1] + j * grid.step,
          grid.origin[2] + k * grid.step,
        ];
        loaded.signedDistance(p, band);
      }
  const sdf = { ms: performance.now() - s0, points: nx * ny * nz };

  // The worker's lighting of a result against this head, with 1,000 straight 10-point strands
  // rising from the top of the head.
  const top = loaded.mesh.bounds.max[1];
  const points = new Float32Array(1000 * 10 * 3);
  for (let s = 0; s < 1000; s++)
    for (let p = 0; p < 10; p++) {
      const at = 3 * (10 * s + p);
      points[at] = -0.5 + (s % 40) / 40;
      points[at + 1] = top + 0.02 * p;
      points[at + 2] = -0.5 + Math.floor(s / 40) / 25;
    }
  const strandStart = Uint32Array.from({ length: 1001 }, (_, s) => 10 * s);
  const lightingMs: number[] = [];
  for (let run = 0; run < RUNS; run++)
    lightingMs.push(resultLighting({ points, strandStart }, loaded.mesh).ms);

  // wasm: setScalp on a fresh module, then masks.
  const scalp: ScalpMesh = loaded.head.scalpMesh();
  const painted = scalp.scalp.slice();
  for (let t = 0; t < nt; t++) {
    let y = 0;
    for (let c = 0; c < 3; c++) y += scalp.positions[3 * scalp.indices[3 * t + c] + 1] / 3;
    if (y > 0.5) painted[t] = 1; // a crown painted on
  }
  const set = { total: [] as number[], sampler: [] as number[], distance: [] as number[] };
  const maskMs: number[] = [];
  let wasm: Row['wasm'] = { growth: 0, head: 0, inUse: 0, cells: 0 };
  for (let run = 0; run < RUNS; run++) {
    const engine = await loadWasmEngine({ wasmBinary });
    const heap0 = engine.heapBytes();
    const t0 = performance.now();
    engine.setScalp(scalp);
    set.total.push(performance.now() - t0);
    const st = engine.headStats();
    set.sampler.push(st.samplerMs);
    set.distance.push(st.distanceMs);
    if (run === 0)
      wasm = {
        growth: engine.heapBytes() - heap0,
        head: st.headBytes,
        inUse: st.inUseBytes,
        cells: st.distanceCells,
      };
    for (const m of [painted, scalp.scalp]) {
      const m0 = performance.now();
      engine.setScalpMask(m);
      maskMs.push(performance.now() - m0);
    }
    engine.dispose();
  }
  return {
    triangles: nt,
    load: {
      total: median(parts.total),
      parse: median(parts.parse),
      normalise: median(parts.normalise),
      bvh: median(parts.bvh),
      scalp: median(parts.scalp),
    },
    jsHeap: headBytes(loaded),
    sdf,
    lighting: median(lightingMs),
    setScalp: {
      total: median(set.total),
      sampler: median(set.sampler),
      distance: median(set.distance),
    },
    mask: median(maskMs),
    wasm,
  };
}

async function main(): Promise<void> {
  const sizes = process.argv.slice(2).map(Number);
  const rows: Row[] = [];
  for (const n of sizes.length ? sizes : [100_000, 1_000_000]) {
    const r = await measure(n);
    rows.push(r);
    console.error(`measured ${r.triangles.toLocaleString('en-US')} triangles`);
  }
  const out = [
    '| triangles | JS load ms (parse / normalise / BVH / default scalp) | JS arrays of the head MB (mesh + BVH) | JS signed distance on the 50k grid ms (points) | wasm setScalp ms (sampler / distance grid) | setScalpMask ms | wasm heap growth MB (head keeps / in use) | distance cells | worker lighting per result ms |',
    '| --- | --- | --- | --- | --- | --- | --- | --- | --- |',
  ];
  for (const r of rows) {
    const l = r.load;
    out.push(
      `| ${r.triangles.toLocaleString('en-US')} | ${ms(l.total)} (${ms(l.parse)} / ${ms(l.normalise)} / ${ms(l.bvh)} / ${ms(l.scalp)}) | ${mb(r.jsHeap)} | ${ms(r.sdf.ms)} (${r.sdf.points.toLocaleString('en-US')}) | ${ms(r.setScalp.total)} (${ms(r.setScalp.sampler)} / ${ms(r.setScalp.distance)}) | ${r.mask.toFixed(1)} | ${mb(r.wasm.growth)} (${mb(r.wasm.head)} / ${mb(r.wasm.inUse)}) | ${r.wasm.cells.toLocaleString('en-US')} | ${ms(r.lighting)} |`,
    );
  }
  console.log(`Generated head (PLY, mm), medians of ${RUNS} runs; Node ${process.version}\n`);
  console.log(out.join('\n'));
  writeBenchResults('head', {
    title: 'Loading and preparing a big head (JS and wasm under Node)',
    script: 'scripts/bench-head.ts',
    command: 'npm run bench:head',
    measures:
      'A head generated by the script (a cranium on a neck with a nose, in mm, closed) written ' +
      "as a binary PLY and read back by the app's loader. Per size, medians of " +
      `${RUNS} runs: the JS load and its parts (parse, weld and normalise, BVH with normals, ` +
      'default scalp), the JS arrays the head keeps, the JS signed distance at every point of ' +
      'the 50k grid around the head (one run), wasm setScalp (root sampler and distance grid, ' +
      "copy-in included), setScalpMask, wasm memory, and the worker's lighting of one small " +
      'result against the head.',
    config: { triangles: rows.map((r) => r.triangles), runs: RUNS },
    results: rows,
    table: out.join('\n'),
  });
}

main().catch((e: unknown) => {
  console.error(e);
  process.exit(1);
});
