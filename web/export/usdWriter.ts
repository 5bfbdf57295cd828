// USD `.usda` (plain text): the hair as one linear BasisCurves prim, the head as an optional Mesh,
// the session in the layer's customLayerData (docs/export.md, "File layouts"). Numbers
// with 6 significant digits (formatFloat); the text comes out in chunks of at most CHUNK_BYTES.
import { formatFloat, type Progress, TextSink } from './chunkSink';
import type { ExportStrands } from './strandsForExport';
import { type ExportInput, METERS_PER_UNIT, ROOT_WIDTH, TIP_WIDTH } from './types';

/** Strands written per batch (one progress report and one drain per batch). */
const BATCH = 2048;

/** The customLayerData key that carries the session JSON. */
export const USD_SESSION_KEY = 'hairsketch:session';

/** A USD string literal in double quotes, escaped as Sdf_FileIOUtility::Quote does (OpenUSD
 *  pxr/usd/sdf/fileIO_Common.cpp): backslash, the double quote, \n \r \t, other ASCII control
 *  characters as \xHH; every other character (UTF-8) as is. */
export function usdQuote(s: string): string {
  const parts: string[] = ['"'];
  let from = 0;
  for (let i = 0; i < s.length; i++) {
    const c = s.charCodeAt(i);
    if (c >= 0x20 && c !== 0x22 && c !== 0x5c && c !== 0x7f) continue;
    parts.push(s.slice(from, i));
    from = i + 1;
    if (c === 0x5c) parts.push('\\\\');
    else if (c === 0x22) parts.push('\\"');
    else if (c === 0x0a) parts.push('\\n');
    else if (c === 0x0d) parts.push('\\r');
    else if (c === 0x09) parts.push('\\t');
    else parts.push(`\\x${c.toString(16).padStart(2, '0')}`);
  }
  parts.push(s.slice(from), '"');
  return parts.join('');
}

function vec3(a: ArrayLike<number>, i: number): string {
  return `(${formatFloat(a[i])}, ${formatFloat(a[i + 1])}, ${formatFloat(a[i + 2])})`;
}

function extentOf(positions: Float32Array): [number[], number[]] {
  if (positions.length < 3)
    return [
      [0, 0, 0],
      [0, 0, 0],
    ];
  const lo = [positions[0], positions[1], positions[2]];
  const hi = [...lo];
  for (let i = 3; i < positions.length; i += 3)
    for (let c = 0; c < 3; c++) {
      const v = positions[i + c];
      if (v < lo[c]) lo[c] = v;
      if (v > hi[c]) hi[c] = v;
    }
  return [lo, hi];
}

