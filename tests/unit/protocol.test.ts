// The protocol's array layouts, checked element by element against hand-built expectations.
import { describe, expect, it } from 'vitest';
import { CurveKind } from '../../web/model/curveParams';
import { packCurves } from '../../web/model/curveSet';
import { gridForPreset, gridPointCount } from '../../web/model/grid';
import { strandCount } from '../../web/model/hairArrays';
import type { StyleCurve } from '../../web/model/session';
import { resultTransferables } from '../../web/solver/protocol';

const vp = {
  position: [0, 0, 5] as [number, number, number],
  target: [0, 0, 0] as [number, number, number],
};

describe('protocol layouts', () => {
  it('packs curves as points[3 * point + axis] with curveStart offsets', () => {
    const curves: StyleCurve[] = [
      {
        id: 'a',
        type: 'stream',
        points: [
          [1, 2, 3],
          [4, 5, 6],
        ],
        extend: true,
        viewpoint: vp,
      },
      {
        id: 'b',
        type: 'stream',
        points: [
          [7, 8, 9],
          [10, 11, 12],
          [13, 14, 15],
        ],
        extend: false,
        viewpoint: vp,
      },
    ];
    const set = packCurves(curves);
    expect(Array.from(set.curveStart)).toEqual([0, 2, 5]);
    expect(Array.from(set.points)).toEqual([1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15]);
    expect(Array.from(set.kinds)).toEqual([CurveKind.stream, CurveKind.stream]);
    expect(Array.from(set.extend)).toEqual([1, 0]);
    // Point 3 of the set = curve b's second point.
    const p = 3;
    expect([set.points[3 * p], set.points[3 * p + 1], set.points[3 * p + 2]]).toEqual([10, 11, 12]);
    const empty = packCurves([]);
    expect(Array.from(empty.curveStart)).toEqual([0]);
    expect(empty.points.length).toBe(0);
  });

  it('lists every buffer of a result for transfer, and counts strands', () => {
    const msg = {
      type: 'result' as const,
      id: 1,
      strands: { points: new Float32Array(6), strandStart: new Uint32Array([0, 2]) },
      constraints: {
        index: new Int32Array(1),
        target: new Float32Array(3),
        colour: new Uint8Array(1),
      },
      field: { vectors: new Float32Array(3) },
      final: true,
      stats: {
        method: 'cg',
        iterations: 1,
        errorEstimate: 0,
        constraints: 1,
        added: 1,
        removed: 0,
        changed: 0,
        setupMs: 0,
        solveMs: 0,
        growMs: 0,
        heapBytes: 0,
      },
    };
    const t = resultTransferables(msg);
    expect(t).toHaveLength(6);
    expect(new Set(t).size).toBe(6);
    expect(t).toContain(msg.constraints.colour.buffer);
    expect(strandCount(msg.strands)).toBe(1);
  });

  it('grid presets hold about 25K and 50K points inside the bounding volume', () => {
    for (const [preset, target] of [
      ['25k', 25_000],
      ['50k', 50_000],
    ] as const) {
      const g = gridForPreset(preset);
      const n = gridPointCount(g);
      expect(Math.abs(n - target) / target).toBeLessThan(0.12);
      for (let a = 0; a < 3; a++) {
        const lo = g.origin[a];
        const hi = g.origin[a] + (g.dims[a] - 1) * g.step;
        expect(lo).toBeGreaterThanOrEqual(-2.9 - 1e-9);
        expect(hi).toBeLessThanOrEqual(1.7 + 1e-9);
      }
    }
  });
});
