// The flat arrays a session becomes for the solver (the grid, the curves, the hair options, the
// head's scalp) and what comes back (the strands, the field, the constraints, the lighting, the
// view's vertex attributes). solver/protocol.ts carries them between the app and the worker; the
// index formula of every array is on its field.
import type { SessionSettingValues } from './sessionSchema';

/** Uniform grid over the bounding volume (method S1.2). Point (i, j, k) has index
 *  p = i + nx * (j + ny * k) and world position origin + step * (i, j, k). */
export interface GridSpec {
  dims: [number, number, number]; // nx, ny, nz
  origin: [number, number, number]; // world position of point (0, 0, 0)
  step: number; // d, world units
}

/** All style curves of a session, flattened. Curve c owns points
 *  curveStart[c] .. curveStart[c + 1] - 1; its segments have length ≈ grid step (S4). */
export interface CurveSet {
  points: Float64Array; // points[3 * point + axis], world units
  curveStart: Uint32Array; // length = curves + 1; curveStart[0] = 0
  kinds: Uint8Array; // kinds[c]: a CurveKind value (curveParams.ts)
  extend: Uint8Array; // extend[c] = 1: append fading extrapolated segments (S4.1)
  /** Parameter blocks: curve c owns params[paramStart[c] .. paramStart[c + 1] - 1]: first the
   *  scalars of its kind in CURVE_PARAMS order (curveParams.ts), then its kind's variable block:
   *  stream: none.
   *  dividing (S4.5): per point of the curve the scalp normal at it: nx, ny, nz (3 per point).
   *  ponytail (S4.6): points are the spine; the circle count m, then per cross-section circle
   *    (C1 first, C2 last): cx, cy, cz, ax, ay, az (unit axis along the spine), r (7 per circle). */
  params: Float64Array;
  paramStart: Uint32Array; // length = curves + 1
  /** Constraints stated directly (e.g. scalp avoidance, S4.7): grid index and target. They are
   *  added to those the curves derive; duplicates are averaged. */
  extraIndex: Int32Array; // extraIndex[e] = grid point p
  extraTarget: Float64Array; // extraTarget[3 * e + axis]
}

/** Hair detail for growth (detail.ts; solver-cpp/src/strand_detail.hpp): groups of
 *  DETAIL_GROUP_STRIDE (14) numbers: curl radius, frequency, start, randomOffset; clump factor,
 *  shape, tipSpread, guideDistance; frizz distance, shape; flyaway share, distance, start;
 *  lengthJitter (radius, factor, distance and share 0 = that block off). Group 0 is the session's; a strand uses the group of the curve
 *  nearest its root. */
export interface DetailArrays {
  groups: Float64Array; // groups[DETAIL_GROUP_STRIDE * g + k]
  curveGroup: Int32Array; // curveGroup[c] = group of curve c of the CurveSet (length = curves)
}

/** What a solve applies besides the curves and growth: the session's settings that shape the
 *  hair (sessionSchema.ts SESSION_SETTINGS, by name: avoidScalp, fall, …) and its detail.
 *  avoidScalp (S4.7), recomputed with the hair: after the curves' field converges, every grid
 *  point near the scalp whose field points inwards is turned along the surface (constraints of
 *  magnitude min(0.3, |v|)), and the field is solved again with them. Full solves only.
 *  fall (solver-cpp/src/hair_fall.hpp): hair no curve governs hangs from the scalp (a weak prior
 *  in the field energy), a curve's hair ends where the curve ends, and curves may take hair over
 *  the face. Off: the paper's method exactly (sessions made before it). */
export type HairOptions = SessionSettingValues & { detail: DetailArrays };

/** Grown strands. Strand s owns points strandStart[s] .. strandStart[s + 1] - 1; the first is
 *  its root on the scalp. */
export interface StrandArrays {
  points: Float32Array; // points[3 * point + axis]
  strandStart: Uint32Array; // length = strands + 1
  /** rootIds[s]: strand s's root sample index i * nPhi + j (theta row i, phi column j of the
   *  growth's root sampling): the same root keeps it across edits of curves and scalp.
   *  Absent where only shapes matter (previews, views). */
  rootIds?: Uint32Array; // length = strands
  /** tailCurves[s]: the curve whose gathered ponytail, braid or bun laid strand s, or -1. */
  tailCurves?: Int32Array; // length = strands
  /** 8 per tie: its curve's index, the centre (3) and unit axis (3) of its tail's first circle,
   *  where the growth gathers its hair, and the hair's radius there as laid (0: not one circle)
   *  (solver-cpp/src/hair_engine.hpp tieFrames): a tie's band goes there (tieBands.ts). Absent:
   *  none known (the band is found from the strands). */
  tieFrames?: Float32Array;
  /** rootSections[s]: the scalp section strand s's root is in (solver-cpp/src/
   *  scalp_sections.hpp), with the session's sections on; absent otherwise. */
  rootSections?: Uint8Array; // length = strands
}

