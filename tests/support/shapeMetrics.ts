// Figures of a hairstyle's shape measured from its strands (docs/natural-fall.md section
// 5), on the built-in head: shared by the browser tests (shape.spec.ts), the engine's unit
// tests (shapeRules.test.ts) and `npm run bench:shape`. Every figure is computed from the strands
// and the head's exact signed distance (headSdf), never from what the engine reports.
import { EAR_X, EAR_Y, EAR_Z, headSdf } from '../../web/head/headSdf';

export type V3 = [number, number, number];
export interface StrandSet {
  points: ArrayLike<number>;
  strandStart: ArrayLike<number>;
}
export interface CurveLike {
  type: string;
  points: readonly (readonly number[])[];
}

export const dist = (a: readonly number[], b: readonly number[]) =>
  Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

export const median = (v: number[]) => {
  const s = [...v].sort((a, b) => a - b);
  return s.length ? s[Math.floor(s.length / 2)] : Number.NaN;
};

export const quantile = (v: number[], q: number) => {
  const s = [...v].sort((a, b) => a - b);
  return s.length ? s[Math.min(s.length - 1, Math.floor(q * s.length))] : Number.NaN;
};

/** Calls f with the points of every strand of two points or more. */
export function eachStrand(s: StrandSet, f: (pts: V3[]) => void) {
  for (let k = 0; k + 1 < s.strandStart.length; k++) {
    const pts: V3[] = [];
    for (let p = s.strandStart[k]; p < s.strandStart[k + 1]; p++)
      pts.push([s.points[3 * p], s.points[3 * p + 1], s.points[3 * p + 2]]);
    if (pts.length > 1) f(pts);
  }
}

const strandLength = (pts: V3[]) => {
  let l = 0;
  for (let i = 1; i < pts.length; i++) l += dist(pts[i], pts[i - 1]);
  return l;
};

/** Whether a strand's root is farther than `far` from every point of the strokes (stream curves
 *  and tie spines: not partings). */
const ungoverned = (root: V3, cs: readonly CurveLike[], far: number) =>
  !cs.some((c) => c.type !== 'dividing' && c.points.some((q) => dist(q, root) < far));

/** Hair no stroke governs (rooted 4 cm or more from every stroke point): the median angle in
 *  degrees of the root-to-tip direction from straight down, and the share ending above its root. */
export function fallOfUngoverned(s: StrandSet, cs: readonly CurveLike[], far = 0.4) {
  const angles: number[] = [];
  let above = 0;
  eachStrand(s, (pts) => {
    if (!ungoverned(pts[0], cs, far)) return;
    const r = pts[0];
    const t = pts[pts.length - 1];
    const v = [t[0] - r[0], t[1] - r[1], t[2] - r[2]];
    const c = Math.max(-1, Math.min(1, -v[1] / Math.hypot(v[0], v[1], v[2])));
    angles.push((Math.acos(c) * 180) / Math.PI);
    if (t[1] > r[1]) above++;
  });
  return {
    strands: angles.length,
    medianAngle: median(angles),
    aboveShare: angles.length ? above / angles.length : 0,
  };
}

/** The median distance from the head (world units) of the points of every strand from `from`
 *  to `within` along it (default its first 3 cm), of strands whose root is `far` from every
 *  stroke point (0: every strand). */
export function standOff(s: StrandSet, cs: readonly CurveLike[], within = 0.3, far = 0, from = 0) {
  const d: number[] = [];
  eachStrand(s, (pts) => {
    if (far > 0 && !ungoverned(pts[0], cs, far)) return;
    let len = 0;
    for (let i = 1; i < pts.length && len < within; i++) {
      len += dist(pts[i], pts[i - 1]);
      if (len >= from) d.push(headSdf(pts[i][0], pts[i][1], pts[i][2]));
    }
  });
  return median(d);
}

/** The same for the strands rooted within `near` of a curve's point (the hair a stroke holds). */
export function standOffNear(
  s: StrandSet,
  cs: readonly CurveLike[],
  near: number,
  within = 0.3,
  from = 0,
) {
  const d: number[] = [];
  eachStrand(s, (pts) => {
    if (ungoverned(pts[0], cs, near)) return;
    let len = 0;
    for (let i = 1; i < pts.length && len < within; i++) {
      len += dist(pts[i], pts[i - 1]);
      if (len >= from) d.push(headSdf(pts[i][0], pts[i][1], pts[i][2]));
    }
  });
  return median(d);
}

/** Share of strands with a point in front of the face from the brows to the mouth. */
export function faceShare(s: StrandSet): number {
  let over = 0;
  let n = 0;
  eachStrand(s, (pts) => {
    n++;
    if (pts.some(([x, y, z]) => Math.abs(x) < 0.45 && y > -0.95 && y < -0.05 && z > 0.55)) over++;
  });
  return n ? over / n : 0;
}

/** Share of strands that hide an ear from the front: a point beside the ear (|x| past the
 *  cranium's side there), within the middle 3 cm of the ear's 6 cm height (hair tucked behind an
 *  ear rests on its top) and in front of its middle. */
