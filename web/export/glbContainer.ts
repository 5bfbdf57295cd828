// What the two binary glTF writers (glbWriter.ts: the strands; cardsWriter.ts: hair cards)
// share: glTF's enum values, an accessor's bounds, and the GLB container's header, JSON chunk
// and BIN chunk header (glTF 2.0, "Binary glTF Layout": chunks padded to 4 bytes, JSON with
// spaces).
import type { BinarySink } from './chunkSink';

export const FLOAT = 5126;
export const UNSIGNED_INT = 5125;
export const ARRAY_BUFFER = 34962;
export const ELEMENT_ARRAY_BUFFER = 34963;
export const LINES = 1;
export const TRIANGLES = 4;

const GLB_MAGIC = 0x46546c67; // "glTF"
const CHUNK_JSON = 0x4e4f534a; // "JSON"
const CHUNK_BIN = 0x004e4942; // "BIN\0"

/** min and max per axis of xyz triples (what a POSITION accessor must carry). */
export function bounds(positions: Float32Array): { min: number[]; max: number[] } {
  const min = [positions[0], positions[1], positions[2]];
  const max = [...min];
  for (let i = 3; i < positions.length; i += 3)
    for (let c = 0; c < 3; c++) {
      const v = positions[i + c];
      if (v < min[c]) min[c] = v;
      if (v > max[c]) max[c] = v;
    }
  return { min, max };
}

/** Writes the GLB header, the JSON chunk of `gltf` and, when `binLength` > 0, the BIN chunk's
 *  header (its length padded to 4 bytes); the caller then writes the BIN chunk's bytes and pads
 *  them. Returns the file's total length in bytes. */
export function writeGlbStart(out: BinarySink, gltf: unknown, binLength: number): number {
  const jsonBytes = new TextEncoder().encode(JSON.stringify(gltf));
  const jsonPadded = (jsonBytes.length + 3) & ~3;
  const binPadded = (binLength + 3) & ~3;
  const total = 12 + 8 + jsonPadded + (binLength > 0 ? 8 + binPadded : 0);
  out.u32(GLB_MAGIC);
  out.u32(2);
  out.u32(total);
  out.u32(jsonPadded);
  out.u32(CHUNK_JSON);
  out.raw(jsonBytes);
  out.raw(new Uint8Array(jsonPadded - jsonBytes.length).fill(0x20));
  if (binLength > 0) {
    out.u32(binPadded);
    out.u32(CHUNK_BIN);
  }
  return total;
}
