// The built-in head (method S1.1): a closed, outward-oriented mesh in the agreed frame, with a
// recognisable face, ears, neck and a scalp region that rays from the centre cross once.
import { beforeAll, describe, expect, it } from 'vitest';
import { buildHead } from '../../web/head/buildHead';
import type { HeadMesh } from '../../web/head/head';
import {
  hairlineTheta,
  isScalpDirection,
  markScalpTriangles,
  scalpFromPlane,
} from '../../web/head/scalpRegion';

const DEG = Math.PI / 180;
let head: HeadMesh;

beforeAll(() => {
  head = buildHead();
});

function vertex(v: number): [number, number, number] {
  const p = head.positions;
  return [p[3 * v], p[3 * v + 1], p[3 * v + 2]];
}

/** All crossings of the ray o + t d (t > 0) with the mesh, brute force (Möller–Trumbore). */
function crossings(
  o: [number, number, number],
  d: [number, number, number],
): { t: number; tri: number }[] {
  const P = head.positions;
  const I = head.indices;
  const out: { t: number; tri: number }[] = [];
  for (let tri = 0; tri < I.length / 3; tri++) {
    const a = 3 * I[3 * tri];
    const b = 3 * I[3 * tri + 1];
    const c = 3 * I[3 * tri + 2];
    const e1 = [P[b] - P[a], P[b + 1] - P[a + 1], P[b + 2] - P[a + 2]];
    const e2 = [P[c] - P[a], P[c + 1] - P[a + 1], P[c + 2] - P[a + 2]];
    const px = d[1] * e2[2] - d[2] * e2[1];
    const py = d[2] * e2[0] - d[0] * e2[2];
    const pz = d[0] * e2[1] - d[1] * e2[0];
    const det = e1[0] * px + e1[1] * py + e1[2] * pz;
    if (Math.abs(det) < 1e-14) continue;
    const inv = 1 / det;
    const sx = o[0] - P[a];
    const sy = o[1] - P[a + 1];
    const sz = o[2] - P[a + 2];
    const u = (sx * px + sy * py + sz * pz) * inv;
    if (u < 0 || u > 1) continue;
    const qx = sy * e1[2] - sz * e1[1];
    const qy = sz * e1[0] - sx * e1[2];
    const qz = sx * e1[1] - sy * e1[0];
    const v = (d[0] * qx + d[1] * qy + d[2] * qz) * inv;
    if (v < 0 || u + v > 1) continue;
    const t = (e2[0] * qx + e2[1] * qy + e2[2] * qz) * inv;
    if (t > 0) out.push({ t, tri });
  }
  // a ray through a shared edge or vertex hits each triangle there: count that crossing once
  out.sort((a, b) => a.t - b.t);
  return out.filter((h, i) => i === 0 || h.t - out[i - 1].t > 1e-7);
}

function direction(theta: number, phi: number): [number, number, number] {
  return [Math.sin(theta) * Math.sin(phi), Math.cos(theta), Math.sin(theta) * Math.cos(phi)];
}