export function earCoverShare(s: StrandSet): number {
  let over = 0;
  let n = 0;
  eachStrand(s, (pts) => {
    n++;
    const hides = pts.some(
      ([x, y, z]) =>
        Math.abs(x) > EAR_X - 0.08 &&
        Math.abs(y - EAR_Y) < 0.15 &&
        z > EAR_Z &&
        z < EAR_Z + 0.45 &&
        Math.abs(x) < EAR_X + 0.5,
    );
    if (hides) over++;
  });
  return n ? over / n : 0;
}

/** The hair's width at ear level (world units): between the 1st and 99th percentiles of x of
 *  the strand points within 2 cm of the ears' height, and the head's own width there (ears
 *  included). */
export function widthAtEars(s: StrandSet) {
  const xs: number[] = [];
  eachStrand(s, (pts) => {
    for (const p of pts) if (Math.abs(p[1] - EAR_Y) < 0.2) xs.push(p[0]);
  });
  let head = 0;
  for (let z = -1; z < 1; z += 0.02)
    for (let x = 0; x < 1.5; x += 0.005) if (headSdf(x, EAR_Y, z) < 0) head = Math.max(head, x);
  return { hair: quantile(xs, 0.99) - quantile(xs, 0.01), head: 2 * head };
}

/** The median length of the strands rooted at the nape (behind the head and below the ears'
 *  middle), and of the strands rooted within 2 cm of a stroke's first point. */
export function napeLength(s: StrandSet, cs: readonly CurveLike[]) {
  const nape: number[] = [];
  const near: number[] = [];
  eachStrand(s, (pts) => {
    const r = pts[0];
    if (r[2] < -0.4 && r[1] < EAR_Y + 0.05) nape.push(strandLength(pts));
    if (cs.some((c) => c.type === 'stream' && dist(c.points[0], r) < 0.2))
      near.push(strandLength(pts));
  });
  return { nape: median(nape), strokes: median(near) };
}

/** Share of strands rooted 3 cm or more from every stroke point that pass in front of the eye's
 *  outer corner or the temple (beside the face's middle, |x| 3 to 7.5 cm, from the brow's height
 *  to 6 cm below it, in front of z = 4.5 cm): hair no stroke put there, falling across the eye. */
export function templeStrays(s: StrandSet, curves: readonly CurveLike[]): number {
  const pts = curves.flatMap((c) => c.points);
  let over = 0;
  let n = 0;
  eachStrand(s, (p) => {
    n++;
    if (pts.some((q) => dist(q, p[0]) < 0.3)) return;
    if (
      p.some(
        ([x, y, z]) => y < 0.15 && y > -0.6 && z > 0.45 && Math.abs(x) > 0.3 && Math.abs(x) < 0.75,
      )
    )
      over++;
  });
  return n ? over / n : 0;
}

/** The lower hairline round the back of the head, computed here from the scalp mesh (a
 *  reference for solver-cpp nape_line): the lowest point of the scalp's boundary edges (between a
 *  scalp triangle and one that is not) per 7.5° of angle about the vertical axis through `center`,
 *  over the head behind 1 cm in front of the centre and below 2.5 cm above it. `at(x, z)` gives
 *  the nearest bin's height (NaN in front, or where no edge passes). */
export function lowerHairline(mesh: {
  positions: Float32Array;
  indices: Uint32Array;
  scalp: Uint8Array;
  center: readonly number[];
}) {
  const { positions: P, indices: I, scalp: S, center: c } = mesh;
  const count = new Map<number, [number, number]>();
  const n = P.length / 3;
  for (let t = 0; t < S.length; t++)
    for (let k = 0; k < 3; k++) {
      const a = I[3 * t + k];
      const b = I[3 * t + ((k + 1) % 3)];
      const key = Math.min(a, b) * n + Math.max(a, b);
      const e = count.get(key) ?? [0, 0];
      e[S[t] ? 0 : 1]++;
      count.set(key, e);
    }
  const bins = 48;
  const line = new Array<number>(bins).fill(Number.POSITIVE_INFINITY);
  const binOf = (x: number, z: number) =>
    Math.min(
      bins - 1,
      Math.floor(((Math.atan2(x - c[0], -(z - c[2])) + Math.PI) / (2 * Math.PI)) * bins),
    );
  for (const [key, [s, o]] of count) {
    if (s === 0 || (o === 0 && s > 1)) continue;
    const ends = [Math.floor(key / n), key % n];
    for (let k = 0; k <= 4; k++) {
      const t = k / 4;
      const p = [0, 1, 2].map(
        (e) => P[3 * ends[0] + e] + t * (P[3 * ends[1] + e] - P[3 * ends[0] + e]),
      );
      if (p[2] - c[2] > 0.1 || p[1] > c[1] + 0.25) continue;
      const b = binOf(p[0], p[2]);
      line[b] = Math.min(line[b], p[1]);
    }
  }
  return {
    at: (x: number, z: number) => {
      if (z - c[2] > 0.1) return Number.NaN;
      const v = line[binOf(x, z)];
      return Number.isFinite(v) ? v : Number.NaN;
    },
  };
}
