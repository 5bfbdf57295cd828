// scalpCoverage against hand-made hair: no hair leaves every visible scalp point bare; a blanket of
// strands just outside the back of the head hides the back but not the front; strands behind
// the scalp point (inside the head, as seen from the ray's side) hide nothing. Then the figure
// presets as grown: their hair covers the back of the head and stays out of it.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { growSessionHair } from '../../web/export/growSession';
import { scalpCoverage, VIEW_DIRECTIONS } from '../../web/head/hairCoverage';
import { Head } from '../../web/head/head';
import { gridForSession } from '../../web/model/grid';
import type { StrandArrays } from '../../web/model/hairArrays';
import { hangLength } from '../../web/model/session';
import { loadSolverEngine } from '../../web/solver/wasmEngine';

const head = Head.builtin();

/** Vertical strands on a lattice of (x, y), at depth z(x, y). */
function blanket(z: (x: number, y: number) => number, spacing: number): StrandArrays {
  const pts: number[] = [];
  const start = [0];
  for (let x = -1.3; x <= 1.3; x += spacing) {
    for (let y = -1.5; y <= 1.4; y += 0.05) pts.push(x, y, z(x, y));
    start.push(pts.length / 3);
  }
  return { points: Float32Array.from(pts), strandStart: Uint32Array.from(start) };
}

describe('scalpCoverage', () => {
  it('finds the scalp bare without hair, from the back and from the top', () => {
    const back = scalpCoverage(head, null, { dir: VIEW_DIRECTIONS.back, stepDeg: 6 });
    expect(back.points).toBeGreaterThan(50);
    expect(back.bare).toBe(back.points);
    const top = scalpCoverage(head, null, { dir: VIEW_DIRECTIONS.top, stepDeg: 6 });
    expect(top.points).toBeGreaterThan(50);
    expect(top.fraction).toBe(1);
  });

  it('counts a dense curtain behind the head as covering the back, not the front', () => {
    // strands every 5 mm at z = -1.5 (behind the head, which ends near z = -1.1)
    const curtain = blanket(() => -1.5, 0.005);
    const back = scalpCoverage(head, curtain, { dir: VIEW_DIRECTIONS.back, stepDeg: 6 });
    expect(back.bare).toBe(0);
    const front = scalpCoverage(head, curtain, { dir: VIEW_DIRECTIONS.front, stepDeg: 6 });
    expect(front.points).toBeGreaterThan(10);
    expect(front.bare).toBe(front.points); // the curtain is behind the scalp seen from the front
  });

  it('does not count strands farther than the radius from a ray', () => {
    // strands every 10 cm: most rays pass more than 1 mm from every strand
    const sparse = blanket(() => -1.5, 0.1);
    const one = { dir: VIEW_DIRECTIONS.back, stepDeg: 6, radius: 0.01, layers: 1 };
    const c = scalpCoverage(head, sparse, one);
    expect(c.bare).toBeGreaterThan(0.7 * c.points);
    expect(c.bare).toBeLessThan(c.points); // a few rays do pass next to one
    // by default a point needs 3 different strands in front: one stray strand hides nothing
    const three = scalpCoverage(head, sparse, { ...one, layers: undefined });
    expect(three.bare).toBe(three.points);
  });
});

// The figure presets as the app grows them (growSessionHair on the session's grid is the app's
// converged hair, see growSession.test.ts), every root: the back of the head is covered, and no segment passes more
// than 1 mm inside the head (its ends and middle, by the head's signed distance).
describe('the figure presets from behind', () => {
  const wasmBinary = new Uint8Array(
    readFileSync(fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url))),
  );
  for (const preset of ['fig8', 'fig1', 'fig6', 'fig7', 'default'] as const)
    it(`${preset}: at most 2 % of the scalp is bare, no segment inside the head`, async () => {
      const engine = await loadSolverEngine({ wasmBinary });
      const session = presetSession(preset, head, '25k', 0);
      const { strands } = growSessionHair(engine, session, head.scalpMesh(), {
        grid: gridForSession(session.grid, session.curves, undefined, hangLength(session)),
        solver: 'fast',
      });
      engine.dispose();
      expect(strands.strandStart.length - 1).toBeGreaterThan(20_000);
      const back = scalpCoverage(head, strands, { dir: VIEW_DIRECTIONS.back });
      console.log(
        `${preset} from behind: ${back.bare} of ${back.points} scalp points bare (${(100 * back.fraction).toFixed(2)} %)`,
      );
      expect(back.points).toBeGreaterThan(1000);
      expect(back.fraction).toBeLessThanOrEqual(0.02);
      const P = strands.points;
      const at = (k: number) => head.signedDistance([P[3 * k], P[3 * k + 1], P[3 * k + 2]]);
      let inside = 0; // every third strand (tens of thousands: the test's time, otherwise)
      for (let i = 0; i + 1 < strands.strandStart.length; i += 3)
        for (let k = strands.strandStart[i]; k + 1 < strands.strandStart[i + 1]; k++) {
          const mid = head.signedDistance([
            (P[3 * k] + P[3 * k + 3]) / 2,
            (P[3 * k + 1] + P[3 * k + 4]) / 2,
            (P[3 * k + 2] + P[3 * k + 5]) / 2,
          ]);
          if (Math.min(at(k), at(k + 1), mid) < -0.01) inside++;
        }
      expect(inside).toBe(0);
    });
});
