// The session model with every curve kind, packed into protocol.ts's CurveSet layout.
import { describe, expect, it } from 'vitest';
import { CurveKind } from '../../web/model/curveParams';
import { packCurves, packHairOptions } from '../../web/model/curveSet';
import type { HairDetail } from '../../web/model/detail';
import { DETAIL_GROUP_STRIDE } from '../../web/model/detail';
import { History } from '../../web/model/history';
import {
  addCurve,
  type DividingCurve,
  deleteCurve,
  emptySession,
  nextCurveId,
  type PonytailCurve,
  type StreamCurve,
  updateCurve,
} from '../../web/model/session';
import type { Vec3 } from '../../web/model/vec3';

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
  section: 1,
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
    // stream: its Volume (0: none); dividing: 4 + 3 per point; ponytail: 2 + 7 per circle
    expect(Array.from(set.paramStart)).toEqual([0, 1, 14, 14 + 16]);
    expect(Array.from(set.params.slice(0, 14))).toEqual([
      0, 1, 0.5, 0.1, -0.2, 0, 1, 0, 0, 1, 0, 0, 0.6, 0.8,
    ]);
    expect(Array.from(set.params.slice(14))).toEqual([
      0.6, 2, 0, 0.5, -1, 0, -1, 0, 0.2, 0, 0.4, -1.1, 0, -1, 0, 0.1,
    ]);
    expect(Array.from(set.extraIndex)).toEqual([5, 9]);
    expect(Array.from(set.extraTarget)).toEqual([1, 2, 3, 4, 5, 6]);
    const none = packCurves([stream]);
    expect(none.extraIndex.length).toBe(0);
    expect(Array.from(none.paramStart)).toEqual([0, 1]);
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
    s = { ...s, avoidScalp: true };
    h.push(s);
    s = deleteCurve(s, 'c1');
    h.push(s);
    expect(JSON.parse(JSON.stringify(s))).toEqual(s); // plain JSON
    h.undo();
    expect(h.current.avoidScalp).toBe(true);
    expect(h.current.curves.map((c) => c.id)).toEqual(['c1', 'c2']);
    h.undo();
    expect(h.current.avoidScalp).toBeUndefined();
    expect((h.current.curves[1] as DividingCurve).sigma).toBe(2);
    h.undo();
    expect((h.current.curves[1] as DividingCurve).sigma).toBe(1);
  });
});

