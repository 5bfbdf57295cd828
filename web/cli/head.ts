// The head `hairsketch grow` grows hair on: the session's head, as the app would show it.
//  - The built-in head, unless --head FILE gives another (then FILE replaces it: the session
//    grown, and the one an export carries, names that file's head).
//  - A loaded head (session.head a HeadRef): from the file the session file embeds, or from
//    --head FILE, whose SHA-256 must be the one the session names.
// The scalp is the head's default scalp with the session's scalp brush strokes applied
// (head/scalpPaint.ts), as in the app.
//
// three's loaders (head/loadHead.ts) run under Node as in the browser, but for textures: a glTF
// with images reaches for `self` (and then an <img>), which Node lacks. Textures do not matter
// here, so while a head loads `self` is the global object (the image then fails to load and the
// loader goes on without it) and the loader's console messages about it are held back.
import { readFileSync, statSync } from 'node:fs';
import { basename } from 'node:path';
import { Head } from '../head/head';
import { hashHeadBytes, headRefOf, loadHeadRef } from '../head/headStore';
import { type LoadHeadResult, loadHeadFile } from '../head/loadHead';
import { applyScalpPaint } from '../head/scalpPaint';
import type { HeadRef, SessionState } from '../model/session';
import type { HeadFileData } from '../model/sessionFile';
import type { ScalpMesh } from '../solver/protocol';
import { CliError } from './errors';

/** Largest head file --head reads (bytes). */
export const MAX_HEAD_FILE_BYTES = 512 << 20;

/** The head grow uses: the Head (mesh, BVH), the scalp mesh the solver gets (the painted mask),
 *  the bounds the grid holds (a loaded head only), and the session with its head as grown. */
export interface GrowHead {
  head: Head;
  scalp: ScalpMesh;
  bounds: Head['mesh']['bounds'] | undefined;
  session: SessionState;
}

/** Runs `load` (a loadHeadFile call) with what three's glTF loader needs under Node. */
export async function loadHeadUnderNode(
  load: () => Promise<LoadHeadResult>,
): Promise<LoadHeadResult> {
  const g = globalThis as { self?: unknown };
  const hadSelf = 'self' in g;
  const { error, warn } = console;
  if (!hadSelf) g.self = globalThis;
  console.error = () => {};
  console.warn = () => {};
  try {
    return await load();
  } finally {
    console.error = error;
    console.warn = warn;
    if (!hadSelf) delete g.self;
  }
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
  let head: Head;
  let loaded = false;
  if (headPath !== null) {
    const bytes = readHeadFile(headPath);
    const hash = await hashHeadBytes(bytes);
    if (s.head !== 'builtin') {
      if (hash !== s.head.hash)
        throw new CliError(
          `head ${headPath} is not the session's head: its SHA-256 is ${hash}, the session's head "${s.head.name}" is ${s.head.hash}`,
        );
      head = await loadRef(s.head, bytes, '');
    } else {
      const name = basename(headPath);
      const r = await loadHeadUnderNode(() => loadHeadFile(name, bytes));
      if (!r.ok) throw new CliError(r.error);
      head = r.head.head;
      const ref = headRefOf(name, hash, r.head);
      s = { ...s, head: ref };
    }
    loaded = true;
  } else if (s.head !== 'builtin') {
    if (!embedded)
      throw new CliError(
        `the session is on the head "${s.head.name}" (SHA-256 ${s.head.hash}), which it does not carry: give that file with --head FILE`,
      );
    head = await loadRef(s.head, embedded.bytes, 'the head in the session file: ');
    loaded = true;
  } else head = Head.builtin();
  const mask = applyScalpPaint(head.mesh, head.mesh.scalp, s.scalpPaint ?? []);
  const scalp: ScalpMesh = { ...head.scalpMesh(), scalp: mask };
  return { head, scalp, bounds: loaded ? head.mesh.bounds : undefined, session: s };
}

async function loadRef(ref: HeadRef, bytes: ArrayBuffer, prefix: string): Promise<Head> {
  const r = await loadHeadUnderNode(() => loadHeadRef(ref, bytes));
  if (!r.ok) throw new CliError(`${prefix}${r.error}`);
  return r.head.head;
}
