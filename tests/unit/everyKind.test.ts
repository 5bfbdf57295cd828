// Every curve kind of the kind table through the paths each kind must take (issue 52): a session
// file read back, a share link's round trip, quantising twice and Mirror twice. The kinds come
// from the table (curveParams.ts CURVE_PARAMS), so a new kind is covered without a line here: a
// stroke kind is made by its own fromStroke, any other must have a maker below (the test says so).
import { describe, expect, it } from 'vitest';
import { Editor } from '../../web/editor/editor';
import { groomLayout } from '../../web/export/groomLayout';
import { strandsForExport } from '../../web/export/strandsForExport';
import { CURVE_PARAMS, type CurveKindName, defaultParams } from '../../web/model/curveParams';
import { DEFAULT_GROWTH } from '../../web/model/growthParams';
import { defOf, STROKE_KINDS } from '../../web/model/kinds';
import { mirrorCurve } from '../../web/model/mirror';
import { quantizeSession } from '../../web/model/quantize';
import { emptySession, type StyleCurve, type Viewpoint } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';
import { decodeSessionLink, encodeSessionLink } from '../../web/model/sessionLink';
import type { Vec3 } from '../../web/model/vec3';

const vp: Viewpoint = { position: [-7.4, 0.2, -0.1], target: [0, 0, 0] };
// a stroke from the back of the crown, up, over and down the back, drifting aside (off the head's
// middle, and no direction along it without a part across the mirror plane)
const stroke: Vec3[] = Array.from({ length: 24 }, (_, i) => {
  const a = Math.min(i, 6) / 6;
  return [
    0.13 + 0.01 * i,
    0.64 + 0.2 * Math.sin(a * Math.PI * 0.5) - 0.08 * Math.max(0, i - 6),
    -0.64 - 0.04 * i,
  ];
});

const KIND_NAMES = Object.keys(CURVE_PARAMS) as CurveKindName[];

/** A curve of kind `k`, as the app makes one; null for a kind nobody taught this test. */
function make(k: CurveKindName): Omit<StyleCurve, 'id'> | null {
  if (Object.hasOwn(STROKE_KINDS, k))
    return STROKE_KINDS[k as keyof typeof STROKE_KINDS].fromStroke(stroke, vp, false);
  if (k === 'dividing')
    return {
      type: 'dividing',
      points: stroke.slice(0, 8),
      normals: stroke.slice(0, 8).map(() => [0.6, 0.8, 0] as Vec3),
      viewpoint: vp,
      ...defaultParams('dividing'),
      alpha0: 0.2,
      alpha1: -0.1,
    } as Omit<StyleCurve, 'id'>;
  return null;
}

/** The session with one curve of kind `k` and its Mirror twin, as the editor adds them. */
function sessionWith(k: CurveKindName) {
  const curve = make(k);
  expect(curve, `a maker for kind ${k} (tests/unit/everyKind.test.ts)`).not.toBeNull();
  const e = new Editor(emptySession('25k'), 'stream');
  expect(
    e.run({ kind: 'addCurve', curve: curve as StyleCurve, what: `${k} {id}`, mirror: true }),
  ).toBe(true);
  return e.session;
}

/** Numbers rounded to 1e-9 (and -0 to 0): equal up to float noise. */
const round = (v: unknown): unknown =>
  JSON.parse(
    JSON.stringify(v, (_, x) => (typeof x === 'number' ? Math.round(x * 1e9) / 1e9 + 0 : x)),
  );

