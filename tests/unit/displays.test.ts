// The display modules' pure parts (method S6.2): constraint colours and glyph arrays, field glyph
// subsampling and its count cap, the bounding box edges, and supporting-surface meshes. Expected
// values are built here by hand or by brute force, not read back from the code under test.
import { describe, expect, it } from 'vitest';
import type { GridSpec } from '../../web/model/hairArrays';
import { ConstraintColour } from '../../web/model/hairArrays';
import { buildSupportingSurface } from '../../web/model/supportingSurface';
import type { Vec3 } from '../../web/model/vec3';
import { DEFAULT_DISPLAY, DISPLAY_TOGGLES } from '../../web/ui/displayToggles';
import { gridBoxEdges } from '../../web/viewer/boundingVolume';
import {
  CONSTRAINT_RGB,
  ConstraintPointsView,
  constraintGlyphs,
  constraintRgb,
  gridPointPosition,
} from '../../web/viewer/constraintPoints';
import {
  FieldGlyphsView,
  fieldGlyphPoints,
  fieldGlyphSegments,
} from '../../web/viewer/fieldGlyphs';
import { SupportingSurfaceView, surfaceGeometry } from '../../web/viewer/supportingSurfaceView';

const grid: GridSpec = { dims: [4, 3, 5], origin: [-1, 0.5, 2], step: 0.25 };
const rgb01 = (hex: number) => [(hex >> 16) / 255, ((hex >> 8) & 255) / 255, (hex & 255) / 255];
const hue = (hex: number) => {
  const [r, g, b] = rgb01(hex);
  return { r, g, b };
};

describe('constraint colours', () => {
  it('maps blue, red, purple, green to hues of those names and unknown codes to grey', () => {
    const blue = hue(constraintRgb(ConstraintColour.blue));
    expect(blue.b).toBeGreaterThan(Math.max(blue.r, blue.g));
    const red = hue(constraintRgb(ConstraintColour.red));
    expect(red.r).toBeGreaterThan(Math.max(red.g, red.b) + 0.4);
    const purple = hue(constraintRgb(ConstraintColour.purple));
    expect(Math.min(purple.r, purple.b)).toBeGreaterThan(purple.g + 0.2);
    const green = hue(constraintRgb(ConstraintColour.green));
    expect(green.g).toBeGreaterThan(Math.max(green.r, green.b) + 0.3);
    for (const code of [ConstraintColour.extra, 9, 255]) {
      const grey = hue(constraintRgb(code));
      expect(Math.max(grey.r, grey.g, grey.b) - Math.min(grey.r, grey.g, grey.b)).toBeLessThan(0.1);
    }
    expect(new Set(CONSTRAINT_RGB).size).toBe(5);
  });

  it('puts each constraint at its grid point with a segment along its target, in its colour', () => {
    // point (1, 2, 3) and (3, 0, 4): p = i + nx * (j + ny * k)
    const p0 = 1 + 4 * (2 + 3 * 3);
    const p1 = 3 + 4 * (0 + 3 * 4);
    const c = {
      index: new Int32Array([p0, p1]),
      target: new Float32Array([1, 0, 0, 0, -0.3, 0]),
      colour: new Uint8Array([ConstraintColour.blue, ConstraintColour.red]),
    };
    expect(gridPointPosition(grid, p0)).toEqual([-0.75, 1, 2.75]);
    const g = constraintGlyphs(c, grid, 0.8);
    expect(Array.from(g.points)).toEqual([-0.75, 1, 2.75, -0.25, 0.5, 3]);
    const seg = Array.from(g.segments);
    expect(seg.slice(0, 6).map((x) => +x.toFixed(6))).toEqual([-0.75, 1, 2.75, -0.55, 1, 2.75]);
    expect(seg.slice(6, 12).map((x) => +x.toFixed(6))).toEqual([-0.25, 0.5, 3, -0.25, 0.44, 3]);
    // vertex colours are linear: the sRGB hex decoded (the sRGB transfer curve, by hand)
    const lin = (x: number) => (x <= 0.04045 ? x / 12.92 : ((x + 0.055) / 1.055) ** 2.4);
    const blue = rgb01(CONSTRAINT_RGB[0]).map(lin);
    const red = rgb01(CONSTRAINT_RGB[1]).map(lin);
    expect(Array.from(g.pointColours).map((x) => +x.toFixed(5))).toEqual(
      [...blue, ...red].map((x) => +x.toFixed(5)),
    );
    // segment roots in the constraint's colour, tips lighter (towards white)
    for (let e = 0; e < 2; e++)
      for (let a = 0; a < 3; a++) {
        expect(g.segmentColours[6 * e + a]).toBeCloseTo(g.pointColours[3 * e + a], 6);
        expect(g.segmentColours[6 * e + 3 + a]).toBeGreaterThanOrEqual(g.segmentColours[6 * e + a]);
      }
  });
});

