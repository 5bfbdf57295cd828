// Precomputed hair lighting, once per hair revision (in the solver worker): self-shadowing
// towards a key light fixed in world space, ambient occlusion, and the shadow the hair casts on
// the head. Pure arithmetic on typed arrays: no three.js, no DOM. The model, on a grid of cubic
// cells of size h (hairLightingContext.ts computes it, lightingKernels.ts holds the grid work):
//
// 1. Density: every strand point is splatted trilinearly into the grid, weighted by the strand
//    length it stands for (half of each adjacent segment), so a node holds fibre length per unit
//    volume ρ (1 / area).
// 2. Extinction: σ = k·ρ (k = `extinction`; by default chosen so that one cell of typical hair,
//    the density-weighted mean, has optical depth `autoOpacity`: the look then does not depend
//    on how many strands stand for the hair). Inside the head (voxelised by ray parity) a cell
//    adds `headOpacity`.
// 3. Transmittance T = exp(−∫σ ds) towards the light (Beer–Lambert), per node, then trilinear
//    per strand point. Hair: σ·h is summed along columns parallel to the light, one sample per
//    plane of nodes (shearedDepth.ts), and a node counts its ray from `selfCells` − ½ cells out
//    (a point does not shadow itself: splat and look-up each blur a strand over ±1 cell). Head:
//    a march in steps of one cell, counted from the second step (roots on the lit side are not
//    shadowed by the scalp they sit on), stopped at optical depth 12, then its edge softened over
//    `penumbraCells` (the key light is a softbox: softenHeadShadow). `npm run bench:lighting`
//    compares the result with a per-node march in steps of one cell.
// 4. Ambient occlusion: the mean optical thickness of the cells within `aoRadiusCells` (a box
//    mean of the hair's σ·h plus a weaker head term), times the radius: ao = exp(−aoStrength·that)
//    per node, trilinear per strand point.
// 5. Head: for each head vertex, the hair's column sum from the vertex on.
//
// The grid: computeHairLighting fits one to each call's hair and head (`resolution` cells along
// the longest side of their bounds); the solver worker keeps one HairLightingContext per head on
// a fixed grid (lightingGridFor: the head's bounds and the solver's box, cells of the head's
// longest side / `resolution`), so what depends only on the head is computed once.
//
// Output layouts (protocol.ts result.lighting):
//   strand[2 * point]     = transmittance towards the light, in [0, 1]
//   strand[2 * point + 1] = ambient occlusion (1 = open), in [0, 1]
//   head[vertex]          = transmittance through the hair towards the light, in [0, 1]
import { HairLightingContext } from './hairLightingContext';
import type { HeadTriangles } from './lightingKernels';

export type { HeadTriangles } from './lightingKernels';

export type V3 = readonly [number, number, number];

export interface HairLightingOptions {
  /** Direction towards the key light, world space (need not be unit). */
  light: V3;
  /** Grid cells along the longest side of the bounds (64). */
  resolution?: number;
  /** k: optical depth per unit distance per unit fibre density (fibre length / volume). Default:
   *  autoOpacity / (typical ρ · cell size). */
  extinction?: number;
  /** With `extinction` unset: optical depth of one cell of typical hair (0.45). */
  autoOpacity?: number;
  /** Optical depth of one cell inside the head (4: nearly opaque). */
  headOpacity?: number;
  /** The march's first sample, in cells from the point (2: the nearest 1.5 cells do not shadow
   *  it). */
  selfCells?: number;
  /** Half-width of the ambient-occlusion neighbourhood, in cells (3). */
  aoRadiusCells?: number;
  /** Scale of the occlusion's optical depth (0.9). */
  aoStrength?: number;
  /** Optical thickness per cell the head adds to the occlusion (0.35). */
  headAoOpacity?: number;
  /** Half-width, in cells, of the box over which the edge of the head's shadow is softened
   *  (5: the key light is a softbox, not a point). */
  penumbraCells?: number;
  /** Compute the hair's shadow on every head vertex (step 5; default true). Previews skip it:
   *  the view keeps the converged hair's shadow on the head while the pen moves, and on a
   *  million-triangle head it is most of the cost. */
  headShadow?: boolean;
}

export interface HairLightingInput {
  points: Float32Array; // points[3 * point + axis]
  strandStart: Uint32Array; // strand s owns points strandStart[s] .. strandStart[s + 1] - 1
}

