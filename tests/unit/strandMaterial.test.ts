// Strand geometry for LineSegments (tangents, `along`, per-strand variation) and the hair
// material's uniforms (method S6.1). The shader itself compiles only in a browser (checked with a
// headless Chromium render); here the geometry layout is checked against direct computation.
import { describe, expect, it } from 'vitest';
import { DEFAULT_HAIR_LOOK, hexToLinear } from '../../web/model/hairLook';
import { LOCK_CELL, lockNoise } from '../../web/model/lockNoise';
import { colorAbsorption } from '../../web/model/melanin';
import { decodeTipDistance, LOD_GROUPS, MAX_TURN } from '../../web/viewer/strandAttributes';
import { buildStrandGeometry, buildStrandStripGeometry } from '../../web/viewer/strandGeometry';
import {
  createStrandMaterial,
  setHairColor,
  setHairLook,
  setLightDirection,
} from '../../web/viewer/strandMaterial';
import {
  drawnStrands,
  representedWidth,
  strandWidthFactor,
  WIDTH_VARIATION,
} from '../../web/viewer/strandWidth';

describe('buildStrandGeometry', () => {
  // strand 0: 3 points along +x then +y; strand 1: a single point; strand 2: 2 points along −z
  const points = new Float32Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 5, 5, 5, 0, 0, 0, 0, 0, -2]);
  const strandStart = new Uint32Array([0, 3, 4, 6]);
  const g = buildStrandGeometry(points, strandStart, 3);

  it('makes one index pair per segment, none across strands', () => {
    // (strands in level-of-detail order: 0, then 2, then 1, which has no segment)
    expect(Array.from(g.getIndex()?.array ?? [])).toEqual([0, 1, 1, 2, 4, 5]);
    expect(g.getAttribute('position').count).toBe(6);
  });

  it('has tangents along neighbouring points, shortened by the turn there', () => {
    const t = g.getAttribute('tangent');
    const s = Math.SQRT1_2;
    const expected = [
      [1, 0, 0], // one-sided at the root
      [s, s, 0], // central difference
      [0, 1, 0], // one-sided at the tip
      [0, 0, -1], // strand 2
      [0, 0, -1],
    ];
    // lengths: 1 without a turn; ½ where the strand turns MAX_TURN or more (its middle point
    // turns 90 degrees)
    const lengths = [1, 0.5, 1, 1, 1];
    const rows = [0, 1, 2, 4, 5];
    rows.forEach((v, k) => {
      const c = [0, 1, 2].map((a) => t.getComponent(v, a));
      const l = Math.hypot(...c);
      expect(l).toBeCloseTo(lengths[k], 2);
      for (let a = 0; a < 3; a++) expect(c[a] / l).toBeCloseTo(expected[k][a], 2);
    });
    // a lone point still gets a finite unit tangent
    const lone = [0, 1, 2].map((a) => t.getComponent(3, a));
    expect(Math.hypot(...lone)).toBeCloseTo(1, 2);
  });

  it('runs `along` from 0 at the root to 1 at the tip; one random value per strand', () => {
    const along = g.getAttribute('along');
    const expected = [0, 0.5, 1, 0, 1];
    [0, 1, 2, 4, 5].forEach((v, k) => {
      expect(along.getX(v)).toBeCloseTo(expected[k], 2);
    });
    const r = g.getAttribute('strandRandom');
    expect(r.getX(0)).toBe(r.getX(2));
    expect(r.getX(4)).toBe(r.getX(5));
    expect(r.getX(0)).not.toBe(r.getX(4));
    for (let v = 0; v < 6; v++) {
      expect(r.getX(v)).toBeGreaterThanOrEqual(0);
      expect(r.getX(v)).toBeLessThanOrEqual(1);
    }
    // seeded: same seed, same values; another seed, other values
    const again = buildStrandGeometry(points, strandStart, 3).getAttribute('strandRandom');
    const other = buildStrandGeometry(points, strandStart, 4).getAttribute('strandRandom');
    expect(again.getX(0)).toBe(r.getX(0));
    expect(other.getX(0)).not.toBe(r.getX(0));
  });

  it("carries each point's distance from its strand's tip by arc length, finest near the tip", () => {
    // strand 0: 2, 1, 0 units from its tip; strand 2: 2, 0. By hand, the byte is
    // round(255 √(d / 10)): 255 √0.2 = 114.04 → 114, 255 √0.1 = 80.64 → 81; 0 at the tips
    const along = g.getAttribute('along');
    expect(along.itemSize).toBe(4);
    const bytes = [0, 1, 2, 4, 5].map((v) => Math.round(along.getY(v) * 255));
    expect(bytes).toEqual([114, 81, 0, 114, 0]);
    // decoded as the shader does (10 (byte / 255)²): within half a step of the distance
    expect(decodeTipDistance(114)).toBeCloseTo(1.9986, 4);
    expect(decodeTipDistance(81)).toBeCloseTo(1.009, 3);
    // the strips carry the same for both sides of each point
    const strips = buildStrandStripGeometry(points, strandStart, 3).getAttribute('along');
    for (const v of [0, 1, 2, 4, 5])
      for (const side of [0, 1]) {
        expect(strips.getX(2 * v + side)).toBe(along.getX(v));
        expect(strips.getY(2 * v + side)).toBe(along.getY(v));
        expect(strips.getZ(2 * v + side)).toBe(along.getZ(v));
        expect(strips.getW(2 * v + side)).toBe(along.getW(v));
      }
    // the grey rank and balayage section: one per strand, the same at each of its points
    for (const c of ['getZ', 'getW'] as const) {
      expect(along[c](1)).toBe(along[c](0));
      expect(along[c](2)).toBe(along[c](0));
      expect(along[c](5)).toBe(along[c](4));
    }
  });

  it('handles no strands', () => {
    const empty = buildStrandGeometry(new Float32Array(0), new Uint32Array([0]));
    expect(empty.getIndex()?.count).toBe(0);
    const none = buildStrandGeometry(new Float32Array(0), new Uint32Array(0));
    expect(none.getAttribute('position').count).toBe(0);
  });

  it('rejects strand ranges beyond the points', () => {
    expect(() => buildStrandGeometry(new Float32Array(3), new Uint32Array([0, 2]))).toThrow();
  });

  it('builds 100K strands × 40 points with the right index count', () => {
    const strands = 100_000;
    const per = 40;
    const pts = new Float32Array(3 * strands * per);
    const start = new Uint32Array(strands + 1);
    for (let s = 0; s < strands; s++) {
      start[s + 1] = (s + 1) * per;
      for (let i = 0; i < per; i++) {
        const p = 3 * (s * per + i);
        pts[p] = Math.sin(s) + 0.01 * i;
        pts[p + 1] = -0.05 * i;
        pts[p + 2] = Math.cos(s);
      }
    }
    // Speed is measured by the benchmarks, not asserted here; this checks the large case's layout.
    const big = buildStrandGeometry(pts, start);
    expect(big.getIndex()?.count).toBe(2 * strands * (per - 1));
  });

  it('orders strands so that every level-of-detail prefix is an even sample', () => {
    const strands = 1000;
    const per = 3;
    const start = Uint32Array.from({ length: strands + 1 }, (_, s) => s * per);
    const geo = buildStrandGeometry(new Float32Array(3 * strands * per), start);
    const index = Array.from(geo.getIndex()?.array ?? []);
    const lod = geo.userData.lodCounts as Uint32Array;
    expect(lod.length).toBe(LOD_GROUPS + 1);
    expect(lod[0]).toBe(0);
    expect(lod[LOD_GROUPS]).toBe(index.length);
    // every segment exactly once, each pair within one strand
    const pairs = [];
    for (let k = 0; k < index.length; k += 2) {
      expect(index[k + 1]).toBe(index[k] + 1);
      expect(Math.floor(index[k] / per)).toBe(Math.floor(index[k + 1] / per));
      pairs.push(index[k]);
    }
    expect(new Set(pairs).size).toBe(strands * (per - 1));
    // the strands drawn by the first 1, 2, 4 … groups are those ≡ 0 mod 64, 32, 16 …
    for (let groups = 1; groups <= LOD_GROUPS; groups *= 2) {
      const drawn = new Set(index.slice(0, lod[groups]).map((v) => Math.floor(v / per)));
      const stride = LOD_GROUPS / groups;
      const expected = Array.from({ length: strands }, (_, s) => s).filter((s) => s % stride === 0);
      expect([...drawn].sort((a, b) => a - b)).toEqual(expected);
    }
  });
});

