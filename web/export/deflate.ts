// A small deflate compressor (RFC 1951): one block with the fixed Huffman codes, greedy LZ77
// matches found through a hash of the next 3 bytes and a chain of earlier positions (at most
// MAX_CHAIN tried). Plain integer arithmetic on typed arrays, so the same input gives the same
// bytes in every JS engine (the browser's CompressionStream makes no such promise and is
// asynchronous; node:zlib is not in the browser). It is no match for zlib's ratio on varied
// data, but the hair cards' atlas is runs of the same pixels, which it shrinks well.

const WINDOW = 32768;
const MAX_MATCH = 258;
const MIN_MATCH = 3;
const MAX_CHAIN = 16;
const HASH_BITS = 15;

// RFC 1951 3.2.5: length codes 257..285 and distance codes 0..29, their bases and extra bits
const LENGTH_BASE = [
  3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131,
  163, 195, 227, 258,
];
const LENGTH_EXTRA = [
  0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0,
];
const DIST_BASE = [
  1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769, 1025, 1537, 2049,
  3073, 4097, 6145, 8193, 12289, 16385, 24577,
];
const DIST_EXTRA = [
  0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13,
];

/** Length 3..258 → index into LENGTH_BASE. */
const LENGTH_INDEX = (() => {
  const t = new Uint8Array(MAX_MATCH + 1);
  for (let k = 0; k < LENGTH_BASE.length; k++) {
    const end = k + 1 < LENGTH_BASE.length ? LENGTH_BASE[k + 1] : MAX_MATCH + 1;
    for (let l = LENGTH_BASE[k]; l < end && l <= MAX_MATCH; l++) t[l] = k;
  }
  t[MAX_MATCH] = LENGTH_BASE.length - 1; // 258 has its own code (285), not 284 + 31
  return t;
})();

function reverseBits(code: number, len: number): number {
  let r = 0;
  for (let i = 0; i < len; i++) r = (r << 1) | ((code >>> i) & 1);
  return r;
}

/** The fixed literal/length code (RFC 1951 3.2.6), bit-reversed for the LSB-first stream. */
const FIXED = (() => {
  const code = new Uint16Array(288);
  const len = new Uint8Array(288);
  for (let s = 0; s < 288; s++) {
    let c: number;
    let l: number;
    if (s < 144) [c, l] = [0x30 + s, 8];
    else if (s < 256) [c, l] = [0x190 + s - 144, 9];
    else if (s < 280) [c, l] = [s - 256, 7];
    else [c, l] = [0xc0 + s - 280, 8];
    code[s] = reverseBits(c, l);
    len[s] = l;
  }
  return { code, len };
})();

class BitWriter {
  private out: Uint8Array;
  private n = 0;
  private acc = 0;
  private bits = 0;

  constructor(capacity: number) {
    this.out = new Uint8Array(Math.max(64, capacity));
  }

  /** `count` (≤ 16) bits of `value`, least significant first. */
  put(value: number, count: number): void {
    this.acc |= value << this.bits;
    this.bits += count;
    while (this.bits >= 8) {
      if (this.n === this.out.length) {
        const grown = new Uint8Array(2 * this.out.length);
        grown.set(this.out);
        this.out = grown;
      }
      this.out[this.n++] = this.acc & 255;
      this.acc >>>= 8;
      this.bits -= 8;
    }
  }

  symbol(s: number): void {
    this.put(FIXED.code[s], FIXED.len[s]);
  }

  finish(): Uint8Array {
    if (this.bits > 0) this.put(0, 8 - this.bits);
    return this.out.slice(0, this.n);
  }
}

/** `data` as a raw deflate stream (one final block, fixed Huffman codes). */
export function deflateFixed(data: Uint8Array): Uint8Array {
  const n = data.length;
  const w = new BitWriter((n >>> 2) + 1024);
  w.put(1, 1); // BFINAL
  w.put(1, 2); // BTYPE 01: fixed Huffman codes
  const head = new Int32Array(1 << HASH_BITS).fill(-1);
  const prev = new Int32Array(WINDOW).fill(-1);
  const hash = (p: number) =>
    ((data[p] << 10) ^ (data[p + 1] << 5) ^ data[p + 2]) & ((1 << HASH_BITS) - 1);
  const insert = (p: number) => {
    if (p + 2 >= n) return;
    const h = hash(p);
    prev[p & (WINDOW - 1)] = head[h];
    head[h] = p;
  };
  let i = 0;
  while (i < n) {
    let bestLen = 0;
    let bestDist = 0;
    if (i + MIN_MATCH <= n) {
      const max = Math.min(MAX_MATCH, n - i);
      let cand = head[hash(i)];
      for (let chain = 0; cand >= 0 && i - cand <= WINDOW && chain < MAX_CHAIN; chain++) {
        if (data[cand + bestLen] === data[i + bestLen]) {
          let l = 0;
          while (l < max && data[cand + l] === data[i + l]) l++;
          if (l > bestLen) {
            bestLen = l;
            bestDist = i - cand;
            if (l === max) break;
          }
        }
        const next = prev[cand & (WINDOW - 1)];
        if (next >= cand) break; // a slot reused by a later position: the chain ends here
        cand = next;
      }
    }
    if (bestLen >= MIN_MATCH) {
      const k = LENGTH_INDEX[bestLen];
      w.symbol(257 + k);
      if (LENGTH_EXTRA[k] > 0) w.put(bestLen - LENGTH_BASE[k], LENGTH_EXTRA[k]);
      let d = DIST_BASE.length - 1;
      while (DIST_BASE[d] > bestDist) d--;
      w.put(reverseBits(d, 5), 5);
      if (DIST_EXTRA[d] > 0) w.put(bestDist - DIST_BASE[d], DIST_EXTRA[d]);
      for (let p = i; p < i + bestLen; p++) insert(p);
      i += bestLen;
    } else {
      w.symbol(data[i]);
      insert(i);
      i++;
    }
  }
  w.symbol(256); // end of block
  return w.finish();
}
