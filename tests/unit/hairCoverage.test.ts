// scalpCoverage against hand-made hair: no hair leaves every visible scalp point bare; a blanket of
// strands just outside the back of the head hides the back but not the front; strands behind
// the scalp point (inside the head, as seen from the ray's side) hide nothing.
import { describe, expect, it } from 'vitest';
import { scalpCoverage, VIEW_DIRECTIONS } from '../../web/head/hairCoverage';
import { Head } from '../../web/head/head';
import type { StrandArrays } from '../../web/model/hairArrays';

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
