// Sessions in and out: one load path for every way a session comes in (file, link, test hook;
// undo/redo are history moves in the editor), the file download, and the address bar's link
// kept in step with the session.
//
// A session on a loaded head names the head by its file's SHA-256 (model/session.ts HeadRef).
// A session file carries the head file: opening it puts the file into the head store before the
// session is applied, so the app finds it there. A link (or a file saved without its head, or an
// export) carries only the name: when the store does not hold that head the session is still
// applied (the app keeps showing the head it has) and the outcome says which head it needs
// (`needsHead`), so the app can say so and offer "Open head". Reference pictures travel the
// same way: a file embeds them (into the picture store before the session is applied), a link
// names them by hash (the reference controller says which picture is missing).
import type { Editor } from '../editor/editor';
import { readExportedSession } from '../export/readExport';
import type { HeadStore } from '../head/headStore';
import { sha256Hex } from '../model/bytes';
import type { SessionState, Viewpoint } from '../model/session';
import { type Parsed, parseSession, readSessionFile, writeSessionFile } from '../model/sessionFile';
import { decodeSessionLink, encodeSessionLink } from '../model/sessionLink';
import type { Vec3 } from '../model/vec3';
import type { PictureStore } from '../reference/pictureStore';

/** Where a session comes from; a link opened at the start begins the history, one pasted into
 *  the address bar later (`pasted`) is an undoable edit, as Open is. */
export type LoadSource =
  | { kind: 'file'; name: string }
  | { kind: 'link'; pasted?: boolean }
  | { kind: 'style'; name: string }
  | { kind: 'test' };

/** Largest file "Open" reads, and largest JSON session file (a JavaScript string holds at most
 *  ~536M characters; a session file embedding a large head is mostly its base64). */
const MAX_OPEN_BYTES = 512 << 20;
const MAX_JSON_BYTES = 500 << 20;

/** A head a session names that the head store does not hold. */
export interface HeadNeeded {
  name: string;
  hash: string;
}

/** What opening a session file or a link came to. `opened` and `needsHead` applied the session
 *  (one undoable edit; a link starts the history); `needsHead` also says which head file the
 *  app must be given (Open head) to show it; `failed` changed nothing. `message` is the status
 *  line's sentence (null when opened: the editor's own "Opened …" is shown). */
export type OpenOutcome =
  | { kind: 'opened'; message: null }
  | { kind: 'needsHead'; needsHead: HeadNeeded; message: string }
  | { kind: 'failed'; message: string };

/** The status sentence for a session whose head is not stored. */
export function needsHeadMessage(h: HeadNeeded, what: 'link' | 'session'): string {
  return `This ${what} needs the head “${h.name}”; Open head to load it.`;
}

/** The one load path: checks `data` with the strict session reader and, when it is valid,
 *  makes it the session (an undoable edit; a link opened with the page starts the history).
 *  A bad session changes nothing; the result says why. */
export function loadSession(editor: Editor, data: unknown, from: LoadSource): Parsed<SessionState> {
  const parsed = parseSession(data);
  if (parsed.ok) applySession(editor, parsed.value, from, savedCamera(data));
  return parsed;
}

/** Makes a session the reader accepted the editor's session (one undoable edit). */
function applySession(
  editor: Editor,
  session: SessionState,
  from: LoadSource,
  camera: Viewpoint | undefined,
): void {
  const what =
    from.kind === 'file'
      ? `Opened ${from.name}`
      : from.kind === 'link'
        ? 'Opened a shared session'
        : from.kind === 'style'
          ? `Started from the style “${from.name}” (Undo brings back the work before)`
          : 'Loaded a session';
  editor.run({
    kind: 'loadSession',
    session,
    what,
    camera,
    resetHistory: from.kind === 'link' && !from.pasted,
  });
}

/** The head `s` needs that `heads` does not hold (null: the built-in head, a stored head, or no
 *  store to ask). */
async function missingHead(s: SessionState, heads?: HeadStore): Promise<HeadNeeded | null> {
  if (s.head === 'builtin' || !heads) return null;
  try {
    if (await heads.get(s.head.hash)) return null;
  } catch {
    // a store that fails holds nothing
  }
  return { name: s.head.name, hash: s.head.hash };
}

/** Applies `s` and says whether its head is missing from the store. */
async function openParsed(
  editor: Editor,
  s: SessionState,
  from: LoadSource,
  camera: Viewpoint | undefined,
  heads: HeadStore | undefined,
): Promise<OpenOutcome> {
  const missing = await missingHead(s, heads);
  applySession(editor, s, from, camera);
  if (!missing) return { kind: 'opened', message: null };
  return {
    kind: 'needsHead',
    needsHead: missing,
    message: needsHeadMessage(missing, from.kind === 'link' ? 'link' : 'session'),
  };
}

