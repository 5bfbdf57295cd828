// Each export format's writer (formats.ts has everything else about the format): apart so that
// only the export worker and the CLI load the writers.
import { writeCardsGlb } from './cardsWriter';
import type { Progress } from './chunkSink';
import type { ExportFormat } from './formats';
import { writeGlb } from './glbWriter';
import { writeHair } from './hairWriter';
import { writeObj } from './objWriter';
import type { ExportStrands } from './strandsForExport';
import type { ExportInput } from './types';
import { writeUsda } from './usdWriter';

/** Writes the strands (strandsForExport) of `input` as one format, in chunks. */
export type ExportWriter = (
  strands: ExportStrands,
  input: ExportInput,
  progress: Progress,
) => Generator<Uint8Array>;

export const EXPORT_WRITERS: { readonly [F in ExportFormat]: ExportWriter } = {
  usda: writeUsda,
  hair: writeHair,
  obj: writeObj,
  glb: writeGlb,
  cards: writeCardsGlb,
};
