// Reads the session back out of an export: the `.usda` layer's customLayerData
// "hairsketch:session" string, or the `.glb`'s asset.extras.hairsketch.session. The app then
// checks the session with its own strict reader (parseSession).
import { oneLine } from '../model/oneLine';

export type ReadExportResult = { ok: true; session: unknown } | { ok: false; error: string };

const USDA_MAGIC = '#usda';
const GLB_MAGIC = 0x46546c67; // "glTF"
const CHUNK_JSON = 0x4e4f534a; // "JSON"
const SESSION_KEY = 'hairsketch:session';

/** The session carried by an exported `.usda` or `.glb`; null when the bytes are neither. */
export function readExportedSession(bytes: Uint8Array): ReadExportResult | null {
  if (startsWithAscii(bytes, USDA_MAGIC)) return readUsda(bytes);
  if (bytes.length >= 4 && u32(bytes, 0) === GLB_MAGIC) return readGlb(bytes);
  return null;
}

function startsWithAscii(bytes: Uint8Array, s: string): boolean {
  if (bytes.length < s.length) return false;
  for (let i = 0; i < s.length; i++) if (bytes[i] !== s.charCodeAt(i)) return false;
  return true;
}

function u32(b: Uint8Array, at: number): number {
  return (b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) | (b[at + 3] << 24)) >>> 0;
}

function parseJson(text: string, what: string): ReadExportResult {
  try {
    return { ok: true, session: JSON.parse(text) };
  } catch (e) {
    return { ok: false, error: `${what} is not valid JSON (${oneLine((e as Error).message)})` };
  }
}

// ---- USD -------------------------------------------------------------------------------------

const NO_USD_SESSION = 'the USD file carries no hairsketch session';

/** Finds the key in the layer header (before the first prim) and reads the string after it. */
function readUsda(b: Uint8Array): ReadExportResult {
  const at = findKey(b);
  if (at < 0) return { ok: false, error: NO_USD_SESSION };
  let i = at;
  while (i < b.length && isSpace(b[i])) i++;
  if (b[i] !== 0x3d) return { ok: false, error: `${NO_USD_SESSION} (no "=" after its key)` };
  i++;
  while (i < b.length && isSpace(b[i])) i++;
  const str = readUsdString(b, i);
  if (typeof str === 'string') return { ok: false, error: str };
  let text: string;
  try {
    text = new TextDecoder('utf-8', { fatal: true }).decode(str);
  } catch {
    return { ok: false, error: "the USD file's hairsketch session is not valid UTF-8" };
  }
  return parseJson(text, "the USD file's hairsketch session");
}

function isSpace(c: number): boolean {
  return c === 0x20 || c === 0x09 || c === 0x0a || c === 0x0d;
}

/** Index just after the quoted key "hairsketch:session" (or 'hairsketch:session'), searched
 *  from the start up to the first prim ("def"/"over"/"class" at the start of a line) outside
 *  strings; -1 when absent. */
function findKey(b: Uint8Array): number {
  const key = SESSION_KEY;
  let i = 0;
  let lineStart = true;
  while (i < b.length) {
    const c = b[i];
    if (c === 0x22 || c === 0x27) {
      // A string: is it the key?
      let match = i + key.length + 1 < b.length && b[i + key.length + 1] === c;
      for (let k = 0; match && k < key.length; k++)
        if (b[i + 1 + k] !== key.charCodeAt(k)) match = false;
      if (match) return i + key.length + 2;
      const end = skipUsdString(b, i);
      if (end < 0) return -1;
      i = end;
      lineStart = false;
      continue;
    }
    if (c === 0x23 && i > 0) {
      // A comment to the end of the line.
      while (i < b.length && b[i] !== 0x0a) i++;
      continue;
    }
    if (lineStart && (word(b, i, 'def') || word(b, i, 'over') || word(b, i, 'class'))) return -1;
    if (c === 0x0a) lineStart = true;
    else if (!isSpace(c)) lineStart = false;
    i++;
  }
  return -1;
}

function word(b: Uint8Array, i: number, w: string): boolean {
  for (let k = 0; k < w.length; k++) if (b[i + k] !== w.charCodeAt(k)) return false;
  const after = b[i + w.length];
  return after === undefined || isSpace(after);
}

/** Index after the string literal starting at i, or -1 if it is not closed. */
function skipUsdString(b: Uint8Array, i: number): number {
  const r = scanUsdString(b, i, false);
  return typeof r === 'number' ? r : -1;
}

