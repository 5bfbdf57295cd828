// What makes the exported strands a groom (docs/export.md, "File layouts"): per strand a stable
// id, a group, a root UV, and its three closest guides with weights; the guides a sparse subset
// of the strands. Pure and deterministic (no randomness beyond a seeded hash), so the browser
// and `hairsketch grow` write the same bytes.
//
//  - id: the root's sample index from the growth (StrandArrays.rootIds: theta row × phi columns
//    + phi column), so a strand keeps its id when curves elsewhere change; without rootIds, the
//    strand's index in the grown hair.
//  - group: the gathered ponytail, braid or bun that laid the strand (the growth says which:
//    StrandArrays.tailCurves); a ponytail the growth does not gather takes the strands that cross
//    its first circle's plane near it (as the growth would capture them); the rest go to a side of the nearest parting (dividing curve)
//    by their root, or to "hair" when there is no parting.
//  - guides: per group, a greedy Poisson-disc pass over the roots (GUIDE_SPACING apart) in a
//    seeded order of their ids. A guide is a copy of its strand and has the strand's id.
//  - closest guides: the three nearest guide roots of the strand's group, weights ∝ 1 / distance
//    summing to 1 (a guide's own strand: itself, weight 1); with fewer than three guides in
//    the group the nearest one is repeated with weight 0.
//  - root UV: on a head with its own UVs (a loaded head whose file has them), those UVs at the
//    closest point of the head to the root (surfaceUv.ts); otherwise the scalp layout
//    (scalpUv.ts) at the root: the built-in head's UVs, a projection on a loaded head.

import type { StrandArrays } from '../model/hairArrays';
import { defOf } from '../model/kinds';
import type { SessionState, StyleCurve } from '../model/session';
import { scalpUvAt } from './scalpUv';
import { type ExportStrands, strandHash } from './strandsForExport';
import { SurfaceUvLookup, type UvSurface } from './surfaceUv';

/** The scalp parameterisation's centre: the origin for the built-in head and for loaded heads
 *  (head/loadHead.ts places them so). */
export const HEAD_CENTER: readonly [number, number, number] = [0, 0, 0];

/** How far from a ponytail's axis, in radii of its first circle, a strand crossing that circle's
 *  plane joins it (solver-cpp/src/gathered_tail.hpp kTailCapture). */
const TAIL_CAPTURE = 2.5;

/** Closest distance between two guide roots, world units (1 cm). */
export const GUIDE_SPACING = 0.1;

export interface GroomLayout {
  /** ids[s]: strand s's groom_id. */
  ids: Int32Array;
  /** groupOf[s]: index into groupNames (= groom_group_id). */
  groupOf: Int32Array;
  groupNames: string[];
  /** rootUv[2 * s + k]. */
  rootUv: Float32Array;
  /** Where rootUv comes from: the head's own UVs, or the scalp layout. */
  rootUvFrom: 'head-uv' | 'scalp-layout';
  /** The exported strands that are also guides, in increasing order. */
  guides: Uint32Array;
  /** closestGuides[3 * s + k]: the groom_id of a guide (as a float, as Unreal reads it). */
  closestGuides: Float32Array;
  guideWeights: Float32Array; // guideWeights[3 * s + k]
}

/** Whether a curve gathers its hair into a group of its own: the kind table's ties. */
const isGathering = (c: StyleCurve): boolean => defOf(c).role === 'tie';

interface Parting {
  curve: number;
  points: number[][];
  sides: number[][]; // sides[i]: unit direction across the parting at points[i] (t × n)
  names: [string, string]; // the positive side's group name, then the negative side's
}

/** The side directions of a dividing curve and the names of its sides, from the mean side
 *  direction: across x the head's left (+x) and right, across z its front (+z) and back. */
function parting(curve: Extract<StyleCurve, { type: 'dividing' }>, index: number, k: number) {
  const P = curve.points;
  const sides: number[][] = [];
  const mean = [0, 0, 0];
  for (let i = 0; i < P.length; i++) {
    const a = P[Math.max(0, i - 1)];
    const b = P[Math.min(P.length - 1, i + 1)];
    const t = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    const n = curve.normals[i] ?? [0, 1, 0];
    const s = [t[1] * n[2] - t[2] * n[1], t[2] * n[0] - t[0] * n[2], t[0] * n[1] - t[1] * n[0]];
    const len = Math.hypot(s[0], s[1], s[2]) || 1;
    sides.push([s[0] / len, s[1] / len, s[2] / len]);
    for (let c = 0; c < 3; c++) mean[c] += s[c] / len;
  }
  const byX = Math.abs(mean[0]) >= Math.abs(mean[2]);
  const plus = byX ? (mean[0] >= 0 ? 'left' : 'right') : mean[2] >= 0 ? 'front' : 'back';
  const minus = byX ? (mean[0] >= 0 ? 'right' : 'left') : mean[2] >= 0 ? 'back' : 'front';
  const names: [string, string] = [`parting${k}_${plus}`, `parting${k}_${minus}`];
  return { curve: index, points: P.map((p) => [...p]), sides, names } satisfies Parting;
}

