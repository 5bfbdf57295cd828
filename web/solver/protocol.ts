// The worker protocol: every message between the app and the solver worker, and the layout of
// every typed array that crosses the boundary. Arrays are flat; the comment on each field gives
// its index formula. Arrays sent by the worker are transferred (not copied).

// Messages only: the session's domain (curve kinds and their parameters, growth settings, the
// detail layout) and every flat array that crosses (the session's, the strands, the field, the
// constraints, the lighting, the view's attributes) live in web/model/ (hairArrays.ts has each
// array's index formula on its field); the wasm boundary's C structs in wasmStructs.ts. In short:
//   GridSpec: point (i, j, k) has index p = i + nx * (j + ny * k), position origin + step * (i, j, k).
//   CurveSet: points[3 * point + axis]; curve c owns points curveStart[c] .. curveStart[c + 1] - 1
//     and params[paramStart[c] .. paramStart[c + 1] - 1]: its kind's CURVE_PARAMS scalars in
//     table order, then its kind's variable block (dividing: a normal per point, 3 numbers;
//     ponytail: the circle count, then cx, cy, cz, ax, ay, az, r per circle); extraIndex[e],
//     extraTarget[3 * e + axis].
//   DetailArrays: groups[DETAIL_GROUP_STRIDE * g + k] (model/detail.ts has k's order),
//     curveGroup[c].
//   StrandArrays: points[3 * point + axis]; strand s owns strandStart[s] .. strandStart[s + 1] - 1;
//     optional rootIds[s] (its root's sample index), tailCurves[s] (the curve whose tail laid it,
//     or -1), rootSections[s] (its root's scalp section, with sections on), tieFrames[8 * t + k]
//     (tie t: k = 0 its curve's index, 1..3 its first circle's centre, 4..6 its unit axis, 7 its
//     hair's radius there, 0 when that is not one circle).
import type { GrowthParams } from '../model/growthParams';
import type { FollowerAttributes, GuideBinding } from '../model/guideFollowers';
import type {
  ConstraintArrays,
  CurveSet,
  FieldArrays,
  GridSpec,
  HairLightingArrays,
  HairOptions,
  ScalpMesh,
  StrandArrays,
  StrandVertexArrays,
} from '../model/hairArrays';
import type { MotionName, WindSettings } from '../model/motion';
export type SolverName = 'cg' | 'fast' | 'exact' | 'auto';

/** What went wrong in a solver call (wasmStructs.ts SOLVER_STATUS gives the binding's code of
 *  each). */
export type SolverErrorKind =
  | 'invalid_input' // malformed input: sizes, ranges, layout, an unknown name
  | 'non_finite' // a NaN or infinity in the input
  | 'over_memory_cap' // the grid or its factor would not fit the memory cap
  | 'not_ready' // called before what it needs (no grid, no scalp, not solved since the edit)
  | 'internal'; // a numerical failure or anything else

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
  /** The wasm module that solved: "threads: N" or "single-threaded: <why>" (status tooltip). */
  module?: string;
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
      /** A new scalp on the same head (the scalp brush): solves after it grow their roots over
       *  it; the head's distance grid, the grid and the field stay. Refused (an 'error' with id
       *  null, the previous scalp kept) when its length is not the head's triangle count. */
      type: 'scalpMask';
      scalp: Uint8Array; // scalp[triangle] = 1 on the scalp; length = triangles of init's head
    }
  | {
      /** The solver moves to another grid (the session's bounding volume changed): the engine
       *  is set up on it in place (no new worker; the head, its scalp and its distance grid
       *  stay), the job running is dropped, and the field is zero until the next solve. A grid
       *  the engine refuses (the memory cap) is reported as an 'error' with id null. */
      type: 'grid';
      grid: GridSpec;
    }
  | {
      type: 'solve';
      id: number; // increases per request; results carry it back
      curves: CurveSet;
      growth: GrowthParams;
      options: HairOptions;
      wantField: boolean;
      /** 'preview': a few iterations and a light growth, for live feedback while drawing;
       *  'full': a quick first look, then iterate to convergence and grow the final hair. */
      mode: 'preview' | 'full';
      /** Strand cap of the light growths (a preview, a full solve's first look); growth.maxStrands
       *  still applies when smaller. 0 = no cap of its own. Chosen by the app (what it can draw
       *  while the pen moves). */
      lightMaxStrands: number;
    }
  | {
      /** Plays a motion over the strands on screen (HairSim in the worker, over the init head and,
       *  with `body`, its body; model/motion.ts): the strands are copied, a motion already playing
       *  is dropped. Answered by 'motionBound' and then the 'motionFrame' of frame 0 (the guides at
       *  rest). */
      type: 'motionStart';
      /** Names this play: its binding and frames carry it (a play stopped before is dropped). */
      play: number;
      /** The page draws every pointStride-th point of each strand and its tip (1: every
       *  point; strandSubsample.ts everyNthPoint): motionBound's attributes are of those. */
      pointStride: number;
      motion: MotionName;
      seed: number; // uint32: the session's seed (the wind's gusts)
      body: boolean;
      wind?: WindSettings; // the Wind motion's direction and speed (DEFAULT_WIND when absent)
      strands: StrandArrays; // points, strandStart, tailCurves (per strand, optional) as above
    }
  | {
      /** Advances the motion `frames` frames (1/24 s each) and answers with the last one.
       *  `recycle`: frames' guide arrays the page is done with (transferred), refilled for later
       *  frames. */
      type: 'motionStep';
      frames: number;
      recycle?: Float32Array[];
    }
  | { type: 'motionStop' };

