// Distance along a mesh's edges (web/head/edgeDistance.ts, Dijkstra with a cut-off) against
// Floyd–Warshall over the same edge graph.
import { describe, expect, it } from 'vitest';
import { edgeDistance } from '../../web/head/edgeDistance';

/** A bumpy grid of n × n vertices, two triangles per cell, seeded. */
function bumpyGrid(n: number, seed: number) {
  let s = seed;
  const rnd = () => {
    s = (s * 1103515245 + 12345) % 2147483648;
    return s / 2147483648;
  };
  const positions: number[] = [];
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++) positions.push(i + 0.4 * rnd(), j + 0.4 * rnd(), rnd());
  const indices: number[] = [];
  for (let j = 0; j + 1 < n; j++)
    for (let i = 0; i + 1 < n; i++) {
      const a = j * n + i;
      if (rnd() < 0.5) indices.push(a, a + 1, a + n + 1, a, a + n + 1, a + n);
      else indices.push(a, a + 1, a + n, a + 1, a + n + 1, a + n);
    }
  return { positions, indices };
}

function floydWarshall(positions: number[], indices: number[]): Float64Array {
  const n = positions.length / 3;
  const d = new Float64Array(n * n).fill(Infinity);
  for (let v = 0; v < n; v++) d[v * n + v] = 0;
  for (let t = 0; t < indices.length; t += 3)
    for (let k = 0; k < 3; k++) {
      const a = indices[t + k];
      const b = indices[t + ((k + 1) % 3)];
      const e = Math.hypot(
        positions[3 * a] - positions[3 * b],
        positions[3 * a + 1] - positions[3 * b + 1],
        positions[3 * a + 2] - positions[3 * b + 2],
      );
      d[a * n + b] = Math.min(d[a * n + b], e);
      d[b * n + a] = Math.min(d[b * n + a], e);
    }
  for (let k = 0; k < n; k++)
    for (let i = 0; i < n; i++)
      for (let j = 0; j < n; j++)
        if (d[i * n + k] + d[k * n + j] < d[i * n + j]) d[i * n + j] = d[i * n + k] + d[k * n + j];
  return d;
}

describe('edgeDistance', () => {
  it('is the shortest path along the edges to the nearest source, Infinity past the cut-off', () => {
    for (const seed of [1, 2, 3]) {
      const { positions, indices } = bumpyGrid(9, seed);
      const n = positions.length / 3;
      const all = floydWarshall(positions, indices);
      const sources = new Set([0, 40, 77].map((v) => (v + seed) % n));
      for (const cutoff of [2.5, Infinity]) {
        const d = edgeDistance(positions, indices, (v) => sources.has(v), cutoff);
        let reached = 0;
        for (let v = 0; v < n; v++) {
          let best = Infinity;
          for (const s of sources) best = Math.min(best, all[s * n + v]);
          if (best < cutoff) {
            expect(d[v]).toBeCloseTo(best, 12);
            reached++;
          } else expect(d[v]).toBe(Infinity);
        }
        expect(reached).toBeGreaterThan(sources.size);
        if (cutoff < Infinity) expect(reached).toBeLessThan(n);
      }
    }
  });
});
