// The byte-level pieces of a share link's body (linkFormat.ts): a growing writer and a checked
// reader of bytes, varints, zigzag varints and f64s, delta-coded polylines, and the CRC-32 that
// closes the body.
import { toGridInt } from './gridNumbers';
import type { Vec3 } from './vec3';

/** A body that does not fit the layout; its message says where (shown in "the session link is
 *  damaged (…)"). */
const CRC_TABLE = (() => {
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    t[n] = c >>> 0;
  }
  return t;
})();

export function crc32(bytes: Uint8Array): number {
  let c = 0xffffffff;
  for (let i = 0; i < bytes.length; i++) c = CRC_TABLE[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

export class Writer {
  private buf = new Uint8Array(1024);
  length = 0;

  private room(n: number) {
    if (this.length + n <= this.buf.length) return;
    const next = new Uint8Array(Math.max(this.buf.length * 2, this.length + n));
    next.set(this.buf.subarray(0, this.length));
    this.buf = next;
  }

  u8(b: number) {
    this.room(1);
    this.buf[this.length++] = b;
  }

  bytes(b: Uint8Array) {
    this.room(b.length);
    this.buf.set(b, this.length);
    this.length += b.length;
  }

  /** Unsigned integers up to 2^53 (arithmetic, not 32-bit shifts). */
  varint(n: number) {
    let v = n;
    while (v >= 0x80) {
      this.u8((v % 0x80) | 0x80);
      v = Math.floor(v / 0x80);
    }
    this.u8(v);
  }

  zigzag(n: number) {
    this.varint(n >= 0 ? 2 * n : -2 * n - 1);
  }

  f64(x: number) {
    const b = new Uint8Array(8);
    new DataView(b.buffer).setFloat64(0, x, true);
    this.bytes(b);
  }

  u32(x: number) {
    const b = new Uint8Array(4);
    new DataView(b.buffer).setUint32(0, x, true);
    this.bytes(b);
  }

  done(): Uint8Array {
    return this.buf.slice(0, this.length);
  }
}

export function writePolyline(w: Writer, pts: readonly Vec3[], scale: number) {
  w.varint(pts.length);
  const prev = [0, 0, 0];
  const prev2 = [0, 0, 0];
  pts.forEach((p, i) => {
    for (let a = 0; a < 3; a++) {
      const k = toGridInt(p[a], scale);
      const guess = i === 0 ? 0 : i === 1 ? prev[a] : 2 * prev[a] - prev2[a];
      w.zigzag(k - guess);
      prev2[a] = prev[a];
      prev[a] = k;
    }
  });
}

export function writeVec(w: Writer, v: Vec3, scale: number) {
  for (let a = 0; a < 3; a++) w.zigzag(toGridInt(v[a], scale));
}

export class LinkError extends Error {}

export class Reader {
  at = 0;
  constructor(private readonly b: Uint8Array) {}

  get left(): number {
    return this.b.length - this.at;
  }

  u8(): number {
    if (this.at >= this.b.length) throw new LinkError('it ends too early');
    return this.b[this.at++];
  }

  bytes(n: number): Uint8Array {
    if (n > this.left) throw new LinkError('it ends too early');
    this.at += n;
    return this.b.subarray(this.at - n, this.at);
  }

  varint(): number {
    let v = 0;
    let mul = 1;
    for (let i = 0; i < 8; i++) {
      const b = this.u8();
      v += (b & 0x7f) * mul;
      if (b < 0x80) return v;
      mul *= 0x80;
    }
    throw new LinkError('a number is too long');
  }

  /** A count of items that need at least `min` bytes each (so a count cannot ask for more than
   *  the data holds). */
  count(min: number): number {
    const n = this.varint();
    if (n * min > this.left) throw new LinkError('a count is larger than the data');
    return n;
  }

  zigzag(): number {
    const z = this.varint();
    return z % 2 === 0 ? z / 2 : -(z + 1) / 2;
  }

  f64(): number {
    const b = this.bytes(8);
    return new DataView(b.buffer, b.byteOffset, 8).getFloat64(0, true);
  }
}

export function readPolyline(r: Reader, scale: number): Vec3[] {
  const n = r.count(3);
  const out: Vec3[] = [];
  const prev = [0, 0, 0];
  const prev2 = [0, 0, 0];
  for (let i = 0; i < n; i++) {
    const p = [0, 0, 0];
    for (let a = 0; a < 3; a++) {
      const guess = i === 0 ? 0 : i === 1 ? prev[a] : 2 * prev[a] - prev2[a];
      const k = guess + r.zigzag();
      prev2[a] = prev[a];
      prev[a] = k;
      p[a] = k / scale + 0;
    }
    out.push(p as Vec3);
  }
  return out;
}

export function readVec(r: Reader, scale: number): Vec3 {
  return [r.zigzag() / scale + 0, r.zigzag() / scale + 0, r.zigzag() / scale + 0];
}
