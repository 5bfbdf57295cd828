// Braid and bun curves in the session model: the strict reader's limits (those of
// solver-cpp/src/braid_bun.hpp), the CurveSet block (exactly the scalars), share links (version 3
// round trip; a link without them is what the build before them wrote), mirror, and "Braid the
// tail".
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { applyCommand, braidOfPonytail } from '../../web/editor/commands';
import { Head } from '../../web/head/head';
import { CurveKind, defaultParams } from '../../web/model/curveParams';
import { packCurves } from '../../web/model/curveSet';
import { packSession } from '../../web/model/linkPack';
import { unpackSession } from '../../web/model/linkUnpack';
import { mirrorCurve } from '../../web/model/mirror';
import { quantizeSession } from '../../web/model/quantize';
import {
  type BraidCurve,
  type BunCurve,
  emptySession,
  type SessionState,
} from '../../web/model/session';
import { decodeSessionLink, encodeSessionLink } from '../../web/model/sessionLink';
import { parseSession } from '../../web/model/sessionRead';
import type { Vec3 } from '../../web/model/vec3';

const vp = { position: [0, 0, 6] as Vec3, target: [0, 0, 0] as Vec3 };
const line = (n: number, x = 0.3): Vec3[] =>
  Array.from({ length: n }, (_, i): Vec3 => [x, 0.9 - 0.1 * i, -0.8]);
const loop = (n: number): Vec3[] =>
  Array.from({ length: n }, (_, i): Vec3 => {
    const a = (2 * Math.PI * i) / n;
    return [0.2 * Math.cos(a), 1.05, -0.3 + 0.2 * Math.sin(a)];
  });

const braid = (p: Partial<BraidCurve> = {}): BraidCurve => ({
  id: 'c1',
  type: 'braid',
  points: line(12),
  extend: false,
  viewpoint: vp,
  ...defaultParams('braid'),
  ...p,
});
const bun = (p: Partial<BunCurve> = {}): BunCurve => ({
  id: 'c2',
  type: 'bun',
  points: loop(16),
  extend: false,
  viewpoint: vp,
  ...defaultParams('bun'),
  ...p,
});
const session = (...curves: SessionState['curves']): SessionState =>
  quantizeSession({ ...emptySession('25k'), curves });

const errorOf = (curve: unknown) => {
  const r = parseSession(JSON.parse(JSON.stringify({ ...session(), curves: [curve] })));
  return r.ok ? null : r.error;
};