/** The bytes of the USD string literal at i (escapes evaluated), or an error message. */
function readUsdString(b: Uint8Array, i: number): Uint8Array | string {
  const r = scanUsdString(b, i, true);
  return typeof r === 'number'
    ? 'the hairsketch session in the USD file is not a closed string'
    : r;
}

/** Scans a '…', "…", '''…''' or """…""" literal at i. collect: return its evaluated bytes
 *  (or, unclosed, a number); else the index after it (or -1 if unclosed, as a number). */
function scanUsdString(b: Uint8Array, i: number, collect: boolean): Uint8Array | string | number {
  const q = b[i];
  if (q !== 0x22 && q !== 0x27)
    return collect ? 'the hairsketch session in the USD file is not a string' : -1;
  const triple = b[i + 1] === q && b[i + 2] === q;
  let p = i + (triple ? 3 : 1);
  const out = collect ? new Uint8Array(b.length - p) : null;
  let n = 0;
  const put = (v: number) => {
    if (out) out[n++] = v;
  };
  while (p < b.length) {
    const c = b[p];
    if (c === q && (!triple || (b[p + 1] === q && b[p + 2] === q))) {
      p += triple ? 3 : 1;
      return out ? out.slice(0, n) : p;
    }
    if (!triple && c === 0x0a) return -1;
    if (c !== 0x5c) {
      put(c);
      p++;
      continue;
    }
    // An escape (TfEscapeStringReplaceChar: C escapes, \xHH, octal \ooo).
    const e = b[p + 1];
    p += 2;
    switch (e) {
      case 0x6e: // n
        put(0x0a);
        break;
      case 0x74: // t
        put(0x09);
        break;
      case 0x72: // r
        put(0x0d);
        break;
      case 0x61: // a
        put(0x07);
        break;
      case 0x62: // b
        put(0x08);
        break;
      case 0x66: // f
        put(0x0c);
        break;
      case 0x76: // v
        put(0x0b);
        break;
      case 0x78: {
        // x: up to two hex digits
        let v = 0;
        let k = 0;
        while (k < 2 && p < b.length && hexValue(b[p]) >= 0) {
          v = 16 * v + hexValue(b[p]);
          p++;
          k++;
        }
        put(v);
        break;
      }
      default:
        if (e !== undefined && e >= 0x30 && e <= 0x37) {
          let v = e - 0x30;
          let k = 1;
          while (k < 3 && p < b.length && b[p] >= 0x30 && b[p] <= 0x37) {
            v = 8 * v + (b[p] - 0x30);
            p++;
            k++;
          }
          put(v & 255);
        } else if (e !== undefined) put(e); // \\ \" \' and any other character as itself
    }
  }
  return -1;
}

function hexValue(c: number): number {
  if (c >= 0x30 && c <= 0x39) return c - 0x30;
  if (c >= 0x61 && c <= 0x66) return c - 0x57;
  if (c >= 0x41 && c <= 0x46) return c - 0x37;
  return -1;
}

// ---- glTF binary -----------------------------------------------------------------------------

function readGlb(b: Uint8Array): ReadExportResult {
  if (b.length < 20) return { ok: false, error: 'the GLB file is truncated (no JSON chunk)' };
  const version = u32(b, 4);
  if (version !== 2) return { ok: false, error: `the GLB file is glTF version ${version}, not 2` };
  const jsonLength = u32(b, 12);
  if (u32(b, 16) !== CHUNK_JSON)
    return { ok: false, error: 'the GLB file does not start with a JSON chunk' };
  if (20 + jsonLength > b.length) return { ok: false, error: 'the GLB file is truncated' };
  let text: string;
  try {
    text = new TextDecoder('utf-8', { fatal: true }).decode(b.subarray(20, 20 + jsonLength));
  } catch {
    return { ok: false, error: "the GLB file's JSON chunk is not valid UTF-8" };
  }
  const parsed = parseJson(text, "the GLB file's JSON chunk");
  if (!parsed.ok) return parsed;
  const gltf = parsed.session as { asset?: { extras?: { hairsketch?: { session?: unknown } } } };
  const session = gltf?.asset?.extras?.hairsketch?.session;
  if (session === undefined)
    return { ok: false, error: 'the glTF file carries no hairsketch session' };
  return { ok: true, session };
}