/** Reads a session file the user chose (a saved session, or an exported USD / glTF that
 *  carries one). A saved session's embedded head file goes into `heads` before the session is
 *  applied, and its embedded picture files into `pictures`. */
export async function openSessionFileOutcome(
  editor: Editor,
  file: File,
  heads?: HeadStore,
  pictures?: PictureStore,
): Promise<OpenOutcome> {
  const failed = (why: string): OpenOutcome => ({
    kind: 'failed',
    message: `Could not open ${file.name}: ${why}. Nothing changed.`,
  });
  if (file.size > MAX_OPEN_BYTES) return failed('larger than 512 MB');
  const from: LoadSource = { kind: 'file', name: file.name };
  const magic = new TextDecoder().decode(await file.slice(0, 5).arrayBuffer());
  if (magic === '#usda' || magic.startsWith('glTF')) {
    // an export: its session is in the USD header or the glTF JSON chunk (never its head file)
    const r = readExportedSession(new Uint8Array(await file.arrayBuffer()));
    if (!r?.ok) return failed(r ? r.error : 'not a hairsketch export');
    const parsed = parseSession(r.session);
    if (!parsed.ok) return failed(parsed.error);
    return openParsed(editor, parsed.value, from, savedCamera(r.session), heads);
  }
  if (file.size > MAX_JSON_BYTES) return failed('larger than 500 MB');
  let data: unknown;
  try {
    data = JSON.parse(await file.text());
  } catch {
    return failed('not JSON, USD or glTF');
  }
  const r = await readSessionFile(data);
  if (!r.ok) return failed(r.error);
  const { session, headFile, pictureFiles } = r.value;
  for (const p of pictureFiles ?? [])
    try {
      await pictures?.put(p);
    } catch {
      // a store that fails: the picture is reported missing when the session is shown
    }
  if (headFile && heads) {
    try {
      await heads.put({ hash: headFile.hash, name: headFile.name, bytes: headFile.bytes });
    } catch {
      // a store that fails: the head is reported missing below
    }
  }
  return openParsed(editor, session, from, savedCamera(data), heads);
}

/** Reads a session file (as openSessionFileOutcome); the sentence for the status line when it
 *  could not be opened or its head is missing, else null. */
export async function openSessionFile(
  editor: Editor,
  file: File,
  heads?: HeadStore,
): Promise<string | null> {
  return (await openSessionFileOutcome(editor, file, heads)).message;
}

/** Opens the session a link carries (#s=…); a link whose head `heads` does not hold is opened
 *  and reported as `needsHead`. A fragment that is not a session link: opened, nothing done. */
export async function openSessionLinkOutcome(
  editor: Editor,
  fragment: string,
  heads?: HeadStore,
  pasted = false,
): Promise<OpenOutcome> {
  if (!fragment.startsWith('#s=')) return { kind: 'opened', message: null };
  const decoded = await decodeSessionLink(fragment);
  if (!decoded.ok)
    return {
      kind: 'failed',
      message: `Could not open the link: ${decoded.error}. ${pasted ? 'Nothing changed.' : 'Showing the preset instead.'}`,
    };
  return openParsed(editor, decoded.value, { kind: 'link', pasted }, undefined, heads);
}

/** Opens the session a link carries (#s=…); the sentence for the status line when the link is
 *  bad or its head is missing, else null. */
export async function openSessionLink(
  editor: Editor,
  fragment: string,
  heads?: HeadStore,
): Promise<string | null> {
  return (await openSessionLinkOutcome(editor, fragment, heads)).message;
}

/** The text "Save" writes: the session, the camera and, for a session on a loaded head whose
 *  file `heads` holds, the head file. `headMissing` when the head could not be embedded. */
export async function sessionFileText(
  s: SessionState,
  camera: Viewpoint,
  heads?: HeadStore,
  pictures?: PictureStore,
): Promise<{ text: string; headMissing: HeadNeeded | null }> {
  const pictureBytes = await storedPictures(s, pictures);
  if (s.head === 'builtin')
    return { text: await writeSessionFile(s, { camera, pictureBytes }), headMissing: null };
  const needed = { name: s.head.name, hash: s.head.hash };
  let headBytes: ArrayBuffer | undefined;
  try {
    headBytes = (await heads?.get(needed.hash))?.bytes;
  } catch {
    // a store that fails holds nothing
  }
  if (headBytes)
    try {
      return {
        text: await writeSessionFile(s, { camera, headBytes, pictureBytes }),
        headMissing: null,
      };
    } catch {
      // the stored bytes are not the head's (a damaged store): save without them
    }
  return { text: await writeSessionFile(s, { camera, pictureBytes }), headMissing: needed };
}

/** The files of the session's pictures that `pictures` holds and whose bytes are theirs (a
 *  damaged store's are left out), by hash. */
