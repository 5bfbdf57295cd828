// The export Web Worker: one export per worker. Loads the wasm engine, grows the session's full
// hair from a cold start (growSession.ts: the same strands as `hairsketch grow`), writes the
// file with writeExport and posts it back in chunks, with progress.
import wasmUrl from '../generated/hairsolver.wasm?url';
import { SolverError } from '../solver/engine';
import { loadSolverEngine } from '../solver/wasmEngine';
import type { ExportRequest, FromExportWorker } from './exportProtocol';
import { growSessionHair } from './growSession';
import { simulateMotion } from './motionExport';
import { exportedCounts } from './strandsForExport';
import type { GroomSummary } from './usdWriter';
import { writeExport } from './writeExport';

const scope = self as unknown as {
  postMessage(msg: FromExportWorker, transfer?: Transferable[]): void;
  onmessage: ((ev: MessageEvent<ExportRequest>) => void) | null;
};
const post = (m: FromExportWorker) =>
  m.type === 'chunk' ? scope.postMessage(m, [m.bytes.buffer as ArrayBuffer]) : scope.postMessage(m);

scope.onmessage = (ev) => {
  run(ev.data).catch((e: unknown) =>
    post({
      type: 'error',
      message: e instanceof Error ? e.message : String(e),
      kind: e instanceof SolverError ? e.kind : 'export',
    }),
  );
};

async function run(req: ExportRequest): Promise<void> {
  const engine = await loadSolverEngine({ locateFile: () => wasmUrl });
  try {
    const hair = growSessionHair(engine, req.session, req.scalp, {
      grid: req.grid,
      solver: req.solver,
      onProgress: (phase, fraction) => post({ type: 'progress', phase, fraction }),
    });
    const t0 = performance.now();
    let bytes = 0;
    const { strands } = exportedCounts(hair.strands);
    let lastProgress = 0;
    let groom: GroomSummary | undefined;
    for (const chunk of writeExport(
      req.format,
      {
        strands: hair.strands,
        session: req.session,
        head: req.head,
        headUv: req.headUv ?? null,
        cards: req.cards,
        ...(req.motion
          ? {
              motion: simulateMotion(
                engine,
                hair.strands,
                req.session,
                req.motion.name,
                req.motion.frames,
              ),
            }
          : {}),
        onGroom: (g) => {
          groom = g;
        },
      },
      (f) => {
        // at most ~50 progress messages
        if (f - lastProgress >= 0.02 || f === 1) {
          lastProgress = f;
          post({ type: 'progress', phase: 'write', fraction: f });
        }
      },
    )) {
      bytes += chunk.byteLength;
      // a copy the worker can transfer (a chunk may be a view into a larger buffer)
      post({ type: 'chunk', bytes: chunk.slice() });
    }
    post({
      type: 'done',
      strands,
      bytes,
      solveMs: hair.solveMs,
      growMs: hair.growMs,
      writeMs: performance.now() - t0,
      ...(groom ? { groom } : {}),
    });
  } finally {
    engine.dispose();
  }
}
