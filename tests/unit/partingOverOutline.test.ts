// A parting drawn up to the head's outline is carried on over it (web/app/partingOverOutline.ts):
// checked on the built-in head against its own geometry (normals, scalp flags), independently of
// the tool: the half-up parting of the user guide drawn from above ends on the outline above each
// ear, where the surface faces sideways.
import { describe, expect, it } from 'vitest';
import { partingOverOutline } from '../../web/app/partingOverOutline';
import { Head } from '../../web/head/head';
import type { Vec3 } from '../../web/model/vec3';

const head = Head.builtin();
const step = 0.127;
const down: Vec3 = [0, -1, 0]; // the top view looks down
const front: Vec3 = [0, -0.1, -1];

/** Round the back of the crown from the outline above one ear (seen from above: the outermost
 *  head point along x at each height) to the other: the head point straight out from the centre
 *  at each angle, at the height of the widest part. */
function halfUpParting(): Vec3[] {
  const c = head.center;
  const pts: Vec3[] = [];
  for (let a = -90; a <= 90; a += 10) {
    const r = (a * Math.PI) / 180;
    // outwards from above the centre: x sideways, z backwards (-z) round the back
    const dir: Vec3 = [Math.sin(r), 0.55 * Math.cos(Math.abs(r)) ** 4, -Math.cos(r)];
    const hit = head.raycast(
      [c[0] + 4 * dir[0], c[1] + 0.35 + 4 * dir[1], c[2] + 4 * dir[2]],
      [-dir[0], -dir[1], -dir[2]],
    );
    if (hit) pts.push(hit.point);
  }
  return pts;
}

describe('partingOverOutline', () => {
  it('carries the ends drawn up to the outline on over it, down the sides to the scalp edge', () => {
    const drawn = halfUpParting();
    expect(drawn.length).toBeGreaterThan(10);
    // the ends face across the top view (on its outline)
    for (const e of [drawn[0], drawn[drawn.length - 1]])
      expect(Math.abs(head.normalAt(e)[1])).toBeLessThan(0.35);
    const r = partingOverOutline(drawn, down, head, step);
    expect(r.carried).toBe(true);
    const first = r.points[0];
    const last = r.points[r.points.length - 1];
    for (const [end, was] of [
      [first, drawn[0]],
      [last, drawn[drawn.length - 1]],
    ]) {
      // lower (over the outline, away from the viewer above), on the head, at most 4 cm on
      expect(end[1]).toBeLessThan(was[1] - 0.15);
      expect(head.closest(end).distance).toBeLessThan(0.005);
      expect(Math.hypot(end[0] - was[0], end[1] - was[1], end[2] - was[2])).toBeLessThan(
        0.4 + step,
      );
    }
    // the drawn part is kept as drawn
    expect(
      r.points.slice(r.points.indexOf(drawn[0]), r.points.indexOf(drawn[0]) + drawn.length),
    ).toEqual(drawn);
  });

  it('carries ends that stop a few pixels inside the outline on too, up to 5 cm', () => {
    // a later new user's half-up stopped where the surface was 23-25 degrees from facing across
    // the top view (|n . view| 0.39 and 0.42): the parting stayed open. The drawn parting cut at
    // its points nearest 0.42 from each end: carried on over; cut where |n . view| is above 0.5
    // (nearer the crown): left as drawn.
    const drawn = halfUpParting();
    const facing = (p: Vec3) => Math.abs(head.normalAt(p)[1]);
    const cutAt = (from: number, to: number) => {
      // the points from each end inward until the surface faces the view by at least `from`
      const n = drawn.length;
      let a = 0;
      let b = n - 1;
      while (a < n && facing(drawn[a]) < from) a++;
      while (b > 0 && facing(drawn[b]) < from) b--;
      const part = drawn.slice(a, b + 1);
      for (const e of [part[0], part[part.length - 1]]) expect(facing(e)).toBeLessThan(to);
      return part;
    };
    const near = cutAt(0.36, 0.5);
    const r = partingOverOutline(near, down, head, step);
    expect(r.carried).toBe(true);
    for (const [end, was] of [
      [r.points[0], near[0]],
      [r.points[r.points.length - 1], near[near.length - 1]],
    ]) {
      expect(end[1]).toBeLessThan(was[1] - 0.15);
      expect(head.closest(end).distance).toBeLessThan(0.005);
      expect(Math.hypot(end[0] - was[0], end[1] - was[1], end[2] - was[2])).toBeLessThan(
        0.5 + step,
      );
    }
    const inner = cutAt(0.55, 1);
    expect(partingOverOutline(inner, down, head, step).carried).toBe(false);
  });

  it('leaves a parting whose ends face the viewer as drawn', () => {
    const drawn = halfUpParting();
    // from above, the crown's middle part alone: its ends face up
    const mid = drawn.slice(6, 13);
    const r = partingOverOutline(mid, down, head, step);
    expect(r.carried).toBe(false);
    expect(r.points).toBe(mid);
    // from the front the back of the crown faces away from the viewer: the ends are not on the
    // outline either
    expect(partingOverOutline(mid, front, head, step).carried).toBe(false);
  });
});
