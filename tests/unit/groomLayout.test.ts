// The groom layout of the USD export (web/export/groomLayout.ts, scalpUv.ts) against brute force
// and hand-computed values: the guides are a Poisson-disc set (no two closer than the spacing,
// every strand within it of a guide of its group), the closest guides are the three nearest by
// brute force, the groups follow tails and parting sides, ids follow the roots.
import { describe, expect, it } from 'vitest';
import { GUIDE_SPACING, groomLayout } from '../../web/export/groomLayout';
import { scalpUvAt, scalpUvs } from '../../web/export/scalpUv';
import { strandsForExport } from '../../web/export/strandsForExport';
import type { GroomSummary } from '../../web/export/usdWriter';
import { writeExport } from '../../web/export/writeExport';
import { DEFAULT_GROWTH } from '../../web/model/growthParams';
import {
  type DividingCurve,
  emptySession,
  type SessionState,
  type StyleCurve,
} from '../../web/model/session';

/** Strands of two points rooted at `roots` on a unit sphere, growing outwards. */
function strandsAt(roots: number[][]) {
  const points = new Float32Array(6 * roots.length);
  const strandStart = new Uint32Array(roots.length + 1);
  roots.forEach((r, s) => {
    points.set(r, 6 * s);
    points.set(
      r.map((v) => 1.1 * v),
      6 * s + 3,
    );
    strandStart[s + 1] = 2 * (s + 1);
  });
  return { points, strandStart };
}

/** `n` roots spread over the upper half of the unit sphere (a seeded spiral). */
function scalpRoots(n: number): number[][] {
  const out: number[][] = [];
  for (let k = 0; k < n; k++) {
    const y = 1 - (k + 0.5) / n; // upper hemisphere, even in area
    const r = Math.sqrt(1 - y * y);
    const a = k * 2.399963229728653;
    out.push([r * Math.sin(a), y, r * Math.cos(a)]);
  }
  return out;
}

const session = (curves: StyleCurve[] = []): Pick<SessionState, 'curves' | 'growth'> => ({
  curves,
  growth: DEFAULT_GROWTH,
});

describe('scalp UV layout', () => {
  it('maps the crown to the centre and the equator to a circle of radius 0.5·√½', () => {
    const uv = new Float32Array(2);
    const at = (x: number, y: number, z: number) => {
      scalpUvAt(x, y, z, [0, 0, 0], uv, 0);
      return [uv[0], uv[1]];
    };
    const c = 0.5 + 0.5 * Math.SQRT1_2;
    expect(at(0, 2, 0)).toEqual([0.5, 0.5]);
    expect(at(3, 0, 0)[0]).toBeCloseTo(c, 6); // the head's left: u up
    expect(at(3, 0, 0)[1]).toBeCloseTo(0.5, 6);
    expect(at(0, 0, 1)[1]).toBeCloseTo(c, 6); // the face: v up
    expect(at(0, 0, -1)[1]).toBeCloseTo(1 - c, 6);
    // equal area: the cap above theta covers 2π(1 − cos θ) of the sphere's 4π and a disc of
    // radius 0.5·sin(θ/2) of the square's 1, so the ratio of the two is the same for every θ
    for (const th of [0.3, 1, 2]) {
      const [u] = at(Math.sin(th), Math.cos(th), 0);
      const disc = Math.PI * (u - 0.5) ** 2;
      expect(disc / (2 * Math.PI * (1 - Math.cos(th)))).toBeCloseTo(1 / 16, 6);
    }
  });
});