/** Builds the layout of `strands` (grown as `source`) for `session`; `headUv`: the head with
 *  its own UVs, when it has them. */
export function groomLayout(
  strands: ExportStrands,
  source: Pick<StrandArrays, 'rootIds' | 'tailCurves'>,
  session: Pick<SessionState, 'curves' | 'growth'>,
  headUv: UvSurface | null = null,
): GroomLayout {
  const { points, strandStart } = strands;
  const n = strandStart.length - 1;
  const rootIds = source.rootIds;
  const tails = source.tailCurves;
  const ids = new Int32Array(n);
  for (let s = 0; s < n; s++) ids[s] = rootIds ? rootIds[strands.source[s]] : strands.source[s];

  // ---- groups -------------------------------------------------------------------------------
  const curves = session.curves;
  // groups numbered per kind in the session's order (ponytail1, bun1, bun2…): every kind the
  // kind table calls a tie counts from 1, whatever its name
  const count = new Map<string, number>();
  const next = (kind: string) => {
    const k = (count.get(kind) ?? 0) + 1;
    count.set(kind, k);
    return k;
  };
  const tailName = new Map<number, string>();
  const partings: Parting[] = [];
  curves.forEach((c, i) => {
    if (isGathering(c)) tailName.set(i, `${c.type}${next(c.type)}`);
    else if (c.type === 'dividing' && c.points.length > 0)
      partings.push(parting(c, i, next('dividing')));
  });
  // a key per strand: 'hair', 'tail:<curve>' or 'part:<curve>:<0|1>'
  const key: string[] = new Array(n);
  const laid = new Set<number>();
  if (tails)
    for (let s = 0; s < n; s++)
      if (tails[strands.source[s]] >= 0) laid.add(tails[strands.source[s]]);
  for (let s = 0; s < n; s++) {
    const t = tails ? tails[strands.source[s]] : -1;
    if (t >= 0 && tailName.has(t)) key[s] = `tail:${t}`;
  }
  // ponytails the growth did not gather: the strands that cross their first circle's plane
  // going along its axis within TAIL_CAPTURE radii of its centre (the growth's capture rule,
  // solver-cpp/src/gathered_tail.hpp)
  curves.forEach((c, i) => {
    if (c.type !== 'ponytail' || laid.has(i) || c.circles.length === 0) return;
    const { centre, axis, radius } = c.circles[0];
    const reach2 = (TAIL_CAPTURE * radius) ** 2;
    for (let s = 0; s < n; s++) {
      if (key[s] !== undefined) continue;
      let w0 = Number.NaN;
      for (let p = strandStart[s]; p < strandStart[s + 1]; p++) {
        const dx = points[3 * p] - centre[0];
        const dy = points[3 * p + 1] - centre[1];
        const dz = points[3 * p + 2] - centre[2];
        const w1 = dx * axis[0] + dy * axis[1] + dz * axis[2];
        if (w0 < 0 && w1 >= 0) {
          // the crossing, interpolated on the segment
          const t = w0 / (w0 - w1);
          const q = [0, 1, 2].map(
            (k) =>
              points[3 * (p - 1) + k] +
              t * (points[3 * p + k] - points[3 * (p - 1) + k]) -
              centre[k],
          );
          const along = q[0] * axis[0] + q[1] * axis[1] + q[2] * axis[2];
          const r2 = q[0] ** 2 + q[1] ** 2 + q[2] ** 2 - along * along;
          if (r2 <= reach2) {
            key[s] = `tail:${i}`;
            break;
          }
        }
        w0 = w1;
      }
    }
  });
  for (let s = 0; s < n; s++) {
    if (key[s] !== undefined) continue;
    if (partings.length === 0) {
      key[s] = 'hair';
      continue;
    }
    const a = 3 * strandStart[s];
    const rx = points[a];
    const ry = points[a + 1];
    const rz = points[a + 2];
    let best = Number.POSITIVE_INFINITY;
    let side = '';
    for (const pt of partings)
      for (let i = 0; i < pt.points.length; i++) {
        const q = pt.points[i];
        const dx = rx - q[0];
        const dy = ry - q[1];
        const dz = rz - q[2];
        const d2 = dx * dx + dy * dy + dz * dz;
        if (d2 < best) {
          best = d2;
          const b = pt.sides[i];
          side = `part:${pt.curve}:${dx * b[0] + dy * b[1] + dz * b[2] >= 0 ? 0 : 1}`;
        }
      }
    key[s] = side;
  }
  // group ids in a fixed order: the rest, the partings' sides, the tails (curve order); only
  // groups that hold strands
  const present = new Set(key);
  const order: [string, string][] = [['hair', 'hair']];
  for (const pt of partings) {
    order.push([`part:${pt.curve}:0`, pt.names[0]], [`part:${pt.curve}:1`, pt.names[1]]);
  }
  for (const [i, name] of tailName) order.push([`tail:${i}`, name]);
  const groupNames: string[] = [];
  const groupIndex = new Map<string, number>();
  for (const [k, name] of order)
    if (present.has(k)) {
      groupIndex.set(k, groupNames.length);
      groupNames.push(name);
    }
  const groupOf = new Int32Array(n);
  for (let s = 0; s < n; s++) groupOf[s] = groupIndex.get(key[s]) as number;

  // ---- guides -------------------------------------------------------------------------------
  const seed = session.growth.seed;
  const rank = new Uint32Array(n);
  for (let s = 0; s < n; s++) rank[s] = strandHash(seed ^ 0x67756964, ids[s]);
  const byRank = Array.from({ length: n }, (_, s) => s).sort(
    (x, y) => rank[x] - rank[y] || ids[x] - ids[y],
  );
  const rootOf = (s: number, c: number) => points[3 * strandStart[s] + c];
  const grids = groupNames.map(() => new Map<string, number[]>());
  const cell = (s: number) =>
    [0, 1, 2].map((c) => Math.floor(rootOf(s, c) / GUIDE_SPACING)) as [number, number, number];
  const isGuide = new Uint8Array(n);
  const r2 = GUIDE_SPACING * GUIDE_SPACING;
  for (const s of byRank) {
    const grid = grids[groupOf[s]];
    const [cx, cy, cz] = cell(s);
    let free = true;
    for (let i = -1; i <= 1 && free; i++)
      for (let j = -1; j <= 1 && free; j++)
        for (let k = -1; k <= 1 && free; k++)
          for (const g of grid.get(`${cx + i},${cy + j},${cz + k}`) ?? []) {
            const dx = rootOf(s, 0) - rootOf(g, 0);
            const dy = rootOf(s, 1) - rootOf(g, 1);
            const dz = rootOf(s, 2) - rootOf(g, 2);
            if (dx * dx + dy * dy + dz * dz < r2) {
              free = false;
              break;
            }
          }
    if (!free) continue;
    isGuide[s] = 1;
    const kc = `${cx},${cy},${cz}`;
    const list = grid.get(kc);
    if (list) list.push(s);
    else grid.set(kc, [s]);
  }
  const guides: number[] = [];
  for (let s = 0; s < n; s++) if (isGuide[s]) guides.push(s);
  const guidesOf: number[][] = groupNames.map(() => []);
  for (const g of guides) guidesOf[groupOf[g]].push(g);

  // ---- closest guides ------------------------------------------------------------------------
  const closestGuides = new Float32Array(3 * n);
  const guideWeights = new Float32Array(3 * n);
  const bestD = new Float64Array(3);
  const bestG = new Int32Array(3);
  for (let s = 0; s < n; s++) {
    if (isGuide[s]) {
      closestGuides.fill(ids[s], 3 * s, 3 * s + 3);
      guideWeights[3 * s] = 1;
      continue;
    }
    bestD.fill(Number.POSITIVE_INFINITY);
    bestG.fill(-1);
    const rx = rootOf(s, 0);
    const ry = rootOf(s, 1);
    const rz = rootOf(s, 2);
    for (const g of guidesOf[groupOf[s]]) {
      const dx = rx - rootOf(g, 0);
      const dy = ry - rootOf(g, 1);
      const dz = rz - rootOf(g, 2);
      const d = Math.sqrt(dx * dx + dy * dy + dz * dz);
      if (d >= bestD[2]) continue;
      let k = 2;
      while (k > 0 && d < bestD[k - 1]) {
        bestD[k] = bestD[k - 1];
        bestG[k] = bestG[k - 1];
        k--;
      }
      bestD[k] = d;
      bestG[k] = g;
    }
    let sum = 0;
    for (let k = 0; k < 3; k++) if (bestG[k] >= 0) sum += 1 / Math.max(bestD[k], 1e-6);
    for (let k = 0; k < 3; k++) {
      const g = bestG[k] >= 0 ? bestG[k] : bestG[0];
      closestGuides[3 * s + k] = ids[g];
      guideWeights[3 * s + k] = bestG[k] >= 0 ? 1 / Math.max(bestD[k], 1e-6) / sum : 0;
    }
  }

  const rootUv = new Float32Array(2 * n);
  const surface = headUv && headUv.indices.length > 0 ? new SurfaceUvLookup(headUv) : null;
  for (let s = 0; s < n; s++)
    if (surface) surface.uvAt(rootOf(s, 0), rootOf(s, 1), rootOf(s, 2), rootUv, 2 * s);
    else scalpUvAt(rootOf(s, 0), rootOf(s, 1), rootOf(s, 2), HEAD_CENTER, rootUv, 2 * s);

  return {
    ids,
    groupOf,
    groupNames,
    rootUv,
    rootUvFrom: surface ? 'head-uv' : 'scalp-layout',
    guides: Uint32Array.from(guides),
    closestGuides,
    guideWeights,
  };
}
