// "Export": runs one export in its own worker (the page never freezes), shows progress on the
// status line and downloads the file. Waits for a running solve to finish first, so the file
// holds the converged hair of the session as it is. The PNG is drawn by the viewer.

import type { Editor } from '../editor/editor';
import type { FromExportWorker } from '../export/exportProtocol';
import {
  EXPORT_FORMATS,
  type ExportFormat,
  exportFileName,
  MOTION_EXPORT,
} from '../export/formats';
import type { UvSurface } from '../export/surfaceUv';
import type { ExportHead } from '../export/types';
import type { GroomSummary } from '../export/usdWriter';
import type { ScalpMesh } from '../model/hairArrays';
import type { MotionName } from '../model/motion';
import { sessionGrid } from '../model/session';
import { parseSession } from '../model/sessionFile';
import type { SolverName } from '../solver/protocol';

export interface ExporterDeps {
  editor: Editor;
  solver: SolverName;
  scalp: () => ScalpMesh;
  head: () => ExportHead;
  /** The head's own UVs, when it is a loaded head whose file has them. */
  headUv?: () => UvSurface | null;
  /** A loaded head's bounds for the bounding volume (sessionGrid); undefined: built-in. */
  headBounds?: () => Parameters<typeof sessionGrid>[1];
  /** Resolves once no solve is pending (at once when idle). */
  solveSettled(): Promise<void>;
  solving(): boolean;
  /** Busy text with progress, or the final sentence. */
  progress(text: string): void;
  done(message: string): void;
  failed(message: string): void;
  makeWorker?: () => Worker;
}

export interface ExportOutcome {
  name: string;
  bytes: number;
  strands: number;
  ms: number;
}

export class Exporter {
  private running: Worker | null = null;
  private abort: ((e: Error) => void) | null = null;

  constructor(private readonly d: ExporterDeps) {}

  get busy(): boolean {
    return this.running !== null;
  }

  /** Test and fault hook: kills the running export's worker as a crash would. */
  crash(): void {
    if (!this.running) return;
    this.running.terminate();
    this.abort?.(new Error('the export worker stopped'));
  }

  /** Exports the session's full hair as `format`; the head when `withHead`; hair cards cut into
   *  `cards` cards (the default when absent). */
  async export(
    format: ExportFormat,
    withHead: boolean,
    cards?: number,
    motion?: { name: MotionName; frames: number },
  ): Promise<ExportOutcome | null> {
    if (this.running) {
      this.d.failed('An export is already running; wait for it to finish.');
      return null;
    }
    const t0 = performance.now();
    const spec = EXPORT_FORMATS[format];
    if (this.d.solving()) {
      this.d.progress(`Export ${spec.statusName}: waiting for the solve to finish…`);
      await this.d.solveSettled();
    }
    const worker =
      this.d.makeWorker?.() ??
      new Worker(new URL('../export/exportWorker.ts', import.meta.url), { type: 'module' });
    this.running = worker;
    const name = motion
      ? `${MOTION_EXPORT.fileStem}.${EXPORT_FORMATS[MOTION_EXPORT.format].extension}`
      : exportFileName(format);
    const chunks: Uint8Array[] = [];
    // the USD groom's root UVs read from a loaded head's own UVs
    const headUv = spec.readsHeadUv ? this.d.headUv?.() : null;
    try {
      const done = await new Promise<Extract<FromExportWorker, { type: 'done' }>>(
        (resolve, reject) => {
          this.abort = reject;
          worker.onmessage = (ev: MessageEvent<FromExportWorker>) => {
            const m = ev.data;
            if (m.type === 'chunk') chunks.push(m.bytes);
            else if (m.type === 'progress') {
              // solve 0–60 %, growth 60–70 %, writing 70–100 %
              const f =
                m.phase === 'solve'
                  ? 0.6 * m.fraction
                  : m.phase === 'grow'
                    ? 0.6 + 0.1 * m.fraction
                    : 0.7 + 0.3 * m.fraction;
              const what =
                m.phase === 'write'
                  ? 'writing'
                  : m.phase === 'grow'
                    ? 'growing the hair'
                    : 'solving';
              this.d.progress(`Exporting ${name}: ${what}… ${Math.round(100 * f)} %`);
            } else if (m.type === 'done') resolve(m);
            else reject(new Error(m.message));
          };
          worker.onerror = (e) => {
            e.preventDefault();
            reject(new Error(e.message || 'the export worker stopped'));
          };
          // the session as the strict reader writes it: the form `hairsketch grow` embeds,
          // so the same session gives the same bytes
          const parsed = parseSession(this.d.editor.session);
          if (!parsed.ok) throw new Error(`the session is not valid (${parsed.error})`);
          worker.postMessage({
            type: 'export',
            format,
            session: parsed.value,
            grid: sessionGrid(parsed.value, this.d.headBounds?.()),
            solver: this.d.solver,
            scalp: this.d.scalp(),
            head: withHead ? this.d.head() : null,
            ...(headUv ? { headUv } : {}),
            ...(spec.takesCardCount && cards !== undefined ? { cards } : {}),
            ...(motion ? { motion } : {}),
          });
        },
      );
      download(new Blob(chunks as BlobPart[], { type: spec.mime }), name);
      const ms = performance.now() - t0;
      this.d.done(
        `Exported ${name} (${done.strands.toLocaleString('en-US')} strands, ${formatBytes(done.bytes)}, ${(ms / 1000).toFixed(1)} s)${done.groom ? `; ${groomNote(done.groom)}` : ''}.`,
      );
      return { name, bytes: done.bytes, strands: done.strands, ms };
    } catch (e) {
      this.d.failed(
        `Export ${spec.statusName} failed: ${e instanceof Error ? e.message : String(e)}. Your session is unchanged.`,
      );
      return null;
    } finally {
      worker.terminate();
      this.running = null;
      this.abort = null;
    }
  }
}

/** Starts a browser download of `blob` as `name`. */
export function download(blob: Blob, name: string): void {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 30_000);
}

/** The USD groom in the status line: groups, guides, and where the root UVs come from. */
export function groomNote(g: GroomSummary): string {
  const uv =
    g.rootUv === 'builtin-head'
      ? "root UVs from the built-in head's scalp UV layout"
      : g.rootUv === 'head-uv'
        ? "root UVs from the head's own UV map"
        : "root UVs from the built-in head's scalp layout projected from the head's centre (this head's file has no UVs)";
  return `groom of ${g.groups.length} group${g.groups.length === 1 ? '' : 's'} (${g.groups.join(', ')}), ${g.guides.toLocaleString('en-US')} guides, ${uv}`;
}

export function formatBytes(n: number): string {
  if (n < 1024) return `${n} B`;
  if (n < 1024 * 1024) return `${(n / 1024).toFixed(0)} KB`;
  return `${(n / 1024 / 1024).toFixed(1)} MB`;
}
