// Grows a session's hair on the built-in head with the real wasm solver (the fast solver, every
// strand up to `maxStrands`), as `hairsketch grow` does: for unit tests that measure the strands.
// One engine serves a test file, as the app's worker keeps one: the request runner grows from the
// field it holds when only growth or detail changed (growSession.test checks that a used engine
// grows what a fresh one grows).
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { growSessionHair } from '../../web/export/growSession';
import { Head } from '../../web/head/head';
import { gridForSession } from '../../web/model/grid';
import type { StrandArrays } from '../../web/model/hairArrays';
import { hangLength, type SessionState } from '../../web/model/session';
import type { SolverEngine } from '../../web/solver/engine';
import { loadSolverEngine } from '../../web/solver/wasmEngine';

let engine: Promise<SolverEngine> | null = null;
const head = Head.builtin();
const scalp = head.scalpMesh();

export async function growOnBuiltinHead(
  s: SessionState,
  maxStrands: number,
): Promise<StrandArrays> {
  engine ??= loadSolverEngine({
    wasmBinary: new Uint8Array(
      readFileSync(fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url))),
    ),
  });
  const grid = gridForSession(s.grid, s.curves, undefined, hangLength(s));
  return growSessionHair(await engine, s, scalp, { grid, solver: 'fast', maxStrands }).strands;
}