export function* writeUsda(
  strands: ExportStrands,
  input: ExportInput,
  progress: Progress,
): Generator<Uint8Array> {
  const out = new TextSink();
  const { points, strandStart, widths, colors } = strands;
  const nStrands = strandStart.length - 1;
  const nPoints = widths.length;
  const head = input.head;
  const headVerts = head ? head.positions.length / 3 : 0;
  const headTris = head ? head.indices.length / 3 : 0;
  // Progress in numbers written: counts + points + widths + colours + head arrays.
  const total =
    nStrands * 4 + nPoints * 4 + (head ? headTris * 4 + headVerts * (head.normals ? 6 : 3) : 0) + 1;
  let done = 0;
  const tick = (n: number) => {
    done += n;
    progress.at(done / total);
  };

  out.write('#usda 1.0\n(\n    customLayerData = {\n');
  out.write(`        string ${usdQuote(USD_SESSION_KEY)} = `);
  out.write(usdQuote(JSON.stringify(input.session)));
  out.write('\n    }\n');
  out.write('    defaultPrim = "hairsketch"\n');
  out.write(`    metersPerUnit = ${formatFloat(METERS_PER_UNIT)}\n`);
  out.write('    upAxis = "Y"\n)\n\n');
  out.write('def Xform "hairsketch"\n{\n');

  // The hair.
  out.write('    def BasisCurves "hair"\n    {\n');
  out.write('        uniform token type = "linear"\n');
  out.write('        uniform token wrap = "nonperiodic"\n');

  out.write('        int[] curveVertexCounts = [');
  for (let s0 = 0; s0 < nStrands; s0 += BATCH) {
    const s1 = Math.min(nStrands, s0 + BATCH);
    const parts: string[] = [];
    for (let s = s0; s < s1; s++) parts.push(String(strandStart[s + 1] - strandStart[s]));
    out.write(s0 > 0 ? `, ${parts.join(', ')}` : parts.join(', '));
    tick(s1 - s0);
    yield* out.drain();
  }
  out.write(']\n');

  // One strand per line inside the brackets.
  out.write('        point3f[] points = [');
  for (let s0 = 0; s0 < nStrands; s0 += BATCH) {
    const s1 = Math.min(nStrands, s0 + BATCH);
    for (let s = s0; s < s1; s++) {
      const parts: string[] = [];
      for (let p = strandStart[s]; p < strandStart[s + 1]; p++) parts.push(vec3(points, 3 * p));
      out.write(s > 0 ? ',\n            ' : '\n            ');
      out.write(parts.join(', '));
    }
    tick(3 * (strandStart[s1] - strandStart[s0]));
    yield* out.drain();
  }
  out.write(nStrands > 0 ? '\n        ]\n' : ']\n');

  out.write('        float[] widths = [');
  for (let s0 = 0; s0 < nStrands; s0 += BATCH) {
    const s1 = Math.min(nStrands, s0 + BATCH);
    for (let s = s0; s < s1; s++) {
      const parts: string[] = [];
      for (let p = strandStart[s]; p < strandStart[s + 1]; p++) parts.push(formatFloat(widths[p]));
      out.write(s > 0 ? ',\n            ' : '\n            ');
      out.write(parts.join(', '));
    }
    tick(strandStart[s1] - strandStart[s0]);
    yield* out.drain();
  }
  out.write(nStrands > 0 ? '\n        ] (\n' : '] (\n');
  out.write('            interpolation = "vertex"\n        )\n');

  // Extent: the points' bounds padded by half the widest strand (as UsdGeomCurves::ComputeExtent).
  const pad = nPoints > 0 ? Math.max(ROOT_WIDTH, TIP_WIDTH) / 2 : 0;
  const lo = strands.min.map((v) => v - pad);
  const hi = strands.max.map((v) => v + pad);
  out.write(`        float3[] extent = [${vec3(lo, 0)}, ${vec3(hi, 0)}]\n`);

  out.write('        color3f[] primvars:displayColor = [');
  for (let s0 = 0; s0 < nStrands; s0 += BATCH) {
    const s1 = Math.min(nStrands, s0 + BATCH);
    const parts: string[] = [];
    for (let s = s0; s < s1; s++) parts.push(vec3(colors, 3 * s));
    out.write(s0 > 0 ? `, ${parts.join(', ')}` : parts.join(', '));
    tick(3 * (s1 - s0));
    yield* out.drain();
  }
  out.write('] (\n            interpolation = "uniform"\n        )\n');
  out.write('    }\n');

  // The head.
  if (head) {
    out.write('\n    def Mesh "head"\n    {\n');
    const [hlo, hhi] = extentOf(head.positions);
    out.write(`        float3[] extent = [${vec3(hlo, 0)}, ${vec3(hhi, 0)}]\n`);
    out.write('        int[] faceVertexCounts = [');
    const ROWS = 8192;
    for (let t0 = 0; t0 < headTris; t0 += ROWS) {
      const t1 = Math.min(headTris, t0 + ROWS);
      out.write((t0 > 0 ? ', ' : '') + new Array(t1 - t0).fill('3').join(', '));
      tick(t1 - t0);
    }
    out.write(']\n        int[] faceVertexIndices = [');
    for (let t0 = 0; t0 < headTris; t0 += ROWS) {
      const t1 = Math.min(headTris, t0 + ROWS);
      const parts: string[] = [];
      for (let i = 3 * t0; i < 3 * t1; i++) parts.push(String(head.indices[i]));
      out.write((t0 > 0 ? ', ' : '') + parts.join(', '));
      tick(3 * (t1 - t0));
      yield* out.drain();
    }
    out.write(']\n');
    out.write('        uniform token orientation = "rightHanded"\n');
    out.write('        point3f[] points = [');
    for (let v0 = 0; v0 < headVerts; v0 += ROWS) {
      const v1 = Math.min(headVerts, v0 + ROWS);
      const parts: string[] = [];
      for (let v = v0; v < v1; v++) parts.push(vec3(head.positions, 3 * v));
      out.write((v0 > 0 ? ', ' : '') + parts.join(', '));
      tick(3 * (v1 - v0));
      yield* out.drain();
    }
    out.write(']\n');
    const normals = head.normals;
    if (normals) {
      out.write('        normal3f[] primvars:normals = [');
      for (let v0 = 0; v0 < headVerts; v0 += ROWS) {
        const v1 = Math.min(headVerts, v0 + ROWS);
        const parts: string[] = [];
        for (let v = v0; v < v1; v++) parts.push(vec3(normals, 3 * v));
        out.write((v0 > 0 ? ', ' : '') + parts.join(', '));
        tick(3 * (v1 - v0));
        yield* out.drain();
      }
      out.write('] (\n            interpolation = "vertex"\n        )\n');
    }
    // A polygonal head: no subdivision (with subdivision the normals would be ignored).
    out.write('        uniform token subdivisionScheme = "none"\n');
    out.write('    }\n');
  }

  out.write('}\n');
  yield* out.end();
  progress.at(1);
}
