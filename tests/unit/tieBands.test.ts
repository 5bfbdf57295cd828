// Hair-tie bands (model/tieBands.ts, model/tieBandMesh.ts) against strands built by hand: a tail
// of known radius round a known axis, strays and other hair beside it; a braid whose strands
// gather at a known stroke point.
import { describe, expect, it } from 'vitest';
import type { StrandArrays } from '../../web/model/hairArrays';
import type { StyleCurve } from '../../web/model/session';
import { BAND_HALF_WIDTH, BAND_THICKNESS, bandMesh } from '../../web/model/tieBandMesh';
import { tieBands } from '../../web/model/tieBands';
import type { Vec3 } from '../../web/model/vec3';

const norm = (v: Vec3): Vec3 => {
  const l = Math.hypot(...v);
  return [v[0] / l, v[1] / l, v[2] / l];
};
const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];

/** Strands as the solver hands them: polylines and the tie of each (-1: none). */
function strandArrays(lines: { pts: Vec3[]; tail: number }[]): StrandArrays {
  const strandStart = new Uint32Array(lines.length + 1);
  let n = 0;
  lines.forEach((l, i) => {
    strandStart[i] = n;
    n += l.pts.length;
  });
  strandStart[lines.length] = n;
  const points = new Float32Array(3 * n);
  let k = 0;
  for (const l of lines) for (const p of l.pts) points.set(p, 3 * k++);
  return { points, strandStart, tailCurves: Int32Array.from(lines, (l) => l.tail) };
}

// The tail: round axis `axis` through `centre` (the band plane's point), strands running along
// the axis from 0.6 before the plane to 1.2 past it at radius R, some strays farther out.
const centre: Vec3 = [0.1, -0.4, -1.1];
const axis = norm([0.2, -1, -0.3]);
const u = norm(cross([1, 0, 0], axis));
const w = cross(axis, u);
const R = 0.25;
const at = (r: number, phi: number, t: number): Vec3 =>
  [0, 1, 2].map(
    (k) => centre[k] + t * axis[k] + r * (Math.cos(phi) * u[k] + Math.sin(phi) * w[k]),
  ) as Vec3;
function tailStrand(r: number, phi: number, tail: number) {
  const pts: Vec3[] = [];
  // not an even step, so no strand point lies on the plane
  for (let t = -0.6; t <= 1.2; t += 0.07) pts.push(at(r, phi, t));
  return { pts, tail };
}

// C1 sketched 3 cm off the hair's axis and tilted 20° from it (the spine stood out, the hair
// fell): the band follows the hair, not the sketch
const sketchCentre: Vec3 = [centre[0] + 0.3 * u[0], centre[1] + 0.3 * u[1], centre[2] + 0.3 * u[2]];
const tilt = (20 * Math.PI) / 180;
const tilted = norm([0, 1, 2].map((k) => Math.cos(tilt) * axis[k] + Math.sin(tilt) * w[k]) as Vec3);
const ponytail = {
  id: 'c2',
  type: 'ponytail',
  points: [sketchCentre, [sketchCentre[0], sketchCentre[1] - 1, sketchCentre[2]]],
  extend: true,
  viewpoint: { position: [0, 0, 5], target: [0, 0, 0] },
  crossSection: [],
  profiles: [[], []],
  circles: [{ centre: sketchCentre, axis: tilted, radius: 0.5, spineIndex: 0 }],
  tightness: 0.5,
  section: 0,
} as unknown as StyleCurve;
const stream = {
  id: 'c1',
  type: 'stream',
  points: [
    [0, 1, 0],
    [0, 0, 1],
  ],
  extend: false,
  viewpoint: { position: [0, 0, 5], target: [0, 0, 0] },
} as unknown as StyleCurve;

function ponytailHair() {
  const lines = [];
  // 200 strands on the tail's surface, 6 strays at three times its radius (3 %), 40 strands of
  // loose hair (no tie) crossing the same plane far out
  for (let i = 0; i < 200; i++) lines.push(tailStrand(R, (2 * Math.PI * i) / 200, 1));
  for (let i = 0; i < 6; i++) lines.push(tailStrand(3 * R, i, 1));
  for (let i = 0; i < 40; i++) lines.push(tailStrand(2, i, -1));
  return strandArrays(lines);
}