describe('groom layout', () => {
  const roots = scalpRoots(3000);
  const src = strandsAt(roots);
  const ex = strandsForExport(src, { hairColor: '#5a3825', growth: DEFAULT_GROWTH });

  it('picks guides a Poisson disc apart and gives each strand its three nearest by brute force', () => {
    const g = groomLayout(ex, { rootIds: Uint32Array.from(roots.keys(), (k) => 7 * k) }, session());
    expect(g.groupNames).toEqual(['hair']);
    expect([...g.ids.slice(0, 3)]).toEqual([0, 7, 14]);
    const guides = [...g.guides];
    expect(guides.length).toBeGreaterThan(50);
    expect(guides.length).toBeLessThan(roots.length / 4);
    const dist = (a: number, b: number) => Math.hypot(...roots[a].map((v, c) => v - roots[b][c]));
    // plain loops, one expect per property (hundreds of thousands of pairs)
    let closePairs = 0;
    for (let i = 0; i < guides.length; i++)
      for (let j = i + 1; j < guides.length; j++)
        if (dist(guides[i], guides[j]) < GUIDE_SPACING * (1 - 1e-6)) closePairs++;
    expect(closePairs).toBe(0);
    const isGuide = new Set(guides);
    const wrong: string[] = [];
    for (let s = 0; s < roots.length; s++) {
      const byDist = guides.map((q) => ({ q, d: dist(s, q) })).sort((x, y) => x.d - y.d);
      // maximal: every strand is within the spacing of a guide
      if (!(byDist[0].d < GUIDE_SPACING)) wrong.push(`${s}: no guide within the spacing`);
      const ids = [...g.closestGuides.slice(3 * s, 3 * s + 3)];
      const w = [...g.guideWeights.slice(3 * s, 3 * s + 3)];
      const want = isGuide.has(s)
        ? { ids: [g.ids[s], g.ids[s], g.ids[s]], w: [1, 0, 0] }
        : (() => {
            const inv = byDist.slice(0, 3).map((x) => 1 / x.d);
            const sum = inv[0] + inv[1] + inv[2];
            return { ids: byDist.slice(0, 3).map((x) => g.ids[x.q]), w: inv.map((v) => v / sum) };
          })();
      if (ids.join() !== want.ids.join()) wrong.push(`${s}: guides ${ids} not ${want.ids}`);
      if (w.some((v, k) => Math.abs(v - want.w[k]) > 1e-5))
        wrong.push(`${s}: weights ${w} not ${want.w}`);
    }
    expect(wrong.slice(0, 5)).toEqual([]);
    for (let k = 0; k < g.rootUv.length; k++) {
      expect(g.rootUv[k]).toBeGreaterThanOrEqual(0);
      expect(g.rootUv[k]).toBeLessThanOrEqual(1);
    }
  });

  it('splits the hair at a parting and gives a tail its own group', () => {
    // a centre parting from the forehead over the crown: x < 0 is the head's right
    const parting: DividingCurve = {
      id: 'p',
      type: 'dividing',
      points: [
        [0, 0.5, 0.866],
        [0, 0.866, 0.5],
        [0, 1, 0],
      ],
      normals: [
        [0, 0.5, 0.866],
        [0, 0.866, 0.5],
        [0, 1, 0],
      ],
      viewpoint: { position: [0, 0, 5], target: [0, 0, 0] },
      sigma: 1,
      h: 1,
      alpha0: 0,
      alpha1: 0,
    } as unknown as DividingCurve;
    const bun = { id: 'b', type: 'bun', points: [[0, 1, 0]] } as unknown as StyleCurve;
    // strands 0..9 laid by the bun (curve 1)
    const tailCurves = Int32Array.from(roots.keys(), (k) => (k < 10 ? 1 : -1));
    const g = groomLayout(ex, { tailCurves }, session([parting, bun]));
    expect(g.groupNames).toEqual(['parting1_left', 'parting1_right', 'bun1']);
    for (let s = 0; s < roots.length; s++) {
      const name = g.groupNames[g.groupOf[s]];
      if (s < 10) expect(name).toBe('bun1');
      else if (Math.abs(roots[s][0]) > 1e-3)
        expect(name).toBe(roots[s][0] > 0 ? 'parting1_left' : 'parting1_right');
    }
    // every group has a guide, and each strand's closest guides are in its group
    const groupOfId = new Map<number, number>();
    for (const q of g.guides) groupOfId.set(g.ids[q], g.groupOf[q]);
    expect(new Set(groupOfId.values()).size).toBe(3);
    for (let s = 0; s < roots.length; s++)
      for (let k = 0; k < 3; k++)
        expect(groupOfId.get(g.closestGuides[3 * s + k])).toBe(g.groupOf[s]);
  });

  it("takes a field ponytail's strands by where they cross its first circle's plane", () => {
    const ponytail = {
      id: 't',
      type: 'ponytail',
      points: [[0, 2, 0]],
      circles: [{ centre: [0, 2, 0], axis: [0, 1, 0], radius: 0.1, spineIndex: 0 }],
    } as unknown as StyleCurve;
    // crossing y = 2 upwards at 0.05 and 0.2 from the axis (within 2.5 radii), at 0.3 (not), and
    // one going down through the circle (against the axis: not)
    const line = (x: number, y0: number, y1: number) => [x, y0, 0, x, (y0 + y1) / 2, 0, x, y1, 0];
    const pts = [
      line(0.05, 1.5, 2.5),
      line(0.2, 1.5, 2.5),
      line(0.3, 1.5, 2.5),
      line(0.05, 2.5, 1.5),
    ];
    const src = {
      points: new Float32Array(pts.flat()),
      strandStart: Uint32Array.from([0, 3, 6, 9, 12]),
    };
    const e = strandsForExport(src, { hairColor: '#5a3825', growth: DEFAULT_GROWTH });
    const g = groomLayout(e, {}, session([ponytail]));
    expect([...g.groupOf].map((k) => g.groupNames[k])).toEqual([
      'ponytail1',
      'ponytail1',
      'hair',
      'hair',
    ]);
  });

  it("writes the built-in head's UV layout as its st and says where root UVs come from", () => {
    const head = {
      positions: new Float32Array([0, 1, 0, 1, 0, 0, 0, 0, 1, -1, 0, 0]),
      indices: new Uint32Array([0, 2, 1, 0, 3, 2]),
    };
    const write = (session: SessionState) => {
      let groom: GroomSummary | null = null;
      const parts = [
        ...writeExport('usda', {
          strands: src,
          session,
          head,
          onGroom: (g) => {
            groom = g;
          },
        }),
      ];
      const text = new TextDecoder().decode(Buffer.concat(parts));
      return { text, groom: groom as GroomSummary | null };
    };
    const builtin = write(emptySession('25k'));
    expect(builtin.groom).toMatchObject({ strands: roots.length, rootUv: 'builtin-head' });
    const st = /texCoord2f\[\] primvars:st = \[([^\]]*)\]/.exec(builtin.text);
    expect(st).not.toBeNull();
    const got = (st?.[1].match(/-?[\d.e-]+/g) ?? []).map(Number);
    const want = [...scalpUvs(head.positions, [0, 0, 0])];
    expect(got.length).toBe(want.length);
    for (let k = 0; k < got.length; k++) expect(got[k]).toBeCloseTo(want[k], 5);
    const loaded = write({
      ...emptySession('25k'),
      head: {
        kind: 'mesh',
        name: 'h.obj',
        hash: '0'.repeat(64),
        format: 'obj',
        up: 'y',
        turns: [],
      },
    });
    expect(loaded.groom?.rootUv).toBe('projection');
    expect(loaded.text).not.toMatch(/primvars:st/);
    // the roots' UVs are the layout's either way
    const uv = /float2\[\] primvars:groom_root_uv = \[\(([^,]+), ([^)]+)\)/.exec(loaded.text);
    const first = new Float32Array(2);
    scalpUvAt(roots[0][0], roots[0][1], roots[0][2], [0, 0, 0], first, 0);
    expect(Number(uv?.[1])).toBeCloseTo(first[0], 5);
    expect(Number(uv?.[2])).toBeCloseTo(first[1], 5);
  });
});
