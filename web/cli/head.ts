// The head `hairsketch grow` grows hair on: the session's head, as the app would show it.
//  - The built-in head, unless --head FILE gives another (then FILE replaces it: the session
//    grown, and the one an export carries, names that file's head).
//  - A loaded head (session.head a HeadRef): from the file the session file embeds, or from
//    --head FILE, whose SHA-256 must be the one the session names.
// The scalp is the head's default scalp with the session's scalp brush strokes applied
// (head/scalpPaint.ts), as in the app.
// Growing needs only the head's triangles and scalp, so the built-in head is built here without
// three.js; reading a head file needs three's loaders, which cli/headFile.ts brings in only then.
import { readFileSync, statSync } from 'node:fs';
import { bodyArrays, builtinBody } from '../head/buildBody';
import { buildHead } from '../head/buildHead';
import type { HeadMesh } from '../head/head';
import { sessionScalpMask } from '../head/scalpPaint';
import { sessionHairline } from '../head/scalpRegion';
import type { ScalpMesh } from '../model/hairArrays';
import type { SessionState } from '../model/session';
import type { HeadFileData } from '../model/sessionFile';
import { CliError } from './errors';

/** Largest head file --head reads (bytes). */
export const MAX_HEAD_FILE_BYTES = 512 << 20;

/** The head grow uses: its mesh, the scalp mesh the solver gets (the painted mask), the bounds
 *  the grid holds (a loaded head only), and the session with its head as grown. */
export interface GrowHead {
  mesh: HeadMesh;
  scalp: ScalpMesh;
  bounds: HeadMesh['bounds'] | undefined;
  session: SessionState;
}

/** The bytes of --head FILE (one-line errors). */
export function readHeadFile(path: string): ArrayBuffer {
  let size: number;
  try {
    const st = statSync(path);
    if (st.isDirectory()) throw new CliError(`cannot read head ${path}: it is a directory`);
    size = st.size;
  } catch (e) {
    if (e instanceof CliError) throw e;
    throw new CliError(`cannot read head ${path}: ${(e as NodeJS.ErrnoException).code ?? e}`);
  }
  if (size > MAX_HEAD_FILE_BYTES)
    throw new CliError(`head ${path} is larger than ${MAX_HEAD_FILE_BYTES >> 20} MB`);
  try {
    const b = readFileSync(path);
    return b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength) as ArrayBuffer;
  } catch (e) {
    throw new CliError(`cannot read head ${path}: ${(e as NodeJS.ErrnoException).code ?? e}`);
  }
}

/** The head `session` grows on (see the top of this file). `embedded`: the head file the
 *  session file carries (its hash already checked by the reader); `headPath`: --head FILE. */
export async function headForGrow(
  session: SessionState,
  embedded: HeadFileData | undefined,
  headPath: string | null,
): Promise<GrowHead> {
  let s = session;
  let mesh: HeadMesh;
  let loaded = false;
  if (headPath !== null) {
    const bytes = readHeadFile(headPath);
    const file = await import('./headFile');
    ({ mesh, session: s } = await file.headFromFile(s, headPath, bytes));
    loaded = true;
  } else if (s.head !== 'builtin') {
    if (!embedded)
      throw new CliError(
        `the session is on the head "${s.head.name}" (SHA-256 ${s.head.hash}), which it does not carry: give that file with --head FILE`,
      );
    const file = await import('./headFile');
    mesh = await file.loadRef(s.head, embedded.bytes, 'the head in the session file: ');
    loaded = true;
  } else mesh = buildHead();
  const mask = sessionScalpMask(mesh, mesh.scalp, s.scalpPaint ?? [], sessionHairline(s));
  // what Head.scalpMesh() gives, with the painted mask
  const scalp: ScalpMesh = {
    positions: mesh.positions.slice(),
    indices: mesh.indices.slice(),
    scalp: mask,
    center: [...mesh.center],
    ...(loaded ? {} : { body: bodyArrays(builtinBody()) }),
  };
  return { mesh, scalp, bounds: loaded ? mesh.bounds : undefined, session: s };
}
