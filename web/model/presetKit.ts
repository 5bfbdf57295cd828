// The sketching kit the built-in presets (presets.ts) are drawn with: curves made in code the way
// a user would draw them. Stream curves start on the scalp, follow the head a little above it and
// then fall (S4.1); dividing curves are strokes on the scalp (S4.5); a ponytail is a spine from
// the scalp with a cross-section and two profile strokes beside it, from which the circles are
// computed as for drawn strokes (S4.6); a braid is a spine, a bun a loop drawn on the head.

import { defaultParams } from './curveParams';
import { ponytailCircles } from './ponytailGeometry';
import { resamplePolyline } from './resample';
import type {
  BraidCurve,
  BunCurve,
  DividingCurve,
  PonytailCurve,
  StreamCurve,
  Viewpoint,
} from './session';
import { add, normalize, scale, sphericalDirection, type Vec3 } from './vec3';

export interface PresetContext {
  /** The head the curves are sketched on (its scalp points, normals and centre). */
  /** What presets ask of the head (head/head.ts Head has it): the scalp point at (θ, φ) degrees,
   *  the surface normal near a point, and the scalp parameterisation's origin. */
  head: {
    scalpPoint(thetaDeg: number, phiDeg: number): { point: Vec3 } | null;
    normalAt(p: Vec3): Vec3;
    center: Vec3;
  };
  step: number; // grid step d
  viewpoint: Viewpoint;
}

/** Outermost head point at spherical angles from the head centre, or null. */
export function headPoint(ctx: PresetContext, thetaDeg: number, phiDeg: number): Vec3 | null {
  return ctx.head.scalpPoint(thetaDeg, phiDeg)?.point ?? null;
}

export interface SweepSpec {
  theta: [number, number]; // θ from → to, degrees
  phi: [number, number]; // φ from → to, degrees
  lift: number; // height above the head at the end of the sweep, world units
  fall: number; // length of the free fall below the sweep, world units
  toY?: number; // or: fall until this height (world y), where the hair should end
}

export function sweepCurve(ctx: PresetContext, spec: SweepSpec): Vec3[] | null {
  const dense: Vec3[] = [];
  const n = 80;
  for (let i = 0; i <= n; i++) {
    const s = i / n;
    const theta = spec.theta[0] + (spec.theta[1] - spec.theta[0]) * s;
    const phi = spec.phi[0] + (spec.phi[1] - spec.phi[0]) * s;
    const hit = headPoint(ctx, theta, phi);
    if (!hit) return null;
    const lift = spec.lift * Math.min(1, s / 0.25);
    dense.push(add(hit, scale(sphericalDirection(theta, phi), lift)));
  }
  // Free fall: straight down, easing slightly outward.
  const last = dense[dense.length - 1];
  const out = sphericalDirection(90, spec.phi[1]);
  const fall = spec.toY === undefined ? spec.fall : Math.max(0, last[1] - spec.toY);
  for (let i = 1; i <= 40 && fall > 0; i++) {
    const s = i / 40;
    dense.push(add(last, add(scale([0, -1, 0], fall * s), scale(out, 0.12 * s * s))));
  }
  return dense;
}

/** A stream curve along a sweep, or null when it leaves the head. */
export function streamFrom(ctx: PresetContext, spec: SweepSpec, id: string): StreamCurve | null {
  const dense = sweepCurve(ctx, spec);
  if (!dense) return null;
  const points = resamplePolyline(dense, ctx.step);
  if (points.length < 2) return null;
  return { id, type: 'stream', points, extend: true, viewpoint: ctx.viewpoint };
}

/** A dividing curve: a stroke on the scalp through the given (θ, φ) points. */
export function dividingFrom(
  ctx: PresetContext,
  path: [number, number][],
  id: string,
  tilt: [number, number] = [0, 0],
): DividingCurve | null {
  const dense: Vec3[] = [];
  for (let k = 1; k < path.length; k++) {
    for (let i = k === 1 ? 0 : 1; i <= 20; i++) {
      const s = i / 20;
      const hit = headPoint(
        ctx,
        path[k - 1][0] + (path[k][0] - path[k - 1][0]) * s,
        path[k - 1][1] + (path[k][1] - path[k - 1][1]) * s,
      );
      if (!hit) return null;
      dense.push(hit);
    }
  }
  const points = resamplePolyline(dense, ctx.step);
  if (points.length < 3) return null;
  const normal = (p: Vec3) => ctx.head.normalAt(p);
  return {
    id,
    type: 'dividing',
    points,
    normals: points.map(normal),
    ...defaultParams('dividing'),
    alpha0: tilt[0],
    alpha1: tilt[1],
    viewpoint: ctx.viewpoint,
  };
}

export interface PonytailSpec {
  base: [number, number]; // (θ, φ) of the spine's root on the scalp
  out: number; // how far the spine first leaves the head, world units
  fall: number; // then how far it falls, world units
  gather: number; // radius where the hair is gathered (C1), world units
  width: number; // radius of the tail below the gather, world units
}