describe('buildHead mesh', () => {
  it('has sensible sizes and indices in range', () => {
    const vertices = head.positions.length / 3;
    const triangles = head.indices.length / 3;
    expect(head.normals.length).toBe(head.positions.length);
    expect(head.scalp.length).toBe(triangles);
    expect(triangles).toBeGreaterThanOrEqual(20000);
    expect(triangles).toBeLessThanOrEqual(40000);
    let out = 0;
    for (const i of head.indices) if (!(i < vertices)) out++;
    expect(out).toBe(0);
    expect(head.center).toEqual([0, 0, 0]);
  });

  it('is watertight and consistently oriented (each directed edge once, its twin once)', () => {
    const V = head.positions.length / 3;
    const directed = new Map<number, number>();
    const I = head.indices;
    let degenerate = 0;
    for (let t = 0; t < I.length; t += 3) {
      for (let e = 0; e < 3; e++) {
        const a = I[t + e];
        const b = I[t + ((e + 1) % 3)];
        if (a === b) degenerate++;
        directed.set(a * V + b, (directed.get(a * V + b) ?? 0) + 1);
      }
    }
    let bad = 0;
    for (const [key, count] of directed) {
      const a = Math.floor(key / V);
      const b = key % V;
      if (count !== 1 || directed.get(b * V + a) !== 1) bad++;
    }
    expect(degenerate).toBe(0);
    expect(bad).toBe(0);
    // one closed surface of genus 0: V − E + F = 2
    expect(V - directed.size / 2 + I.length / 3).toBe(2);
  });

  it('faces outward: positive signed volume of a plausible size', () => {
    let vol = 0;
    const I = head.indices;
    for (let t = 0; t < I.length; t += 3) {
      const [ax, ay, az] = vertex(I[t]);
      const [bx, by, bz] = vertex(I[t + 1]);
      const [cx, cy, cz] = vertex(I[t + 2]);
      vol += (ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx)) / 6;
    }
    // cranium ellipsoid alone ≈ 4/3 π 0.75 · 1.0 · 0.95 ≈ 3.0; plus face and neck
    expect(vol).toBeGreaterThan(3.5);
    expect(vol).toBeLessThan(9);
  });

  it('has unit vertex normals pointing away from the inside', () => {
    const N = head.normals;
    const vertices = N.length / 3;
    let upper = 0;
    let outward = 0;
    let notUnit = 0;
    for (let v = 0; v < vertices; v++) {
      if (Math.abs(Math.hypot(N[3 * v], N[3 * v + 1], N[3 * v + 2]) - 1) > 1e-4) notUnit++;
      // on the upper cranium the radial direction from the centre is outward
      const [x, y, z] = vertex(v);
      if (y > 0.3) {
        upper++;
        const r = Math.hypot(x, y, z);
        if ((N[3 * v] * x + N[3 * v + 1] * y + N[3 * v + 2] * z) / r > 0.5) outward++;
      }
    }
    expect(notUnit).toBe(0);
    expect(upper).toBeGreaterThan(1000);
    expect(outward).toBe(upper);
  });

  it('stays inside the agreed box with the agreed landmarks', () => {
    const { min, max } = head.bounds;
    expect(min[0]).toBeGreaterThanOrEqual(-1.7);
    expect(max[0]).toBeLessThanOrEqual(1.7);
    expect(min[1]).toBeGreaterThanOrEqual(-2.9);
    expect(max[1]).toBeLessThanOrEqual(1.5);
    expect(min[2]).toBeGreaterThanOrEqual(-1.7);
    expect(max[2]).toBeLessThanOrEqual(1.7);
    expect(max[1]).toBeCloseTo(1.0, 1); // top of the head
    expect(min[1]).toBeLessThan(-2.5); // neck goes down to ≈ −2.6
    // bounds match the positions
    let top = -Infinity;
    for (let v = 0; v < head.positions.length / 3; v++) top = Math.max(top, vertex(v)[1]);
    expect(top).toBe(max[1]);
  });

  it('has the nose as its frontmost point and a chin near y = −1.3', () => {
    let front = 0;
    let chin = -1;
    for (let v = 0; v < head.positions.length / 3; v++) {
      const p = vertex(v);
      if (p[2] > vertex(front)[2]) front = v;
      // the chin: lowest point of the front of the face near the midline
      if (p[2] > 0.5 && Math.abs(p[0]) < 0.1 && (chin < 0 || p[1] < vertex(chin)[1])) chin = v;
    }
    const [nx, ny, nz] = vertex(front);
    expect(Math.abs(nx)).toBeLessThan(0.05);
    expect(ny).toBeGreaterThan(-0.7);
    expect(ny).toBeLessThan(-0.2);
    expect(nz).toBeGreaterThan(1.1);
    expect(vertex(chin)[1]).toBeGreaterThan(-1.45);
    expect(vertex(chin)[1]).toBeLessThan(-1.2);
  });

  it('has two ears sticking out in ±x at ear height, beyond the cranium', () => {
    for (const side of [1, -1]) {
      let best = 0;
      for (let v = 0; v < head.positions.length / 3; v++) {
        if (side * vertex(v)[0] > side * vertex(best)[0]) best = v;
      }
      const [x, y, z] = vertex(best);
      expect(side * x).toBeGreaterThan(0.78); // cranium half-width is 0.75
      expect(y).toBeGreaterThan(-0.7);
      expect(y).toBeLessThan(0.1);
      expect(z).toBeGreaterThan(-0.5);
      expect(z).toBeLessThan(0.2);
    }
    // cross-check with rays from the centre: the ray toward an ear leaves the surface farther
    // out than a ray just above the ear's top (the scalp)
    const ear = crossings([0, 0, 0], direction(100 * DEG, 90 * DEG));
    const above = crossings([0, 0, 0], direction(70 * DEG, 90 * DEG));
    const far = (c: { t: number }[]) => Math.max(...c.map((h) => h.t));
    expect(far(ear)).toBeGreaterThan(far(above) + 0.03);
  });

  it('is deterministic and follows the resolution option', () => {
    const again = buildHead();
    const same = (x: ArrayLike<number>, y: ArrayLike<number>) =>
      x.length === y.length && Array.prototype.every.call(x, (v: number, i: number) => v === y[i]);
    expect(same(again.indices, head.indices)).toBe(true);
    expect(same(again.positions, head.positions)).toBe(true);
    const coarse = buildHead({ resolution: 14 });
    expect(coarse.indices.length).toBeLessThan(head.indices.length / 2);
    expect(() => buildHead({ resolution: 0 })).toThrow();
  });
});

