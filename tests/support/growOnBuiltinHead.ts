// Grows a session's hair on the built-in head with the real wasm solver (the fast solver, every
// strand up to `maxStrands`), as `hairsketch grow` does: for unit tests that measure the strands.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { growSessionHair } from '../../web/export/growSession';
import { Head } from '../../web/head/head';
import { gridForSession } from '../../web/model/grid';
import type { StrandArrays } from '../../web/model/hairArrays';
import { hangLength, type SessionState } from '../../web/model/session';
import { loadSolverEngine } from '../../web/solver/wasmEngine';

let wasmBinary: Uint8Array | null = null;
const head = Head.builtin();

export async function growOnBuiltinHead(
  s: SessionState,
  maxStrands: number,
): Promise<StrandArrays> {
  wasmBinary ??= new Uint8Array(
    readFileSync(fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url))),
  );
  const engine = await loadSolverEngine({ wasmBinary });
  try {
    const grid = gridForSession(s.grid, s.curves, undefined, hangLength(s));
    return growSessionHair(engine, s, head.scalpMesh(), { grid, solver: 'fast', maxStrands })
      .strands;
  } finally {
    engine.dispose();
  }
}
