// The wasm module's memory estimate against its real heap: for several grids, a fresh module's
// memory (HEAPU8.length, which only grows) after setGrid + solve stays under the estimate plus
// what was in use before, and the estimate is not absurdly larger (3x). Prints the figures.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import createHairSolver from '../../web/generated/hairsolver.mjs';
import { loadRawSolver } from '../../web/solver/wasmEngine';

const wasmBinary = readFileSync('web/generated/hairsolver.wasm');

describe('wasm memory estimate', () => {
  for (const [solver, dims] of [
    ['exact', [24, 24, 24]],
    ['exact', [29, 29, 29]],
    ['fast', [48, 48, 48]],
    ['fast', [4, 4, 50000]],
    ['cg', [64, 64, 64]],
  ] as Array<[string, [number, number, number]]>)
    it(`${solver} ${dims.join('x')}: heap growth <= estimate <= 3x it`, async () => {
      const s = await loadRawSolver(solver, { wasmBinary });
      const mod = await createHairSolver({ wasmBinary }); // the size of an empty module
      const empty = mod.HEAPU8.length;
      const { needsBytes, capBytes } = s.estimate(dims);
      expect(needsBytes).toBeLessThan(capBytes);
      s.setGrid(dims, 100);
      const [nx, ny] = dims;
      const idx = new Int32Array([nx / 2 + nx * (ny / 2), nx * ny * 2 + 1]);
      s.setConstraints(idx, new Float64Array([0, 0, 1, 1, 0, 0]));
      const t0 = Date.now(); // iterative solves are stopped after 2 s: memory is what counts
      s.onProgress(100, () => Date.now() - t0 < 2000);
      try {
        s.solve();
      } catch {
        // an iterative solve may stop unconverged; the memory is what is measured
      }
      // @ts-expect-error the module behind the raw solver (test only)
      const heap: number = s.mod.HEAPU8.length - empty;
      console.log(
        `[wasm memory] ${solver} ${dims.join('x')}: estimate ${(needsBytes / 1e6).toFixed(1)} MB, heap growth ${(heap / 1e6).toFixed(1)} MB, ratio ${(needsBytes / heap).toFixed(2)}`,
      );
      // Growth comes in steps (up to 20% or 96 MB past a request): allow one step.
      expect(heap).toBeLessThanOrEqual(needsBytes * 1.2 + 16 * 2 ** 20);
      expect(needsBytes).toBeLessThanOrEqual(3 * heap + 32 * 2 ** 20);
      s.dispose();
    });
});
