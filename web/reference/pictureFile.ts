// What a reference picture file is, before any decoder sees it: its format from its first
// bytes, its size in pixels from its header, and for a PNG every chunk's CRC and the chunk
// order (a damaged PNG is refused by name, not shown half-decoded). Pure functions over bytes:
// the app decodes the picture (createImageBitmap) only after these checks pass.
import type { PictureFormat } from '../model/referenceImage';
import { SESSION_LIMITS as L } from '../model/sessionLimits';

export interface PictureHeader {
  format: PictureFormat;
  width: number;
  height: number;
}

export type PictureCheck = { ok: true; value: PictureHeader } | { ok: false; error: string };

const PNG_SIGNATURE = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];

/** The MIME type of each format (for the decoder's Blob). */
export const PICTURE_MIME: Record<PictureFormat, string> = {
  png: 'image/png',
  jpeg: 'image/jpeg',
  webp: 'image/webp',
};

let crcTable: Uint32Array | null = null;
/** CRC-32 (ISO 3309, as PNG uses it) of bytes. */
export function crc32(bytes: Uint8Array): number {
  if (!crcTable) {
    crcTable = new Uint32Array(256);
    for (let n = 0; n < 256; n++) {
      let c = n;
      for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
      crcTable[n] = c >>> 0;
    }
  }
  let c = 0xffffffff;
  for (let i = 0; i < bytes.length; i++) c = crcTable[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

const u32be = (b: Uint8Array, i: number) =>
  ((b[i] << 24) | (b[i + 1] << 16) | (b[i + 2] << 8) | b[i + 3]) >>> 0;
const u16be = (b: Uint8Array, i: number) => (b[i] << 8) | b[i + 1];
const u16le = (b: Uint8Array, i: number) => b[i] | (b[i + 1] << 8);
const u24le = (b: Uint8Array, i: number) => b[i] | (b[i + 1] << 8) | (b[i + 2] << 16);
const ascii = (b: Uint8Array, i: number, n: number) =>
  String.fromCharCode(...b.subarray(i, Math.min(b.length, i + n)));

/** A PNG's size, with every chunk's CRC checked, IHDR first, IDAT present and IEND last. */
function png(b: Uint8Array): PictureCheck | string {
  let i = 8;
  let size: { width: number; height: number } | null = null;
  let idat = false;
  while (true) {
    if (i + 12 > b.length) return 'a damaged PNG: it ends before its IEND chunk';
    const length = u32be(b, i);
    const type = ascii(b, i + 4, 4);
    if (length > b.length - i - 12)
      return `a damaged PNG: its ${JSON.stringify(type)} chunk runs past the end of the file`;
    const crc = u32be(b, i + 8 + length);
    if (crc32(b.subarray(i + 4, i + 8 + length)) !== crc)
      return `a damaged PNG: its ${JSON.stringify(type)} chunk fails its checksum`;
    if (size === null) {
      if (type !== 'IHDR' || length !== 13) return 'a damaged PNG: it does not start with IHDR';
      size = { width: u32be(b, i + 8), height: u32be(b, i + 12) };
    } else if (type === 'IDAT') idat = true;
    else if (type === 'IEND') {
      if (!idat) return 'a damaged PNG: it has no image data (IDAT)';
      return { ok: true, value: { format: 'png', ...size } };
    }
    i += 12 + length;
  }
}

/** A JPEG's size from its first start-of-frame marker. */
function jpeg(b: Uint8Array): PictureCheck | string {
  let i = 2;
  while (i + 4 <= b.length) {
    if (b[i] !== 0xff) return 'a damaged JPEG: a marker is missing';
    const m = b[i + 1];
    if (m === 0xff) {
      i++; // fill byte
      continue;
    }
    if (m === 0xd8 || (m >= 0xd0 && m <= 0xd7) || m === 0x01) {
      i += 2;
      continue;
    }
    const length = u16be(b, i + 2);
    if (length < 2) return 'a damaged JPEG: a segment has no length';
    const sof = m >= 0xc0 && m <= 0xcf && m !== 0xc4 && m !== 0xc8 && m !== 0xcc;
    if (sof) {
      if (i + 9 > b.length) break;
      return {
        ok: true,
        value: { format: 'jpeg', height: u16be(b, i + 5), width: u16be(b, i + 7) },
      };
    }
    if (m === 0xda || m === 0xd9) return 'a damaged JPEG: it has no frame header';
    i += 2 + length;
  }
  return 'a damaged JPEG: it ends before its frame header';
}

/** A WebP's size from its VP8, VP8L or VP8X chunk. */
function webp(b: Uint8Array): PictureCheck | string {
  const chunk = ascii(b, 12, 4);
  const d = 20;
  if (chunk === 'VP8X' && b.length >= d + 10)
    return {
      ok: true,
      value: { format: 'webp', width: u24le(b, d + 4) + 1, height: u24le(b, d + 7) + 1 },
    };
  if (chunk === 'VP8L' && b.length >= d + 5 && b[d] === 0x2f) {
    const bits = (b[d + 1] | (b[d + 2] << 8) | (b[d + 3] << 16) | (b[d + 4] << 24)) >>> 0;
    return {
      ok: true,
      value: { format: 'webp', width: (bits & 0x3fff) + 1, height: ((bits >>> 14) & 0x3fff) + 1 },
    };
  }
  if (chunk === 'VP8 ' && b.length >= d + 10 && b[d + 3] === 0x9d && b[d + 4] === 0x01)
    return {
      ok: true,
      value: { format: 'webp', width: u16le(b, d + 6) & 0x3fff, height: u16le(b, d + 8) & 0x3fff },
    };
  return 'a damaged WebP: it has no VP8, VP8L or VP8X header';
}

/** The format and size of a picture file, or one sentence saying why it cannot be a reference
 *  picture: not a PNG, JPEG or WebP, larger than maxPictureFileBytes, more than
 *  maxPicturePixels, or a damaged header (a PNG: any chunk). */
export function checkPictureFile(bytes: Uint8Array): PictureCheck {
  if (bytes.length > L.maxPictureFileBytes)
    return {
      ok: false,
      error: `it is larger than ${L.maxPictureFileBytes / (1 << 20)} MB, the most a picture may be`,
    };
  let r: PictureCheck | string;
  if (PNG_SIGNATURE.every((x, i) => bytes[i] === x)) r = png(bytes);
  else if (bytes[0] === 0xff && bytes[1] === 0xd8 && bytes[2] === 0xff) r = jpeg(bytes);
  else if (ascii(bytes, 0, 4) === 'RIFF' && ascii(bytes, 8, 4) === 'WEBP') r = webp(bytes);
  else return { ok: false, error: 'it is not a PNG, JPEG or WebP picture' };
  if (typeof r === 'string') return { ok: false, error: `it is ${r}` };
  if (!r.ok) return r;
  const { width, height } = r.value;
  if (width < 1 || height < 1) return { ok: false, error: `it is ${width} × ${height} pixels` };
  const mp = (width * height) / 1e6;
  if (width * height > L.maxPicturePixels)
    return {
      ok: false,
      error: `it is ${width} × ${height} pixels (${mp.toFixed(1)} megapixels), more than the ${L.maxPicturePixels / 1e6} megapixels a picture may have`,
    };
  return r;
}
