// Head files for `hairsketch grow` (--head FILE, or the file a session file embeds), read with
// the app's loaders (head/loadHead.ts). Imported by cli/head.ts only when a head file is read, so
// the built-in head grows without three.js.
//
// three's loaders run under Node as in the browser, but for textures: a glTF with images reaches
// for `self` (and then an <img>), which Node lacks. Textures do not matter here, so while a head
// loads `self` is the global object (the image then fails to load and the loader goes on without
// it) and the loader's console messages about it are held back.
import { basename } from 'node:path';
import type { HeadMesh } from '../head/head';
import { hashHeadBytes, headRefOf, loadHeadRef } from '../head/headStore';
import { type LoadHeadResult, loadHeadFile } from '../head/loadHead';
import type { HeadRef, SessionState } from '../model/session';
import { CliError } from './errors';

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

/** The head of --head FILE (`bytes`, read from `path`): the session's own head when the session
 *  names one (then the file's SHA-256 must match), else a new head the session then names. */
export async function headFromFile(
  session: SessionState,
  path: string,
  bytes: ArrayBuffer,
): Promise<{ mesh: HeadMesh; session: SessionState }> {
  const hash = await hashHeadBytes(bytes);
  if (session.head !== 'builtin') {
    if (hash !== session.head.hash)
      throw new CliError(
        `head ${path} is not the session's head: its SHA-256 is ${hash}, the session's head "${session.head.name}" is ${session.head.hash}`,
      );
    return { mesh: await loadRef(session.head, bytes, ''), session };
  }
  const name = basename(path);
  const r = await loadHeadUnderNode(() => loadHeadFile(name, bytes));
  if (!r.ok) throw new CliError(r.error);
  return { mesh: r.head.head.mesh, session: { ...session, head: headRefOf(name, hash, r.head) } };
}

/** The mesh of the head `ref` names, from its file's bytes (errors prefixed by `prefix`). */
export async function loadRef(ref: HeadRef, bytes: ArrayBuffer, prefix: string): Promise<HeadMesh> {
  const r = await loadHeadUnderNode(() => loadHeadRef(ref, bytes));
  if (!r.ok) throw new CliError(`${prefix}${r.error}`);
  return r.head.head.mesh;
}
