// Cem Yuksel's `.hair` (binary, little-endian; docs/export.md "File layouts"): a 128-byte header, then
// segments uint16[N] (points − 1 per strand), points float32[3P], thickness float32[P] (the
// diameter, = the USD width) and colours float32[3P] (linear RGB, the strand's colour at each of
// its points). No transparency array.
import { BinarySink, type Progress, writeStrandFloats } from './chunkSink';
import { type ExportStrands, parseHexColor, srgbToLinear } from './strandsForExport';
import { type ExportInput, ROOT_WIDTH } from './types';

export const HAIR_HEADER_BYTES = 128;
export const HAIR_HAS_SEGMENTS = 1;
export const HAIR_HAS_POINTS = 2;
export const HAIR_HAS_THICKNESS = 4;
export const HAIR_HAS_TRANSPARENCY = 8;
export const HAIR_HAS_COLORS = 16;
/** The free-text field (bytes 40–127, zero padded). */
export const HAIR_INFO = 'hairsketch';

const BATCH = 4096;

/** The exact size of the file for N strands and P points. */
export function hairFileSize(nStrands: number, nPoints: number): number {
  return HAIR_HEADER_BYTES + 2 * nStrands + 12 * nPoints + 4 * nPoints + 12 * nPoints;
}

export function* writeHair(
  strands: ExportStrands,
  input: ExportInput,
  progress: Progress,
): Generator<Uint8Array> {
  const { strandStart, widths } = strands;
  const n = strandStart.length - 1;
  const p = widths.length;
  const total = hairFileSize(n, p);
  const out = new BinarySink();

  out.raw(new Uint8Array([0x48, 0x41, 0x49, 0x52])); // "HAIR"
  out.u32(n);
  out.u32(p);
  out.u32(HAIR_HAS_SEGMENTS | HAIR_HAS_POINTS | HAIR_HAS_THICKNESS | HAIR_HAS_COLORS);
  out.u32(0); // default segments: unused (the segments array is present)
  out.f32(ROOT_WIDTH); // default thickness: unused
  out.f32(0); // default transparency: unused (0 = opaque)
  const base = parseHexColor(input.session.hairColor).map(srgbToLinear);
  for (const c of base) out.f32(c); // default colour: unused (the session colour, linear)
  const info = new TextEncoder().encode(HAIR_INFO);
  out.raw(info);
  out.zeros(HAIR_HEADER_BYTES - 40 - info.length);

  const report = () => progress.at(out.bytes / total);

  for (let s0 = 0; s0 < n; s0 += BATCH) {
    const s1 = Math.min(n, s0 + BATCH);
    for (let s = s0; s < s1; s++) out.u16(strandStart[s + 1] - strandStart[s] - 1);
    report();
    yield* out.drain();
  }
  yield* writeStrandFloats(out, strands, 'points', report);
  yield* writeStrandFloats(out, strands, 'widths', report);
  yield* writeStrandFloats(out, strands, 'colors', report);
  yield* out.end();
  progress.at(1);
}
