import { describe, expect, it } from 'vitest';
import { polylineLength, resamplePolyline } from '../../web/model/resample';
import { distance, type Vec3 } from '../../web/model/vec3';

describe('resamplePolyline', () => {
  it('gives consecutive points exactly one step apart on a bent polyline', () => {
    const pts: Vec3[] = [];
    for (let i = 0; i <= 200; i++) {
      const t = i / 200;
      pts.push([Math.cos(3 * t), Math.sin(3 * t), 0.5 * t]); // helix arc, many tiny events
    }
    const out = resamplePolyline(pts, 0.1);
    expect(out[0]).toEqual(pts[0]);
    for (let i = 1; i < out.length; i++) expect(distance(out[i - 1], out[i])).toBeCloseTo(0.1, 10);
    // Chords of a smooth curve: count ≈ arc length / step (within one).
    expect(Math.abs(out.length - 1 - polylineLength(pts) / 0.1)).toBeLessThan(1.5);
  });

  it('places points on a straight line at hand-computed positions', () => {
    const out = resamplePolyline(
      [
        [0, 0, 0],
        [0.25, 0, 0],
        [1, 0, 0],
      ],
      0.3,
    );
    expect(out.map((p) => p[0])).toEqual(
      [0, 0.3, 0.6, 0.8999999999999999].map((x) => expect.closeTo(x, 12)),
    );
    expect(out).toHaveLength(4); // 1.0 - 0.9 < 0.3: the tail is dropped
  });

  it('handles a long segment holding several steps and a sharp corner', () => {
    const out = resamplePolyline(
      [
        [0, 0, 0],
        [1, 0, 0],
        [1, 1, 0],
      ],
      0.4,
    );
    for (let i = 1; i < out.length; i++) expect(distance(out[i - 1], out[i])).toBeCloseTo(0.4, 10);
    expect(out[2]).toEqual([expect.closeTo(0.8, 12), 0, 0]);
    // The next point straddles the corner: (1, y) with |(1, y) - (0.8, 0)| = 0.4.
    expect(out[3][1]).toBeCloseTo(Math.sqrt(0.4 ** 2 - 0.2 ** 2), 12);
  });

  it('ignores degenerate input without throwing', () => {
    expect(resamplePolyline([], 0.1)).toEqual([]);
    expect(resamplePolyline([[1, 2, 3]], 0.1)).toEqual([[1, 2, 3]]);
    expect(
      resamplePolyline(
        [
          [0, 0, 0],
          [0, 0, 0],
          [0, 0, 0],
        ],
        0.1,
      ),
    ).toHaveLength(1);
    expect(
      resamplePolyline(
        [
          [0, 0, 0],
          [Number.NaN, 0, 0],
          [0.25, 0, 0],
        ],
        0.1,
      ),
    ).toHaveLength(3);
    expect(() => resamplePolyline([[0, 0, 0]], 0)).toThrow(RangeError);
  });
});