async function storedPictures(
  s: SessionState,
  pictures?: PictureStore,
): Promise<Map<string, ArrayBuffer>> {
  const out = new Map<string, ArrayBuffer>();
  for (const r of s.references ?? []) {
    try {
      const p = await pictures?.get(r.hash);
      if (p && (await sha256Hex(p.bytes)) === r.hash) out.set(r.hash, p.bytes);
    } catch {
      // a store that fails holds nothing
    }
  }
  return out;
}

/** "Save": the session and the camera (and, on a loaded head, its file from `heads`) as a JSON
 *  file download. Resolves to a sentence when the head file could not be included, else null. */
export async function downloadSession(
  s: SessionState,
  camera: Viewpoint,
  heads?: HeadStore,
  pictures?: PictureStore,
): Promise<string | null> {
  const { text: json, headMissing } = await sessionFileText(s, camera, heads, pictures);
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([json], { type: 'application/json' }));
  a.download = 'hairstyle.hairsketch.json';
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 10_000);
  return headMissing
    ? `Saved without the head file “${headMissing.name}” (this browser has not stored it): whoever opens the file needs that head too.`
    : null;
}

/** Keeps the address bar's #s= link in step with the session (a reload keeps the work). */
export class LinkWriter {
  private timer: ReturnType<typeof setTimeout> | null = null;
  /** The session the address bar's link encodes (null: none yet). */
  private linked: SessionState | null = null;

  constructor(private readonly editor: Editor) {
    editor.listen((c) => {
      if (c.sessionChanged) this.schedule();
    });
  }

  /** The page was opened with a link to this session: the address bar already says it. */
  markLinked(s: SessionState): void {
    this.linked = s;
  }

  /** Writes the link shortly (edits in a burst write it once). */
  schedule(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = setTimeout(() => {
      this.timer = null;
      // links need CompressionStream; without it the address bar just does not follow
      this.write().catch(() => {});
    }, 400);
  }

  /** Writes the current session's link to the address bar; returns it. */
  async write(): Promise<string> {
    const s = this.editor.session;
    if (this.linked !== s) {
      const url = new URL(window.location.href);
      url.hash = await encodeSessionLink(s);
      if (this.editor.session !== s) return url.toString(); // superseded meanwhile
      window.history.replaceState(null, '', url);
      this.linked = s;
    }
    return window.location.href;
  }

  /** "Share link": the link, copied to the clipboard when allowed; the sentence to show. */
  share(): Promise<string> {
    return this.copy(
      (href) => href,
      (href) => `Link copied (${href.length.toLocaleString('en-US')} characters).`,
      'The link is in the address bar (the clipboard is not available here).',
    );
  }

  /** "Copy embed code": the <iframe> snippet for this session, copied to the clipboard; the
   *  sentence to show. */
  copyEmbed(): Promise<string> {
    return this.copy(
      embedCode,
      () => 'Embed code copied: paste the <iframe> into a page to show this hairstyle there.',
      'The clipboard is not available here: the embed is embed.html with the address bar’s #s= link.',
    );
  }

  /** Writes the link, then copies `text(link)` to the clipboard; the sentence to show. */
  private async copy(
    text: (href: string) => string,
    copied: (href: string) => string,
    noClipboard: string,
  ): Promise<string> {
    let href: string;
    try {
      href = await this.write();
    } catch {
      return 'This browser cannot make session links (no CompressionStream); use Save.';
    }
    try {
      await navigator.clipboard.writeText(text(href));
      return copied(href);
    } catch {
      return noClipboard;
    }
  }
}

/** The <iframe> snippet that shows the session of the editor link `href` in another page. */
export function embedCode(href: string): string {
  const u = new URL(href);
  const src = `${u.origin}${u.pathname.replace(/[^/]*$/, '')}embed.html${u.hash}`;
  const attr = src.replace(/&/g, '&amp;').replace(/"/g, '&quot;');
  return `<iframe src="${attr}" width="640" height="480" style="border:0" title="Hairstyle (hairsketch)" loading="lazy" allowfullscreen></iframe>`;
}

function savedCamera(data: unknown): Viewpoint | undefined {
  // read as the reader reads: own data properties only, so no getter or proxy trap runs
  const own = (o: unknown, k: string): unknown => {
    try {
      if (typeof o !== 'object' || o === null) return undefined;
      const d = Object.getOwnPropertyDescriptor(o, k);
      return d && 'value' in d ? d.value : undefined;
    } catch {
      return undefined;
    }
  };
  const cam = own(data, 'camera');
  const position = own(cam, 'position');
  const target = own(cam, 'target');
  const vec = (v: unknown): Vec3 | null => {
    try {
      if (!Array.isArray(v) || own(v, 'length') !== 3) return null;
    } catch {
      return null; // a revoked proxy
    }
    const out = [own(v, '0'), own(v, '1'), own(v, '2')];
    return out.every((x) => typeof x === 'number' && Number.isFinite(x)) ? (out as Vec3) : null;
  };
  const p = vec(position);
  const t = vec(target);
  return p && t ? { position: p, target: t } : undefined;
}