export interface LightingGrid {
  dims: [number, number, number];
  origin: [number, number, number]; // node (0, 0, 0)
  step: number;
}

export interface HairLighting {
  /** 2 per strand point: transmittance, ambient occlusion. */
  strand: Float32Array;
  /** 1 per head vertex: transmittance through the hair (empty without a head). */
  head: Float32Array;
  grid: LightingGrid;
  /** The extinction k used (auto or given). */
  extinction: number;
}

/** Lighting of one hair on a grid fitted to it and the head (`resolution` cells along the
 *  longest side of their bounds, 2 cells of padding), computed from scratch. */
export function computeHairLighting(
  strands: HairLightingInput,
  head: HeadTriangles | null,
  options: HairLightingOptions,
): HairLighting {
  const pointCount = strands.strandStart.length > 1 ? (strands.strandStart.at(-1) ?? 0) : 0;
  const bounds = boundsOf([
    [strands.points, pointCount],
    [head?.positions ?? new Float32Array(0), head ? head.positions.length / 3 : 0],
  ]);
  if (!bounds) {
    return {
      strand: new Float32Array(2 * pointCount).fill(1),
      head: new Float32Array(head ? head.positions.length / 3 : 0).fill(1),
      grid: { dims: [0, 0, 0], origin: [0, 0, 0], step: 0 },
      extinction: 0,
    };
  }
  const extent = Math.max(...bounds.max.map((v, a) => v - bounds.min[a]), 1e-6);
  const grid = gridOver(bounds, extent / resolutionOf(options));
  return new HairLightingContext(head, grid, options).compute(strands);
}

/** The fixed lighting grid for a head whose hair stays in `box` (the solver's grid: every strand
 *  point lies in it): over the head's bounds and the box, cells of the head's longest side /
 *  `resolution` (what computeHairLighting picks for hair that stays within the head's height),
 *  coarser when that would need more than `maxCells` along the longest side. */
export function lightingGridFor(
  head: HeadTriangles | null,
  box: { min: V3; max: V3 },
  resolution = 64,
  maxCells = 96,
): LightingGrid {
  const headBounds = head ? boundsOf([[head.positions, head.positions.length / 3]]) : null;
  const all = boundsOf([[new Float32Array([...box.min, ...box.max]), 2]]) ?? {
    min: [0, 0, 0],
    max: [1, 1, 1],
  };
  const side = (b: Bounds) => Math.max(...b.max.map((v, a) => v - b.min[a]), 1e-6);
  if (headBounds)
    for (let a = 0; a < 3; a++) {
      all.min[a] = Math.min(all.min[a], headBounds.min[a]);
      all.max[a] = Math.max(all.max[a], headBounds.max[a]);
    }
  const res = Math.max(4, Math.round(resolution));
  const step = Math.max(side(headBounds ?? all) / res, side(all) / Math.max(res, maxCells));
  return gridOver(all, step);
}

interface Bounds {
  min: [number, number, number];
  max: [number, number, number];
}

const resolutionOf = (o: HairLightingOptions) => Math.max(4, Math.round(o.resolution ?? 64));

/** The grid of step h over `b` with 2 cells of padding on every side. */
function gridOver(b: Bounds, h: number): LightingGrid {
  const pad = 2;
  const dims = [0, 1, 2].map((a) => Math.ceil((b.max[a] - b.min[a]) / h) + 1 + 2 * pad);
  return {
    dims: dims as [number, number, number],
    origin: b.min.map((v) => v - pad * h) as [number, number, number],
    step: h,
  };
}

/** Bounds of the finite points of each [array, count] (null when there are none). */
function boundsOf(sets: [Float32Array, number][]): Bounds | null {
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  for (const [arr, n] of sets)
    for (let i = 0; i < n; i++) {
      const x = arr[3 * i];
      const y = arr[3 * i + 1];
      const z = arr[3 * i + 2];
      if (!(Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z))) continue;
      if (x < min[0]) min[0] = x;
      if (x > max[0]) max[0] = x;
      if (y < min[1]) min[1] = y;
      if (y > max[1]) max[1] = y;
      if (z < min[2]) min[2] = z;
      if (z > max[2]) max[2] = z;
    }
  return min[0] <= max[0] ? { min, max } : null;
}