export type FromWorker =
  | { type: 'ready'; gridPoints: number; roots: number }
  | { type: 'progress'; id: number; phase: 'constraints' | 'solve' | 'grow'; fraction: number }
  | {
      type: 'result';
      id: number;
      /** The grown strands; a preview's with every other point and the tip of each
       *  (model/strandSubsample.ts everyOtherPoint), lighting per those points. */
      strands: StrandArrays;
      constraints: ConstraintArrays;
      field: FieldArrays | null;
      /** Self-shadowing, occlusion and the hair's shadow on the head; absent or null when the
       *  worker computed none. */
      lighting?: HairLightingArrays | null;
      stats: SolveStats;
      /** True for the converged field's hair; false for a preview or a first look. */
      final: boolean;
      /** The final hair's vertex attributes for the view, built in the worker with `lighting`
       *  (viewer/strandAttributes.ts lineAttributes), so the page does not stall building them;
       *  absent or null for previews and first looks (the page builds those). */
      attributes?: StrandVertexArrays | null;
      /** The field is converged: true with `final`, and for the light growth of the converged
       *  field posted before the full hair (final false); absent or false otherwise. */
      converged?: boolean;
    }
  | { type: 'error'; id: number | null; message: string; kind: SolverErrorKind }
  | {
      /** The motion started: its guides and how motionStart's strands are bound to them, and
       *  the strand shader's attributes of each point drawn (motionStart.pointStride;
       *  model/guideFollowers.ts: follow, 2 floats; offset, 3 floats; tangent, 3 signed bytes),
       *  made here so the page does not. Transferred. */
      type: 'motionBound';
      play: number;
      binding: GuideBinding;
      attributes: FollowerAttributes;
    }
  | {
      /** A frame of the motion playing: its guides, guides[3 * (guide * G + point) + axis] (G:
       *  the binding's guidePoints); pose[0..8] the head's rotation row-major, pose[9..11] its
       *  translation (world = R * groom + t, the head and body meshes move by it). The strands
       *  are placed on the guides by the strand shader (guideFollowers.ts placeFollowers on the
       *  CPU). Transferred. */
      type: 'motionFrame';
      play: number;
      frame: number;
      /** The worker's time stepping the guides to this frame and reading them (ms). */
      stepMs: number;
      guides: Float32Array;
      pose: Float32Array;
    }
  | { type: 'motionError'; message: string };

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
  if (msg.lighting)
    list.push(msg.lighting.strand.buffer as ArrayBuffer, msg.lighting.head.buffer as ArrayBuffer);
  const a = msg.attributes;
  if (a)
    for (const v of [a.tangent, a.along, a.random, a.light, a.box, a.index, a.lodCounts])
      if (!list.includes(v.buffer as ArrayBuffer)) list.push(v.buffer as ArrayBuffer);
  return list;
}
