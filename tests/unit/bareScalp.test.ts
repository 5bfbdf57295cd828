// bareScalp against hand-made scalps and hair: a flat square of scalp seen from the front with
// hair lines over all of it but a hole in the middle (the hole is bare where hair should be; the
// open square without hair is bare, but not where hair should be); sparse lines cover with the
// stricter minOpacity only where they fill the cells; hair behind the scalp hides nothing; head
// triangles in front of the scalp take its points out of the view; the built-in head gives
// points from every view.
import { describe, expect, it } from 'vitest';
import { type BareScalpHair, type BareScalpMesh, bareScalp } from '../../web/app/bareScalp';
import { Head } from '../../web/head/head';

const FRONT = [{ name: 'front', toViewer: [0, 0, 1] as [number, number, number] }];
const BACK = [{ name: 'back', toViewer: [0, 0, -1] as [number, number, number] }];

/** An n × n grid of squares (two triangles each, counter-clockwise seen from +z) covering
 *  [-h, h]² at depth z, every triangle scalp (or none). */
function square(h: number, n: number, z: number, scalp = 1): BareScalpMesh {
  const positions: number[] = [];
  const indices: number[] = [];
  for (let j = 0; j <= n; j++)
    for (let i = 0; i <= n; i++) positions.push(-h + (2 * h * i) / n, -h + (2 * h * j) / n, z);
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++) {
      const v = j * (n + 1) + i;
      indices.push(v, v + 1, v + n + 2, v, v + n + 2, v + n + 1);
    }
  return { positions, indices, scalp: new Array(2 * n * n).fill(scalp) };
}

/** Both meshes in one (the second's vertices after the first's). */
function join(p: BareScalpMesh, q: BareScalpMesh): BareScalpMesh {
  const nv = p.positions.length / 3;
  return {
    positions: [...Array.from(p.positions), ...Array.from(q.positions)],
    indices: [...Array.from(p.indices), ...Array.from(q.indices).map((i) => i + nv)],
    scalp: [...Array.from(p.scalp), ...Array.from(q.scalp)],
  };
}

/** Strands along x every `spacing` in y over [-h, h]² at depth z, leaving out |x|, |y| < hole. */
function combed(h: number, spacing: number, z: number, hole: number): BareScalpHair {
  const points: number[] = [];
  const strandStart = [0];
  const run = (y: number, x0: number, x1: number) => {
    for (let x = x0; x <= x1 + 1e-9; x += 0.025) points.push(x, y, z);
    strandStart.push(points.length / 3);
  };
  for (let y = -h; y <= h + 1e-9; y += spacing) {
    if (Math.abs(y) < hole) {
      run(y, -h, -hole);
      run(y, hole, h);
    } else run(y, -h, h);
  }
  return { points, strandStart };
}

describe('bareScalp', () => {
  const scalp = square(0.5, 100, 0); // 10 cm across, triangles of 1 mm
  const hole = 0.06; // a 12 mm hole in the hair

  it('counts a hole in hair that covers the rest of the scalp as bare where hair should be', () => {
    const hair = combed(0.5, 0.005, 0.01, hole);
    const r = bareScalp(scalp, hair, FRONT, { keepPoints: true });
    const v = r.views[0];
    expect(v.points).toBe(2 * 100 * 100);
    expect(v.bareWhereHair).toBeGreaterThan(0);
    // the bare points are in the hole, and every uncovered point is bare where hair should be
    const at = v.bareAt ?? [];
    expect(at.length).toBe(3 * v.bareWhereHair);
    for (let k = 0; k < at.length; k += 3) {
      expect(Math.abs(at[k])).toBeLessThan(hole);
      expect(Math.abs(at[k + 1])).toBeLessThan(hole);
    }
    expect(v.bareWhereHair).toBe(v.points - v.covered);
    // the middle of the hole, farther than a cell and a half from hair, is bare
    expect(v.bareWhereHair).toBeGreaterThanOrEqual(2 * 4 * 4);
    expect(v.bareWhereHair).toBeLessThan(2 * 12 * 12);
    expect(v.bareShare).toBeCloseTo(v.bareWhereHair / v.points, 12);
    expect(r.total).toEqual({
      points: v.points,
      covered: v.covered,
      bareWhereHair: v.bareWhereHair,
      coveredShare: v.coveredShare,
      bareShare: v.bareShare,
    });
  });

  it('without hair finds the scalp bare but none of it bare where hair should be', () => {
    for (const hair of [null, { points: [], strandStart: [0] }]) {
      const v = bareScalp(scalp, hair, FRONT).views[0];
      expect(v.points).toBe(20_000);
      expect(v.covered).toBe(0);
      expect(v.bareWhereHair).toBe(0);
    }
  });

  it('does not count hair behind the scalp, and sees no scalp from behind it', () => {
    const behind = combed(0.5, 0.005, -0.01, 0);
    const front = bareScalp(scalp, behind, FRONT).views[0];
    expect(front.covered).toBe(0);
    expect(front.bareWhereHair).toBe(0);
    const back = bareScalp(scalp, behind, BACK).views[0];
    expect(back.points).toBe(0);
    expect(back.bareShare).toBe(0);
  });

  it('with minOpacity, counts sparse hair as covering only where its lines fill the cell', () => {
    // lines 5 mm apart: a 0.5 mm line crossing a 2 mm cell fills about a quarter of it (opacity
    // under 0.5) and every other cell or so holds none; without minOpacity every point is covered
    const sparse = combed(0.5, 0.05, 0.01, 0);
    const any = bareScalp(scalp, sparse, FRONT).views[0];
    expect(any.covered).toBe(any.points);
    const strict = bareScalp(scalp, sparse, FRONT, { minOpacity: 0.5 }).views[0];
    expect(strict.covered).toBe(0);
    // lines 1 mm apart fill every cell (opacity 1 − e^−5 > 0.99) but the hole's
    const dense = combed(0.5, 0.001, 0.01, hole);
    const a = bareScalp(scalp, dense, FRONT).views[0];
    const b = bareScalp(scalp, dense, FRONT, { minOpacity: 0.9 }).views[0];
    expect(b.points - b.covered).toBeGreaterThanOrEqual(a.points - a.covered);
    expect(b.bareWhereHair).toBeGreaterThanOrEqual(a.bareWhereHair);
    expect(b.bareWhereHair).toBe(b.points - b.covered);
    // the hole and the cells across its border (up to two cells round it)
    expect(b.points - b.covered).toBeLessThan(2 * 20 * 20);
  });

  it('leaves out scalp that head triangles in front of it hide', () => {
    // a non-scalp square 1 cm in front of the middle of the scalp, 4 cm across
    const mesh = join(scalp, square(0.2, 20, 0.1, 0));
    const v = bareScalp(mesh, null, FRONT).views[0];
    // the hidden part, |x|, |y| < 0.2 give or take a cell
    const hidden = 20_000 - v.points;
    expect(hidden).toBeGreaterThan(2 * 36 * 36);
    expect(hidden).toBeLessThan(2 * 44 * 44);
  });

  it('sees the built-in head from the front, the side, the back and the top', () => {
    const head = Head.builtin();
    const r = bareScalp(head.mesh, null);
    expect(r.views.map((v) => v.view)).toEqual(['front', 'side', 'back', 'top']);
    for (const v of r.views) {
      expect(v.points).toBeGreaterThan(500);
      expect(v.bareWhereHair).toBe(0);
    }
    expect(r.total.points).toBe(r.views.reduce((n, v) => n + v.points, 0));
  });
});
