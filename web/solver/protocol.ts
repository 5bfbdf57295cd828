// The worker protocol: every message between the app and the solver worker, and the layout of
// every typed array that crosses the boundary. Arrays are flat; the comment on each field gives
// its index formula. Arrays sent by the worker are transferred (not copied).

/** Uniform grid over the bounding volume (SPEC S1.2). Point (i, j, k) has index
 *  p = i + nx * (j + ny * k) and world position origin + step * (i, j, k). */
export interface GridSpec {
  dims: [number, number, number]; // nx, ny, nz
  origin: [number, number, number]; // world position of point (0, 0, 0)
  step: number; // d, world units
}

/** The head as the solver needs it: triangles with a scalp flag (SPEC S1.1). */
export interface ScalpMesh {
  positions: Float32Array; // positions[3 * vertex + axis]
  indices: Uint32Array; // indices[3 * triangle + corner]
  scalp: Uint8Array; // scalp[triangle] = 1 when the triangle is part of the scalp
  center: [number, number, number]; // origin of the spherical root parameterisation (S5.1)
}

/** Style curve kinds, as stored in CurveSet.kinds. */
export const CurveKind = { stream: 0, dividing: 1, ponytail: 2 } as const;
export type CurveKindName = keyof typeof CurveKind;

/** All style curves of a session, flattened. Curve c owns points
 *  curveStart[c] .. curveStart[c + 1] - 1; its segments have length ≈ grid step (S4). */
export interface CurveSet {
  points: Float64Array; // points[3 * point + axis], world units
  curveStart: Uint32Array; // length = curves + 1; curveStart[0] = 0
  kinds: Uint8Array; // kinds[c]: a CurveKind value
  extend: Uint8Array; // extend[c] = 1: append fading extrapolated segments (S4.1)
  /** Kind-specific parameters: curve c owns params[paramStart[c] .. paramStart[c + 1] - 1].
   *  stream: none.
   *  dividing (S4.5): [sigma, h, alpha0, alpha1 (radians)], then per point of the curve the
   *    scalp normal at it: nx, ny, nz (3 per point).
   *  ponytail (S4.6): points are the spine; [tightness, circles], then per cross-section circle
   *    (C1 first, C2 last): cx, cy, cz, ax, ay, az (unit axis along the spine), r (7 per circle). */
  params: Float64Array;
  paramStart: Uint32Array; // length = curves + 1
  /** Constraints stated directly (e.g. scalp avoidance, S4.7): grid index and target. They are
   *  added to those the curves derive; duplicates are averaged. */
  extraIndex: Int32Array; // extraIndex[e] = grid point p
  extraTarget: Float64Array; // extraTarget[3 * e + axis]
}

/** Hair growth settings (SPEC S5). */
export interface GrowthParams {
  thetaStepDeg: number; // sampling step of θ ∈ [0, 180)
  phiStepDeg: number; // sampling step of φ ∈ [0, 360)
  jitter: number; // random offset as a fraction of a step, 0..1
  seed: number; // uint32: the same seed grows the same roots
  stepFraction: number; // l / d (paper: 0.5)
  minMagnitude: number; // stop when |v(p)| falls below this (paper: 0.05)
  maxLength: number; // world units: stop a strand at this length
  maxSegments: number; // stop a strand after this many segments
  maxStrands: number; // cap on the number of roots used (0 = no cap)
}

/** Grown strands. Strand s owns points strandStart[s] .. strandStart[s + 1] - 1; the first is
 *  its root on the scalp. */
export interface StrandArrays {
  points: Float32Array; // points[3 * point + axis]
  strandStart: Uint32Array; // length = strands + 1
}

/** The solved field, one vector per grid point. */
export interface FieldArrays {
  vectors: Float32Array; // vectors[3 * p + axis], p = grid index
}