describe('createStrandMaterial', () => {
  it('takes its colour as absorption: a direct colour maps to the σa whose colour it is', () => {
    const m = createStrandMaterial({ color: '#ff8040', lightDirection: [0, 2, 0] });
    const expected = colorAbsorption(hexToLinear('#ff8040') as [number, number, number]);
    const s = m.uniforms.rootSigma.value;
    expect([s.x, s.y, s.z].map((v, c) => v - expected[c]).every((d) => Math.abs(d) < 1e-6)).toBe(
      true,
    );
    expect(s.x).toBeCloseTo(0, 6); // a full channel absorbs nothing
    expect(m.uniforms.keyDirection.value.y).toBeCloseTo(1, 6); // normalised
    setHairColor(m, '#0000ff');
    expect(m.uniforms.rootSigma.value.z).toBeCloseTo(0, 6);
    expect(m.uniforms.rootSigma.value.x).toBeGreaterThan(0.2);
    setHairLook(m, { ...DEFAULT_HAIR_LOOK, grey: 30, tipStart: 0.5, tipMelanin: 0.1 }, '#000000');
    expect(m.uniforms.lookShares.value.x).toBeCloseTo(0.3, 6);
    expect(m.uniforms.lookShares.value.y).toBeCloseTo(0.5, 6);
    expect(m.uniforms.tipSigma.value.x).toBeLessThan(m.uniforms.rootSigma.value.x);
    // lighter tips over 8 cm: the length as it is, no older fraction
    setHairLook(m, { ...DEFAULT_HAIR_LOOK, tipLength: 0.8, tipMelanin: 0.1 }, '#000000');
    expect(m.uniforms.tipLength.value).toBeCloseTo(0.8, 6);
    expect(m.uniforms.lookShares.value.y).toBe(1);
    expect(m.uniforms.tipSigma.value.x).toBeLessThan(m.uniforms.rootSigma.value.x);
    setLightDirection(m, 3, 0, 4);
    expect(m.uniforms.keyDirection.value.x).toBeCloseTo(0.6, 6);
    expect(m.vertexShader).toContain('attribute vec3 tangent');
    expect(m.vertexShader).toContain('attribute vec2 lighting');
  });

  it('has the three lobes with the published shifts, lit by the world-fixed key light', () => {
    const m = createStrandMaterial();
    const glsl = m.vertexShader + m.fragmentShader; // lines shade per vertex
    // Marschner / Unreal: R −0.07, TT +0.035, TRT +0.14 rad; widths β², β²/2, 2β²
    expect(glsl).toContain('hairG(B.x, x + 0.07)');
    expect(glsl).toContain('hairG(B.y, x - 0.035)');
    expect(glsl).toContain('hairG(B.z, x - 0.14)');
    expect(glsl).toContain('vec3(b2, 0.5 * b2, 2.0 * b2)');
    expect(glsl).not.toContain('selfShadow');
    // the key light is fixed in world space: no view-space light
    expect(glsl).toContain('light.x');
  });

  it('strips: tapered, camera-facing, deep opacity maps on request', () => {
    const m = createStrandMaterial({ kind: 'strips', deepOpacity: true, alphaToCoverage: true });
    expect(m.vertexShader).toContain('gl_VertexID');
    expect(m.defines.DEEP_OPACITY).toBe('');
    expect(m.alphaToCoverage).toBe(true);
    expect(m.uniforms.tipWidth.value).toBeLessThan(1);
    expect(m.transparent).toBe(false);
    // without multisampling: coverage blended, unsorted, no depth writes
    const blended = createStrandMaterial({ kind: 'strips' });
    expect(blended.transparent).toBe(true);
    expect(blended.depthWrite).toBe(false);
  });
});

