// "Longer" / "Shorter" (model/lengthen.ts): stroke ends that end hair move on by the amount asked,
// falling as hair past a cut falls, or are cut back; the maximum length moves with them; other
// curves are left alone. Lengths and directions worked out by hand.
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { applyCommand } from '../../web/editor/commands';
import { Head } from '../../web/head/head';
import { endsAsFringe, lengthenSession } from '../../web/model/lengthen';
import { emptySession, type StyleCurve } from '../../web/model/session';
import type { Vec3 } from '../../web/model/vec3';

const head = Head.builtin();
const arc = (p: readonly Vec3[]) =>
  p.slice(1).reduce((L, q, i) => L + Math.hypot(q[0] - p[i][0], q[1] - p[i][1], q[2] - p[i][2]), 0);
const vp = { position: [0, 0, 5] as Vec3, target: [0, 0, 0] as Vec3 };
const stroke = (points: Vec3[], extend = false): StyleCurve => ({
  id: `c${points.length}${extend}`,
  type: 'stream',
  points,
  extend,
  viewpoint: vp,
  volume: 0,
});

describe('lengthenSession', () => {
  it('carries a stroke on past its end, turning half-way to straight down at every 1 cm', () => {
    const s = {
      ...emptySession('25k'),
      curves: [
        stroke([
          [1, 0.5, 0],
          [1, 0, 0],
        ]),
        stroke([
          [0.5, 0.5, 0.5],
          [0.6, 0.5, 0.5],
        ]),
        stroke(
          [
            [0, 1, 0],
            [0, 0.5, -1],
          ],
          true,
        ),
      ],
    };
    const r = lengthenSession(s, 0.3);
    expect(r.strokes).toBe(2);
    // straight down stays straight down: 3 cm lower
    const down = r.session.curves[0].points;
    expect(down.length).toBe(5);
    expect(down[4][1]).toBeCloseTo(-0.3, 3);
    expect(down[4][0]).toBeCloseTo(1, 3);
    // level (+x): the first step at 45° down, the second at 67.5°, the third at 78.75°
    const level = r.session.curves[1].points;
    const angles = [45, 67.5, 78.75].map((a) => (a * Math.PI) / 180);
    let [x, y] = [0.6, 0.5];
    for (const a of angles) {
      x += 0.1 * Math.cos(a);
      y -= 0.1 * Math.sin(a);
    }
    expect(level[4][0]).toBeCloseTo(x, 3);
    expect(level[4][1]).toBeCloseTo(y, 3);
    // a curve whose hair grows on is left, and the maximum length rises with the ends
    expect(r.session.curves[2]).toEqual(s.curves[2]);
    expect(r.session.growth.maxLength).toBeCloseTo(s.growth.maxLength + 0.3, 6);
  });

  it("moves every bob stroke's end by the amount, on and back, and leaves the fringe", () => {
    const bob = presetSession('bob', head, '25k', 0);
    // the bob's fringe: seven strokes ending at the eyebrows (y = 0.06), in front of the face
    const isFringe = (c: StyleCurve) => Math.abs((c.points.at(-1)?.[1] ?? 0) - 0.06) < 0.02;
    const fringe = bob.curves.filter(isFringe);
    expect(fringe.length).toBe(7);
    expect(fringe.every((c) => endsAsFringe(c.points[c.points.length - 1]))).toBe(true);
    const ends = bob.curves.filter((c) => c.type === 'stream' && !c.extend && !isFringe(c));
    expect(ends.length).toBeGreaterThan(4);
    expect(ends.some((c) => endsAsFringe(c.points[c.points.length - 1]))).toBe(false);
    const longer = lengthenSession(bob, 0.5);
    expect(longer.strokes).toBe(ends.length);
    bob.curves.forEach((c, i) => {
      const after = longer.session.curves[i];
      if (c.type !== 'stream' || c.extend || isFringe(c)) expect(after).toEqual(c);
      else {
        expect(arc(after.points) - arc(c.points)).toBeCloseTo(0.5, 2);
        expect(after.points.at(-1)?.[1]).toBeLessThan(c.points.at(-1)?.[1] ?? 0);
      }
    });
    // and back: each stroke its own length again
    const back = lengthenSession(longer.session, -0.5);
    bob.curves.forEach((c, i) => {
      expect(arc(back.session.curves[i].points)).toBeCloseTo(arc(c.points), 2);
    });
    expect(back.session.growth.maxLength).toBeCloseTo(bob.growth.maxLength, 6);
    // a stroke shorter than 2 cm after the cut is left as it is
    const tiny = {
      ...emptySession('25k'),
      curves: [
        stroke([
          [1, 0, 0],
          [1, -0.25, 0],
        ]),
      ],
    };
    expect(lengthenSession(tiny, -0.1).strokes).toBe(0);
    expect(arc(lengthenSession(tiny, -0.04).session.curves[0].points)).toBeCloseTo(0.21, 3);
    // the status says what changed: the cap only (a new user read "shortened by 23 cm: 0 stroke
    // ends moved" as a fault), or the strokes with it
    const max = tiny.growth.maxLength * 10;
    expect(applyCommand(tiny, { kind: 'lengthen', by: -0.1 }).message).toBe(
      `Max length ${max - 1} cm (was ${max} cm): hair no stroke ends grows to at most that; no stroke's end moved.`,
    );
    expect(applyCommand(tiny, { kind: 'lengthen', by: 0.1 }).message).toBe(
      `Hair lengthened by 1 cm: 1 stroke end moved, Max length ${max + 1} cm.`,
    );
  });
});
