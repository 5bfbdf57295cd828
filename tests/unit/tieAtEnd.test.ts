// A stream stroke that ends at a tie continues into it (session.ts tieAtEnd, streamExtends):
// distances worked out by hand against a ponytail's start, a braid's start and a bun's loop.

import { describe, expect, it } from 'vitest';
import { defaultParams } from '../../web/model/curveParams';
import { type StyleCurve, streamExtends, tieAtEnd } from '../../web/model/session';
import type { Vec3 } from '../../web/model/vec3';

const vp = { position: [0, 0, 5] as Vec3, target: [0, 0, 0] as Vec3 };
const braid: StyleCurve = {
  id: 'b',
  type: 'braid',
  points: [
    [0.5, 0, -0.8],
    [0.6, -1, -0.8],
  ],
  extend: false,
  viewpoint: vp,
  ...defaultParams('braid'),
};
const bun: StyleCurve = {
  id: 'u',
  type: 'bun',
  points: [
    [0.2, 1, 0],
    [0, 1, 0.2],
    [-0.2, 1, 0],
    [0, 1, -0.2],
  ],
  extend: false,
  viewpoint: vp,
  ...defaultParams('bun'),
};
const stream: StyleCurve = {
  id: 's',
  type: 'stream',
  points: [
    [0, 0.5, 0.9],
    [0.5, 0, -0.8],
  ],
  extend: false,
  viewpoint: vp,
};

describe('tieAtEnd', () => {
  it('finds the tie within 3 cm of the end, the nearest of several, and nothing farther', () => {
    const curves = [stream, braid, bun];
    expect(tieAtEnd(curves, [0.5, 0.2, -0.8])?.id).toBe('b'); // 2 cm above the braid's start
    expect(tieAtEnd(curves, [0.5, 0.35, -0.8])).toBeNull(); // 3.5 cm: too far
    expect(tieAtEnd(curves, [0.6, -1, -0.8])).toBeNull(); // the braid's end is not its tie
    expect(tieAtEnd(curves, [0, 1.1, -0.3])?.id).toBe('u'); // 1.4 cm from the bun's loop
    expect(tieAtEnd([stream], [0, 0.5, 0.9])).toBeNull(); // a stream curve is no tie
  });

  it('turns "Extend past the end" on for a stroke into a tie, with natural fall', () => {
    const s = { fall: true, curves: [braid] };
    expect(
      streamExtends(s, [
        [0, 0.8, 0.5],
        [0.5, 0.1, -0.8],
      ]),
    ).toBe(true);
    expect(
      streamExtends(s, [
        [0, 0.8, 0.5],
        [0.5, 0.6, -0.8],
      ]),
    ).toBe(false);
    // without natural fall every new curve extends (the paper's method)
    expect(streamExtends({ fall: false, curves: [] }, [[0, 0, 1]])).toBe(true);
  });
});
