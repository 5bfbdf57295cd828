// everyOtherPoint (web/model/strandSubsample.ts): which points a preview strand keeps, worked
// out by hand here.
import { describe, expect, it } from 'vitest';
import { everyOtherPoint } from '../../web/model/strandSubsample';

/** Strands of the given point counts; point j of the whole array is (j, 10 j, -j). */
function strands(counts: number[]) {
  const total = counts.reduce((a, b) => a + b, 0);
  const points = new Float32Array(3 * total);
  for (let j = 0; j < total; j++) points.set([j, 10 * j, -j], 3 * j);
  const strandStart = new Uint32Array(counts.length + 1);
  counts.forEach((c, k) => {
    strandStart[k + 1] = strandStart[k] + c;
  });
  return { points, strandStart };
}

/** The first coordinates of the kept points, strand by strand. */
function kept(s: { points: Float32Array; strandStart: Uint32Array }): number[][] {
  const out: number[][] = [];
  for (let k = 0; k + 1 < s.strandStart.length; k++) {
    const row: number[] = [];
    for (let i = s.strandStart[k]; i < s.strandStart[k + 1]; i++) {
      expect([s.points[3 * i + 1], s.points[3 * i + 2]]).toEqual([
        10 * s.points[3 * i],
        -s.points[3 * i],
      ]);
      row.push(s.points[3 * i]);
    }
    out.push(row);
  }
  return out;
}

describe('everyOtherPoint', () => {
  it('keeps the even points and the tip of every strand', () => {
    // strands: 5 points (0-4), 6 points (5-10), 2 points (11-12), 1 point (13), 0 points, 3 (14-16)
    const r = everyOtherPoint(strands([5, 6, 2, 1, 0, 3]));
    expect(kept(r)).toEqual([[0, 2, 4], [5, 7, 9, 10], [11, 12], [13], [], [14, 16]]);
    expect(Array.from(r.strandStart)).toEqual([0, 3, 7, 9, 10, 10, 12]);
    expect(r.points.length).toBe(3 * 12);
  });

  it('leaves no hair as no hair', () => {
    const r = everyOtherPoint({ points: new Float32Array(0), strandStart: new Uint32Array([0]) });
    expect(r.points.length).toBe(0);
    expect(Array.from(r.strandStart)).toEqual([0]);
  });
});
