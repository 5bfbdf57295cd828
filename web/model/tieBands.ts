// Hair ties: where each tie's band sits and how wide it is, from the session and the
// grown strands. Pure: the viewer (viewer/tieBandView.ts) and the exporters turn the same bands
// into meshes (tieBandMesh.ts), so what the user sees is what a file holds.
//
//  - Ponytail: the band sits on the first circle C1 (the spine's first circle: where the tail is
//    gathered).
//  - Braid: at the gather, where the bundles leave the head. The solver finds it from the head
//    (solver-cpp/src/braid_bun.hpp braidGatherIndex: the first stroke point off the scalp); the
//    model has no head, so it reads the gather off the hair itself (braidGather): where the
//    stroke points whose planes nearly all of the braid's strands cross close together (within
//    BRAID_GATHERED of the braid's width, and not much wider than the braid is along its
//    length) begin for good, which is where the solver starts the braid's circles.
//  - Bun: none (its coil covers its base).
// The band's radius is measured, not taken from the sketch, so it hugs the hair the growth
// actually gathered: the distance from the centre that holds BAND_SHARE of the tie's strands
// where they cross the band's plane, plus BAND_MARGIN. Its centre and axis too: the mean of
// those crossings, and the way that mean moves a little further along the strands (a tail hangs
// off its sketched circle and along the fall, not always along the sketched spine). A tie that
// holds no strands gets no band; sessions without `ties` get none, so they look as they always
// did.
import type { StrandArrays } from './hairArrays';
import { defOf } from './kinds';
import { reflectDirection, reflectPoint, X_PLANE } from './mirror';
import { polylineTangents } from './ponytailGeometry';
import type { SessionState, StyleCurve } from './session';
import { add, length, normalize, scale, sub, type Vec3 } from './vec3';

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
/** A braid is gathered where BAND_SHARE of its crossings lie within this many widths of their
 *  centre (its circles' radius is half the width; the bundles bulge a little past it). */
const BRAID_GATHERED = 0.6;
/** … and at most this many times the braid's median thickness, … */
const BRAID_THICKER = 1.2;
/** … crossed by at least this share of the braid's strands. */
const BRAID_CROSSING = 0.8;

/** At most about this many of a tie's strands are measured (every k-th: deterministic). */
const SAMPLE_STRANDS = 2000;

type Strands = Pick<StrandArrays, 'points' | 'strandStart' | 'tailCurves' | 'tieFrames'>;

/** The bands of the session's ties, in curve order (empty without `ties`). A tie made with
 *  Mirror gets its twin's band reflected (its hair is the twin's mirrored, but its strands' roots
 *  are not exactly so, and a measured band could sit at another height: twins must match). */
export function tieBands(
  session: Pick<SessionState, 'curves' | 'ties' | 'symmetry'>,
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
  const plane = session.symmetry ?? X_PLANE;
  session.curves.forEach((c, i) => {
    const all = members.get(i);
    if (!all || all.length === 0) return;
    const twin = c.mirror ? bands.find((b) => session.curves[b.curve].id === c.mirror) : undefined;
    if (twin) {
      bands.push({
        curve: i,
        centre: reflectPoint(twin.centre, plane),
        axis: reflectDirection(twin.axis, plane),
        radius: twin.radius,
      });
      return;
    }
    // an even subsample of a large tie: its 95th percentile is as good within a few tenths of a
    // per cent, and the band is measured on the page's thread whenever new hair is shown
    const stride = Math.ceil(all.length / SAMPLE_STRANDS);
    const own = stride > 1 ? all.filter((_, k) => k % stride === 0) : all;
    const band = bandOf(c, i, own, strands);
    if (band) bands.push(band);
  });
  return bands;
}

function bandOf(c: StyleCurve, i: number, own: number[], strands: Strands): TieBand | null {
  // a tie along a spine has a band (it has a supporting surface; a bun lies on the head)
  const kind = defOf(c);
  if (kind.role !== 'tie' || kind.surface(c) === null) return null;
  // where the growth gathered it, when the engine says (exact, and no plane search)
  const f = strands.tieFrames;
  if (f)
    for (let t = 0; t + 8 <= f.length; t += 8) {
      if (f[t] !== i) continue;
      const centre: Vec3 = [f[t + 1], f[t + 2], f[t + 3]];
      const axis = normalize([f[t + 4], f[t + 5], f[t + 6]]);
      // the hair's radius as laid: the band hugs it (no fitting)
      if (f[t + 7] > 0) return { curve: i, centre, axis, radius: f[t + 7] + BAND_MARGIN };
      return fitBand(i, centre, axis, own, strands);
    }
  // drawn circles (a ponytail's): on the first, C1
  const circles = kind.guides?.(c);
  if (circles) {
    const c1 = circles[0];
    return c1 ? fitBand(i, c1.centre, normalize(c1.axis), own, strands) : null;
  }
  // a stroke alone (a braid's): where its hair comes together along it
  const width = (c as { width?: number }).width ?? 0;
  const k = braidGather(c.points, width, own, strands);
  return k < 0 ? null : fitBand(i, c.points[k], polylineTangents(c.points)[k], own, strands);
}

