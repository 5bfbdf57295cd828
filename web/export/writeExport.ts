// The export entry point: one format, one input, the file as a sequence of chunks (each at most
// CHUNK_BYTES). Pure TypeScript (typed arrays and TextEncoder only): it runs the same in the
// browser's export worker and under Node, and the same input gives byte-identical output.
import { Progress } from './chunkSink';
import { type ExportFormat, isExportFormat } from './formats';
import { EXPORT_WRITERS } from './formatWriters';
import { strandsForExport } from './strandsForExport';
import type { ExportInput, ExportProgress } from './types';

/** Writes `input` as `format` (its writer in formatWriters.ts), yielding the file in chunks of at most
 *  CHUNK_BYTES (1 MiB). onProgress gets non-decreasing fractions 0..1 as strand batches are
 *  written, ending with 1. */
export function* writeExport(
  format: ExportFormat,
  input: ExportInput,
  onProgress?: ExportProgress,
): Generator<Uint8Array> {
  const progress = new Progress(onProgress);
  progress.at(0);
  const strands = strandsForExport(input.strands, input.session);
  if (!isExportFormat(format)) throw new Error(`unknown export format ${String(format)}`);
  yield* EXPORT_WRITERS[format](strands, input, progress);
}