describe('braid and bun curves', () => {
  it('have the C++ defaults', () => {
    expect(defaultParams('braid')).toEqual({
      width: 0.5,
      crossings: 6,
      tightness: 0.5,
      tailLength: 0.4,
      section: 1,
    });
    expect(defaultParams('bun')).toEqual({ radius: 0, height: 0.35, turns: 2.5, section: 1 });
  });

  it('the reader accepts them within the limits and refuses them outside', () => {
    expect(errorOf(braid())).toBeNull();
    expect(errorOf(bun())).toBeNull();
    expect(errorOf(braid({ width: 3, crossings: 40, tightness: 1, tailLength: 20 }))).toBeNull();
    expect(errorOf(bun({ radius: 2, height: 2, turns: 10 }))).toBeNull();
    expect(errorOf(braid({ tightness: 0, tailLength: 0 }))).toBeNull();
    expect(errorOf(bun({ radius: 0 }))).toBeNull();
    const bad: [unknown, RegExp][] = [
      [braid({ width: 0 }), /curves\[0\]\.width: must be between/],
      [braid({ width: 3.01 }), /curves\[0\]\.width: must be between/],
      [braid({ crossings: 0 }), /curves\[0\]\.crossings: must be between/],
      [braid({ crossings: 41 }), /curves\[0\]\.crossings/],
      [braid({ tightness: -0.1 }), /curves\[0\]\.tightness/],
      [braid({ tightness: 1.1 }), /curves\[0\]\.tightness/],
      [braid({ tailLength: 20.5 }), /curves\[0\]\.tailLength/],
      [braid({ tailLength: -1 }), /curves\[0\]\.tailLength/],
      [bun({ radius: -0.1 }), /curves\[0\]\.radius/],
      [bun({ radius: 2.1 }), /curves\[0\]\.radius/],
      [bun({ height: 0 }), /curves\[0\]\.height/],
      [bun({ height: 2.5 }), /curves\[0\]\.height/],
      [bun({ turns: 0 }), /curves\[0\]\.turns/],
      [bun({ turns: 11 }), /curves\[0\]\.turns/],
      [{ ...braid(), circles: [] }, /curves\[0\]/],
      [{ ...bun(), normals: [] }, /curves\[0\]/],
    ];
    for (const [c, re] of bad) expect(errorOf(c)).toMatch(re);
    // a braid saved without a parameter gets its default
    const { tailLength: _, ...short } = braid();
    const r = parseSession(JSON.parse(JSON.stringify({ ...session(), curves: [short] })));
    expect(r.ok && (r.value.curves[0] as BraidCurve).tailLength).toBe(0.4);
  });

  it('pack into the CurveSet as kinds 3 and 4 with exactly their scalars', () => {
    const set = packCurves([braid({ width: 0.7 }), bun({ turns: 3 })], null, true);
    expect(Array.from(set.kinds)).toEqual([CurveKind.braid, CurveKind.bun]);
    expect([CurveKind.braid, CurveKind.bun]).toEqual([3, 4]);
    expect(Array.from(set.paramStart)).toEqual([0, 5, 9]);
    expect(Array.from(set.params)).toEqual([0.7, 6, 0.5, 0.4, 1, 0, 0.35, 3, 1]);
  });

  it('travel in version 3 links and come back equal', async () => {
    const s = session(
      braid({ width: 0.62, crossings: 7.5, tightness: 0.25, tailLength: 1.2, extend: true }),
      bun({ radius: 0.3, height: 0.5, turns: 4 }),
      { ...braid({ id: 'c3', points: line(8, -0.3) }), detail: { lengthJitter: 0.1 } },
    );
    const link = await encodeSessionLink(s);
    const back = await decodeSessionLink(link);
    expect(back.ok && back.value).toEqual(s);
  });

  it('a link without braids or buns states three kinds, as the build before them wrote', () => {
    const fig1 = presetSession('fig1', Head.builtin());
    expect(packSession(fig1)[0]).toBe(3);
    expect(packSession(session(braid()))[0]).toBe(4);
    expect(packSession(session(bun()))[0]).toBe(5);
    // a body that states three kinds but holds a braid is refused
    const body = packSession(session(braid()));
    expect(() =>
      unpackSession(Uint8Array.from([3, ...body.subarray(1, 4), ...body.subarray(5)])),
    ).toThrow();
  });

  it('Mirror doubles a braid and a bun (the twin reflected across x = 0)', () => {
    const b = braid();
    const twin = mirrorCurve(b, 'c9', 'c1') as BraidCurve;
    expect(twin.type).toBe('braid');
    expect(twin.mirror).toBe('c1');
    expect(twin.points[3]).toEqual([-b.points[3][0], b.points[3][1], b.points[3][2]]);
    expect(twin.width).toBe(b.width);
    const s = session();
    const r = applyCommand(s, {
      kind: 'addCurve',
      curve: {
        ...bun({ points: loop(16).map((p): Vec3 => [p[0] + 0.5, p[1], p[2]]) }),
        id: undefined,
      } as never,
      what: 'bun {id}',
      mirror: true,
    });
    expect(r.session.curves.map((c) => c.type)).toEqual(['bun', 'bun']);
    expect(r.session.curves[0].mirror).toBe(r.session.curves[1].id);
    expect(parseSession(JSON.parse(JSON.stringify(r.session))).ok).toBe(true);
  });

  it('"Braid the tail" turns a ponytail into a braid on its spine, one undoable edit', () => {
    const s = presetSession('fig1', Head.builtin());
    const tail = s.curves.find((c) => c.type === 'ponytail');
    if (tail?.type !== 'ponytail') throw new Error('fig1 has a ponytail');
    const mean = tail.circles.reduce((a, q) => a + q.radius, 0) / tail.circles.length;
    const r = applyCommand(s, { kind: 'braidTail', id: tail.id });
    const b = r.session.curves.find((c) => c.id === tail.id);
    expect(b?.type).toBe('braid');
    if (b?.type !== 'braid') return;
    expect(b.points).toEqual(tail.points);
    expect(b.width).toBeCloseTo(2 * mean, 4);
    expect(b.width).toBeCloseTo(braidOfPonytail(tail).width, 4);
    expect(r.session.curves.length).toBe(s.curves.length);
    expect(parseSession(JSON.parse(JSON.stringify(r.session))).ok).toBe(true);
    // a curve that is not a ponytail changes nothing
    const none = applyCommand(r.session, { kind: 'braidTail', id: tail.id });
    expect(none.session).toBe(r.session);
  });

  it('the presets hold them: braid, bun, pigtail-braids (two twin braids)', () => {
    const head = Head.builtin();
    const kinds = (n: 'braid' | 'bun' | 'pigtail-braids') =>
      presetSession(n, head).curves.map((c) => c.type);
    expect(kinds('braid').filter((k) => k === 'braid')).toHaveLength(1);
    expect(kinds('bun').filter((k) => k === 'bun')).toHaveLength(1);
    const pig = presetSession('pigtail-braids', head);
    const braids = pig.curves.filter((c) => c.type === 'braid');
    expect(braids).toHaveLength(2);
    expect(braids[0].mirror).toBe(braids[1].id);
    expect(braids[1].mirror).toBe(braids[0].id);
    for (const n of ['braid', 'bun', 'pigtail-braids'] as const) {
      const s = presetSession(n, head);
      expect(s.fall).toBe(true);
      expect(parseSession(JSON.parse(JSON.stringify(s))).ok).toBe(true);
    }
  });
});