describe('per-strand width', () => {
  // 20,000 strands' random bytes as the shaders read them (normalised: byte / 255)
  const n = 20_000;
  const pts = new Float32Array(6 * n);
  const start = new Uint32Array(n + 1);
  for (let s = 0; s <= n; s++) start[s] = 2 * s;
  for (let s = 0; s < n; s++) pts[6 * s + 4] = 0.1;
  const random = buildStrandGeometry(pts, start, 7).getAttribute('strandRandom')
    .array as Uint8Array;
  const factors: number[] = [];
  const value: number[] = [];
  for (let s = 0; s < n; s++) {
    const r = [0, 1, 2, 3].map((c) => random[8 * s + c] / 255) as [number, number, number, number];
    factors.push(strandWidthFactor(r));
    value.push(r[0]);
  }

  it('varies from 0.6 to 1.4 of the width, evenly, so the mean width stays the same', () => {
    expect(WIDTH_VARIATION).toBe(0.4);
    const mean = factors.reduce((a, f) => a + f, 0) / n;
    expect(Math.abs(mean - 1)).toBeLessThan(0.01);
    expect(Math.min(...factors)).toBeGreaterThanOrEqual(0.6);
    expect(Math.max(...factors)).toBeLessThanOrEqual(1.4);
    // uniform: a quarter below 0.8, a quarter above 1.2
    const share = (f: (x: number) => boolean) => factors.filter(f).length / n;
    expect(Math.abs(share((x) => x < 0.8) - 0.25)).toBeLessThan(0.03);
    expect(Math.abs(share((x) => x > 1.2) - 0.25)).toBeLessThan(0.03);
    // not tied to the strand's brightness (its first random byte)
    const mv = value.reduce((a, v) => a + v, 0) / n;
    let cov = 0;
    let vf = 0;
    let vv = 0;
    for (let s = 0; s < n; s++) {
      cov += (factors[s] - mean) * (value[s] - mv);
      vf += (factors[s] - mean) ** 2;
      vv += (value[s] - mv) ** 2;
    }
    expect(Math.abs(cov / Math.sqrt(vf * vv))).toBeLessThan(0.05);
  });

  it("is applied to the strips' width and the lines' coverage alike", () => {
    for (const kind of ['lines', 'strips'] as const) {
      const m = createStrandMaterial({ kind });
      expect(m.vertexShader).toContain('float width = strandWidth * widthOf(strandRandom) *');
      expect(m.uniforms.widthVariation.value).toBe(WIDTH_VARIATION);
    }
    expect(createStrandMaterial({ kind: 'lines' }).vertexShader).toContain(
      'vCoverage = min(1.0, width / pixel)',
    );
    expect(createStrandMaterial({ kind: 'strips' }).vertexShader).toContain(
      'float drawn = max(width, pixel)',
    );
  });
});