/** The stroke point where the braid's hair comes together: the first of the stroke's last run of
 *  gathered points (nearly all its strands cross the point's plane, BAND_SHARE of them within
 *  BRAID_GATHERED widths of their centre and BRAID_THICKER times the median such radius). Read from the tip's side: near the scalp the
 *  strands can pass close by a stroke point by chance before they fan out again over the head. */
function braidGather(stroke: readonly Vec3[], width: number, own: number[], strands: Strands) {
  const tangents = polylineTangents(stroke);
  const radii = stroke.map((at, k) => {
    if (length(tangents[k]) === 0) return null;
    const crossings = planeCrossings(at, tangents[k], own, strands);
    if (crossings.length < BRAID_CROSSING * own.length) return null;
    return shareRadius(crossings, crossingCentre(crossings, at, 2));
  });
  // the braid itself is about as thick all along: a point whose hair is much thicker than the
  // median is still the funnel from the scalp
  const known = radii.filter((r) => r !== null).sort((a, b) => a - b);
  const typical = known[Math.floor(known.length / 2)] ?? 0;
  const limit = Math.min(BRAID_GATHERED * width, BRAID_THICKER * typical);
  const gathered = radii.map((r) => (r === null ? null : r <= limit));
  let k = gathered.lastIndexOf(true);
  if (k < 0) return -1;
  while (k > 0 && gathered[k - 1] === true) k--;
  return k;
}

/** The mean of the crossings within 1.5 × the BAND_SHARE radius of `start`, taken again from
 *  it `rounds` times (half as far again as the band: a cut at the band itself would drop one
 *  side's outermost strands and pull the centre to the other). */
function crossingCentre(crossings: readonly Crossing[], start: Vec3, rounds: number): Vec3 {
  let centre = start;
  for (let round = 0; round < rounds; round++) {
    const reach = 1.5 * shareRadius(crossings, centre);
    let sum: Vec3 = [0, 0, 0];
    let n = 0;
    for (const c of crossings)
      if (length(sub(c.at, centre)) <= reach) {
        sum = add(sum, c.at);
        n++;
      }
    if (n === 0) break;
    centre = scale(sum, 1 / n);
  }
  return centre;
}

/** The band on the plane through `at` normal to `sketched` (the tail's sketched direction),
 *  turned to the tail's own direction and centred on the strands' crossings. */
function fitBand(
  i: number,
  at: Vec3,
  sketched: Vec3,
  own: number[],
  strands: Strands,
): TieBand | null {
  // the hair hangs where it will (natural fall), not always along the sketched spine: the tail's
  // direction is the way its crossings' mean moves AHEAD further along the same strands (the
  // strands' own directions would not do: where a tail is gathered they still funnel in from
  // all round). A plane across a tail cuts it narrowest when square to it, so a new direction is
  // taken only while it makes the cut narrower: a plane tilted into the funnel never is.
  let best = planeFit(at, sketched, own, strands);
  for (let round = 0; best && round < 4; round++) {
    const way = sub(aheadMean(best, strands), best.centre);
    if (length(way) === 0) break;
    const turned = planeFit(best.centre, normalize(way), own, strands);
    if (!turned || turned.radius >= best.radius) break;
    best = turned;
  }
  return (
    best && { curve: i, centre: best.centre, axis: best.axis, radius: best.radius + BAND_MARGIN }
  );
}

interface PlaneFit {
  centre: Vec3;
  axis: Vec3;
  /** The BAND_SHARE radius of the crossings about the centre. */
  radius: number;
  crossings: Crossing[];
}

/** The strands' crossings of the plane through `at` normal to `axis`, their centre and radius. */
function planeFit(at: Vec3, axis: Vec3, own: number[], strands: Strands): PlaneFit | null {
  const crossings = planeCrossings(at, axis, own, strands);
  if (crossings.length === 0) return null;
  const centre = crossingCentre(crossings, at, 4);
  return { centre, axis, radius: shareRadius(crossings, centre), crossings };
}

/** The mean of the points AHEAD of the crossings near the fit's centre (as crossingCentre
 *  takes them). */
