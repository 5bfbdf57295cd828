// The CPU reference of strands riding their guides (model/guideFollowers.ts), against hand values:
// at rest every point is its groom; a guide turned rigidly carries a follower near it with it as a
// rigid body would, and one far from it without turning; the head's pose moves a strand with no
// guide exactly as the pose says.
import { describe, expect, it } from 'vitest';
import {
  followerAttributes,
  type GuideBinding,
  guideTangents,
  placeFollowers,
} from '../../web/model/guideFollowers';

const IDENTITY = [1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0];

/** One guide hanging straight down from the origin (3 points, 1 apart), and two strands: one
 *  0.1 to its side along x, bound to it point for point, and one of a single point (no guide). */
function hanging(): {
  points: Float32Array;
  strandStart: Uint32Array;
  binding: GuideBinding;
} {
  return {
    points: new Float32Array([0.1, 0, 0, 0.1, -1, 0, 0.1, -2, 0, 0.5, 0.5, 0.5]),
    strandStart: new Uint32Array([0, 3, 4]),
    binding: {
      guideCount: 1,
      guidePoints: 3,
      guideRest: new Float32Array([0, 0, 0, 0, -1, 0, 0, -2, 0]),
      guideOf: new Int32Array([0, -1]),
      along: new Float32Array([0, 1, 2, 0]),
    },
  };
}

function expectClose(a: ArrayLike<number>, b: ArrayLike<number>, tol: number): void {
  expect(a.length).toBe(b.length);
  let worst = 0;
  for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
  expect(worst).toBeLessThan(tol);
}

describe('guide followers', () => {
  it('tangents: central differences, one-sided at the ends, unit length', () => {
    const t = guideTangents(new Float32Array([0, 0, 0, 0, -1, 0, 1, -1, 0]), 3);
    const h = Math.SQRT1_2;
    expectClose(t, [0, -1, 0, h, -h, 0, 1, 0, 0], 1e-7);
  });

  it("the attributes of some points are those points' attributes of all of them", () => {
    const { points, strandStart, binding } = hanging();
    const all = followerAttributes(points, strandStart, binding);
    const only = new Uint32Array([0, 2, 3]);
    const some = followerAttributes(points, strandStart, binding, only);
    only.forEach((p, i) => {
      expect(Array.from(some.follow.subarray(2 * i, 2 * i + 2))).toEqual(
        Array.from(all.follow.subarray(2 * p, 2 * p + 2)),
      );
      expect(Array.from(some.offset.subarray(3 * i, 3 * i + 3))).toEqual(
        Array.from(all.offset.subarray(3 * p, 3 * p + 3)),
      );
      expect(Array.from(some.tangent.subarray(3 * i, 3 * i + 3))).toEqual(
        Array.from(all.tangent.subarray(3 * p, 3 * p + 3)),
      );
    });
  });

  it('at rest, every point is its groom', () => {
    const { points, strandStart, binding } = hanging();
    const attrs = followerAttributes(points, strandStart, binding);
    const out = placeFollowers(points, attrs, binding.guideRest, 3, IDENTITY);
    expectClose(out, points, 1e-6);
  });

  it('a guide turned a quarter turn about z carries its follower as a rigid body', () => {
    const { points, strandStart, binding } = hanging();
    const attrs = followerAttributes(points, strandStart, binding);
    // the guide now points along +x: (x, y) -> (-y, x) of the rest
    const guides = new Float32Array([0, 0, 0, 1, 0, 0, 2, 0, 0]);
    const out = placeFollowers(points, attrs, guides, 3, IDENTITY);
    // the follower 0.1 along x of the guide is now 0.1 along y of it (hand values)
    expectClose(out.subarray(0, 9), [0, 0.1, 0, 1, 0.1, 0, 2, 0.1, 0], 1e-6);
    // the point with no guide rides the head, which has not moved
    expect(Array.from(out.subarray(9))).toEqual([0.5, 0.5, 0.5]);
  });

  it('a point far from its guide moves as the guide does without turning about it', () => {
    const { binding } = hanging();
    // 1 along x of the guide: past FOLLOW_TURN_FAR (a strand parted the other way)
    const points = new Float32Array([1, 0, 0, 1, -1, 0, 1, -2, 0]);
    const attrs = followerAttributes(points, new Uint32Array([0, 3]), {
      ...binding,
      guideOf: new Int32Array([0]),
    });
    const guides = new Float32Array([0, 0, 0, 1, 0, 0, 2, 0, 0]);
    const out = placeFollowers(points, attrs, guides, 3, IDENTITY);
    // each point is its guide point now plus its rest offset (hand values)
    expectClose(out, [1, 0, 0, 2, 0, 0, 3, 0, 0], 1e-6);
  });

  it('the head turned and the guide with it: every point turned and moved with the head', () => {
    const { points, strandStart, binding } = hanging();
    const attrs = followerAttributes(points, strandStart, binding);
    // 30 degrees about y, then moved by (1, 2, 3)
    const c = Math.cos(Math.PI / 6);
    const s = Math.sin(Math.PI / 6);
    const pose = [c, 0, s, 0, 1, 0, -s, 0, c, 1, 2, 3];
    const move = (p: ArrayLike<number>): number[] => {
      const out: number[] = [];
      for (let i = 0; i < p.length; i += 3)
        out.push(c * p[i] + s * p[i + 2] + 1, p[i + 1] + 2, -s * p[i] + c * p[i + 2] + 3);
      return out;
    };
    const guides = new Float32Array(move(binding.guideRest));
    const out = placeFollowers(points, attrs, guides, 3, pose);
    expectClose(out, move(points), 1e-6);
  });

  it('a point between guide points rides the guide where it is', () => {
    const { binding } = hanging();
    // one point halfway down the first segment, 0.2 along z of the guide
    const points = new Float32Array([0, -0.5, 0.2]);
    const attrs = followerAttributes(points, new Uint32Array([0, 1]), {
      ...binding,
      guideOf: new Int32Array([0]),
      along: new Float32Array([0.5]),
    });
    // the guide translated by (0, 0, 1): the point with it
    const guides = new Float32Array([0, 0, 1, 0, -1, 1, 0, -2, 1]);
    const out = placeFollowers(points, attrs, guides, 3, IDENTITY);
    expectClose(out, [0, -0.5, 1.2], 1e-6);
  });
});
