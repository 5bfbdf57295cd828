// The ties' bands in an export (model/tieBands.ts, model/tieBandMesh.ts): the same bands the view
// shows, measured from the exported session's full hair, as one mesh in the band colour. The
// writers that take meshes add it beside the hair (glbWriter.ts, cardsWriter.ts: a mesh "band"
// with its own material; usdWriter.ts: a Mesh prim "band"; objWriter.ts: an object "band");
// the .hair format holds strands only and leaves it out.
import { DEFAULT_BAND_COLOR, hexToLinear } from '../model/hairLook';
import type { Rgb } from '../model/melanin';
import { type BandMesh, bandMesh } from '../model/tieBandMesh';
import { tieBands } from '../model/tieBands';
import { formatFloat } from './chunkSink';
import type { ExportInput } from './types';

export interface ExportBand {
  mesh: BandMesh;
  /** The band colour as the session names it (#rrggbb, sRGB) and as linear RGB. */
  hex: string;
  linear: Rgb;
  /** How many bands the mesh holds. */
  count: number;
}

/** The bands of the exported hair, or null without any (no ties, or `ties` off). */
export function exportBand(input: Pick<ExportInput, 'session' | 'strands'>): ExportBand | null {
  const bands = tieBands(input.session, input.strands);
  if (bands.length === 0) return null;
  const hex = input.session.bandColor ?? DEFAULT_BAND_COLOR;
  return {
    mesh: bandMesh(bands),
    hex,
    linear: hexToLinear(hex) ?? [0, 0, 0],
    count: bands.length,
  };
}

/** The band's material properties: an elastic's matte sheen. */
export const BAND_ROUGHNESS = 0.55;

const v3 = (a: ArrayLike<number>, i: number) =>
  `${formatFloat(a[i])} ${formatFloat(a[i + 1])} ${formatFloat(a[i + 2])}`;

/** OBJ lines of the band: `o band`, its vertices, normals and faces; `base` is the number of
 *  vertices (and normals, as `vn` are numbered on their own) written before it. */
export function objBand(band: ExportBand, base: { v: number; vn: number }): string {
  const { positions, normals, indices } = band.mesh;
  const lines = [`# band colour ${band.hex} (sRGB)\n`, 'o band\n'];
  for (let i = 0; i < positions.length; i += 3) lines.push(`v ${v3(positions, i)}\n`);
  for (let i = 0; i < normals.length; i += 3) lines.push(`vn ${v3(normals, i)}\n`);
  for (let t = 0; t < indices.length; t += 3) {
    const c = [0, 1, 2].map(
      (k) => `${indices[t + k] + base.v + 1}//${indices[t + k] + base.vn + 1}`,
    );
    lines.push(`f ${c.join(' ')}\n`);
  }
  return lines.join('');
}

/** The band as a USD Mesh prim "band" (inside the layer's root Xform), its colour as
 *  displayColor; `transform`: its xformOp lines (a motion's head pose), or ''. */
export function usdBand(band: ExportBand, transform = ''): string {
  const { positions, normals, indices } = band.mesh;
  const tuples = (a: ArrayLike<number>) => {
    const out: string[] = [];
    for (let i = 0; i < a.length; i += 3)
      out.push(`(${formatFloat(a[i])}, ${formatFloat(a[i + 1])}, ${formatFloat(a[i + 2])})`);
    return out.join(', ');
  };
  const lo = [0, 1, 2].map((k) => Math.min(...positions.filter((_, i) => i % 3 === k)));
  const hi = [0, 1, 2].map((k) => Math.max(...positions.filter((_, i) => i % 3 === k)));
  const [r, g, b] = band.linear.map(formatFloat);
  return [
    '\n    def Mesh "band"\n    {\n',
    transform,
    `        float3[] extent = [${tuples(lo)}, ${tuples(hi)}]\n`,
    `        int[] faceVertexCounts = [${Array(indices.length / 3)
      .fill('3')
      .join(', ')}]\n`,
    `        int[] faceVertexIndices = [${Array.from(indices).join(', ')}]\n`,
    '        uniform token orientation = "rightHanded"\n',
    `        point3f[] points = [${tuples(positions)}]\n`,
    `        normal3f[] primvars:normals = [${tuples(normals)}] (\n            interpolation = "vertex"\n        )\n`,
    `        color3f[] primvars:displayColor = [(${r}, ${g}, ${b})] (\n            interpolation = "constant"\n        )\n`,
    '        uniform token subdivisionScheme = "none"\n',
    '    }\n',
  ].join('');
}
