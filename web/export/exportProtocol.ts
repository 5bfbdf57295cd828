// Messages between the app and the export worker. The worker grows the session's full hair from
// scratch (growSession.ts, the same pipeline as `hairsketch grow`) and streams the file back in
// chunks (transferred), so a 100K-strand export never blocks the page or builds one giant string.

import type { GridSpec, ScalpMesh } from '../model/hairArrays';
import type { MotionName } from '../model/motion';
import type { SessionState } from '../model/session';
import type { SolverErrorKind, SolverName } from '../solver/protocol';
import type { ExportFormat } from './formats';
import type { UvSurface } from './surfaceUv';
import type { ExportHead } from './types';
import type { GroomSummary } from './usdWriter';

export interface ExportRequest {
  type: 'export';
  format: ExportFormat;
  session: SessionState;
  grid: GridSpec;
  solver: SolverName;
  scalp: ScalpMesh;
  /** The head mesh to include in the file, or null. */
  head: ExportHead | null;
  /** A loaded head's own UVs (USD root UVs), when its file has them. */
  headUv?: UvSurface;
  /** Hair cards: the card count (absent: the default). */
  cards?: number;
  /** USD only: play this motion for this many frames and write them as time samples
   *  (motionExport.ts). */
  motion?: { name: MotionName; frames: number };
}

export type FromExportWorker =
  | { type: 'progress'; phase: 'solve' | 'grow' | 'write'; fraction: number }
  /** A piece of the file, in order. */
  | { type: 'chunk'; bytes: Uint8Array }
  | {
      type: 'done';
      strands: number;
      bytes: number;
      solveMs: number;
      growMs: number;
      writeMs: number;
      /** The USD groom's groups, guides and root-UV source (USD only). */
      groom?: GroomSummary;
    }
  | { type: 'error'; message: string; kind: SolverErrorKind | 'export' };