describe('scalp region', () => {
  it('follows a natural hairline', () => {
    expect(isScalpDirection(0, 0)).toBe(true); // crown
    expect(isScalpDirection(45 * DEG, 0)).toBe(true); // upper forehead
    expect(isScalpDirection(65 * DEG, 0)).toBe(false); // forehead
    expect(isScalpDirection(90 * DEG, 0)).toBe(false); // face
    expect(isScalpDirection(100 * DEG, 90 * DEG)).toBe(false); // ear
    expect(isScalpDirection(100 * DEG, -90 * DEG)).toBe(false); // other ear
    expect(isScalpDirection(70 * DEG, 90 * DEG)).toBe(true); // above the ear
    expect(isScalpDirection(108 * DEG, 180 * DEG)).toBe(true); // nape
    expect(isScalpDirection(125 * DEG, 180 * DEG)).toBe(false); // neck
    const front = hairlineTheta(0) / DEG;
    const back = hairlineTheta(Math.PI) / DEG;
    expect(front).toBeGreaterThanOrEqual(55);
    expect(front).toBeLessThanOrEqual(60);
    expect(back).toBeGreaterThanOrEqual(110);
    expect(back).toBeLessThanOrEqual(120);
    // symmetric left/right
    for (let p = 0; p <= 180; p += 7) {
      expect(hairlineTheta(p * DEG)).toBeCloseTo(hairlineTheta(-p * DEG), 12);
    }
  });

  it('marks both scalp and non-scalp triangles, the scalp a sensible share', () => {
    let n = 0;
    for (const s of head.scalp) n += s;
    expect(n).toBeGreaterThan(0.15 * head.scalp.length);
    expect(n).toBeLessThan(0.5 * head.scalp.length);
    const again = markScalpTriangles(head);
    expect(again.every((v, i) => v === head.scalp[i])).toBe(true);
  });

  it('is crossed exactly once by rays from the centre in scalp directions', () => {
    let rays = 0;
    for (let t = 3; t < 120; t += 9) {
      for (let p = -180; p < 180; p += 15) {
        const theta = t * DEG;
        const phi = p * DEG;
        if (theta > hairlineTheta(phi) - 4 * DEG) continue; // away from the hairline
        const hits = crossings(head.center, direction(theta, phi));
        expect(hits.length, `θ=${t} φ=${p}`).toBe(1);
        expect(head.scalp[hits[0].tri], `θ=${t} φ=${p}`).toBe(1);
        rays++;
      }
    }
    expect(rays).toBeGreaterThan(100);
  });

  it('leaves the face, ears and neck out', () => {
    const probes: [number, number][] = [
      [90, 0], // nose / face
      [100, 30], // cheek
      [100, 90], // left ear
      [100, -90], // right ear
      [150, 180], // back of the neck
      [150, 0], // throat
    ];
    for (const [t, p] of probes) {
      const hits = crossings(head.center, direction(t * DEG, p * DEG));
      expect(hits.length).toBeGreaterThan(0);
      const last = hits.reduce((a, b) => (b.t > a.t ? b : a));
      expect(head.scalp[last.tri], `θ=${t} φ=${p}`).toBe(0);
    }
  });

  it('scalpFromPlane marks the triangles above a plane', () => {
    const above = scalpFromPlane(head, [0, 0.2, 0], [0, 2, 0]); // normal need not be unit
    const below = scalpFromPlane(head, [0, 0.2, 0], [0, -1, 0]);
    const I = head.indices;
    let wrong = 0;
    let both = 0;
    let count = 0;
    for (let t = 0; t < I.length / 3; t++) {
      const y = (vertex(I[3 * t])[1] + vertex(I[3 * t + 1])[1] + vertex(I[3 * t + 2])[1]) / 3;
      if (above[t] !== (y > 0.2 ? 1 : 0)) wrong++;
      if (above[t] && below[t]) both++;
      count += above[t];
    }
    expect(wrong).toBe(0);
    expect(both).toBe(0);
    expect(count).toBeGreaterThan(1000);
  });
});
