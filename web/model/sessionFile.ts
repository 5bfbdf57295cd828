// Session files ("Save", "Open"): the session as JSON (the strict reader, sessionRead.ts, reads
// it back), with the head file of a session on a loaded head embedded beside it.
//
// A session on a loaded head (head: {kind: 'mesh', hash, …}) names the head by the SHA-256 of its
// file. A session file ("Save", writeSessionFile) embeds that file beside the session:
//   "headFile": {"name": "head.obj", "hash": "<64 hex>", "encoding": "deflate-base64",
//                "data": "<base64 of the raw deflate of the file's bytes>"}
// readSessionFile reads it back, inflating with a cap (MAX_HEAD_FILE_BYTES) and checking that the
// bytes' SHA-256 is the hash the session's head names. A file without it reads fine: the app
// finds the head by its hash in the browser's store or asks for it.
//
// The reference pictures a session places (session.references, named by SHA-256 too) are
// embedded the same way, each file once, as plain base64 (pictures are compressed already):
//   "pictureFiles": [{"name": "front.png", "hash": "<64 hex>", "encoding": "base64",
//                     "data": "<base64 of the file's bytes>"}]
// each checked against its hash and a picture of the session, at most maxPictureFileBytes.
//
// The file's session is the session's own fields, in the reader's order (sessionSchema.ts
// SESSION_FIELDS): what the reader accepts, written as it is, reads back the same.

import { deflateRaw, fromBase64, inflateCapped, sha256Hex, toBase64 } from './bytes';
import { fail, failed } from './readFailure';
import { array, fileName, record, sha256Of } from './readValues';
import type { SessionState, Viewpoint } from './session';
import { SESSION_LIMITS as L, type Parsed } from './sessionLimits';
import type { Plain, PlainRecord } from './sessionMigrations';
import { readInput } from './sessionRead';
import { SESSION_FIELD_NAMES } from './sessionSchema';

// where the reader and its limits were first defined: callers import them from here
export { MAX_HEAD_FILE_BYTES, type Parsed, SESSION_LIMITS } from './sessionLimits';
export { parseSession } from './sessionRead';

/** The encoding of headFile.data. */
export const HEAD_FILE_ENCODING = 'deflate-base64';

/** A head file carried by a session file: its name, SHA-256 and bytes. */
export interface HeadFileData {
  name: string;
  hash: string;
  bytes: ArrayBuffer;
}

/** The encoding of pictureFiles[i].data. */
export const PICTURE_FILE_ENCODING = 'base64';

/** What a session file holds: the session, the head file and the picture files it embeds. */
export interface SessionFileContents {
  session: SessionState;
  headFile?: HeadFileData;
  /** Files of the session's reference pictures (by hash), those the file embeds. */
  pictureFiles?: HeadFileData[];
}

/** The SHA-256 of bytes as 64 lowercase hex digits (the content hash that names a head). */
export const hashBytes = (bytes: ArrayBuffer | Uint8Array): Promise<string> => sha256Hex(bytes);

/** Reads a session file's data (parsed JSON, or any value): the session by the strict reader,
 *  and its `headFile` when present, inflated (refused past MAX_HEAD_FILE_BYTES) and checked
 *  against its hash and the session head's. Never throws; the first problem names its field
 *  (`session.headFile.hash: …`). A session on a loaded head without a headFile reads fine. */
export async function readSessionFile(data: unknown): Promise<Parsed<SessionFileContents>> {
  let top: PlainRecord;
  let value: SessionState;
  let embedded: { name: string; hash: string; data: string } | null;
  let pictures: { name: string; hash: string; data: string }[];
  try {
    ({ top, session: value } = readInput(data));
    embedded = headFileRecord(top.headFile, value);
    pictures = pictureFileRecords(top.pictureFiles, value);
  } catch (e) {
    return failed(e);
  }
  const pictureFiles: HeadFileData[] = [];
  for (let i = 0; i < pictures.length; i++) {
    const r = await pictureBytes(pictures[i], `session.pictureFiles[${i}]`);
    if (!r.ok) return r;
    pictureFiles.push(r.value);
  }
  const withPictures = pictureFiles.length > 0 ? { pictureFiles } : {};
  if (!embedded) return { ok: true, value: { session: value, ...withPictures } };
  const at = 'session.headFile';
  const deflated = fromBase64(embedded.data);
  if (!deflated) return { ok: false, error: `${at}.data: must be base64 text` };
  const inflated = await inflateCapped(deflated, L.maxHeadFileBytes);
  if (inflated === 'too large')
    return {
      ok: false,
      error: `${at}.data: inflates to more than ${L.maxHeadFileBytes / (1 << 20)} MiB (the cap)`,
    };
  if (inflated === 'damaged')
    return { ok: false, error: `${at}.data: does not inflate (damaged deflate data)` };
  const bytes = await hashChecked(inflated, embedded.hash, at);
  if (!bytes.ok) return bytes;
  return {
    ok: true,
    value: {
      session: value,
      headFile: { name: embedded.name, hash: embedded.hash, bytes: bytes.value },
      ...withPictures,
    },
  };
}

/** An embedded file's bytes as an ArrayBuffer of their own, if their SHA-256 is `hash`. */
async function hashChecked(
  bytes: Uint8Array,
  hash: string,
  at: string,
): Promise<Parsed<ArrayBuffer>> {
  const actual = await sha256Hex(bytes);
  if (actual !== hash)
    return {
      ok: false,
      error: `${at}.hash: does not match the data (the SHA-256 of the data is ${actual}): the file is damaged`,
    };
  const whole = bytes.byteOffset === 0 && bytes.byteLength === bytes.buffer.byteLength;
  return {
    ok: true,
    value: (whole ? bytes.buffer : bytes.slice().buffer) as ArrayBuffer,
  };
}

