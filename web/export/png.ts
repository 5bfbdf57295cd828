// A small PNG encoder (8-bit greyscale or RGBA, no interlace, filter "None" on every row) whose
// zlib stream comes from deflate.ts, our own deterministic compressor, so the bytes are the same
// in the browser and under Node (node:zlib is not in the browser, and the browser's
// CompressionStream is asynchronous and not specified byte for byte).
// Layout from the PNG specification (ISO/IEC 15948): signature, IHDR, IDAT, IEND, each chunk
// length, type, data, CRC-32 of type + data; the zlib wrapper from RFC 1950.
import { deflateFixed } from './deflate';

const SIGNATURE = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];
let crcTable: Uint32Array | null = null;

function crc32Table(): Uint32Array {
  if (crcTable) return crcTable;
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    t[n] = c >>> 0;
  }
  crcTable = t;
  return t;
}

/** CRC-32 (ISO 3309, as PNG uses it) of bytes[a .. b - 1]. */
export function crc32(bytes: Uint8Array, a = 0, b = bytes.length): number {
  const t = crc32Table();
  let c = 0xffffffff;
  for (let i = a; i < b; i++) c = t[(c ^ bytes[i]) & 255] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

/** Adler-32 (RFC 1950) of `bytes`. */
export function adler32(bytes: Uint8Array): number {
  let a = 1;
  let b = 0;
  // 5552 bytes keep both sums below 2^32 before the modulo
  for (let i = 0; i < bytes.length; ) {
    const end = Math.min(bytes.length, i + 5552);
    for (; i < end; i++) {
      a += bytes[i];
      b += a;
    }
    a %= 65521;
    b %= 65521;
  }
  return ((b << 16) | a) >>> 0;
}

/** A zlib stream of `raw` (RFC 1950: header, deflate data, Adler-32). */
export function zlibCompress(raw: Uint8Array): Uint8Array {
  const body = deflateFixed(raw);
  const out = new Uint8Array(2 + body.length + 4);
  out[0] = 0x78; // deflate, 32 KB window
  out[1] = 0x01; // check bits: 0x7801 is a multiple of 31; no dictionary
  out.set(body, 2);
  const ad = adler32(raw);
  const o = 2 + body.length;
  out[o] = ad >>> 24;
  out[o + 1] = (ad >>> 16) & 255;
  out[o + 2] = (ad >>> 8) & 255;
  out[o + 3] = ad & 255;
  return out;
}

/** A PNG of `pixels` (rows top to bottom, `channels` bytes per pixel: 1 grey, 4 RGBA). */
export function encodePng(
  width: number,
  height: number,
  channels: 1 | 4,
  pixels: Uint8Array,
): Uint8Array {
  if (!(width >= 1 && height >= 1 && pixels.length === width * height * channels))
    throw new Error(`PNG: ${pixels.length} bytes do not make ${width}×${height}×${channels}`);
  const rowBytes = width * channels;
  const raw = new Uint8Array((rowBytes + 1) * height);
  for (let y = 0; y < height; y++) {
    raw[y * (rowBytes + 1)] = 0; // filter None
    raw.set(pixels.subarray(y * rowBytes, (y + 1) * rowBytes), y * (rowBytes + 1) + 1);
  }
  const idat = zlibCompress(raw);
  const ihdr = new Uint8Array(13);
  const dv = new DataView(ihdr.buffer);
  dv.setUint32(0, width);
  dv.setUint32(4, height);
  ihdr[8] = 8; // bit depth
  ihdr[9] = channels === 4 ? 6 : 0; // colour type: RGBA or greyscale
  // compression 0, filter 0, interlace 0
  const total = SIGNATURE.length + 3 * 12 + ihdr.length + idat.length;
  const out = new Uint8Array(total);
  out.set(SIGNATURE, 0);
  let o = SIGNATURE.length;
  const chunk = (type: string, data: Uint8Array) => {
    const v = new DataView(out.buffer);
    v.setUint32(o, data.length);
    for (let i = 0; i < 4; i++) out[o + 4 + i] = type.charCodeAt(i);
    out.set(data, o + 8);
    v.setUint32(o + 8 + data.length, crc32(out, o + 4, o + 8 + data.length));
    o += 12 + data.length;
  };
  chunk('IHDR', ihdr);
  chunk('IDAT', idat);
  chunk('IEND', new Uint8Array(0));
  return out;
}
