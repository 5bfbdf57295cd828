// The hair export's shared contract: what a writer is given, and how files come out (in chunks,
// so 100K strands never make one giant string; the formats are in formats.ts). The same code runs
// in the browser's export worker and in `hairsketch grow` under Node, so the same session gives
// the same bytes.

import type { StrandArrays } from '../model/hairArrays';
import type { SessionState } from '../model/session';
import type { UvSurface } from './surfaceUv';
import type { GroomSummary } from './usdWriter';

/** Unreal's groom importer keeps at most this many points per strand. */
export const MAX_POINTS_PER_STRAND = 255;

/** 1 world unit = 10 cm (web/head/headSdf.ts). */
export const METERS_PER_UNIT = 0.1;

/** Strand diameter at the root and at the tip, world units (tapered linearly root → tip). */
export const ROOT_WIDTH = 0.0008;
export const TIP_WIDTH = 0.0002;

/** The head mesh to include, if any. */
export interface ExportHead {
  positions: Float32Array; // positions[3 * vertex + axis]
  indices: Uint32Array; // indices[3 * triangle + corner], counter-clockwise from outside
  normals?: Float32Array; // normals[3 * vertex + axis]
}

export interface ExportInput {
  /** The full hair: every strand at full resolution (strands of fewer than 2 points are
   *  skipped by every writer). */
  strands: StrandArrays;
  /** The session the hair was grown from: embedded where the format can carry it (USD custom
   *  layer data, glTF asset extras) so that "Open" reads the export back. */
  session: SessionState;
  /** The head, or null to leave it out. */
  head: ExportHead | null;
  /** A loaded head's own UVs (its mesh with HeadMesh.cornerUvs), whether or not the head is
   *  included: the USD groom's root UVs are read from them. Absent: the built-in head's
   *  scalp layout (on a loaded head, as a projection). */
  headUv?: UvSurface | null;
  /** Told what the USD groom holds (groups, guides, where root UVs come from). */
  onGroom?: (groom: GroomSummary) => void;
  /** Hair cards: how many cards to cut the hair into (cardsWriter.ts DEFAULT_CARD_COUNT when
   *  absent); the other formats ignore it. */
  cards?: number;
  /** A motion (USD only, export/motionExport.ts): the strands' points at each frame
   *  (frames[0] the groom, the layout of `strands`), the head's pose at each (model/motion.ts
   *  MotionFrame.pose) and the frame rate. The USD then carries the hair's points and the
   *  head's transform as time samples. */
  motion?: { frames: Float32Array[]; poses: Float32Array[]; frameRate: number };
}

/** Progress of a long export, 0..1. */
export type ExportProgress = (fraction: number) => void;