/** Number of strands in a StrandArrays. */
export function strandCount(s: StrandArrays): number {
  return Math.max(0, s.strandStart.length - 1);
}

/** The head as the solver needs it: triangles with a scalp flag (method S1.1). */
export interface ScalpMesh {
  positions: Float32Array; // positions[3 * vertex + axis]
  indices: Uint32Array; // indices[3 * triangle + corner]
  scalp: Uint8Array; // scalp[triangle] = 1 when the triangle is part of the scalp
  center: [number, number, number]; // origin of the spherical root parameterisation (S5.1)
  /** The body below the head, which hair rests on and slides over in sessions with `bust`
   *  (the built-in bust, head/bodySdf.ts; absent on a loaded head, which is its own body). */
  body?: BodyArrays;
}

/** A closed triangle mesh beside the head: positions[3 * vertex + axis], world units;
 *  indices[3 * triangle + corner], counter-clockwise seen from outside. */
export interface BodyArrays {
  positions: Float32Array;
  indices: Uint32Array;
}

/** Lighting precomputed for a hair revision towards the fixed key light
 *  (web/lighting/hairLighting.ts, web/lighting/keyLight.ts KEY_LIGHT_DIRECTION). */
export interface HairLightingArrays {
  /** 2 per strand point (StrandArrays point order): strand[2 * point] = transmittance towards
   *  the light through hair and head, strand[2 * point + 1] = ambient occlusion (1 = open);
   *  both in [0, 1]. */
  strand: Float32Array;
  /** 1 per head vertex (ScalpMesh vertex order): transmittance through the hair towards the
   *  light, in [0, 1] (the hair's shadow on scalp and face). */
  head: Float32Array;
  ms: number; // time the precompute took in the worker
}

/** The solved field, one vector per grid point. */
export interface FieldArrays {
  vectors: Float32Array; // vectors[3 * p + axis], p = grid index
}

/** Display colour of a constraint (paper Figs. 2, 4, 5; solver-cpp/src/constraint_colour.hpp). */
export const ConstraintColour = { blue: 0, red: 1, purple: 2, green: 3, extra: 4 } as const;
export type ConstraintColourName = keyof typeof ConstraintColour;

/** The constraint set derived from the curves (method S2.3). */
export interface ConstraintArrays {
  index: Int32Array; // index[c] = grid point p of constraint c (sorted, unique)
  target: Float32Array; // target[3 * c + axis] = c_p
  /** colour[c]: ConstraintColour of constraint c (same order as index): 0 blue (stream-curve
   *  tangents, dividing-curve Gaussian profile, ponytail spine), 1 red (a stream curve's fading
   *  extension, the dividing-curve discontinuity), 2 purple (ponytail cross sections),
   *  3 green (ponytail centripetal ring), 4 extra (stated directly, e.g. scalp avoidance). */
  colour: Uint8Array;
}

/** The strands' vertex attributes for the view's line geometry (viewer/strandAttributes.ts
 *  builds them: the worker for the final hair, the page for lighter hair). Per point of
 *  StrandArrays (strand s owns points strandStart[s] .. strandStart[s + 1] − 1). */
export interface StrandVertexArrays {
  pointCount: number;
  tangent: Int8Array; // tangent[3 * point + axis]: tangent × 127 (central differences), its length encodeTurn of the strand's turn there (strandAttributes.ts)
  /** along[4 * point]: 0 at the root … 255 at the tip (by point); along[4 * point + 1]: the
   *  distance from the strand's tip by arc length (strandAttributes.ts encodeTipDistance);
   *  along[4 * point + 2], [4 * point + 3]: the strand's grey rank and balayage section
   *  (colourPlacement.ts). */
  along: Uint8Array;
  random: Uint8Array; // random[4 * point + k]: the strand's value, hue, length look, its lock's highlight × 255
  light: Uint8Array; // light[2 * point + k]: lighting.strand (transmittance, occlusion) × 255
  box: Float32Array; // min x, y, z, max x, y, z of the points; empty without points
  index: Uint32Array; // index[2 * segment + end]: point indices, strands in level-of-detail order
  lodCounts: Uint32Array; // lodCounts[g]: index entries of the first g of the 64 LOD groups
}
