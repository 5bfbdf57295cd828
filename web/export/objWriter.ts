// Wavefront OBJ: `o hair`, a `v` line per point, one `l` line per strand (1-based indices);
// with the head, `o head`, its `v` lines and `f a b c` faces (indices after the hair's points);
// with ties' bands (bandExport.ts), `o band` last, its `v`, `vn` and `f a//a …` lines (its colour
// in a comment: OBJ has colours only through a material file). No widths or colours (OBJ has
// none for lines). Numbers with 6 significant digits.
import { exportBand, objBand } from './bandExport';
import { formatFloat, type Progress, TextSink } from './chunkSink';
import type { ExportStrands } from './strandsForExport';
import type { ExportInput } from './types';

const BATCH = 2048;
const ROWS = 8192;

export function* writeObj(
  strands: ExportStrands,
  input: ExportInput,
  progress: Progress,
): Generator<Uint8Array> {
  const out = new TextSink();
  const { points, strandStart } = strands;
  const n = strandStart.length - 1;
  const p = strandStart[n];
  const head = input.head;
  const headVerts = head ? head.positions.length / 3 : 0;
  const headTris = head ? head.indices.length / 3 : 0;
  const total = 2 * p + headVerts + headTris + 1;
  let done = 0;
  const tick = (k: number) => {
    done += k;
    progress.at(done / total);
  };

  out.write('# hairsketch hair export: 1 unit = 10 cm, Y up\n');
  out.write('o hair\n');
  for (let s0 = 0; s0 < n; s0 += BATCH) {
    const s1 = Math.min(n, s0 + BATCH);
    const lines: string[] = [];
    for (let q = strandStart[s0]; q < strandStart[s1]; q++) {
      const i = 3 * q;
      lines.push(
        `v ${formatFloat(points[i])} ${formatFloat(points[i + 1])} ${formatFloat(points[i + 2])}\n`,
      );
    }
    out.write(lines.join(''));
    tick(strandStart[s1] - strandStart[s0]);
    yield* out.drain();
  }
  for (let s0 = 0; s0 < n; s0 += BATCH) {
    const s1 = Math.min(n, s0 + BATCH);
    const lines: string[] = [];
    for (let s = s0; s < s1; s++) {
      const idx: string[] = [];
      for (let q = strandStart[s]; q < strandStart[s + 1]; q++) idx.push(String(q + 1));
      lines.push(`l ${idx.join(' ')}\n`);
    }
    out.write(lines.join(''));
    tick(strandStart[s1] - strandStart[s0]);
    yield* out.drain();
  }

  if (head) {
    out.write('o head\n');
    const pos = head.positions;
    for (let v0 = 0; v0 < headVerts; v0 += ROWS) {
      const v1 = Math.min(headVerts, v0 + ROWS);
      const lines: string[] = [];
      for (let v = v0; v < v1; v++) {
        const i = 3 * v;
        lines.push(
          `v ${formatFloat(pos[i])} ${formatFloat(pos[i + 1])} ${formatFloat(pos[i + 2])}\n`,
        );
      }
      out.write(lines.join(''));
      tick(v1 - v0);
      yield* out.drain();
    }
    const base = p + 1;
    const ix = head.indices;
    for (let t0 = 0; t0 < headTris; t0 += ROWS) {
      const t1 = Math.min(headTris, t0 + ROWS);
      const lines: string[] = [];
      for (let t = t0; t < t1; t++) {
        const i = 3 * t;
        lines.push(`f ${ix[i] + base} ${ix[i + 1] + base} ${ix[i + 2] + base}\n`);
      }
      out.write(lines.join(''));
      tick(t1 - t0);
      yield* out.drain();
    }
  }
  const band = exportBand(input);
  if (band) out.write(objBand(band, { v: p + headVerts, vn: 0 }));
  yield* out.end();
  progress.at(1);
}
