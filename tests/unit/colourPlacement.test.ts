// Where each strand's colour goes (web/model/colourPlacement.ts): ranks spread evenly, so a
// grey share greys that share of the strands; temples grey first and the nape last; the
// balayage's sections lighter round the face; seeded.
import { describe, expect, it } from 'vitest';
import { colourPlacement, greyRegionWeight, ranks } from '../../web/model/colourPlacement';

/** `n` one-point strands rooted over a sphere about the built-in head's scalp (centre
 *  (0, 0.1, −0.12), radius 0.9; y above −1), from a fixed linear congruential sequence. */
function scalp(n: number): { points: Float32Array; strandStart: Uint32Array } {
  const points = new Float32Array(3 * n);
  let state = 12345;
  const next = () => {
    state = (Math.imul(state, 1103515245) + 12345) >>> 0;
    return state / 4294967296;
  };
  for (let s = 0; s < n; ) {
    const x = 2 * next() - 1;
    const y = 2 * next() - 1;
    const z = 2 * next() - 1;
    const l = Math.hypot(x, y, z);
    if (l > 1 || l < 0.1 || 0.1 + (0.9 * y) / l < -1) continue;
    points.set([(0.9 * x) / l, 0.1 + (0.9 * y) / l, -0.12 + (0.9 * z) / l], 3 * s);
    s++;
  }
  return { points, strandStart: Uint32Array.from({ length: n + 1 }, (_, i) => i) };
}

const isGrey = (rank: number, share: number) => (rank + 0.5) / 256 < share;

describe('colour placement', () => {
  it('ranks values evenly: 256 × the share below each, by hand', () => {
    // 1000 distinct values far enough apart to fall in bins of their own, shuffled
    const n = 1000;
    const order = Array.from({ length: n }, (_, i) => (i * 389) % n);
    const r = ranks(Float64Array.from(order, (k) => k / (n - 1)));
    order.forEach((k, i) => {
      expect(r[i]).toBe(Math.floor((256 * (k + 0.5)) / n));
    });
    expect(ranks(new Float64Array(0)).length).toBe(0);
    // all equal: every one in the middle
    expect([...ranks(new Float64Array(10).fill(3))]).toEqual(new Array(10).fill(128));
  });

  it('greys the share asked for, over the whole head, whatever the share', () => {
    const { points, strandStart } = scalp(20000);
    const { greyRank } = colourPlacement(points, strandStart, 7);
    for (const share of [0, 0.05, 0.18, 0.5, 0.85, 1]) {
      const grey = greyRank.reduce((k, r) => k + (isGrey(r, share) ? 1 : 0), 0);
      expect(Math.abs(grey / greyRank.length - share)).toBeLessThan(0.006);
    }
  });

  it('greys the temples first and the nape last', () => {
    // the weights by hand: a temple (|x| 0.75, z 0): side 1, front 0, nape 0: 1 + 0.7 = 1.7;
    // the crown (0, 1, 0): 1; the nape (0, −0.5, −0.9): nape 1: 1 − 0.42 = 0.58
    expect(greyRegionWeight(0.75, 0.3, 0)).toBeCloseTo(1.7, 6);
    expect(greyRegionWeight(0, 1, 0)).toBeCloseTo(1, 6);
    expect(greyRegionWeight(0, -0.5, -0.9)).toBeCloseTo(0.58, 6);
    const { points, strandStart } = scalp(40000);
    const { greyRank } = colourPlacement(points, strandStart, 11);
    const shareWhere = (inside: (x: number, y: number, z: number) => boolean) => {
      let n = 0;
      let grey = 0;
      for (let s = 0; s < greyRank.length; s++) {
        if (!inside(points[3 * s], points[3 * s + 1], points[3 * s + 2])) continue;
        n++;
        if (isGrey(greyRank[s], 0.18)) grey++;
      }
      expect(n).toBeGreaterThan(300);
      return grey / n;
    };
    const temples = shareWhere((x, _y, z) => Math.abs(x) > 0.68 && z > -0.1 && z < 0.1);
    const crown = shareWhere((x, y, z) => y > 0.9 && Math.abs(x) < 0.2 && Math.abs(z) < 0.2);
    const nape = shareWhere((_x, y, z) => z < -0.8 && y < -0.3);
    // each share is nearer its weight's than an even spread's (1 : 1 : 1)
    expect(temples / crown).toBeGreaterThan(1.5);
    expect(crown / nape).toBeGreaterThan(1.5);
  });

  it("paints the balayage's sections lighter round the face", () => {
    const { points, strandStart } = scalp(20000);
    const { piece } = colourPlacement(points, strandStart, 3);
    const mean = (inside: (x: number, z: number) => boolean) => {
      let n = 0;
      let sum = 0;
      for (let s = 0; s < piece.length; s++)
        if (inside(points[3 * s], points[3 * s + 2])) {
          n++;
          sum += piece[s];
        }
      return sum / n;
    };
    expect(mean((x, z) => z > 0.5 && Math.abs(x) > 0.3)).toBeGreaterThan(
      mean((_x, z) => z < -0.3) + 40,
    );
  });

  it('ranks the other strands alike beside a strand without points or with a root not finite', () => {
    const { points, strandStart } = scalp(1000);
    const plain = colourPlacement(points, strandStart, 5);
    // strand 0's root made NaN, and an empty strand added at the end
    const bad = Float32Array.from(points);
    bad[0] = Number.NaN;
    const withEmpty = Uint32Array.from([...strandStart, strandStart[strandStart.length - 1]]);
    const placed = colourPlacement(bad, withEmpty, 5);
    expect(placed.greyRank.length).toBe(1001);
    // the ranks still spread evenly: the share holds
    const grey = placed.greyRank.reduce((k, r) => k + (isGrey(r, 0.18) ? 1 : 0), 0);
    expect(Math.abs(grey / 1001 - 0.18)).toBeLessThan(0.01);
    // and the other strands keep nearly their ranks (two more values among a thousand)
    let moved = 0;
    for (let s = 1; s < 1000; s++)
      moved = Math.max(moved, Math.abs(placed.greyRank[s] - plain.greyRank[s]));
    expect(moved).toBeLessThanOrEqual(2);
  });

  it('places the same strands alike for a seed, and otherwise for another', () => {
    const { points, strandStart } = scalp(2000);
    const a = colourPlacement(points, strandStart, 5);
    const b = colourPlacement(points, strandStart, 5);
    const c = colourPlacement(points, strandStart, 6);
    expect(b.greyRank).toEqual(a.greyRank);
    expect(b.piece).toEqual(a.piece);
    const same = a.greyRank.reduce((k, r, i) => k + (r === c.greyRank[i] ? 1 : 0), 0);
    expect(same).toBeLessThan(0.1 * a.greyRank.length);
  });
});
