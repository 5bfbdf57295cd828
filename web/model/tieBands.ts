// Hair ties (issue 49): where each tie's band sits and how wide it is, from the session and the
// grown strands. Pure: the viewer (viewer/tieBandView.ts) and the exporters turn the same bands
// into meshes (tieBandMesh.ts), so what the user sees is what a file holds.
//
//  - Ponytail: the band sits on the first circle C1 (the spine's first circle: where the tail is
//    gathered).
//  - Braid: at the gather, where the bundles leave the head. The solver finds it from the head
//    (solver-cpp/src/braid_bun.hpp braidGatherIndex: the first stroke point off the scalp); the
//    model has no head, so it reads the gather off the hair itself: the first stroke point whose
//    plane nearly all of the braid's strands cross close together (within BRAID_GATHERED of the
//    braid's width), which is where the solver starts the braid's circles.
//  - Bun: none (its coil covers its base).
// The band's radius is measured, not taken from the sketch, so it hugs the hair the growth
// actually gathered: the distance from the centre that holds BAND_SHARE of the tie's strands
// where they cross the band's plane, plus BAND_MARGIN. Its centre and axis too: the mean of
// those crossings and of the strands' directions there (a tail hangs off its sketched circle
// and along the fall, not always along the sketched spine). A tie that holds no strands gets no band;
// sessions without `ties` get none, so they look as they always did.
import type { StrandArrays } from './hairArrays';
import { polylineTangents } from './ponytailGeometry';
import type { SessionState, StyleCurve } from './session';
import { add, dot, length, normalize, scale, sub, type Vec3 } from './vec3';

export interface TieBand {
  /** The tie's index in session.curves. */
  curve: number;
  centre: Vec3;
  /** Unit, the tail's direction (root → tip). */
  axis: Vec3;
  /** Inner radius: the hair's (BAND_SHARE of its strands) plus BAND_MARGIN, world units. */
  radius: number;
}

/** The share of a tie's strands the band's inner radius holds (the rest are strays). */
export const BAND_SHARE = 0.95;
/** Room between the hair and the band, world units (1.5 mm). */
export const BAND_MARGIN = 0.015;
/** A braid's gather: its crossings within this many widths of the stroke (its circles' radius
 *  is half the width; the bundles bulge a little past it). */
const BRAID_GATHERED = 0.75;
/** … crossed by at least this share of the braid's strands. */
const BRAID_CROSSING = 0.8;

type Strands = Pick<StrandArrays, 'points' | 'strandStart' | 'tailCurves'>;

/** The bands of the session's ties, in curve order (empty without `ties`). */
export function tieBands(
  session: Pick<SessionState, 'curves' | 'ties'>,
  strands: Strands,
): TieBand[] {
  const tails = strands.tailCurves;
  if (!session.ties || !tails) return [];
  const members = new Map<number, number[]>();
  for (let s = 0; s < tails.length; s++) {
    const t = tails[s];
    if (t < 0) continue;
    const list = members.get(t);
    if (list) list.push(s);
    else members.set(t, [s]);
  }
  const bands: TieBand[] = [];
  session.curves.forEach((c, i) => {
    const own = members.get(i);
    if (!own || own.length === 0) return;
    const band = bandOf(c, i, own, strands);
    if (band) bands.push(band);
  });
  return bands;
}

function bandOf(c: StyleCurve, i: number, own: number[], strands: Strands): TieBand | null {
  if (c.type === 'ponytail') {
    const c1 = c.circles[0];
    return c1 ? fitBand(i, c1.centre, normalize(c1.axis), own, strands) : null;
  }
  if (c.type === 'braid') {
    const tangents = polylineTangents(c.points);
    for (let k = 0; k < c.points.length; k++) {
      const axis = tangents[k];
      if (length(axis) === 0) continue;
      const crossings = planeCrossings(c.points[k], axis, own, strands);
      if (crossings.length < BRAID_CROSSING * own.length) continue;
      if (shareRadius(crossings, c.points[k]) > BRAID_GATHERED * c.width) continue;
      return fitBand(i, c.points[k], axis, own, strands);
    }
  }
  return null;
}

/** The band on the plane through `at` normal to `sketched` (the tail's sketched direction),
 *  turned to the strands' own direction and centred on their crossings. */
function fitBand(
  i: number,
  at: Vec3,
  sketched: Vec3,
  own: number[],
  strands: Strands,
): TieBand | null {
  // the hair hangs where it will (natural fall), not always along the sketched spine: the axis is
  // the strands' mean direction where they cross, the centre their crossings' mean; both from
  // the crossings near the band only, so strays do not pull them off the tail (half as far
  // again as the band: a cut at the band itself would drop one side's outermost strands and pull
  // the centre to the other). A few rounds, as the sketched point may lie off the hair and let
  // strays in at first.
  let centre = at;
  let axis = sketched;
  for (let round = 0; round < 4; round++) {
    const crossings = planeCrossings(centre, axis, own, strands);
    if (crossings.length === 0) return null;
    const reach = 1.5 * shareRadius(crossings, centre);
    let sum: Vec3 = [0, 0, 0];
    let along: Vec3 = [0, 0, 0];
    let n = 0;
    for (const c of crossings)
      if (length(sub(c.at, centre)) <= reach) {
        sum = add(sum, c.at);
        along = add(along, c.along);
        n++;
      }
    if (n === 0) break;
    centre = scale(sum, 1 / n);
    if (length(along) > 0) axis = normalize(along);
  }
  const crossings = planeCrossings(centre, axis, own, strands);
  if (crossings.length === 0) return null;
  return { curve: i, centre, axis, radius: shareRadius(crossings, centre) + BAND_MARGIN };
}

interface Crossing {
  at: Vec3;
  /** The strand's unit direction there, turned along the plane's normal. */
  along: Vec3;
}

/** Per strand, where it crosses the plane (point `at`, unit normal `axis`): the crossing nearest
 *  `at` when it crosses more than once (a curl, a strand turning back up), none when it does not. */
function planeCrossings(at: Vec3, axis: Vec3, own: number[], strands: Strands): Crossing[] {
  const { points: P, strandStart } = strands;
  const out: Crossing[] = [];
  const point = (q: number): Vec3 => [P[3 * q], P[3 * q + 1], P[3 * q + 2]];
  for (const s of own) {
    let best: Crossing | null = null;
    let bestD = Number.POSITIVE_INFINITY;
    let a = point(strandStart[s]);
    let da = dot(sub(a, at), axis);
    for (let q = strandStart[s] + 1; q < strandStart[s + 1]; q++) {
      const b = point(q);
      const db = dot(sub(b, at), axis);
      if ((da <= 0 && db > 0) || (da >= 0 && db < 0)) {
        const x = add(a, scale(sub(b, a), da / (da - db)));
        const d = length(sub(x, at));
        if (d < bestD) {
          bestD = d;
          const dir = normalize(sub(b, a));
          best = { at: x, along: db > da ? dir : scale(dir, -1) };
        }
      }
      a = b;
      da = db;
    }
    if (best) out.push(best);
  }
  return out;
}

/** The distance from `centre` within which BAND_SHARE of the points lie. */
function shareRadius(crossings: readonly Crossing[], centre: Vec3): number {
  const d = crossings.map((c) => length(sub(c.at, centre))).sort((x, y) => x - y);
  return d[Math.min(d.length - 1, Math.max(0, Math.ceil(BAND_SHARE * d.length) - 1))] ?? 0;
}
