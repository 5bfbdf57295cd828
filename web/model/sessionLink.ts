// Share links: a session in the address bar's fragment, URL-safe characters only, no line
// breaks. The format, byte by byte, is in linkFormat.ts; the body is written by linkPack.ts and
// read by linkUnpack.ts. Here: the fragment (version, length, deflate) around it.
import { deflateRaw, fromBase64Url, inflateCapped, toBase64Url } from './bytes';
import { LinkError, Reader, Writer } from './linkBytes';
import { LINK_VERSION, LINK_VERSIONS_READ, MAX_LINK_BYTES, MAX_LINK_CHARS } from './linkFormat';
import { packSession } from './linkPack';
import { unpackSession } from './linkUnpack';
import type { SessionState } from './session';
import type { Parsed } from './sessionLimits';
import { parseSession } from './sessionRead';

// where they were first defined: callers and tests import them from here
export { crc32 } from './linkBytes';
export { MAX_LINK_BYTES, MAX_LINK_CHARS } from './linkFormat';
export { packSession } from './linkPack';
export { unpackSession } from './linkUnpack';
export { fromBase64Url, inflateCapped, toBase64Url };

/** The link fragment for a session (without '#'): `s=3.` + base64url(varint n +
 *  deflate-raw(body), n bytes). */
export async function encodeSessionLink(s: SessionState): Promise<string> {
  return encodeBinaryLink(s, LINK_VERSION);
}

/** The version 2 fragment, as links were written before version 3 (with the parameters version
 *  2 had); kept so tests can make the links people already hold. */
export async function encodeSessionLinkV2(s: SessionState): Promise<string> {
  return encodeBinaryLink(s, 2);
}

async function encodeBinaryLink(s: SessionState, version: 2 | 3): Promise<string> {
  const deflated = await deflateRaw(packSession(s, version));
  const w = new Writer();
  w.varint(deflated.length);
  w.bytes(deflated);
  return `s=${version}.${toBase64Url(w.done())}`;
}

/** The version 1 fragment (`s=` + base64url(deflate-raw(JSON)), numbers to 1e-5), as links were
 *  written before version 2; kept so tests can make the links people already hold. */
export async function encodeSessionLinkV1(s: SessionState): Promise<string> {
  const json = JSON.stringify(s, (_k, v) =>
    typeof v === 'number' ? Math.round(v * 1e5) / 1e5 : v,
  );
  return `s=${toBase64Url(await deflateRaw(new TextEncoder().encode(json)))}`;
}

/** The versions read, in words ("1, 2 and 3"). */
const READ = `${LINK_VERSIONS_READ.slice(0, -1).join(', ')} and ${LINK_VERSIONS_READ.at(-1)}`;

const damaged = (why: string): Parsed<SessionState> => ({
  ok: false,
  error: `the session link is damaged (${why})`,
});

/** Reads a link fragment made by encodeSessionLink, or a version 1 or 2 link (with or without the
 *  leading '#'). Never throws: a bad link gives a sentence saying what is wrong. */
export async function decodeSessionLink(fragment: string): Promise<Parsed<SessionState>> {
  if (fragment.length > MAX_LINK_CHARS)
    return {
      ok: false,
      error: `the session link is too long (${fragment.length.toLocaleString('en-US')} characters; at most ${MAX_LINK_CHARS.toLocaleString('en-US')})`,
    };
  const m = /^#?s=(?:(\d+)\.)?(.*)$/s.exec(fragment);
  if (!m) return { ok: false, error: 'the link holds no session (#s=…)' };
  const version = m[1] === undefined ? 1 : Number(m[1]);
  if (version !== 1 && version !== 2 && version !== 3)
    return {
      ok: false,
      error: `the session link is version ${m[1].slice(0, 12)}; this app opens versions ${READ}`,
    };
  if (/^[A-Za-z0-9_-]*$/.test(m[2]) && m[2].length % 4 === 1)
    return damaged('a character too many or too few: cut short?');
  let packed = fromBase64Url(m[2]);
  if (!packed || packed.length === 0) return damaged('not base64url');
  if (version !== 1) {
    const r = new Reader(packed);
    let n: number;
    try {
      n = r.varint();
    } catch {
      return damaged('it is cut short');
    }
    if (r.left < n) return damaged(`it is cut short (${r.left} of ${n} bytes)`);
    if (r.left > n) return damaged(`it has ${r.left - n} bytes too many at the end`);
    packed = packed.subarray(r.at);
  }
  const inflated = await inflateCapped(packed, MAX_LINK_BYTES);
  if (inflated === 'too large') return { ok: false, error: 'the session link is too large' };
  if (inflated === 'damaged') return damaged('it does not inflate');
  let data: unknown;
  if (version === 1) {
    try {
      data = JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(inflated));
    } catch {
      return damaged('not JSON');
    }
  } else {
    try {
      data = unpackSession(inflated, version);
    } catch (e) {
      if (e instanceof LinkError) return damaged(e.message);
      return damaged('it cannot be read');
    }
  }
  const parsed = parseSession(data);
  return parsed.ok ? parsed : { ok: false, error: `the session link is invalid: ${parsed.error}` };
}
