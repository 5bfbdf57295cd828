// The export entry point: one format, one input, the file as a sequence of chunks (each at most
// CHUNK_BYTES). Pure TypeScript (typed arrays and TextEncoder only): it runs the same in the
// browser's export worker and under Node, and the same input gives byte-identical output.
import { writeCardsGlb } from './cardsWriter';
import { CHUNK_BYTES, Progress } from './chunkSink';
import { writeGlb } from './glbWriter';
import { writeHair } from './hairWriter';
import { writeObj } from './objWriter';
import { strandsForExport } from './strandsForExport';
import type { ExportFormat, ExportInput, ExportProgress } from './types';
import { writeUsda } from './usdWriter';

export { CHUNK_BYTES };

/** Writes `input` as `format`, yielding the file in chunks of at most CHUNK_BYTES (1 MiB).
 *  onProgress gets non-decreasing fractions 0..1 as strand batches are written, ending with 1. */
export function* writeExport(
  format: ExportFormat,
  input: ExportInput,
  onProgress?: ExportProgress,
): Generator<Uint8Array> {
  const progress = new Progress(onProgress);
  progress.at(0);
  const strands = strandsForExport(input.strands, input.session);
  switch (format) {
    case 'usda':
      yield* writeUsda(strands, input, progress);
      return;
    case 'hair':
      yield* writeHair(strands, input, progress);
      return;
    case 'obj':
      yield* writeObj(strands, input, progress);
      return;
    case 'glb':
      yield* writeGlb(strands, input, progress);
      return;
    case 'cards':
      yield* writeCardsGlb(strands, input, progress);
      return;
    default: {
      const never: never = format;
      throw new Error(`unknown export format ${String(never)}`);
    }
  }
}

/** The format of a file name by its extension (case-insensitive): .usda, .hair, .obj, .glb;
 *  null for anything else (.usd, .usdc and .gltf included). */
export function formatFromFileName(name: string): ExportFormat | null {
  const m = /\.([A-Za-z]+)$/.exec(name.trim());
  if (!m) return null;
  switch (m[1].toLowerCase()) {
    case 'usda':
      return 'usda';
    case 'hair':
      return 'hair';
    case 'obj':
      return 'obj';
    case 'glb':
      return 'glb';
    default:
      return null;
  }
}