describe('packHairOptions (solve options: avoid scalp and detail groups)', () => {
  // Group layout (protocol.ts DETAIL_GROUP_STRIDE = 14): curl radius, frequency, start,
  // randomOffset; clump factor, shape, tipSpread, guideDistance; frizz distance, shape; flyaway
  // share, distance, start; lengthJitter (solver-cpp/src/hair_engine.cpp detailFromArray). An
  // absent block is off: its first number is 0.
  const CURL = 0;
  const CLUMP = 4;
  const FRIZZ = 8;
  const FLYAWAY = 10;
  const JITTER = 13;
  const group = (o: { groups: Float64Array }, g: number) =>
    Array.from(o.groups.subarray(DETAIL_GROUP_STRIDE * g, DETAIL_GROUP_STRIDE * (g + 1)));

  it('has 14 numbers per group', () => {
    expect(DETAIL_GROUP_STRIDE).toBe(14);
  });

  it('packs a flyaway block after frizz; absent, its share is 0 (off)', () => {
    const flying: HairDetail = {
      frizz: { distance: 0.006, shape: -0.4 },
      flyaway: { share: 0.05, distance: 0.2, start: 0.6 },
      lengthJitter: 0.1,
    };
    const o = packHairOptions({ detail: flying }, [stream, { ...stream, id: 'c2', detail: {} }]);
    const g0 = group(o.detail, 0);
    expect(g0.slice(FRIZZ, FRIZZ + 2)).toEqual([0.006, -0.4]);
    expect(g0.slice(FLYAWAY, FLYAWAY + 3)).toEqual([0.05, 0.2, 0.6]);
    expect(g0[JITTER]).toBe(0.1);
    expect(group(o.detail, 1)[FLYAWAY]).toBe(0);
    expect(group(o.detail, 1)[JITTER]).toBe(0);
  });

  it('group 0 is the session detail; a curve with its own detail gets its own group', () => {
    const sessionDetail: HairDetail = {
      curl: { radius: 0.05, frequency: 3, start: 0.15, randomOffset: 1 },
      lengthJitter: 0.25,
    };
    const clumped: HairDetail = {
      clump: { factor: 0.5, shape: 0.3, tipSpread: 0.02, guideDistance: 0.12 },
    };
    const frizzy: HairDetail = { frizz: { distance: 0.006, shape: -0.4 } };
    const curves = [
      stream,
      { ...dividing, detail: clumped },
      ponytail,
      { ...stream, id: 'c4', detail: frizzy },
    ];
    const o = packHairOptions({ avoidScalp: true, detail: sessionDetail }, curves);
    expect(o.avoidScalp).toBe(true);
    expect(o.detail.groups.length).toBe(3 * DETAIL_GROUP_STRIDE);
    expect(Array.from(o.detail.curveGroup)).toEqual([0, 1, 0, 2]);

    const g0 = group(o.detail, 0);
    expect(g0.slice(CURL, CURL + 4)).toEqual([0.05, 3, 0.15, 1]);
    expect(g0[CLUMP]).toBe(0); // no clump block: off
    expect(g0[FRIZZ]).toBe(0); // no frizz block: off
    expect(g0[JITTER]).toBe(0.25);

    const g1 = group(o.detail, 1);
    expect(g1[CURL]).toBe(0); // the curve's own detail replaces the session's (no curl)
    expect(g1.slice(CLUMP, CLUMP + 4)).toEqual([0.5, 0.3, 0.02, 0.12]);
    expect(g1[FRIZZ]).toBe(0);
    expect(g1[JITTER]).toBe(0);

    const g2 = group(o.detail, 2);
    expect(g2[CURL]).toBe(0);
    expect(g2[CLUMP]).toBe(0);
    expect(g2.slice(FRIZZ, FRIZZ + 2)).toEqual([0.006, -0.4]);
    expect(g2[JITTER]).toBe(0);
  });

  it('no detail anywhere: one group, every block off; avoid scalp and fall absent are off', () => {
    const o = packHairOptions({}, [stream, dividing]);
    expect(o.avoidScalp).toBe(false);
    expect(o.fall).toBe(false);
    expect(packHairOptions({ fall: false }, []).fall).toBe(false);
    expect(packHairOptions({ fall: true }, []).fall).toBe(true);
    expect(packHairOptions(emptySession('25k'), []).fall).toBe(true); // on in a new session
    expect(o.detail.groups.length).toBe(DETAIL_GROUP_STRIDE);
    expect(Array.from(o.detail.curveGroup)).toEqual([0, 0]);
    const g0 = group(o.detail, 0);
    expect([g0[CURL], g0[CLUMP], g0[FRIZZ], g0[FLYAWAY], g0[JITTER]]).toEqual([0, 0, 0, 0, 0]);
    expect(packHairOptions({ avoidScalp: false }, []).avoidScalp).toBe(false);
    expect(packHairOptions({}, []).detail.curveGroup.length).toBe(0);
  });

  it("an empty detail of a curve is its own group (no detail, not the session's)", () => {
    const o = packHairOptions({ detail: { lengthJitter: 0.5 } }, [{ ...stream, detail: {} }]);
    expect(Array.from(o.detail.curveGroup)).toEqual([1]);
    expect(group(o.detail, 0)[JITTER]).toBe(0.5);
    const g1 = group(o.detail, 1);
    expect([g1[CURL], g1[CLUMP], g1[FRIZZ], g1[JITTER]]).toEqual([0, 0, 0, 0]);
  });
});
