// Finished edges on the scalp (sessionScalpMask with `finish`): the built-in head's natural
// hairline, and erasing that leaves no lone hair (a scrap of scalp cut off by an erase goes with
// it, a strip narrower than a triangle is peeled), while painting the erased part back gives the
// mask exactly, and scalp away from the erase is never touched.
import { describe, expect, it } from 'vitest';
import { Head } from '../../web/head/head';
import { earDistance } from '../../web/head/headSdf';
import {
  applyScalpPaint,
  type ScalpPaintStroke,
  sessionScalpMask,
} from '../../web/head/scalpPaint';
import type { Vec3 } from '../../web/model/vec3';

const head = Head.builtin();
const mesh = head.mesh;
const natural = mesh.naturalScalp as Uint8Array;
const T = mesh.indices.length / 3;

const surface = (theta: number, phi: number): Vec3 => {
  const hit = head.scalpPoint(theta, phi);
  if (!hit) throw new Error(`no head at (${theta}, ${phi})`);
  return hit.point;
};

function centroid(t: number): Vec3 {
  const { positions: P, indices: I } = mesh;
  const c: Vec3 = [0, 0, 0];
  for (let k = 0; k < 3; k++) for (let a = 0; a < 3; a++) c[a] += P[3 * I[3 * t + k] + a] / 3;
  return c;
}

/** Scalp triangles of `mask` (by edge adjacency) that share an edge with fewer than two others. */
function loneTriangles(mask: Uint8Array): number {
  const byEdge = new Map<string, number[]>();
  const I = mesh.indices;
  for (let t = 0; t < T; t++)
    for (let k = 0; k < 3; k++) {
      const a = I[3 * t + k];
      const b = I[3 * t + ((k + 1) % 3)];
      const key = `${Math.min(a, b)},${Math.max(a, b)}`;
      byEdge.set(key, [...(byEdge.get(key) ?? []), t]);
    }
  const count = new Uint8Array(T);
  for (const tris of byEdge.values())
    if (tris.length === 2 && mask[tris[0]] && mask[tris[1]]) {
      count[tris[0]]++;
      count[tris[1]]++;
    }
  let lone = 0;
  for (let t = 0; t < T; t++) if (mask[t] && count[t] < 2) lone++;
  return lone;
}

// An erase round the crown (a ring 12° from the top, brush 1.5 cm) leaves a scrap of about
// 1 cm² inside it; two parallel passes 2.3 cm apart (brush 1.1 cm) leave a sliver between.
const ring: ScalpPaintStroke = {
  erase: true,
  radius: 0.15,
  points: Array.from({ length: 25 }, (_, i) => surface(12, i * 15)),
};
const passes: ScalpPaintStroke[] = [-1, 1].map((side) => ({
  erase: true,
  radius: 0.11,
  points: Array.from({ length: 9 }, (_, i) => {
    const p = surface(40 + i * 5, 90);
    return [p[0], p[1], p[2] + side * 0.115] as Vec3;
  }),
}));

describe('sessionScalpMask with finished edges', () => {
  it('starts the built-in head from its natural hairline: lower round the ears and at the nape', () => {
    const classic = sessionScalpMask(mesh, mesh.scalp, [], 'classic');
    expect(classic).toEqual(mesh.scalp);
    const finished = sessionScalpMask(mesh, mesh.scalp, [], 'natural');
    expect(finished).toEqual(natural);
    let added = 0;
    let lowest = Number.POSITIVE_INFINITY;
    for (let t = 0; t < T; t++) {
      expect(finished[t] >= mesh.scalp[t]).toBe(true); // it only adds
      if (finished[t] && !mesh.scalp[t]) {
        added++;
        lowest = Math.min(lowest, centroid(t)[1]);
      }
    }
    expect(added).toBeGreaterThan(500);
    // the nape's hairline reaches below the ear's middle (y = -0.25), the classic one stops above
    expect(lowest).toBeLessThan(-0.4);
  });

  it('with a low nape goes on down the upper neck behind the ears, and is the natural one elsewhere', () => {
    const low = sessionScalpMask(mesh, mesh.scalp, [], 'lowNape');
    expect(low).toEqual(mesh.lowNapeScalp);
    let lowestNatural = Number.POSITIVE_INFINITY;
    let lowestLow = Number.POSITIVE_INFINITY;
    let added = 0;
    for (let t = 0; t < T; t++) {
      const c = centroid(t);
      expect(low[t] >= natural[t]).toBe(true); // it only adds
      if (natural[t]) lowestNatural = Math.min(lowestNatural, c[1]);
      if (low[t]) lowestLow = Math.min(lowestLow, c[1]);
      if (low[t] && !natural[t]) {
        added++;
        // only behind the ears (|φ| > 100°, seen from the scalp's centre, the origin) and never
        // on or within 8 mm of an ear
        expect(Math.abs(Math.atan2(c[0], c[2])) * (180 / Math.PI)).toBeGreaterThan(100);
        expect(earDistance(c[0], c[1], c[2])).toBeGreaterThanOrEqual(0.08);
      }
    }
    expect(added).toBeGreaterThan(300);
    // 3 cm or more further down the neck at the back than the natural nape (at -0.6)
    expect(lowestLow).toBeLessThan(lowestNatural - 0.3);
  });

  it('leaves no scrap or sliver an erase cut off, and touches nothing away from it', () => {
    const strokes = [ring, ...passes];
    const plain = applyScalpPaint(mesh, natural, strokes);
    const finished = sessionScalpMask(mesh, mesh.scalp, strokes, 'natural');
    // what the brush alone leaves: the scrap inside the ring and lone triangles between passes
    const top = surface(0, 0);
    let scrap = 0;
    for (let t = 0; t < T; t++) {
      const c = centroid(t);
      if (plain[t] && Math.hypot(c[0] - top[0], c[1] - top[1], c[2] - top[2]) < 0.1) scrap++;
    }
    expect(scrap).toBeGreaterThan(0);
    expect(loneTriangles(plain)).toBeGreaterThan(0);
    // finished: none of either
    for (let t = 0; t < T; t++) {
      const c = centroid(t);
      if (Math.hypot(c[0] - top[0], c[1] - top[1], c[2] - top[2]) < 0.1)
        expect(finished[t]).toBe(0);
    }
    expect(loneTriangles(finished)).toBe(loneTriangles(natural));
    // it only takes away, and only scalp within 3 cm of an erase
    const near = new Uint8Array(T);
    for (const s of strokes)
      applyScalpPaint(mesh, near, [{ ...s, erase: false, radius: s.radius + 0.3 }]).forEach(
        (v, t) => {
          if (v) near[t] = 1;
        },
      );
    for (let t = 0; t < T; t++) {
      expect(finished[t] <= plain[t]).toBe(true);
      if (!near[t]) expect(finished[t]).toBe(plain[t]);
    }
  });

  it('painting the erased part back gives the mask as it was, exactly', () => {
    const strokes = [ring, ...passes];
    const back = strokes.map((s) => ({ ...s, erase: false }));
    expect(sessionScalpMask(mesh, mesh.scalp, [...strokes, ...back], 'natural')).toEqual(
      applyScalpPaint(mesh, natural, [...strokes, ...back]),
    );
    // an erase of part of the hairline painted back: the natural scalp again
    const dab: ScalpPaintStroke = { erase: true, radius: 0.2, points: [surface(60, 0)] };
    expect(sessionScalpMask(mesh, mesh.scalp, [dab, { ...dab, erase: false }], 'natural')).toEqual(
      applyScalpPaint(mesh, natural, [dab, { ...dab, erase: false }]),
    );
  });
});
