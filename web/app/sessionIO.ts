// Sessions in and out: one load path for every way a session comes in (file, link, test hook;
// undo/redo are history moves in the editor), the file download, and the address bar's link
// kept in step with the session.
import type { Editor } from '../editor/editor';
import { readExportedSession } from '../export/readExport';
import type { SessionState, Viewpoint } from '../model/session';
import { type Parsed, parseSession } from '../model/sessionFile';
import { decodeSessionLink, encodeSessionLink } from '../model/sessionLink';
import type { Vec3 } from '../model/vec3';

export type LoadSource = { kind: 'file'; name: string } | { kind: 'link' } | { kind: 'test' };

/** The one load path: checks `data` with the strict session reader and, when it is valid,
 *  makes it the session (an undoable edit; a link opened with the page starts the history).
 *  A bad session changes nothing; the result says why. */
export function loadSession(editor: Editor, data: unknown, from: LoadSource): Parsed<SessionState> {
  const parsed = parseSession(data);
  if (!parsed.ok) return parsed;
  const what =
    from.kind === 'file'
      ? `Opened ${from.name}`
      : from.kind === 'link'
        ? 'Opened a shared session'
        : 'Loaded a session';
  editor.run({
    kind: 'loadSession',
    session: parsed.value,
    what,
    camera: savedCamera(data),
    resetHistory: from.kind === 'link',
  });
  return parsed;
}

/** Reads a session file the user chose (a saved session, or an exported USD / glTF that
 *  carries one); the sentence for the status line when it cannot be opened. */
export async function openSessionFile(editor: Editor, file: File): Promise<string | null> {
  if (file.size > 512 << 20)
    return `Could not open ${file.name}: larger than 512 MB. Nothing changed.`;
  let data: unknown;
  const magic = new TextDecoder().decode(await file.slice(0, 5).arrayBuffer());
  if (magic === '#usda' || magic.startsWith('glTF')) {
    // an export: its session is in the USD header or the glTF JSON chunk
    const r = readExportedSession(new Uint8Array(await file.arrayBuffer()));
    if (!r?.ok)
      return `Could not open ${file.name}: ${r ? r.error : 'not a hairsketch export'}. Nothing changed.`;
    data = r.session;
  } else {
    if (file.size > 64 << 20)
      return `Could not open ${file.name}: larger than 64 MB. Nothing changed.`;
    try {
      data = JSON.parse(await file.text());
    } catch {
      return `Could not open ${file.name}: not JSON, USD or glTF. Nothing changed.`;
    }
  }
  const r = loadSession(editor, data, { kind: 'file', name: file.name });
  return r.ok ? null : `Could not open ${file.name}: ${r.error}. Nothing changed.`;
}

/** Opens the session a link carries (#s=…); the error sentence when the link is bad. */
export async function openSessionLink(editor: Editor, fragment: string): Promise<string | null> {
  if (!fragment.startsWith('#s=')) return null;
  const decoded = await decodeSessionLink(fragment);
  const r = decoded.ok ? loadSession(editor, decoded.value, { kind: 'link' }) : decoded;
  return r.ok ? null : `Could not open the link: ${r.error}. Showing the preset instead.`;
}

/** "Save": the session and the camera as a JSON file download. */
export function downloadSession(s: SessionState, camera: Viewpoint): void {
  const json = JSON.stringify({ ...s, camera });
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([json], { type: 'application/json' }));
  a.download = 'hairstyle.hairsketch.json';
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 10_000);
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
  async share(): Promise<string> {
    let href: string;
    try {
      href = await this.write();
    } catch {
      return 'This browser cannot make session links (no CompressionStream); use Save.';
    }
    try {
      await navigator.clipboard.writeText(href);
      return `Link copied (${Math.round(href.length / 1024)} KB).`;
    } catch {
      return 'The link is in the address bar (the clipboard is not available here).';
    }
  }
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
