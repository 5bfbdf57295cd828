// A stream curve drawn in a side view along the head's middle is put on it (web/app/streamOnMiddle.ts):
// the points that lay on the head are put back on it in the middle plane, checked against the
// head's own signed distance; drawn from the front, or far from the middle, it stays as drawn.
import { describe, expect, it } from 'vitest';
import { streamOnMiddle } from '../../web/app/streamOnMiddle';
import { Head } from '../../web/head/head';
import { X_PLANE } from '../../web/model/mirror';
import type { Vec3 } from '../../web/model/vec3';

const head = Head.builtin();

/** A crest over the top from the forehead back, `x` off the middle, on the head: the outermost
 *  head point straight below each of a row of points above it. */
function crest(x: number): Vec3[] {
  const pts: Vec3[] = [];
  for (let z = 0.6; z >= -0.8; z -= 0.2) {
    const hit = head.raycast([x, 3, z], [0, -1, 0]);
    if (hit) pts.push(hit.point);
  }
  return pts;
}

describe('streamOnMiddle', () => {
  const side: Vec3 = [-1, -0.1, 0]; // looking along -x: the left view
  const front: Vec3 = [0, -0.1, -1];

  it('puts a crest drawn 3 cm off the middle in a side view on the middle, on the head', () => {
    const drawn = crest(0.3);
    expect(drawn.length).toBeGreaterThan(4);
    for (const p of drawn) expect(Math.abs(head.signedDistance(p))).toBeLessThan(0.01);
    const lifted: Vec3 = [0.3, drawn[drawn.length - 1][1] + 0.3, drawn[drawn.length - 1][2]];
    const r = streamOnMiddle([...drawn, lifted], X_PLANE, side, head);
    expect(r.snapped).toBe(true);
    for (const [i, p] of r.points.entries()) {
      expect(p[0]).toBeCloseTo(0, 9);
      // on the head where it was drawn on the head (within a millimetre), off it where it was off
      if (i < drawn.length) expect(Math.abs(head.signedDistance(p))).toBeLessThan(0.01);
    }
    // the point past the scalp keeps its place in the plane
    expect(r.points[r.points.length - 1]).toEqual([0, lifted[1], lifted[2]]);
  });

  it('leaves it as drawn from the front, 6 cm off the middle, or pressed inside the outline', () => {
    const drawn = crest(0.3);
    const a = streamOnMiddle(drawn, X_PLANE, front, head);
    expect(a.snapped).toBe(false);
    expect(a.points).toBe(drawn);
    const far = crest(0.6);
    expect(streamOnMiddle(far, X_PLANE, side, head).snapped).toBe(false);
    // pressed inside the outline (the surface there faces the side view more than across it),
    // though within the side view's 4 cm of the middle: meant where it is (a bob's side stroke)
    const inside = crest(0.38);
    const n = head.normalAt(inside[0]);
    expect(Math.abs(n[0])).toBeGreaterThan(0.55);
    expect(streamOnMiddle(inside, X_PLANE, side, head).snapped).toBe(false);
  });

  it('leaves a lock drawn from the top of the outline down in front of the face where it is drawn', () => {
    // fresh eyes round 18: pressed just inside the top of the outline in a side view and drawn
    // forward and down past the face, it was put on the middle and hung over the nose. The same
    // press drawn up and back (a crest's spike) is still put on the middle
    const top = crest(0.3).slice(0, 3);
    const front = top[0];
    const down: Vec3[] = [1, 2, 3, 4].map((k) => [0.3, front[1] - 0.4 * k, front[2] + 0.6]);
    for (const p of down) expect(head.signedDistance(p)).toBeGreaterThan(0.05);
    const lock = streamOnMiddle([...top, ...down], X_PLANE, side, head);
    expect(lock.snapped).toBe(false);
    const up: Vec3[] = [1, 2].map((k) => [0.3, top[2][1] + 0.3 * k, top[2][2] - 0.2 * k]);
    expect(streamOnMiddle([...top, ...up], X_PLANE, side, head).snapped).toBe(true);
  });

  it("puts a crest's front spike, pressed at the front hairline and drawn forward, on the middle", () => {
    // fresh eyes' mohawk: spikes pressed on the outline at the front hairline (below the face's
    // top, 5 cm above the head's centre) and drawn forward, drooping a little, were taken for
    // locks hanging past the face and left 1 to 3 cm off the middle (5 of 16, 3 of 18)
    let from: Vec3 | null = null;
    for (let y = 0.3; y < 0.8 && !from; y += 0.01) {
      const hit = head.raycast([0.1, y, 3], [0, 0, -1]);
      if (hit?.scalp) from = hit.point;
    }
    if (!from) throw new Error('no scalp at the front');
    const start = from;
    const spike: Vec3[] = [1, 2, 3, 4].map((k) => [0.1, start[1] - 0.04 * k, start[2] + 0.3 * k]);
    for (const p of spike) expect(head.signedDistance(p)).toBeGreaterThan(0.05);
    // its tip below the face's top: a lock past the face by height alone
    expect(spike[3][1]).toBeLessThan(head.center[1] + 0.5);
    const r = streamOnMiddle([start, ...spike], X_PLANE, side, head);
    expect(r.snapped).toBe(true);
    for (const p of r.points) expect(p[0]).toBeCloseTo(0, 9);
  });

  it('with Mirror on, puts a stroke within 1.5 cm of the middle on it from any view', () => {
    // a crest 1 cm off the middle, drawn from the front: as drawn without Mirror, on the middle
    // (on the head) with it
    const drawn = crest(0.1);
    expect(streamOnMiddle(drawn, X_PLANE, front, head).snapped).toBe(false);
    const r = streamOnMiddle(drawn, X_PLANE, front, head, true);
    expect(r.snapped).toBe(true);
    for (const p of r.points) {
      expect(p[0]).toBeCloseTo(0, 9);
      expect(Math.abs(head.signedDistance(p))).toBeLessThan(0.01);
    }
    // 3 cm off, or a parting's stroke from the middle out to the side: its twin is meant
    expect(streamOnMiddle(crest(0.3), X_PLANE, front, head, true).snapped).toBe(false);
    const out = crest(0.05).map((p, i): Vec3 => {
      const hit = head.raycast([0.05 + 0.12 * i, 3, p[2]], [0, -1, 0]);
      return hit ? hit.point : p;
    });
    expect(Math.abs(out[0][0])).toBeLessThan(0.15);
    expect(streamOnMiddle(out, X_PLANE, front, head, true).snapped).toBe(false);
  });
});
