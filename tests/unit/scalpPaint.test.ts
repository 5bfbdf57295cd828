// The scalp brush: the indexed stroke coverage against a brute-force scan of every triangle
// centroid, strokes applied in order, and the default mask left alone.
import { describe, expect, it } from 'vitest';
import { buildHead } from '../../web/head/buildHead';
import { applyScalpPaint, forEachCovered, type ScalpPaintStroke } from '../../web/head/scalpPaint';
import type { Vec3 } from '../../web/model/vec3';
import {
  createHeadMesh,
  headVertexColors,
  paintHeadTriangles,
} from '../../web/viewer/headMaterial';

const mesh = buildHead();
const T = mesh.indices.length / 3;

function centroid(t: number): Vec3 {
  const { positions: P, indices: I } = mesh;
  const c: Vec3 = [0, 0, 0];
  for (let k = 0; k < 3; k++) for (let a = 0; a < 3; a++) c[a] += P[3 * I[3 * t + k] + a] / 3;
  return c;
}

/** Brute force: distance from c to the polyline, by dense sampling of every segment. */
function nearPolyline(c: Vec3, pts: readonly Vec3[], r: number): boolean {
  const segs = Math.max(1, pts.length - 1);
  let best = Infinity;
  for (let s = 0; s < segs; s++) {
    const a = pts[s];
    const b = pts[Math.min(s + 1, pts.length - 1)];
    for (let k = 0; k <= 100; k++) {
      const u = k / 100;
      const q = [0, 1, 2].map((i) => a[i] + u * (b[i] - a[i]));
      best = Math.min(best, Math.hypot(c[0] - q[0], c[1] - q[1], c[2] - q[2]));
    }
  }
  // sampling error at most half a sample spacing: decide only clear cases
  return best <= r;
}

describe('applyScalpPaint', () => {
  const stroke: ScalpPaintStroke = {
    erase: false,
    radius: 0.15,
    points: [
      [0.2, 0.5, 0.8],
      [0.5, 0.2, 0.8],
      [0.8, -0.2, 0.5],
    ],
  };

  it('paints exactly the triangles whose centroid is within the radius (brute force)', () => {
    const none = new Uint8Array(T);
    const painted = applyScalpPaint(mesh, none, [stroke]);
    let count = 0;
    for (let t = 0; t < T; t++) {
      const c = centroid(t);
      const ref = nearPolyline(c, stroke.points, stroke.radius);
      // brute force samples the segment every ~5 mm: skip centroids right on the boundary
      const margin =
        nearPolyline(c, stroke.points, stroke.radius + 0.006) !== ref ||
        nearPolyline(c, stroke.points, stroke.radius - 0.006) !== ref;
      if (!margin) expect(painted[t], `triangle ${t}`).toBe(ref ? 1 : 0);
      count += painted[t];
    }
    expect(count).toBeGreaterThan(50);
    expect(none.every((v) => v === 0)).toBe(true);
  });

  it('erase after paint removes, and order matters', () => {
    const erase: ScalpPaintStroke = { ...stroke, erase: true, radius: 0.08 };
    const a = applyScalpPaint(mesh, new Uint8Array(T), [stroke, erase]);
    const b = applyScalpPaint(mesh, new Uint8Array(T), [erase, stroke]);
    const onlyPaint = applyScalpPaint(mesh, new Uint8Array(T), [stroke]);
    let removed = 0;
    for (let t = 0; t < T; t++) {
      if (onlyPaint[t] && !a[t]) removed++;
      expect(a[t]).toBeLessThanOrEqual(onlyPaint[t]);
    }
    expect(removed).toBeGreaterThan(10);
    expect(b).toEqual(onlyPaint);
  });

  it('a dab (one point) covers a ball; erasing the default scalp leaves the rest', () => {
    const top: Vec3 = [0, 1, 0];
    const erased = applyScalpPaint(mesh, mesh.scalp, [{ erase: true, radius: 0.3, points: [top] }]);
    for (let t = 0; t < T; t++) {
      const c = centroid(t);
      const d = Math.hypot(c[0] - top[0], c[1] - top[1], c[2] - top[2]);
      if (d < 0.299) expect(erased[t]).toBe(0);
      if (d > 0.301) expect(erased[t]).toBe(mesh.scalp[t]);
    }
  });

  it('painting a stroke segment by segment recolours the head as a full recolour does', () => {
    const head = { ...buildHead(), scalp: buildHead().scalp.slice() };
    const view = createHeadMesh(head);
    const pts = stroke.points;
    for (let k = 1; k < pts.length; k++) {
      const covered: number[] = [];
      forEachCovered(head, { ...stroke, points: pts.slice(k - 1, k + 1) }, (t) => covered.push(t));
      paintHeadTriangles(view, head, covered, 1);
    }
    const erased: number[] = [];
    forEachCovered(head, { erase: true, radius: 0.3, points: [[0, 1, 0]] }, (t) => erased.push(t));
    paintHeadTriangles(view, head, erased, 0);
    // the mask is what applyScalpPaint gives, and the colours what a full pass gives
    expect(head.scalp).toEqual(
      applyScalpPaint(mesh, mesh.scalp, [
        stroke,
        { erase: true, radius: 0.3, points: [[0, 1, 0]] },
      ]),
    );
    const full = headVertexColors(head);
    const shown = view.geometry.getAttribute('color').array as Float32Array;
    let worst = 0;
    for (let i = 0; i < full.length; i++) worst = Math.max(worst, Math.abs(full[i] - shown[i]));
    expect(worst).toBeLessThan(1e-6);
  });
});
