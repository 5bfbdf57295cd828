// Bytes as text and back, for share links (sessionLink.ts) and session files that embed a head
// (sessionFile.ts): raw deflate through the platform's CompressionStream, inflating with a size
// cap, base64 (standard and URL-safe), and SHA-256 as hex (the content hash naming a head).
// Each works the same in the browser and in Node 20+.

// ---- base64 ------------------------------------------------------------------------------------

/** Standard base64 (with padding). */
export function toBase64(bytes: Uint8Array): string {
  let bin = '';
  for (let i = 0; i < bytes.length; i += 0x8000)
    bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(bin);
}

/** Standard base64 (padding optional) to bytes; null when it is not base64. */
export function fromBase64(text: string): Uint8Array | null {
  if (!/^[A-Za-z0-9+/]*={0,2}$/.test(text) || text.replace(/=+$/, '').length % 4 === 1) return null;
  try {
    const bin = atob(text);
    const out = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
    return out;
  } catch {
    return null;
  }
}

/** URL-safe base64 without padding (RFC 4648 §5). */
export function toBase64Url(bytes: Uint8Array): string {
  return toBase64(bytes).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

export function fromBase64Url(text: string): Uint8Array | null {
  if (!/^[A-Za-z0-9_-]*$/.test(text) || text.length % 4 === 1) return null;
  return fromBase64(text.replace(/-/g, '+').replace(/_/g, '/'));
}

// ---- deflate -----------------------------------------------------------------------------------

/** Raw deflate (RFC 1951) of `bytes`. */
export async function deflateRaw(bytes: Uint8Array): Promise<Uint8Array> {
  const out = new Response(
    new Blob([bytes as BlobPart]).stream().pipeThrough(new CompressionStream('deflate-raw')),
  );
  return new Uint8Array(await out.arrayBuffer());
}

/** Compressed bytes handed to the inflater at a time: deflate expands at most ~1032:1, so one
 *  slice inflates to at most ~4 MiB. (Chromium inflates a whole input chunk before its output
 *  can be read: fed the link in one piece, a 1 GiB bomb took 3.8 s before the first check.) */
const INFLATE_SLICE = 4096;

/** Inflates raw deflate `bytes`, giving up as soon as the output passes `cap` bytes ('too
 *  large') or the data is not valid deflate ('damaged'). The input goes in in slices, read as
 *  they inflate. */
export async function inflateCapped(
  bytes: Uint8Array,
  cap: number,
): Promise<Uint8Array | 'too large' | 'damaged'> {
  const ds = new DecompressionStream('deflate-raw');
  const writer = ds.writable.getWriter();
  const reader = ds.readable.getReader();
  let stop = false;
  void (async () => {
    for (let i = 0; i < bytes.length && !stop; i += INFLATE_SLICE)
      await writer.write(bytes.slice(i, i + INFLATE_SLICE));
    if (!stop) await writer.close();
  })().catch(() => {}); // a damaged stream: the reader below says so
  const chunks: Uint8Array[] = [];
  let total = 0;
  try {
    for (;;) {
      const { done, value } = await reader.read();
      if (done) break;
      total += value.length;
      if (total > cap) {
        stop = true;
        reader.cancel().catch(() => {});
        return 'too large';
      }
      chunks.push(value);
    }
  } catch {
    stop = true;
    return 'damaged';
  }
  const out = new Uint8Array(total);
  let at = 0;
  for (const c of chunks) {
    out.set(c, at);
    at += c.length;
  }
  return out;
}

// ---- SHA-256 -----------------------------------------------------------------------------------

const hex = (b: Uint8Array) => Array.from(b, (x) => x.toString(16).padStart(2, '0')).join('');

/** SHA-256 of `bytes` as 64 lowercase hex digits: the platform's crypto.subtle, or (where it is
 *  missing: a page served over plain http from another machine is not a secure context) the
 *  same digest computed here. */
export async function sha256Hex(bytes: ArrayBuffer | Uint8Array): Promise<string> {
  const view = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
  const subtle = globalThis.crypto?.subtle;
  if (subtle) {
    try {
      return hex(new Uint8Array(await subtle.digest('SHA-256', view as BufferSource)));
    } catch {
      // a detached or shared buffer the platform refuses: compute it here
    }
  }
  return sha256HexPortable(view);
}

const K = new Uint32Array([
  0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
  0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
  0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
  0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
  0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
  0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
  0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
  0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2,
]);

/** SHA-256 (FIPS 180-4) computed in JavaScript: the fallback of sha256Hex. */
export function sha256HexPortable(bytes: Uint8Array): string {
  const h = new Uint32Array([
    0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19,
  ]);
  const w = new Uint32Array(64);
  const n = bytes.length;
  // the message, a 1 bit, zeros, and the bit length (64-bit big-endian) in whole 64-byte blocks;
  // `tail` holds the blocks from the one where the message ends (one or two blocks)
  const blocks = Math.ceil((n + 9) / 64);
  const tailStart = 64 * Math.floor(n / 64);
  const tailLength = 64 * blocks - tailStart;
  const tail = new Uint8Array(tailLength);
  tail.set(bytes.subarray(tailStart));
  tail[n - tailStart] = 0x80;
  const bits = n * 8;
  const dv = new DataView(tail.buffer);
  dv.setUint32(tailLength - 8, Math.floor(bits / 2 ** 32));
  dv.setUint32(tailLength - 4, bits >>> 0);
  const word = (b: number, i: number): number => {
    const at = 64 * b + 4 * i;
    const src = at < tailStart ? bytes : tail;
    const o = at < tailStart ? at : at - tailStart;
    return ((src[o] << 24) | (src[o + 1] << 16) | (src[o + 2] << 8) | src[o + 3]) >>> 0;
  };
  for (let b = 0; b < blocks; b++) {
    for (let i = 0; i < 16; i++) w[i] = word(b, i);
    for (let i = 16; i < 64; i++) {
      const a = w[i - 15];
      const c = w[i - 2];
      const s0 = ((a >>> 7) | (a << 25)) ^ ((a >>> 18) | (a << 14)) ^ (a >>> 3);
      const s1 = ((c >>> 17) | (c << 15)) ^ ((c >>> 19) | (c << 13)) ^ (c >>> 10);
      w[i] = (w[i - 16] + s0 + w[i - 7] + s1) >>> 0;
    }
    let [a, bb, c, d, e, f, g, hh] = h;
    for (let i = 0; i < 64; i++) {
      const S1 = ((e >>> 6) | (e << 26)) ^ ((e >>> 11) | (e << 21)) ^ ((e >>> 25) | (e << 7));
      const ch = (e & f) ^ (~e & g);
      const t1 = (hh + S1 + ch + K[i] + w[i]) >>> 0;
      const S0 = ((a >>> 2) | (a << 30)) ^ ((a >>> 13) | (a << 19)) ^ ((a >>> 22) | (a << 10));
      const maj = (a & bb) ^ (a & c) ^ (bb & c);
      const t2 = (S0 + maj) >>> 0;
      hh = g;
      g = f;
      f = e;
      e = (d + t1) >>> 0;
      d = c;
      c = bb;
      bb = a;
      a = (t1 + t2) >>> 0;
    }
    h[0] += a;
    h[1] += bb;
    h[2] += c;
    h[3] += d;
    h[4] += e;
    h[5] += f;
    h[6] += g;
    h[7] += hh;
  }
  const out = new Uint8Array(32);
  const ov = new DataView(out.buffer);
  for (let i = 0; i < 8; i++) ov.setUint32(4 * i, h[i]);
  return hex(out);
}