describe('thin strands stand for a head of hair', () => {
  it('cover what 100,000 hairs of 75 µm cover, however many are drawn (within the clamps)', () => {
    // 1 unit = 10 cm: a hair is 0.00075 units wide; 100,000 of them as 30,000 strands
    expect(representedWidth(30_000)).toBeCloseTo((0.00075 * 100_000) / 30_000, 9);
    for (const n of [8_000, 12_000, 50_000, 99_000])
      expect(representedWidth(n) * n).toBeCloseTo(75, 6);
    expect(representedWidth(250_000)).toBe(0.00075); // never thinner than a hair
    expect(representedWidth(100)).toBe(0.012); // a sparse sample stays strands
    expect(representedWidth(0)).toBe(0.012);
  });

  it('count the strands a draw range covers (a prefix of the level-of-detail index)', () => {
    const n = 40;
    const pts = new Float32Array(n * 3 * 3);
    const start = new Uint32Array(n + 1).map((_, i) => 3 * i);
    const g = buildStrandGeometry(pts, start);
    expect(drawnStrands(g)).toBe(n);
    const all = g.getIndex()?.count ?? 0;
    g.setDrawRange(0, all / 4);
    expect(drawnStrands(g)).toBe(n / 4);
    // the material sets the width for the range drawn
    const m = createStrandMaterial({ kind: 'lines' });
    m.onBeforeRender(
      { getCurrentViewport: (v: { w: number }) => Object.assign(v, { w: 600 }) } as never,
      null as never,
      null as never,
      g,
      null as never,
      null as never,
    );
    expect(m.uniforms.strandWidth.value).toBe(representedWidth(n / 4));
    expect(m.transparent).toBe(true);
    expect(m.depthWrite).toBe(false);
  });
});

describe('lighting attribute and strips', () => {
  const points = new Float32Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 0, 0, -2]);
  const strandStart = new Uint32Array([0, 3, 5]);
  const lighting = new Float32Array([1, 1, 0.5, 0.25, 0, 0.75, 0.2, 0.4, 2, -1]);

  it('carries the precomputed transmittance and occlusion per point (1, 1 without them)', () => {
    const g = buildStrandGeometry(points, strandStart, 0, lighting);
    const a = g.getAttribute('lighting');
    expect(a.itemSize).toBe(2);
    expect(a.getX(1)).toBeCloseTo(0.5, 2);
    expect(a.getY(1)).toBeCloseTo(0.25, 2);
    expect(a.getX(4)).toBe(1); // clamped to [0, 1]
    expect(a.getY(4)).toBe(0);
    const none = buildStrandGeometry(points, strandStart).getAttribute('lighting');
    for (let v = 0; v < 5; v++) expect([none.getX(v), none.getY(v)]).toEqual([1, 1]);
  });

  it('strips double every point and draw two triangles per segment in LOD order', () => {
    const g = buildStrandStripGeometry(points, strandStart, 0, lighting);
    expect(g.getAttribute('position').count).toBe(10);
    expect(g.getAttribute('position').getX(3)).toBe(1); // point 1, second side
    expect(g.getAttribute('lighting').getX(3)).toBeCloseTo(0.5, 2);
    const index = Array.from(g.getIndex()?.array ?? []);
    expect(index.length).toBe(6 * 3);
    expect(index.slice(0, 6)).toEqual([0, 1, 2, 1, 3, 2]);
    const lod = g.userData.lodCounts as Uint32Array;
    expect(lod[LOD_GROUPS]).toBe(index.length);
  });
});