function aheadMean(fit: PlaneFit, strands: Strands): Vec3 {
  const reach = 1.5 * fit.radius;
  let sum: Vec3 = [0, 0, 0];
  let n = 0;
  for (const c of fit.crossings)
    if (length(sub(c.at, fit.centre)) <= reach) {
      sum = add(sum, ahead(c, strands));
      n++;
    }
  return n > 0 ? scale(sum, 1 / n) : fit.centre;
}

/** How far along the strands the tail's direction is read, world units (2 cm). */
const AHEAD = 0.2;

interface Crossing {
  at: Vec3;
  strand: number;
  /** The strand's point after the crossing (towards the tip), and whether the strand crosses
   *  along the plane's normal (else against it: the tail runs towards its root there). */
  next: number;
  forward: boolean;
}

/** The point AHEAD along the strand from a crossing, on the side the plane's normal points to
 *  (the strand's end when it is shorter). */
function ahead(c: Crossing, strands: Strands): Vec3 {
  const { points: P, strandStart } = strands;
  const point = (q: number): Vec3 => [P[3 * q], P[3 * q + 1], P[3 * q + 2]];
  const step = c.forward ? 1 : -1;
  const first = strandStart[c.strand];
  const last = strandStart[c.strand + 1] - 1;
  let from = c.at;
  let left = AHEAD;
  for (let q = c.forward ? c.next : c.next - 1; q >= first && q <= last; q += step) {
    const to = point(q);
    const d = length(sub(to, from));
    if (d >= left) return add(from, scale(sub(to, from), left / d));
    left -= d;
    from = to;
  }
  return from;
}

/** Per strand, where it crosses the plane (point `at`, unit normal `axis`): the crossing nearest
 *  `at` when it crosses more than once (a curl, a strand turning back up), none when it does not. */
function planeCrossings(at: Vec3, axis: Vec3, own: number[], strands: Strands): Crossing[] {
  // plain numbers, no vectors made per point: this runs over every point of a tie's strands for
  // each plane tried (a braid tries each stroke point), on the page's thread
  const { points: P, strandStart } = strands;
  const [ox, oy, oz] = at;
  const [nx, ny, nz] = axis;
  const side = (q: number) =>
    (P[3 * q] - ox) * nx + (P[3 * q + 1] - oy) * ny + (P[3 * q + 2] - oz) * nz;
  const out: Crossing[] = [];
  for (const s of own) {
    let next = -1;
    let bestF = 0;
    let bestD2 = Number.POSITIVE_INFINITY;
    let forward = true;
    let da = side(strandStart[s]);
    for (let q = strandStart[s] + 1; q < strandStart[s + 1]; q++) {
      const db = side(q);
      if ((da <= 0 && db > 0) || (da >= 0 && db < 0)) {
        const f = da / (da - db);
        const a = 3 * (q - 1);
        const dx = P[a] + (P[a + 3] - P[a]) * f - ox;
        const dy = P[a + 1] + (P[a + 4] - P[a + 1]) * f - oy;
        const dz = P[a + 2] + (P[a + 5] - P[a + 2]) * f - oz;
        const d2 = dx * dx + dy * dy + dz * dz;
        if (d2 < bestD2) {
          bestD2 = d2;
          next = q;
          bestF = f;
          forward = db > da;
        }
      }
      da = db;
    }
    if (next < 0) continue;
    const a = 3 * (next - 1);
    const x: Vec3 = [0, 1, 2].map((k) => P[a + k] + (P[a + 3 + k] - P[a + k]) * bestF) as Vec3;
    out.push({ at: x, strand: s, next, forward });
  }
  return out;
}

/** The distance from `centre` within which BAND_SHARE of the points lie, at most STRAY_RATIO
 *  times the median distance: a gathered tail's crossings are compact (its 95th percentile is
 *  about 1.4 times its median), so crossings far past that are strands that meet the plane
 *  elsewhere (hair combed over the scalp under a band close to the head), not the tail's. */
function shareRadius(crossings: readonly Crossing[], centre: Vec3): number {
  if (crossings.length === 0) return 0;
  // a typed array sorts numerically without a comparator, many times faster (it runs often)
  const d = Float64Array.from(crossings, (c) =>
    Math.hypot(c.at[0] - centre[0], c.at[1] - centre[1], c.at[2] - centre[2]),
  ).sort();
  const share = d[Math.min(d.length - 1, Math.max(0, Math.ceil(BAND_SHARE * d.length) - 1))];
  return Math.min(share, STRAY_RATIO * d[Math.floor(d.length / 2)]);
}

/** See shareRadius. */
const STRAY_RATIO = 2;
