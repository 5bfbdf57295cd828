// What a parting did, in a sentence for the status line: whether it bounds a section (scalp_sections
// in the solver splits the scalp along partings; the worker names each strand's section,
// StrandArrays.rootSections) and, if it does, the sections on either side with their share of
// the hair: "c1 splits the scalp: top 38 %, rest 62 %" or "c1 parts the hair: a parting…". A user
// who ends a parting short of the hairline sees at once whether it made the section a tie needs.
import type { StrandArrays } from './hairArrays';
import type { Vec3 } from './vec3';

/** Roots this close to the parting's line (world units, 1.5 cm) tell which sections it bounds. */
const NEAR = 0.15;
/** A section bounds the parting when at least this share of the roots near it lies in it. */
const SIDE_SHARE = 0.05;

type Hair = Pick<StrandArrays, 'points' | 'strandStart' | 'rootSections'>;

function distanceToPolyline(p: Vec3, line: readonly Vec3[]): number {
  let best = Infinity;
  for (let k = 0; k + 1 < line.length; k++) {
    const a = line[k];
    const b = line[k + 1];
    const ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    const ap = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
    const len2 = ab[0] ** 2 + ab[1] ** 2 + ab[2] ** 2;
    const t =
      len2 > 0
        ? Math.min(1, Math.max(0, (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / len2))
        : 0;
    const d = Math.hypot(ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]);
    if (d < best) best = d;
  }
  if (line.length === 1) best = Math.hypot(p[0] - line[0][0], p[1] - line[0][1], p[2] - line[0][2]);
  return best;
}

/** Names for a section by where its hair grows against another's (or the whole head's): the axis
 *  they differ most along. The head faces +z, its left is +x. */
function sideName(d: Vec3): string {
  const ax = Math.abs(d[0]);
  const ay = Math.abs(d[1]);
  const az = Math.abs(d[2]);
  // a section held round the crown is "top" even when it also lies forward (a half-up's)
  if (ay >= 0.5 * Math.max(ax, az)) return d[1] > 0 ? 'top' : 'rest';
  if (az >= ax) return d[2] > 0 ? 'front' : 'back';
  return d[0] > 0 ? 'left' : 'right';
}

const pct = (x: number) => `${Math.round(100 * x)} %`;

/** The sentence for parting `id` drawn along `line`, from the hair grown with it; null when the
 *  hair carries no sections (sections off, or no hair). */
export function partingReport(id: string, line: readonly Vec3[], hair: Hair | null): string | null {
  const sections = hair?.rootSections;
  if (
    !hair ||
    !sections ||
    sections.length === 0 ||
    sections.length + 1 !== hair.strandStart.length
  )
    return null;
  const P = hair.points;
  const n = sections.length;
  const count = new Map<number, number>();
  const sum = new Map<number, Vec3>();
  const near = new Map<number, number>();
  let nearAll = 0;
  for (let s = 0; s < n; s++) {
    const k = 3 * hair.strandStart[s];
    const r: Vec3 = [P[k], P[k + 1], P[k + 2]];
    const sec = sections[s];
    count.set(sec, (count.get(sec) ?? 0) + 1);
    const c = sum.get(sec) ?? [0, 0, 0];
    sum.set(sec, [c[0] + r[0], c[1] + r[1], c[2] + r[2]]);
    if (distanceToPolyline(r, line) <= NEAR) {
      near.set(sec, (near.get(sec) ?? 0) + 1);
      nearAll++;
    }
  }
  const sides = [...near.entries()]
    .filter(([, m]) => m >= Math.max(3, SIDE_SHARE * nearAll))
    .map(([sec]) => sec);
  if (sides.length < 2)
    return `${id} parts the hair: a parting (for sections to tie, end it within 5 cm of the hairline or of another parting)`;
  const centre = (sec: number): Vec3 => {
    const c = sum.get(sec) as Vec3;
    const m = count.get(sec) ?? 1;
    return [c[0] / m, c[1] / m, c[2] / m];
  };
  let names: string[];
  if (sides.length === 2) {
    const a = centre(sides[0]);
    const b = centre(sides[1]);
    const first = sideName([a[0] - b[0], a[1] - b[1], a[2] - b[2]]);
    const other: Record<string, string> = {
      top: 'rest',
      rest: 'top',
      front: 'back',
      back: 'front',
      left: 'right',
      right: 'left',
    };
    names = [first, other[first]];
  } else {
    const all: Vec3 = [0, 0, 0];
    for (const sec of count.keys()) {
      const c = sum.get(sec) as Vec3;
      for (let e = 0; e < 3; e++) all[e] += c[e] / n;
    }
    names = sides.map((sec) => {
      const c = centre(sec);
      return sideName([c[0] - all[0], c[1] - all[1], c[2] - all[2]]);
    });
    // the same name twice: number them
    names = names.map((nm, i) =>
      names.indexOf(nm) !== names.lastIndexOf(nm)
        ? `${nm} ${names.slice(0, i + 1).filter((x) => x === nm).length}`
        : nm,
    );
  }
  // the larger name first reads oddly for "top"/"rest": keep top, front, left first
  const order = sides.map((sec, i) => ({ name: names[i], share: (count.get(sec) ?? 0) / n }));
  const rank = ['top', 'front', 'left'];
  order.sort((x, y) => {
    const rx = rank.some((r) => x.name.startsWith(r)) ? 0 : 1;
    const ry = rank.some((r) => y.name.startsWith(r)) ? 0 : 1;
    return rx - ry;
  });
  return `${id} splits the scalp: ${order.map((o) => `${o.name} ${pct(o.share)}`).join(', ')}`;
}