/** A spine stroke as drawn from the scalp: out of the head, slanting down, then bending gently
 *  until it hangs straight down (a ponytail's spine, a braid). */
export function spineFrom(
  ctx: PresetContext,
  spec: Pick<PonytailSpec, 'base' | 'out' | 'fall'>,
): Vec3[] {
  const root = headPoint(ctx, spec.base[0], spec.base[1]);
  if (!root) return [];
  const outDir = sphericalDirection(spec.base[0], spec.base[1]);
  const dense: Vec3[] = [root];
  let dir = normalize(add(outDir, [0, -0.5, 0]));
  let p = root;
  const ds = ctx.step / 4;
  for (let len = 0; len < spec.out + spec.fall; len += ds) {
    if (len > spec.out) dir = normalize(add(dir, [0, -0.1, 0]));
    p = add(p, scale(dir, ds));
    dense.push(p);
  }
  return resamplePolyline(dense, ctx.step);
}

/** A braid: one stroke from the scalp along where it hangs (drawn as a ponytail's spine). */
export function braidFrom(
  ctx: PresetContext,
  spec: Pick<PonytailSpec, 'base' | 'out' | 'fall'>,
  id: string,
): BraidCurve | null {
  const points = spineFrom(ctx, spec);
  if (points.length < 5) return null;
  return {
    id,
    type: 'braid',
    points,
    extend: true,
    viewpoint: ctx.viewpoint,
    ...defaultParams('braid'),
  };
}

/** A bun: a loop drawn on the head round (θ, φ), `size` degrees from it as seen from the head's
 *  centre. */
export function bunFrom(
  ctx: PresetContext,
  centre: [number, number],
  size: number,
  id: string,
): BunCurve | null {
  const d0 = sphericalDirection(centre[0], centre[1]);
  const e1 = normalize(Math.abs(d0[1]) < 0.9 ? [d0[2], 0, -d0[0]] : [1, 0, 0]);
  const e2: Vec3 = [
    d0[1] * e1[2] - d0[2] * e1[1],
    d0[2] * e1[0] - d0[0] * e1[2],
    d0[0] * e1[1] - d0[1] * e1[0],
  ];
  const r = Math.tan((size * Math.PI) / 180);
  const dense: Vec3[] = [];
  for (let i = 0; i <= 72; i++) {
    const a = (2 * Math.PI * i) / 72;
    const d = normalize(add(d0, add(scale(e1, r * Math.cos(a)), scale(e2, r * Math.sin(a)))));
    const theta = (Math.acos(Math.max(-1, Math.min(1, d[1]))) * 180) / Math.PI;
    const phi = (Math.atan2(d[0], d[2]) * 180) / Math.PI;
    const hit = headPoint(ctx, theta, phi);
    if (!hit) return null;
    dense.push(hit);
  }
  const points = resamplePolyline(dense, ctx.step);
  if (points.length < 6) return null;
  return {
    id,
    type: 'bun',
    points,
    extend: true,
    viewpoint: ctx.viewpoint,
    ...defaultParams('bun'),
  };
}

/** A ponytail sketched as the paper's four strokes: the spine (out from the scalp, then down),
 *  a cross-section across it at the gather, and two profiles beside it, widening below the
 *  gather and tapering to the tip. */
export function ponytailFrom(
  ctx: PresetContext,
  spec: PonytailSpec,
  id: string,
): PonytailCurve | null {
  const outDir = sphericalDirection(spec.base[0], spec.base[1]);
  const spine = spineFrom(ctx, spec);
  if (spine.length < 5) return null;
  // The side the profiles are drawn on: across the spine, horizontally.
  const side = normalize([outDir[2], 0, -outDir[0]]);
  const gatherAt = 4; // spine index where the hair is gathered (even: circles sit on every 2nd)
  const radius = (i: number) => {
    if (i <= gatherAt) return spec.gather;
    const t = (i - gatherAt) / (spine.length - 1 - gatherAt);
    return (
      spec.gather + (spec.width - spec.gather) * Math.sin(Math.PI * Math.min(1, t * 1.4)) ** 0.7
    );
  };
  // the profiles start at the gather: C1 (the first circle) is the gathered cross-section
  const profile = (sign: number) =>
    spine
      .slice(gatherAt - 1)
      .map((p, k) =>
        add(p, scale(side, sign * Math.max(0.3 * spec.gather, radius(k + gatherAt - 1)))),
      );
  const g = spine[gatherAt];
  const crossSection: Vec3[] = [];
  for (let i = 0; i <= 8; i++) crossSection.push(add(g, scale(side, spec.gather * (i / 4 - 1))));
  const profiles: [Vec3[], Vec3[]] = [profile(1), profile(-1)];
  const { circles } = ponytailCircles(spine, crossSection, profiles[0], profiles[1], { every: 2 });
  if (circles.length === 0) return null;
  return {
    id,
    type: 'ponytail',
    points: spine,
    extend: true,
    viewpoint: ctx.viewpoint,
    crossSection,
    profiles,
    circles,
    ...defaultParams('ponytail'),
  };
}