describe("the lock's highlight", () => {
  // strands on a 20 x 20 cm patch of scalp, as pairs: a strand and one rooted `gap` away
  const pairs = (gap: number) => {
    const n = 4000;
    const pts = new Float32Array(12 * n);
    const start = new Uint32Array(2 * n + 1);
    for (let s = 0; s <= 2 * n; s++) start[s] = 2 * s;
    for (let k = 0; k < n; k++) {
      const x = 2 * ((k * 0.618034) % 1) - 1;
      const z = 2 * ((k * 0.7548777) % 1) - 1;
      const a = (k * 2.3999632) % (2 * Math.PI);
      const put = (s: number, px: number, pz: number) => {
        pts.set([px, 1, pz, px, 0.9, pz], 6 * s);
      };
      put(2 * k, x, z);
      put(2 * k + 1, x + gap * Math.cos(a), z + gap * Math.sin(a));
    }
    const random = buildStrandGeometry(pts, start, 3).getAttribute('strandRandom')
      .array as Uint8Array;
    // the highlight byte of each strand's first point
    const w = (s: number) => random[4 * start[s] + 3] / 255;
    return Array.from({ length: n }, (_, k) => [w(2 * k), w(2 * k + 1)] as const);
  };
  const correlation = (p: readonly (readonly [number, number])[]) => {
    const n = p.length;
    const ma = p.reduce((t, q) => t + q[0], 0) / n;
    const mb = p.reduce((t, q) => t + q[1], 0) / n;
    let c = 0;
    let va = 0;
    let vb = 0;
    for (const [a, b] of p) {
      c += (a - ma) * (b - mb);
      va += (a - ma) ** 2;
      vb += (b - mb) ** 2;
    }
    return c / Math.sqrt(va * vb);
  };

  it('is shared by strands rooted together and independent a few locks apart', () => {
    // 2 mm apart: one lock; 6 cm apart (five lattice cells): unrelated
    expect(correlation(pairs(0.02))).toBeGreaterThan(0.8);
    expect(Math.abs(correlation(pairs(5 * LOCK_CELL)))).toBeLessThan(0.1);
  });

  it('spreads over most of 0 to 1, so locks tilt both ways', () => {
    const v = pairs(0.02).map((q) => q[0]);
    const below = v.filter((x) => x < 0.3).length / v.length;
    const above = v.filter((x) => x > 0.7).length / v.length;
    expect(below).toBeGreaterThan(0.15);
    expect(above).toBeGreaterThan(0.15);
    // a lattice's values interpolated: the same at a lattice point as on its neighbour's side
    expect(lockNoise(0, 0, 0, 5)).toBeCloseTo(lockNoise(1e-7, 0, 0, 5), 5);
  });
});

describe("the strand's turn, in its tangent's length", () => {
  it('reads back the angle between segments: 30 degrees round a 12-sided coil, 0 on a straight strand', () => {
    // strand 0: 25 points round a circle of 12 steps a turn (each point turns 2 pi / 12 between
    // its two segments, by hand), rising a little; strand 1: 10 points in a straight line
    const pts: number[] = [];
    for (let i = 0; i < 25; i++) {
      const a = (2 * Math.PI * i) / 12;
      pts.push(0.03 * Math.cos(a), 1 - 0.001 * i, 0.03 * Math.sin(a));
    }
    for (let i = 0; i < 10; i++) pts.push(0.5, 1 - 0.01 * i, 0);
    const start = new Uint32Array([0, 25, 35]);
    const t = buildStrandGeometry(new Float32Array(pts), start, 1).getAttribute('tangent')
      .array as Int8Array;
    // the shaders' turnOf: clamp(2 (1 - |t|), 0, 1) MAX_TURN
    const turn = (i: number) => {
      const l = Math.hypot(t[3 * i], t[3 * i + 1], t[3 * i + 2]) / 127;
      return Math.min(1, Math.max(0, 2 * (1 - l))) * MAX_TURN;
    };
    // the coil's own turn: the angle between its two chords, with the rise (hand: 2 pi / 12)
    for (let i = 1; i < 24; i++) expect(turn(i)).toBeCloseTo(Math.PI / 6, 1);
    for (let i = 26; i < 34; i++) expect(turn(i)).toBeLessThan(0.02);
    // the ends have one segment: no turn
    expect(turn(0)).toBeLessThan(0.02);
  });
});
