// method S4.2 against a sphere "scalp" (the whole sphere is scalp here), ray-traced by hand.
import { describe, expect, it } from 'vitest';
import { dot, normalize, sub, type Vec3 } from '../../web/model/vec3';
import { liftStroke, STROKE_MARGIN, type StrokeSample } from '../../web/tools/depthRule';

const R = 1;
const eye: Vec3 = [0, 0, 5];
const forward: Vec3 = [0, 0, -1];

function sphereHit(o: Vec3, d: Vec3): Vec3 | null {
  const b = dot(o, d);
  const c = dot(o, o) - R * R;
  const disc = b * b - c;
  if (disc < 0) return null;
  const t = -b - Math.sqrt(disc);
  return [o[0] + d[0] * t, o[1] + d[1] * t, o[2] + d[2] * t];
}

// A pointer sample through the image-plane point (x, y) at z = 4 (one unit in front of the eye).
function sample(x: number, y: number): StrokeSample {
  const direction = normalize(sub([x, y, 4], eye));
  return { origin: eye, direction, scalpHit: sphereHit(eye, direction) };
}

describe('liftStroke (S4.2 depth rule)', () => {
  it('rejects a stroke that does not start on the scalp', () => {
    expect(liftStroke([sample(0.5, 0.5), sample(0, 0)], eye, forward)).toEqual({
      ok: false,
      reason: 'not-on-scalp',
    });
    expect(liftStroke([], eye, forward).ok).toBe(false);
  });

  it('keeps points on the sphere while over it, then the depth of the last scalp point', () => {
    const xs = [0, 0.05, 0.1, 0.15, 0.19, 0.25, 0.3, 0.4];
    const lifted = liftStroke(
      xs.map((x) => sample(x, 0)),
      eye,
      forward,
    );
    if (!lifted.ok) throw new Error('expected ok');
    let lastScalpDepth = Number.NaN;
    xs.forEach((x, i) => {
      const p = lifted.points[i];
      const s = sample(x, 0);
      if (s.scalpHit) {
        expect(Math.hypot(...p)).toBeCloseTo(R, 12); // on the sphere
        lastScalpDepth = dot(sub(p, eye), forward);
      } else {
        // Off the sphere: same depth as the last scalp point, and on the pointer's ray.
        expect(dot(sub(p, eye), forward)).toBeCloseTo(lastScalpDepth, 12);
        const along = normalize(sub(p, eye));
        expect(dot(along, s.direction)).toBeCloseTo(1, 12);
      }
    });
    // Hand check: the sphere's silhouette seen from z = 5 is at image x = 1/sqrt(24) ≈ 0.204,
    // so 0.19 is the last point on it and 0.25, 0.3, 0.4 are off it.
    expect(sample(0.19, 0).scalpHit).not.toBeNull();
    expect(sample(0.25, 0).scalpHit).toBeNull();
    // Point at x = 0.4 on the plane at the last scalp depth: t = depth, position x = 0.4 * depth.
    const depth = dot(sub(lifted.points[4], eye), forward);
    expect(lifted.points[7][0]).toBeCloseTo(0.4 * (depth / 1) * (1 / 1), 10);
  });

  it('brings a point the depth rule puts inside the head to the margin in front of it', () => {
    // The scalp is the sphere's cap above y = 0.5; below it the sphere is "face": rays that hit
    // it carry its distance but no scalp hit. A stroke from the top down over the front: at the
    // last scalp depth the points below would lie inside the sphere.
    const over = (x: number, y: number): StrokeSample => {
      const direction = normalize(sub([x, y, 4], eye));
      const hit = sphereHit(eye, direction);
      const headDistance = hit ? Math.hypot(...sub(hit, eye)) : null;
      return { origin: eye, direction, scalpHit: hit && hit[1] > 0.5 ? hit : null, headDistance };
    };
    const ys = [0.16, 0.14, 0.12, 0.1, 0.08, 0.05, 0.02, -0.05];
    const lifted = liftStroke(
      ys.map((y) => over(0, y)),
      eye,
      forward,
    );
    if (!lifted.ok) throw new Error('expected ok');
    const bare = liftStroke(
      ys.map((y) => ({ ...over(0, y), headDistance: null })),
      eye,
      forward,
    );
    if (!bare.ok) throw new Error('expected ok');
    const bareDepth = (i: number) => Math.hypot(...sub(bare.points[i], eye));
    let moved = 0;
    ys.forEach((y, i) => {
      const p = lifted.points[i];
      const s = over(0, y);
      if (Math.hypot(...sub(p, bare.points[i])) > 1e-9) moved++;
      const r = Math.hypot(...p);
      if (s.scalpHit) expect(r).toBeCloseTo(R, 12);
      else if (s.headDistance !== null && s.headDistance !== undefined) {
        // at least STROKE_MARGIN in front of the sphere along the ray, exactly that when the
        // last scalp depth lies behind it
        const t = Math.hypot(...sub(p, eye));
        expect(t).toBeLessThanOrEqual(s.headDistance - STROKE_MARGIN + 1e-12);
        if (bareDepth(i) > s.headDistance - STROKE_MARGIN)
          expect(t).toBeCloseTo(s.headDistance - STROKE_MARGIN, 12);
        expect(r).toBeGreaterThan(R);
      } else expect(r).toBeGreaterThan(R); // past the silhouette: the plane of the last scalp point
    });
    // Without the head distance some of the same points are inside: the rule is what moved them.
    expect(Math.hypot(...bare.points[5])).toBeLessThan(R);
    expect(moved).toBeGreaterThanOrEqual(2);
  });
});