describe('tie bands', () => {
  it('a ponytail: on C1’s plane, round the hair, its radius the hair’s plus 1.5 mm', () => {
    const bands = tieBands({ ties: true, curves: [stream, ponytail] }, ponytailHair());
    expect(bands).toHaveLength(1);
    const b = bands[0];
    expect(b.curve).toBe(1);
    // within 1 mm (0.01 units) of the tail's radius + margin, with the strays and loose hair left out
    expect(Math.abs(b.radius - (R + 0.015))).toBeLessThan(0.01);
    for (let k = 0; k < 3; k++) {
      expect(Math.abs(b.centre[k] - centre[k])).toBeLessThan(0.01);
      expect(b.axis[k]).toBeCloseTo(axis[k], 6);
    }
  });

  it("a Mirror twin's band is its twin's reflected, whatever its own hair measures", () => {
    // the twin (tail 2) holds a tail twice as wide, 5 cm lower: its band is still the first's
    const hair = ponytailHair();
    const lines = [];
    for (let i = 0; i < 200; i++) {
      const q = tailStrand(2 * R, (2 * Math.PI * i) / 200, 2);
      lines.push({ pts: q.pts.map((p) => [-p[0], p[1] - 0.5, p[2]] as Vec3), tail: 2 });
    }
    const twinHair = strandArrays([
      ...Array.from({ length: hair.strandStart.length - 1 }, (_, s) => ({
        pts: Array.from(
          { length: hair.strandStart[s + 1] - hair.strandStart[s] },
          (_, q) => [0, 1, 2].map((k) => hair.points[3 * (hair.strandStart[s] + q) + k]) as Vec3,
        ),
        tail: (hair.tailCurves as Int32Array)[s],
      })),
      ...lines,
    ]);
    const first = { ...ponytail, mirror: 'c3' } as StyleCurve;
    const twin = { ...ponytail, id: 'c3', mirror: 'c2' } as StyleCurve;
    const bands = tieBands({ ties: true, curves: [stream, first, twin] }, twinHair);
    expect(bands.map((b) => b.curve)).toEqual([1, 2]);
    const [a, b] = bands;
    expect(b.centre).toEqual([-a.centre[0], a.centre[1], a.centre[2]]);
    expect(b.axis).toEqual([-a.axis[0], a.axis[1], a.axis[2]]);
    expect(b.radius).toBe(a.radius);
  });

  it("the engine's tie frame (where the growth gathered the hair) places the band", () => {
    // a braid whose stroke runs far from its hair: no gather found on it; the frame says where
    const braid = {
      id: 'c2',
      type: 'braid',
      points: [
        [2, 1, 0],
        [2, 0, 0],
        [2, -1, 0],
      ],
      extend: false,
      viewpoint: { position: [0, 0, 5], target: [0, 0, 0] },
      width: 0.5,
      crossings: 6,
      tightness: 0.5,
      tailLength: 0.4,
      section: 1,
    } as unknown as StyleCurve;
    // the frame half a unit down the tail (5 cm): the band there, round the hair
    const hair = ponytailHair();
    const down = at(0, 0, 0.5);
    const framed = { ...hair, tieFrames: new Float32Array([1, ...down, ...axis, 0]) };
    const [b] = tieBands({ ties: true, curves: [stream, braid] }, framed);
    expect(b.curve).toBe(1);
    expect(Math.abs(b.radius - (R + 0.015))).toBeLessThan(0.01);
    for (let k = 0; k < 3; k++) expect(Math.abs(b.centre[k] - down[k])).toBeLessThan(0.01);
    // with the hair's radius as laid there, the band hugs it: that radius plus 1.5 mm
    const sized = { ...hair, tieFrames: new Float32Array([1, ...down, ...axis, 0.12]) };
    const [c] = tieBands({ ties: true, curves: [stream, braid] }, sized);
    expect(c.radius).toBeCloseTo(0.12 + 0.015, 6);
    expect(c.centre).toEqual([...new Float32Array(down)]);
  });

  it('a thinner tail gives a smaller band', () => {
    const lines = [];
    for (let i = 0; i < 100; i++) lines.push(tailStrand(0.1, i, 1));
    const [b] = tieBands({ ties: true, curves: [stream, ponytail] }, strandArrays(lines));
    expect(Math.abs(b.radius - 0.115)).toBeLessThan(0.01);
  });

  it('none when the tie holds no strands, and none without ties', () => {
    const loose = strandArrays(Array.from({ length: 50 }, (_, i) => tailStrand(R, i, -1)));
    expect(tieBands({ ties: true, curves: [stream, ponytail] }, loose)).toEqual([]);
    expect(tieBands({ ties: false, curves: [stream, ponytail] }, ponytailHair())).toEqual([]);
    expect(tieBands({ curves: [stream, ponytail] }, ponytailHair())).toEqual([]);
    const { tailCurves: _, ...untold } = ponytailHair();
    expect(tieBands({ ties: true, curves: [stream, ponytail] }, untold)).toEqual([]);
  });

  it('a braid: at the gather, where its strands come together off the head', () => {
    // stroke straight down x = 0, z = -1 from y = 0.5 (on the head) to y = -1.5, step 0.1; the
    // strands' roots spread 0.8 round it at y = 0.5, narrowing to 0.12 at y = 0 (the gather)
    const stroke: Vec3[] = Array.from({ length: 21 }, (_, i) => [0, 0.5 - 0.1 * i, -1]);
    const braid = {
      id: 'c1',
      type: 'braid',
      points: stroke,
      extend: true,
      viewpoint: { position: [0, 0, 5], target: [0, 0, 0] },
      width: 0.3,
      crossings: 6,
      tightness: 0.5,
      tailLength: 0.4,
      section: 0,
    } as unknown as StyleCurve;
    const lines = [];
    for (let i = 0; i < 120; i++) {
      const phi = (2 * Math.PI * i) / 120;
      const pts: Vec3[] = [];
      for (let y = 0.53; y > -1.5; y -= 0.015) {
        // a waist at y = 0.4 (strands passing close by the stroke by chance, then fanning out
        // over the head again): not the gather
        const r = y > 0.35 && y < 0.45 ? 0.1 : y > 0 ? 0.12 + (0.68 * y) / 0.5 : 0.12;
        pts.push([r * Math.cos(phi), y, -1 + r * Math.sin(phi)]);
      }
      lines.push({ pts, tail: 0 });
    }
    const [b, ...rest] = tieBands({ ties: true, curves: [braid] }, strandArrays(lines));
    expect(rest).toEqual([]);
    // where the stroke points whose planes the strands cross within 0.6 × width (0.18) of their
    // centre begin for good: y = 0 (at y = 0.1 they are 0.256 out; at y = 0.4, 0.1, by chance)
    expect(b.centre[1]).toBeCloseTo(0, 6);
    expect(Math.abs(b.centre[0])).toBeLessThan(0.01);
    expect(Math.abs(b.centre[2] + 1)).toBeLessThan(0.01);
    expect(b.axis[1]).toBeCloseTo(-1, 9);
    expect(Math.abs(b.radius - 0.135)).toBeLessThan(0.01);
  });

  it('its mesh rings the tail: inner edge on the band radius, 8 mm wide, normals outward', () => {
    const band = { curve: 0, centre, axis, radius: 0.3 };
    const m = bandMesh([band]);
    const vertices = m.positions.length / 3;
    expect(vertices).toBeGreaterThan(100);
    expect(m.indices.length % 3).toBe(0);
    let minR = Infinity;
    let maxR = 0;
    let maxAlong = 0;
    for (let v = 0; v < vertices; v++) {
      const d = [0, 1, 2].map((k) => m.positions[3 * v + k] - centre[k]) as Vec3;
      const along = d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2];
      const radial = Math.hypot(...d.map((x, k) => x - along * axis[k]));
      minR = Math.min(minR, radial);
      maxR = Math.max(maxR, radial);
      maxAlong = Math.max(maxAlong, Math.abs(along));
    }
    expect(minR).toBeCloseTo(0.3, 5);
    expect(maxR).toBeCloseTo(0.3 + 2 * BAND_THICKNESS, 5);
    expect(2 * maxAlong).toBeCloseTo(0.08, 5);
    expect(BAND_HALF_WIDTH).toBe(0.04);
    // every triangle's winding agrees with its vertices' normals (counter-clockwise from outside)
    const P = (i: number): Vec3 => [
      m.positions[3 * i],
      m.positions[3 * i + 1],
      m.positions[3 * i + 2],
    ];
    for (let t = 0; t < m.indices.length; t += 3) {
      const [a, b, c] = [m.indices[t], m.indices[t + 1], m.indices[t + 2]].map(P);
      const n = cross(
        [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
        [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
      );
      const i = m.indices[t];
      const dn =
        n[0] * m.normals[3 * i] + n[1] * m.normals[3 * i + 1] + n[2] * m.normals[3 * i + 2];
      expect(dn).toBeGreaterThan(0);
    }
    expect(bandMesh([]).positions.length).toBe(0);
  });
});
