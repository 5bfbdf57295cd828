// A ponytail in one stroke: the spine alone, drawn from the scalp where the tie sits along where
// the tail hangs. The paper's other three strokes (a cross-section and two profiles, method S4.6)
// are made for it, so the curve is the same kind as a four-stroke ponytail (edited, mirrored,
// saved and linked the same way; a later cross-section and profiles replace these):
//   the band: the first spine point at least BAND_ARC along the spine from its root (just off
//     the head: the tail is gathered there, C1);
//   the profiles: the spine offset by +-radius across it, in the plane facing the view it was
//     drawn from (side = tangent x view direction), from the band to the tip;
//   the cross-section: a line of length 2 radius across the spine at the band.
// ponytailCircles (ponytailGeometry.ts) then gives circles of that radius along the spine from
// the band. The radius is small on purpose: a tie that gathers its whole section grows to hold
// its hair (solver-cpp/src/gathered_tail.hpp sectionTailRadius), drawn circles only widen it.
import type { PonytailCircle } from './ponytailGeometry';
import { polylineTangents, ponytailCircles } from './ponytailGeometry';
import type { Viewpoint } from './session';
import { add, cross, length, normalize, scale, sub, type Vec3 } from './vec3';

/** Arc length from the spine's root to the band (world units, 1.2 cm). */
export const BAND_ARC = 0.12;
/** The made profiles' half-width (world units, 8 mm). */
export const ONE_STROKE_RADIUS = 0.08;
/** The curve panel's width of a ponytail at its band (world units: 0.5 to 20 cm). */
export const PONYTAIL_WIDTH = { min: 0.05, max: 2 };

export interface PonytailStrokes {
  crossSection: Vec3[];
  profiles: [Vec3[], Vec3[]];
  circles: PonytailCircle[];
}

/** The index of the band on `spine` (BAND_ARC along it; the last but one point at most). */
export function bandIndex(spine: readonly Vec3[]): number {
  let walked = 0;
  for (let i = 1; i < spine.length; i++) {
    walked += length(sub(spine[i], spine[i - 1]));
    if (walked >= BAND_ARC) return Math.min(i, spine.length - 2);
  }
  return Math.max(0, spine.length - 2);
}

/** The cross-section, profiles and circles of a one-stroke ponytail on `spine` drawn from
 *  `viewpoint`; no circles when the spine is too short (fewer than 3 points). */
export function ponytailFromSpine(
  spine: readonly Vec3[],
  viewpoint: Viewpoint,
  radius = ONE_STROKE_RADIUS,
): PonytailStrokes {
  const empty: PonytailStrokes = { crossSection: [], profiles: [[], []], circles: [] };
  if (spine.length < 3) return empty;
  const view = normalize(sub(viewpoint.target, viewpoint.position));
  const tangents = polylineTangents(spine);
  const sides = tangents.map((t) => {
    let s = cross(t, view);
    // drawn straight at the eye: any direction across the spine
    if (length(s) < 1e-3) s = cross(t, Math.abs(t[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0]);
    return normalize(s);
  });
  const b = bandIndex(spine);
  const from = b;
  const a: Vec3[] = [];
  const c: Vec3[] = [];
  for (let i = from; i < spine.length; i++) {
    a.push(add(spine[i], scale(sides[i], radius)));
    c.push(sub(spine[i], scale(sides[i], radius)));
  }
  const crossSection: Vec3[] = [
    sub(spine[b], scale(sides[b], radius)),
    add(spine[b], scale(sides[b], radius)),
  ];
  // the circles ponytailCircles gives between these profiles from the band on (its planes
  // before the band could meet the profiles far down a spine that rises and falls)
  // (and of the made radius: ponytailCircles scales every radius by the cross-section against
  // its nearest circle, which can be one of those before the band)
  const circles = ponytailCircles(spine as Vec3[], crossSection, a, c, { every: 2 })
    .circles.filter((q) => q.spineIndex >= b)
    .map((q) => ({ ...q, radius }));
  return { crossSection, profiles: [a, c], circles };
}

/** Ponytail strokes made `factor` times as wide about the spine (the curve panel's width): each
 *  circle's radius, each profile point's offset from its nearest spine point and the
 *  cross-section's spread about its centre (a later spine edit recomputes the circles from the
 *  profiles, PONYTAIL.respine). */
export function widenPonytail(
  spine: readonly Vec3[],
  strokes: PonytailStrokes,
  factor: number,
): PonytailStrokes {
  const aboutSpine = (p: Vec3): Vec3 => {
    let best = spine[0];
    for (const s of spine) if (length(sub(p, s)) < length(sub(p, best))) best = s;
    return add(best, scale(sub(p, best), factor));
  };
  const n = strokes.crossSection.length;
  const mid = strokes.crossSection.reduce<Vec3>((m, p) => add(m, scale(p, 1 / n)), [0, 0, 0]);
  return {
    crossSection: strokes.crossSection.map((p) => add(mid, scale(sub(p, mid), factor))),
    profiles: [strokes.profiles[0].map(aboutSpine), strokes.profiles[1].map(aboutSpine)],
    circles: strokes.circles.map((c) => ({ ...c, radius: c.radius * factor })),
  };
}