describe('liftStroke from a camera looking down (a lock drawn hanging)', () => {
  it('puts the off-head points on the vertical plane through the last scalp point', () => {
    // A side camera (looking along -x) pitched 25° down; the stroke starts on a scalp point and
    // runs straight down the screen past the head.
    const pitch = (25 * Math.PI) / 180;
    const forward: Vec3 = [-Math.cos(pitch), -Math.sin(pitch), 0];
    const eye: Vec3 = [5 * Math.cos(pitch), 5 * Math.sin(pitch), 0];
    const up: Vec3 = [-Math.sin(pitch), Math.cos(pitch), 0]; // the screen's up, square to forward
    const anchor: Vec3 = [0.2, 0.9, -0.6];
    const rayTo = (p: Vec3) => {
      const d = sub(p, eye);
      const n = Math.hypot(...d);
      return [d[0] / n, d[1] / n, d[2] / n] as Vec3;
    };
    // screen-vertical steps: points of the plane square to the view through the anchor
    const samples: StrokeSample[] = [{ origin: eye, direction: rayTo(anchor), scalpHit: anchor }];
    for (let k = 1; k <= 8; k++) {
      const p: Vec3 = [
        anchor[0] - 0.2 * k * up[0],
        anchor[1] - 0.2 * k * up[1],
        anchor[2] - 0.2 * k * up[2],
      ];
      samples.push({ origin: eye, direction: rayTo(p), scalpHit: null });
    }
    const r = liftStroke(samples, eye, forward);
    if (!r.ok) throw new Error('expected ok');
    // every point keeps the anchor's x (the level depth), so seen from the front or behind the
    // lock hangs plumb; the old rule (depth along the pitched view) moved it by up to 0.64
    for (const p of r.points) expect(p[0]).toBeCloseTo(anchor[0], 10);
    // and each stays on its own ray (where it was drawn in the drawing view)
    r.points.forEach((p, i) => {
      const d = rayTo(p);
      const s = samples[i].direction;
      expect(Math.hypot(d[0] - s[0], d[1] - s[1], d[2] - s[2])).toBeLessThan(1e-9);
    });
  });

  it('keeps depth along the view when looking nearly straight down', () => {
    const forward: Vec3 = [0, -1, 0];
    const eye: Vec3 = [0, 5, 0];
    const anchor: Vec3 = [0, 1, 0];
    const r = liftStroke(
      [
        { origin: eye, direction: [0, -1, 0], scalpHit: anchor },
        {
          origin: eye,
          direction: [0.1 / Math.hypot(0.1, 1), -1 / Math.hypot(0.1, 1), 0],
          scalpHit: null,
        },
      ],
      eye,
      forward,
    );
    if (!r.ok) throw new Error('expected ok');
    expect(r.points[1][1]).toBeCloseTo(1, 10);
  });

  it('drapes points over the head below the scalp on it when looking straight down', () => {
    // The unit sphere from above; its scalp is the cap above y = 0.5 (a crown), the rest is the
    // "forehead". A stroke from the crown outwards: past the cap the rays still hit the sphere,
    // lower down; each point lies STROKE_MARGIN in front of that hit along its ray (on the
    // sphere's surface within the margin), not level with the cap's edge in the air.
    const forward: Vec3 = [0, -1, 0];
    const eye: Vec3 = [0, 5, 0];
    const at = (x: number): StrokeSample => {
      const direction = normalize(sub([x, 4, 0], eye));
      const hit = sphereHit(eye, direction);
      const headDistance = hit ? Math.hypot(...sub(hit, eye)) : null;
      return { origin: eye, direction, scalpHit: hit && hit[1] > 0.5 ? hit : null, headDistance };
    };
    const xs = [0, 0.1, 0.17, 0.19, 0.195, 0.2, 0.203]; // the silhouette is at 1/sqrt(24) ≈ 0.204
    const r = liftStroke(xs.map(at), eye, forward);
    if (!r.ok) throw new Error('expected ok');
    let lastScalpHeight = Number.NaN;
    let draped = 0;
    xs.forEach((x, i) => {
      const s = at(x);
      const p = r.points[i];
      if (s.scalpHit) lastScalpHeight = s.scalpHit[1];
      if (s.scalpHit || s.headDistance == null) return;
      draped++;
      // along its ray, STROKE_MARGIN short of the sphere: hand value from the hit distance
      expect(Math.hypot(...sub(p, eye))).toBeCloseTo(s.headDistance - STROKE_MARGIN, 12);
      expect(Math.hypot(...p)).toBeGreaterThan(R);
      expect(Math.hypot(...p)).toBeLessThan(R + STROKE_MARGIN);
    });
    expect(draped).toBeGreaterThanOrEqual(3);
    // the last point: by hand, the ray (0.203, -1) meets the sphere at y ≈ 0.30; the level rule
    // would have held it at the last scalp point's height
    expect(r.points[xs.length - 1][1]).toBeLessThan(0.4);
    expect(lastScalpHeight).toBeGreaterThan(0.5);
  });

  it("a tie's spine over scalp deeper than its first point's keeps the first point's depth", () => {
    // from the front (eye on +z), pressed at x = 0.05 of the image plane and drawn out towards the
    // silhouette: the sphere's surface falls away (deeper) under the stroke. A stream curve follows
    // it; a tie's spine (a pigtail drawn from the side, from behind an ear) keeps the plane
    // z = z0 of its first point, in front of the sphere
    const xs = [0.05, 0.1, 0.15, 0.18, 0.2]; // the silhouette is at 1/sqrt(24) ≈ 0.204
    const samples = xs.map((x) => sample(x, 0));
    const stream = liftStroke(samples, eye, forward);
    const spine = liftStroke(samples, eye, forward, true);
    if (!stream.ok || !spine.ok) throw new Error('expected ok');
    const z0 = samples[0].scalpHit?.[2] ?? Number.NaN;
    expect(spine.points[0]).toEqual(samples[0].scalpHit);
    for (let i = 1; i < xs.length; i++) {
      const hit = samples[i].scalpHit;
      if (!hit) throw new Error('expected every sample on the sphere');
      expect(stream.points[i]).toEqual(hit);
      expect(spine.points[i][2]).toBeCloseTo(z0, 12);
      // on the pointer's ray, in front of the sphere
      const toP = sub(spine.points[i], eye);
      expect(Math.hypot(...toP)).toBeLessThan(Math.hypot(...sub(hit, eye)));
      expect(dot(normalize(toP), samples[i].direction)).toBeCloseTo(1, 12);
    }
    // drawn back in over shallower scalp, it lies on the scalp again
    const back = liftStroke([sample(0.15, 0), sample(0.05, 0)], eye, forward, true);
    if (!back.ok) throw new Error('expected ok');
    expect(back.points[1]).toEqual(sample(0.05, 0).scalpHit);
  });
});
