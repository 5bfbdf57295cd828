// Shared by the export writers: chunked output (text and little-endian binary) and the one
// number format of the text formats.
import type { ExportStrands } from './strandsForExport';

/** No chunk a writer yields is larger than this (1 MiB). */
export const CHUNK_BYTES = 1 << 20;

/** A float as text with at most 6 significant digits, the same in every JS engine:
 *  Number.prototype.toPrecision is specified exactly by ECMA-262 (round to nearest, ties to the
 *  larger magnitude), then trailing zeros are dropped. Plain notation for 1e-6 <= |x| < 1e6
 *  ("0.0008", "-1.23457", "123457"), C exponent notation otherwise ("1.5e-7", "2e+6"), which
 *  every strtod-based reader (USD, OBJ) accepts. 0 and -0 give "0"; NaN and ±Infinity give "0"
 *  (no export format can carry them). */
export function formatFloat(x: number): string {
  if (x === 0 || !Number.isFinite(x)) return '0';
  const s = x.toPrecision(6);
  const e = s.indexOf('e');
  if (e < 0) return s.indexOf('.') < 0 ? s : stripZeros(s);
  return stripZeros(s.slice(0, e)) + s.slice(e);
}

function stripZeros(s: string): string {
  if (s.indexOf('.') < 0) return s;
  let end = s.length;
  while (s.charCodeAt(end - 1) === 48) end--; // '0'
  if (s.charCodeAt(end - 1) === 46) end--; // '.'
  return s.slice(0, end);
}

/** Progress over weighted sections: section i covers [start_i, start_i + weight_i) of 0..1. */
export class Progress {
  private last = -1;
  constructor(private readonly report?: (fraction: number) => void) {}

  /** Reports `fraction` (clamped to 0..1, never decreasing). */
  at(fraction: number): void {
    if (!this.report) return;
    const f = Math.min(1, Math.max(0, fraction));
    if (f <= this.last) return;
    this.last = f;
    this.report(f);
  }
}

/** Text accumulated into UTF-8 chunks of at most CHUNK_BYTES. Writers call write() and, after
 *  each batch, `yield* sink.drain()`; finally `yield* sink.end()`. */
export class TextSink {
  private readonly encoder = new TextEncoder();
  private pending: string[] = [];
  private pendingChars = 0;
  private buf = new Uint8Array(CHUNK_BYTES);
  private used = 0;
  private ready: Uint8Array[] = [];
  /** Total bytes emitted so far (ready + yielded) plus bytes in the current buffer. */
  bytes = 0;

  write(s: string): void {
    this.pending.push(s);
    this.pendingChars += s.length;
    if (this.pendingChars >= 1 << 16) this.encodePending();
  }

  /** Completed chunks so far. */
  *drain(): Generator<Uint8Array> {
    const r = this.ready;
    this.ready = [];
    for (const c of r) yield c;
  }

  /** Everything left, the last chunk possibly short. */
  *end(): Generator<Uint8Array> {
    this.encodePending();
    if (this.used > 0) this.ready.push(this.buf.slice(0, this.used));
    this.used = 0;
    yield* this.drain();
  }

  private encodePending(): void {
    if (this.pending.length === 0) return;
    let s = this.pending.length === 1 ? this.pending[0] : this.pending.join('');
    this.pending = [];
    this.pendingChars = 0;
    while (s.length > 0) {
      const { read, written } = this.encoder.encodeInto(s, this.buf.subarray(this.used));
      this.used += written;
      this.bytes += written;
      s = read < s.length ? s.slice(read) : '';
      // encodeInto stops before a character that does not fit (never splits one).
      if (s.length > 0 || this.used === CHUNK_BYTES) {
        this.ready.push(this.buf.slice(0, this.used));
        this.used = 0;
      }
    }
  }
}

/** Little-endian binary accumulated into chunks of at most CHUNK_BYTES. */
export class BinarySink {
  private buf = new ArrayBuffer(CHUNK_BYTES);
  private view = new DataView(this.buf);
  private bytesView = new Uint8Array(this.buf);
  private used = 0;
  private ready: Uint8Array[] = [];
  bytes = 0;

  private room(n: number): void {
    if (this.used + n > CHUNK_BYTES) this.flush();
  }

  private flush(): void {
    if (this.used === 0) return;
    this.ready.push(this.bytesView.slice(0, this.used));
    this.used = 0;
  }

  u16(v: number): void {
    this.room(2);
    this.view.setUint16(this.used, v, true);
    this.used += 2;
    this.bytes += 2;
  }

  u32(v: number): void {
    this.room(4);
    this.view.setUint32(this.used, v, true);
    this.used += 4;
    this.bytes += 4;
  }

  f32(v: number): void {
    this.room(4);
    this.view.setFloat32(this.used, v, true);
    this.used += 4;
    this.bytes += 4;
  }

  /** float32 values from[a .. b - 1]. */
  f32s(from: Float32Array, a = 0, b = from.length): void {
    for (let i = a; i < b; i++) {
      if (this.used + 4 > CHUNK_BYTES) this.flush();
      this.view.setFloat32(this.used, from[i], true);
      this.used += 4;
    }
    this.bytes += 4 * (b - a);
  }

  /** uint32 values from[a .. b - 1]. */
  u32s(from: Uint32Array, a = 0, b = from.length): void {
    for (let i = a; i < b; i++) {
      if (this.used + 4 > CHUNK_BYTES) this.flush();
      this.view.setUint32(this.used, from[i], true);
      this.used += 4;
    }
    this.bytes += 4 * (b - a);
  }

  raw(bytes: Uint8Array): void {
    let off = 0;
    while (off < bytes.length) {
      if (this.used === CHUNK_BYTES) this.flush();
      const n = Math.min(bytes.length - off, CHUNK_BYTES - this.used);
      this.bytesView.set(bytes.subarray(off, off + n), this.used);
      this.used += n;
      off += n;
    }
    this.bytes += bytes.length;
  }

  zeros(n: number): void {
    for (let i = 0; i < n; i++) {
      this.room(1);
      this.bytesView[this.used++] = 0;
    }
    this.bytes += n;
  }

  *drain(): Generator<Uint8Array> {
    const r = this.ready;
    this.ready = [];
    for (const c of r) yield c;
  }

  *end(): Generator<Uint8Array> {
    this.flush();
    yield* this.drain();
  }
}

/** Strands per batch when writing per-point arrays (a progress report and a drain after each). */
const STRAND_BATCH = 4096;

/** Writes one per-point float32 array of the exported strands, in batches of strands:
 *  'points' (x, y, z), 'widths', or 'colors' (each strand's colour at each of its points). */
export function* writeStrandFloats(
  out: BinarySink,
  strands: ExportStrands,
  what: 'points' | 'widths' | 'colors',
  report: () => void,
): Generator<Uint8Array> {
  const { strandStart, points, widths, colors } = strands;
  const n = strandStart.length - 1;
  for (let s0 = 0; s0 < n; s0 += STRAND_BATCH) {
    const s1 = Math.min(n, s0 + STRAND_BATCH);
    if (what === 'points') out.f32s(points, 3 * strandStart[s0], 3 * strandStart[s1]);
    else if (what === 'widths') out.f32s(widths, strandStart[s0], strandStart[s1]);
    else
      for (let s = s0; s < s1; s++)
        for (let q = strandStart[s]; q < strandStart[s + 1]; q++) {
          out.f32(colors[3 * s]);
          out.f32(colors[3 * s + 1]);
          out.f32(colors[3 * s + 2]);
        }
    report();
    yield* out.drain();
  }
}
