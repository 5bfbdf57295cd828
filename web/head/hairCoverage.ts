// How much of the scalp the hair hides from a direction: rays along `dir` (parallel, as from far
// away) at a grid of scalp points; a ray is covered when at least `layers` different strands
// pass within `radius` of it in front of the scalp point (nearer to where the ray comes from),
// bare otherwise: a root's own short stubble (a strand that hardly grew, in a weak field) does
// not hide the scalp around it, hair combed over it does (many strands). Segments are binned on
// the plane across the rays, so each ray looks only at the segments near it.

import type { StrandArrays } from '../model/hairArrays';
import { cross, type Vec3 } from '../model/vec3';
import type { Head } from './head';

export interface CoverageOptions {
  /** Unit direction the rays travel (e.g. [0, 0, 1]: seen from behind, the face looks at +z). */
  dir: Vec3;
  /** How close a segment must pass to hide a point, world units (default 0.01 = 1 mm). */
  radius?: number;
  /** Angular step of the scalp grid in θ and φ, degrees (default 3). */
  stepDeg?: number;
  /** Different strands that must pass in front of a point to hide it (default 3). */
  layers?: number;
  /** Only the head points in these ranges of θ (from the top) and φ (0 at the front, 90 at the
   *  head's left; a range may wrap past 360), degrees (default: everywhere). */
  region?: { theta: [number, number]; phi: [number, number] };
  /** Which head points count: the scalp (default) or any (the forehead, cheeks, ears). */
  surface?: 'scalp' | 'any';
}

export interface Coverage {
  /** Scalp points of the grid seen from the direction (not hidden by the head itself). */
  points: number;
  /** Of those, points no strand hides. */
  bare: number;
  fraction: number;
  /** (θ, φ) of the bare points, for messages. */
  bareAt: [number, number][];
}

export function scalpCoverage(
  head: Pick<Head, 'scalpPoint' | 'raycast'>,
  strands: StrandArrays | null,
  opts: CoverageOptions,
): Coverage {
  const r = opts.radius ?? 0.01;
  const step = opts.stepDeg ?? 3;
  const layers = opts.layers ?? 3;
  const d = opts.dir;
  // a frame across the rays: u, v with d
  const a: Vec3 = Math.abs(d[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0];
  const u = norm(cross(a, d));
  const v = cross(d, u);
  const cell = Math.max(r * 4, 0.02);
  const bins = new Map<number, number[]>();
  const key = (i: number, j: number) => (i + 32768) * 65536 + (j + 32768);
  const P = strands?.points;
  const S = strands?.strandStart;
  const strandOf = new Int32Array(P ? P.length / 3 : 0);
  if (P && S)
    for (let s = 0; s + 1 < S.length; s++)
      for (let k = S[s]; k + 1 < S[s + 1]; k++) {
        strandOf[k] = s;
        const au = dot3(P, k, u);
        const av = dot3(P, k, v);
        const bu = dot3(P, k + 1, u);
        const bv = dot3(P, k + 1, v);
        const i0 = Math.floor((Math.min(au, bu) - r) / cell);
        const i1 = Math.floor((Math.max(au, bu) + r) / cell);
        const j0 = Math.floor((Math.min(av, bv) - r) / cell);
        const j1 = Math.floor((Math.max(av, bv) + r) / cell);
        for (let i = i0; i <= i1; i++)
          for (let j = j0; j <= j1; j++) {
            const b = bins.get(key(i, j));
            if (b) b.push(k);
            else bins.set(key(i, j), [k]);
          }
      }
  let points = 0;
  const bareAt: [number, number][] = [];
  const region = opts.region;
  const inPhi = (phi: number) => {
    if (!region) return true;
    const [a, b] = region.phi;
    const w = (x: number) => ((x % 360) + 360) % 360;
    return w(phi - a) <= w(b - a);
  };
  for (let theta = step / 2; theta < 180; theta += step)
    for (let phi = 0; phi < 360; phi += step) {
      if (region && (theta < region.theta[0] || theta > region.theta[1] || !inPhi(phi))) continue;
      const hit = head.scalpPoint(theta, phi);
      if (!hit || (!hit.scalp && opts.surface !== 'any')) continue;
      const p = hit.point;
      // seen from the direction: the first head hit of the ray through p is p itself
      const far = 20;
      const origin: Vec3 = [p[0] - d[0] * far, p[1] - d[1] * far, p[2] - d[2] * far];
      const first = head.raycast(origin, d);
      if (!first || Math.abs(first.distance - far) > 1e-3) continue;
      points++;
      const pu = p[0] * u[0] + p[1] * u[1] + p[2] * u[2];
      const pv = p[0] * v[0] + p[1] * v[1] + p[2] * v[2];
      const pd = p[0] * d[0] + p[1] * d[1] + p[2] * d[2];
      const list = bins.get(key(Math.floor(pu / cell), Math.floor(pv / cell))) ?? [];
      const hiding = new Set<number>();
      for (const k of list) {
        if (hiding.has(strandOf[k])) continue;
        if (segmentHides(P as Float32Array, k, u, v, d, pu, pv, pd, r)) hiding.add(strandOf[k]);
        if (hiding.size >= layers) break;
      }
      if (hiding.size < layers) bareAt.push([theta, phi]);
    }
  return { points, bare: bareAt.length, fraction: points ? bareAt.length / points : 0, bareAt };
}

/** Whether segment k..k+1 passes within r of the ray (pu, pv) across, in front of depth pd. */
function segmentHides(
  P: ArrayLike<number>,
  k: number,
  u: Vec3,
  v: Vec3,
  d: Vec3,
  pu: number,
  pv: number,
  pd: number,
  r: number,
): boolean {
  const au = dot3(P, k, u);
  const av = dot3(P, k, v);
  const bu = dot3(P, k + 1, u);
  const bv = dot3(P, k + 1, v);
  const eu = bu - au;
  const ev = bv - av;
  const len2 = eu * eu + ev * ev;
  const t = len2 > 0 ? Math.min(1, Math.max(0, ((pu - au) * eu + (pv - av) * ev) / len2)) : 0;
  const cu = au + t * eu - pu;
  const cv = av + t * ev - pv;
  if (cu * cu + cv * cv > r * r) return false;
  const depth = dot3(P, k, d) * (1 - t) + dot3(P, k + 1, d) * t;
  return depth < pd - 1e-4; // nearer to where the ray comes from than the scalp point
}

const dot3 = (P: ArrayLike<number>, k: number, w: Vec3) =>
  P[3 * k] * w[0] + P[3 * k + 1] * w[1] + P[3 * k + 2] * w[2];
function norm(a: Vec3): Vec3 {
  const l = Math.hypot(a[0], a[1], a[2]) || 1;
  return [a[0] / l, a[1] / l, a[2] / l];
}

/** The view directions by name: rays travel from the named side towards the head. */
export const VIEW_DIRECTIONS: Record<'front' | 'back' | 'left' | 'right' | 'top', Vec3> = {
  front: [0, 0, -1],
  back: [0, 0, 1],
  left: [-1, 0, 0],
  right: [1, 0, 0],
  top: [0, -1, 0],
};