describe.each(KIND_NAMES)('every curve kind: %s', (k) => {
  it('makes a curve and its Mirror twin', () => {
    const s = sessionWith(k);
    expect(s.curves.map((c) => c.type)).toEqual([k, k]);
    expect(s.curves[0].mirror).toBe(s.curves[1].id);
  });

  it('reads back from a session file as it was', () => {
    const s = sessionWith(k);
    const r = parseSession(JSON.parse(JSON.stringify(s)));
    if (!r.ok) throw new Error(r.error);
    expect(round(r.value.curves)).toEqual(round(s.curves));
  });

  it('quantises once for all: quantising again changes nothing', () => {
    const q = quantizeSession(sessionWith(k));
    expect(quantizeSession(q)).toEqual(q);
  });

  it('travels in a share link: the link opens to the quantised session', async () => {
    const s = sessionWith(k);
    const r = await decodeSessionLink(await encodeSessionLink(s));
    if (!r.ok) throw new Error(r.error);
    expect(r.value.curves).toEqual(quantizeSession(s).curves);
  });

  it('Mirror reflects every point and direction the curve holds, across x = 0', () => {
    const [c, twin] = sessionWith(k).curves;
    // every triple of numbers in the curve (points, circles' centres and axes, normals, the
    // viewpoint) reflected: a field a kind forgot to mirror stays unreflected in the twin
    const reflect = (v: unknown): unknown => {
      if (Array.isArray(v) && v.length === 3 && v.every((n) => typeof n === 'number'))
        return [-v[0], v[1], v[2]];
      if (Array.isArray(v)) return v.map(reflect);
      if (v && typeof v === 'object')
        return Object.fromEntries(Object.entries(v).map(([key, x]) => [key, reflect(x)]));
      return v;
    };
    const { id: _i, mirror: _m, ...own } = c as StyleCurve & Record<string, unknown>;
    const { id: _ti, mirror: _tm, ...twinOwn } = twin as StyleCurve & Record<string, unknown>;
    const expected = reflect(own) as Record<string, unknown>;
    // a parting's tilts change sign: the reflection turns its handedness
    for (const tilt of ['alpha0', 'alpha1'])
      if (typeof expected[tilt] === 'number') expected[tilt] = -(expected[tilt] as number);
    expect(round(twinOwn)).toEqual(round(expected));
  });

  it('Mirror twice gives the curve back', () => {
    const [c, twin] = sessionWith(k).curves;
    const back = mirrorCurve(twin, c.id, twin.id);
    expect(round(back)).toEqual(round(c));
  });

  it('the export names its groups by kind: a tie and its twin are <kind>1 and <kind>2, a parting splits in two', () => {
    const curves = sessionWith(k).curves;
    // 40 two-point strands, the first 10 laid by the first curve, the next 10 by its twin
    const n = 40;
    const points = new Float32Array(6 * n);
    const strandStart = Uint32Array.from({ length: n + 1 }, (_, s) => 2 * s);
    for (let s = 0; s < n; s++) {
      const a = (2 * Math.PI * s) / n;
      points.set(
        [Math.sin(a), 0.5, Math.cos(a), 1.1 * Math.sin(a), 0.55, 1.1 * Math.cos(a)],
        6 * s,
      );
    }
    const tailCurves = Int32Array.from({ length: n }, (_, s) => (s < 10 ? 0 : s < 20 ? 1 : -1));
    const ex = strandsForExport(
      { points, strandStart },
      { hairColor: '#5a3825', growth: DEFAULT_GROWTH },
    );
    const g = groomLayout(ex, { tailCurves }, { curves, growth: DEFAULT_GROWTH });
    const role = defOf(curves[0]).role;
    for (const name of g.groupNames) expect(name).toMatch(/^[a-z]+[0-9]*(_[a-z]+)?$/);
    if (role === 'tie') {
      expect(g.groupNames).toEqual(expect.arrayContaining([`${k}1`, `${k}2`]));
      for (let s = 0; s < 20; s++) expect(g.groupNames[g.groupOf[s]]).toBe(`${k}${s < 10 ? 1 : 2}`);
    } else if (k === 'dividing') {
      expect(g.groupNames.filter((x) => x.startsWith('parting1_'))).toHaveLength(2);
      expect(g.groupNames.filter((x) => x.startsWith('parting2_'))).toHaveLength(2);
    }
  });
});