/** Display colour of a constraint (paper Figs. 2, 4, 5; solver-cpp/src/constraint_colour.hpp). */
export const ConstraintColour = { blue: 0, red: 1, purple: 2, green: 3, extra: 4 } as const;
export type ConstraintColourName = keyof typeof ConstraintColour;

/** The constraint set derived from the curves (SPEC S2.3). */
export interface ConstraintArrays {
  index: Int32Array; // index[c] = grid point p of constraint c (sorted, unique)
  target: Float32Array; // target[3 * c + axis] = c_p
  /** colour[c]: ConstraintColour of constraint c (same order as index): 0 blue (stream-curve
   *  tangents, dividing-curve Gaussian profile, ponytail spine), 1 red (a stream curve's fading
   *  extension, the dividing-curve discontinuity), 2 purple (ponytail cross sections),
   *  3 green (ponytail centripetal ring), 4 extra (stated directly, e.g. scalp avoidance). */
  colour: Uint8Array;
}

export type SolverName = 'cg' | 'fast' | 'exact' | 'auto';

export interface SolveStats {
  method: string;
  iterations: number;
  errorEstimate: number; // estimated relative field error of what was grown (0 = exact)
  constraints: number;
  added: number;
  removed: number;
  changed: number;
  setupMs: number;
  solveMs: number;
  growMs: number;
  heapBytes: number; // wasm heap size after the job
}

// ---- messages -------------------------------------------------------------------------------

export type ToWorker =
  | {
      type: 'init';
      grid: GridSpec;
      omega: number;
      solver: SolverName;
      scalp: ScalpMesh;
    }
  | {
      type: 'solve';
      id: number; // increases per request; results carry it back
      curves: CurveSet;
      growth: GrowthParams;
      wantField: boolean;
      /** 'preview': a few iterations and a light growth, for live feedback while drawing;
       *  'full': a quick first look, then iterate to convergence and grow the final hair. */
      mode: 'preview' | 'full';
    }
  | {
      /** Scalp penetration avoidance (S4.7): solve `curves` to convergence, then derive the
       *  avoidance constraints from that field. Answered by 'avoidance' with the same id. */
      type: 'avoidScalp';
      id: number;
      curves: CurveSet;
      band: number; // grid steps from the head surface
      magnitude: number; // target length (paper: 0.3)
      wholeHead: boolean; // measure against every head triangle, not only the scalp
      /** Also grid points inside the head within the band: growth interpolates them just
       *  outside the surface. */
      insideToo: boolean;
    };

export type FromWorker =
  | { type: 'ready'; gridPoints: number; roots: number }
  | { type: 'progress'; id: number; phase: 'constraints' | 'solve' | 'grow'; fraction: number }
  | {
      type: 'result';
      id: number;
      strands: StrandArrays;
      constraints: ConstraintArrays;
      field: FieldArrays | null;
      stats: SolveStats;
      /** True for the converged field's hair; false for a preview or a first look. */
      final: boolean;
    }
  | {
      /** Answer to 'avoidScalp': ready for CurveSet.extraIndex / extraTarget. */
      type: 'avoidance';
      id: number;
      index: Int32Array; // index[e] = grid point p (sorted)
      target: Float64Array; // target[3 * e + axis]
    }
  | { type: 'error'; id: number | null; message: string };

/** Transfer list for a result message: every array buffer it carries. */
export function resultTransferables(msg: Extract<FromWorker, { type: 'result' }>): ArrayBuffer[] {
  const list: ArrayBuffer[] = [
    msg.strands.points.buffer as ArrayBuffer,
    msg.strands.strandStart.buffer as ArrayBuffer,
    msg.constraints.index.buffer as ArrayBuffer,
    msg.constraints.target.buffer as ArrayBuffer,
    msg.constraints.colour.buffer as ArrayBuffer,
  ];
  if (msg.field) list.push(msg.field.vectors.buffer as ArrayBuffer);
  return list;
}

/** Number of strands in a StrandArrays. */
export function strandCount(s: StrandArrays): number {
  return Math.max(0, s.strandStart.length - 1);
}