/** One embedded picture file's bytes, checked against its hash. */
async function pictureBytes(
  p: { name: string; hash: string; data: string },
  at: string,
): Promise<Parsed<HeadFileData>> {
  const bytes = fromBase64(p.data);
  if (!bytes) return { ok: false, error: `${at}.data: must be base64 text` };
  if (bytes.byteLength > L.maxPictureFileBytes)
    return {
      ok: false,
      error: `${at}.data: is more than ${L.maxPictureFileBytes / (1 << 20)} MiB (the cap)`,
    };
  const buffer = await hashChecked(bytes, p.hash, at);
  if (!buffer.ok) return buffer;
  return { ok: true, value: { name: p.name, hash: p.hash, bytes: buffer.value } };
}

/** The pictureFiles records' fields, each naming a picture of the session once ([] when
 *  absent). */
function pictureFileRecords(
  v: Plain | undefined,
  s: SessionState,
): { name: string; hash: string; data: string }[] {
  if (v === undefined) return [];
  const path = 'session.pictureFiles';
  const a = array(v, path, 'picture files');
  const refs = s.references ?? [];
  if (a.length > refs.length)
    fail(path, `has ${a.length} files for ${refs.length} pictures (session.references)`);
  const seen = new Set<string>();
  return a.map((item, i) => {
    const at = `${path}[${i}]`;
    const o = record(item, at, ['name', 'hash', 'encoding', 'data']);
    const name = fileName(o.name, `${at}.name`);
    const hash = sha256Of(o.hash, `${at}.hash`);
    if (o.encoding !== PICTURE_FILE_ENCODING)
      fail(`${at}.encoding`, `must be "${PICTURE_FILE_ENCODING}"`);
    if (typeof o.data !== 'string') fail(`${at}.data`, 'must be base64 text');
    if (!refs.some((r) => r.hash === hash))
      fail(`${at}.hash`, 'must be the hash of a picture of the session (session.references)');
    if (seen.has(hash)) fail(`${at}.hash`, 'names the same file as an earlier one');
    seen.add(hash);
    return { name, hash, data: o.data };
  });
}

/** The headFile record's fields, checked against the session's head (null when absent). */
function headFileRecord(
  v: Plain | undefined,
  s: SessionState,
): { name: string; hash: string; data: string } | null {
  if (v === undefined) return null;
  const at = 'session.headFile';
  const o = record(v, at, ['name', 'hash', 'encoding', 'data']);
  const name = fileName(o.name, `${at}.name`);
  const hash = sha256Of(o.hash, `${at}.hash`);
  if (o.encoding !== HEAD_FILE_ENCODING) fail(`${at}.encoding`, `must be "${HEAD_FILE_ENCODING}"`);
  if (typeof o.data !== 'string') fail(`${at}.data`, 'must be base64 text');
  if (s.head === 'builtin')
    fail(at, 'the session is on the built-in head (session.head), so it carries no head file');
  if (hash !== s.head.hash)
    fail(`${at}.hash`, `must be the hash of the session's head (session.head.hash ${s.head.hash})`);
  if (name !== s.head.name)
    fail(
      `${at}.name`,
      `must be the name of the session's head (session.head.name ${JSON.stringify(s.head.name)})`,
    );
  return { name, hash, data: o.data };
}

export interface WriteSessionFileOptions {
  /** The bytes of the file the session's head names (its SHA-256 must be the head's hash); left
   *  out, a session on a loaded head is written without its head. Ignored on the built-in head. */
  headBytes?: ArrayBuffer;
  /** Written beside the session as `camera` ("Save" keeps the view). */
  camera?: Viewpoint;
  /** The files of the session's reference pictures, by hash (each SHA-256 checked); those
   *  not given are left out. */
  pictureBytes?: ReadonlyMap<string, ArrayBuffer>;
}

/** A session file's text (JSON): the session, the camera and, for a session on a loaded head
 *  given its bytes, the head file (`headFile`, last). Throws when the bytes are not the head's
 *  (their SHA-256 is not session.head.hash): writing them would make a file that cannot be read. */
export async function writeSessionFile(
  s: SessionState,
  options: WriteSessionFileOptions = {},
): Promise<string> {
  // the session's fields in the schema's order (a file's key order), then what goes beside it
  const out: Record<string, unknown> = {};
  const fields = s as unknown as Record<string, unknown>;
  for (const k of SESSION_FIELD_NAMES) if (fields[k] !== undefined) out[k] = fields[k];
  if (options.camera) out.camera = options.camera;
  if (s.head !== 'builtin' && options.headBytes) {
    const bytes = new Uint8Array(options.headBytes);
    const hash = await sha256Hex(bytes);
    if (hash !== s.head.hash)
      throw new Error(
        `writeSessionFile: the head bytes' SHA-256 ${hash} is not the session head's ${s.head.hash}`,
      );
    out.headFile = {
      name: s.head.name,
      hash,
      encoding: HEAD_FILE_ENCODING,
      data: toBase64(await deflateRaw(bytes)),
    };
  }
  const pictures: Record<string, string>[] = [];
  for (const r of s.references ?? []) {
    const b = options.pictureBytes?.get(r.hash);
    if (!b) continue;
    const bytes = new Uint8Array(b);
    const hash = await sha256Hex(bytes);
    if (hash !== r.hash)
      throw new Error(`writeSessionFile: the picture bytes' SHA-256 ${hash} is not ${r.hash}`);
    pictures.push({ name: r.name, hash, encoding: PICTURE_FILE_ENCODING, data: toBase64(bytes) });
  }
  if (pictures.length > 0) out.pictureFiles = pictures;
  return JSON.stringify(out);
}