describe('field glyphs', () => {
  const big: GridSpec = { dims: [20, 16, 12], origin: [0, 0, 0], step: 0.1 };
  const n = 20 * 16 * 12;
  // v = (x-ramp) along x: |v| = i / 19, so points with i <= 0.95 are below 0.05
  const ramp = new Float32Array(3 * n);
  for (let p = 0; p < n; p++) ramp[3 * p] = (p % 20) / 19;

  it('takes every 2nd point along each axis where |v| > 0.05', () => {
    const pts = Array.from(fieldGlyphPoints(ramp, big, { stride: 2, maxGlyphs: 1e9 }));
    const expected: number[] = [];
    for (let k = 0; k < 12; k += 2)
      for (let j = 0; j < 16; j += 2)
        for (let i = 0; i < 20; i += 2) if (i / 19 > 0.05) expected.push(i + 20 * (j + 16 * k));
    expect(pts).toEqual(expected);
    expect(pts.length).toBe(9 * 8 * 6); // i = 2, 4, ..., 18
  });

  it('caps the count with an even sample across the whole grid', () => {
    const all = fieldGlyphPoints(ramp, big, { stride: 1, maxGlyphs: 1e9 });
    const capped = fieldGlyphPoints(ramp, big, { stride: 1, maxGlyphs: 100 });
    expect(capped.length).toBe(100);
    for (let g = 1; g < capped.length; g++) expect(capped[g]).toBeGreaterThan(capped[g - 1]);
    const allSet = new Set(all);
    for (const p of capped) expect(allSet.has(p)).toBe(true);
    // spread: the sample reaches the last tenth of the grid, not just a prefix
    expect(capped[capped.length - 1]).toBeGreaterThan(0.9 * all[all.length - 1]);
    expect(fieldGlyphPoints(new Float32Array(3 * n), big).length).toBe(0); // zero field: none
  });

  it('draws each glyph from its grid point along v, stride · length · d per unit of |v|', () => {
    const s = fieldGlyphSegments(ramp, big, { stride: 2, length: 0.5, maxGlyphs: 1e9 });
    expect(s.count).toBe(9 * 8 * 6);
    expect(s.positions.length).toBe(6 * s.count);
    // the first glyph: point (2, 0, 0), v = (2/19, 0, 0)
    expect(s.positions[0]).toBeCloseTo(0.2, 6);
    expect(s.positions[3]).toBeCloseTo(0.2 + 0.5 * 2 * 0.1 * (2 / 19), 6);
    expect(s.positions[4]).toBeCloseTo(0, 6);
  });
});

describe('bounding volume', () => {
  it('has the 12 edges of the box from the first to the last grid point', () => {
    const e = gridBoxEdges(grid);
    expect(e.length).toBe(12 * 6);
    const lo = [-1, 0.5, 2];
    const hi = [-1 + 3 * 0.25, 0.5 + 2 * 0.25, 2 + 4 * 0.25];
    // brute force: every pair of corners differing in exactly one axis, each once
    const corners: number[][] = [];
    for (let c = 0; c < 8; c++) corners.push([0, 1, 2].map((a) => ((c >> a) & 1 ? hi[a] : lo[a])));
    const key = (a: number[], b: number[]) =>
      [a, b]
        .map((v) => v.map((x) => x.toFixed(6)).join(','))
        .sort()
        .join('|');
    const expected = new Set<string>();
    for (const a of corners)
      for (const b of corners)
        if (a.filter((x, i) => Math.abs(x - b[i]) > 1e-9).length === 1) expected.add(key(a, b));
    const got = new Set<string>();
    for (let k = 0; k < 12; k++) {
      const a = Array.from(e.slice(6 * k, 6 * k + 3));
      const b = Array.from(e.slice(6 * k + 3, 6 * k + 6));
      got.add(key(a, b));
    }
    expect(got).toEqual(expected);
    expect(expected.size).toBe(12);
  });
});

describe('supporting surface mesh', () => {
  const curve: Vec3[] = Array.from({ length: 8 }, (_, i) => [0.1 * i, 0.02 * i * i, 0]);
  const eye: Vec3 = [0.3, 0.5, 4];

  it('draws 2 triangles per segment of a ruled surface', () => {
    const s = buildSupportingSurface(curve, eye, 'ruled', 0.4);
    const g = surfaceGeometry(s);
    expect((g.getIndex()?.count ?? 0) / 3).toBe(2 * (curve.length - 1));
    const v = new SupportingSurfaceView();
    v.update(s);
    expect(v.triangles).toBe(14);
    expect(v.object.visible).toBe(true);
    v.update(null);
    expect(v.triangles).toBe(0);
    expect(v.object.visible).toBe(false);
  });

  it('adds the wedge triangles of a bent strip (2 per segment, 2 per bent joint)', () => {
    const s = buildSupportingSurface(curve, eye, 'strip', 0.4);
    const g = surfaceGeometry(s);
    // the curve bends at each of its 6 inner joints
    expect((g.getIndex()?.count ?? 0) / 3).toBe(2 * 7 + 2 * 6);
    expect(g.getAttribute('position').count).toBe(s.positions.length / 3);
  });
});

describe('display toggles', () => {
  it('defaults to curves only, labels the six toggles and maps keys 1–6 to them in order', () => {
    expect(DEFAULT_DISPLAY).toEqual({
      curves: true,
      constraints: false,
      surface: false,
      field: false,
      box: false,
      cards: false,
    });
    expect(DISPLAY_TOGGLES.map((t) => t.label)).toEqual([
      'Curves',
      'Constraints',
      'Surface',
      'Field',
      'Box',
      'Cards',
    ]);
  });
});

describe('display views', () => {
  it('draw nothing, and hide, without input; count what they draw otherwise', () => {
    const c = new ConstraintPointsView();
    c.update(null, grid);
    expect([c.count, c.object.visible]).toEqual([0, false]);
    c.update(
      {
        index: new Int32Array([0, 5, 7]),
        target: new Float32Array(9).fill(0.5),
        colour: new Uint8Array([0, 2, 3]),
      },
      grid,
    );
    expect([c.count, c.object.visible]).toEqual([3, true]);
    const f = new FieldGlyphsView({ stride: 1 });
    f.update(null, grid);
    expect([f.count, f.object.visible]).toEqual([0, false]);
    const n = 4 * 3 * 5;
    const v = new Float32Array(3 * n);
    v[3 * 7 + 1] = 1; // one point with |v| = 1
    f.update(v, grid);
    expect([f.count, f.object.visible]).toEqual([1, true]);
  });
});
