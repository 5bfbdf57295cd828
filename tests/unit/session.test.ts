// The session model with every curve kind, packed into protocol.ts's CurveSet layout.
import { describe, expect, it } from 'vitest';
import { packCurves } from '../../web/model/curveSet';
import { History } from '../../web/model/history';
import {
  addCurve,
  type DividingCurve,
  deleteCurve,
  emptySession,
  nextCurveId,
  type PonytailCurve,
  type StreamCurve,
  setAvoid,
  updateCurve,
} from '../../web/model/session';
import type { Vec3 } from '../../web/model/vec3';
import { CurveKind } from '../../web/solver/protocol';

const vp = { position: [0, 0, 5] as Vec3, target: [0, 0, 0] as Vec3 };
const stream: StreamCurve = {
  id: 'c1',
  type: 'stream',
  points: [
    [0, 1, 0],
    [0, 0.9, 0.1],
  ],
  extend: true,
  viewpoint: vp,
  surfaceMode: 'strip',
};
const dividing: DividingCurve = {
  id: 'c2',
  type: 'dividing',
  points: [
    [0, 1, 0.2],
    [0, 1, 0.1],
    [0, 1, 0],
  ],
  normals: [
    [0, 1, 0],
    [0, 1, 0],
    [0, 0.6, 0.8],
  ],
  sigma: 1,
  h: 0.5,
  alpha0: 0.1,
  alpha1: -0.2,
  viewpoint: vp,
};
const ponytail: PonytailCurve = {
  id: 'c3',
  type: 'ponytail',
  points: [
    [0, 0.5, -1],
    [0, 0.4, -1.1],
  ],
  extend: false,
  viewpoint: vp,
  crossSection: [],
  profiles: [[], []],
  circles: [
    { centre: [0, 0.5, -1], axis: [0, -1, 0], radius: 0.2, spineIndex: 0 },
    { centre: [0, 0.4, -1.1], axis: [0, -1, 0], radius: 0.1, spineIndex: 1 },
  ],
  tightness: 0.6,
};

describe('session with every curve kind', () => {
  it('packs stream, dividing and ponytail curves and the extra constraints', () => {
    const set = packCurves([stream, dividing, ponytail], {
      index: [5, 9],
      target: [1, 2, 3, 4, 5, 6],
    });
    expect(Array.from(set.kinds)).toEqual([
      CurveKind.stream,
      CurveKind.dividing,
      CurveKind.ponytail,
    ]);
    expect(Array.from(set.curveStart)).toEqual([0, 2, 5, 7]);
    expect(Array.from(set.extend)).toEqual([1, 0, 0]);
    // stream: no params; dividing: 4 + 3 per point; ponytail: 2 + 7 per circle
    expect(Array.from(set.paramStart)).toEqual([0, 0, 13, 13 + 16]);
    expect(Array.from(set.params.slice(0, 13))).toEqual([
      1, 0.5, 0.1, -0.2, 0, 1, 0, 0, 1, 0, 0, 0.6, 0.8,
    ]);
    expect(Array.from(set.params.slice(13))).toEqual([
      0.6, 2, 0, 0.5, -1, 0, -1, 0, 0.2, 0, 0.4, -1.1, 0, -1, 0, 0.1,
    ]);
    expect(Array.from(set.extraIndex)).toEqual([5, 9]);
    expect(Array.from(set.extraTarget)).toEqual([1, 2, 3, 4, 5, 6]);
    const none = packCurves([stream]);
    expect(none.extraIndex.length).toBe(0);
    expect(Array.from(none.paramStart)).toEqual([0, 0]);
  });

  it('edits curves immutably and undoes every edit', () => {
    let s = emptySession('25k');
    const h = new History(s);
    s = addCurve(s, stream);
    h.push(s);
    s = addCurve(s, { ...dividing, id: nextCurveId(s) });
    h.push(s);
    expect(s.curves.map((c) => c.id)).toEqual(['c1', 'c2']);
    const same = updateCurve(s, 'nope', (c) => ({ ...c }));
    expect(same).toBe(s);
    s = updateCurve(s, 'c2', (c) => (c.type === 'dividing' ? { ...c, sigma: 2 } : c));
    h.push(s);
    s = setAvoid(s, { index: [1], target: [0, 0.3, 0] });
    h.push(s);
    s = deleteCurve(s, 'c1');
    h.push(s);
    expect(JSON.parse(JSON.stringify(s))).toEqual(s); // plain JSON
    h.undo();
    h.undo();
    expect(h.current.avoid ?? null).toBeNull();
    expect((h.current.curves[1] as DividingCurve).sigma).toBe(2);
    h.undo();
    expect((h.current.curves[1] as DividingCurve).sigma).toBe(1);
  });
});
