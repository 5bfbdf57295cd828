// The bar that marks where a stroke's hair ends (viewer.ts endBar): across the stroke's last
// point, square to its last segment and to the view, 3 cm long.
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../web/model/vec3';
import { endBar } from '../../web/viewer/viewer';

const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

describe('endBar', () => {
  it('crosses the last point, square to the last segment and the view', () => {
    const pts: Vec3[] = [
      [0, 1, 0],
      [0.1, 0.5, 0.2],
      [0.15, 0.2, 0.3],
    ];
    const forward: Vec3 = [0, 0, -1];
    const bar = endBar(pts, forward);
    if (!bar) throw new Error('expected a bar');
    const [a, b] = bar;
    const mid: Vec3 = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2];
    for (let i = 0; i < 3; i++) expect(mid[i]).toBeCloseTo(pts[2][i], 12);
    const across = sub(b, a);
    expect(Math.hypot(...across)).toBeCloseTo(0.3, 12);
    expect(dot(across, sub(pts[2], pts[1]))).toBeCloseTo(0, 12);
    expect(dot(across, forward)).toBeCloseTo(0, 12);
  });

  it('is absent when the last segment runs along the view', () => {
    expect(
      endBar(
        [
          [0, 0, 1],
          [0, 0, 0],
        ],
        [0, 0, -1],
      ),
    ).toBeNull();
  });
});
