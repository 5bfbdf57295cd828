// USD `.usda` (plain text): the hair as a groom as Unreal's USD importer reads one (an Xform with
// GroomAPI holding the strands and the guides as linear BasisCurves, groom_* primvars from
// groomLayout.ts), the head as an optional Mesh, the session in the layer's customLayerData
// (docs/export.md, "File layouts"). Numbers with 6 significant digits (formatFloat); the text
// comes out in chunks of at most CHUNK_BYTES.
import { formatFloat, type Progress, TextSink } from './chunkSink';
import { groomLayout, HEAD_CENTER } from './groomLayout';
import { scalpUvs } from './scalpUv';
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

/** Bounds of the points of the strands `order` names, or null when there are none. */
function boundsOf(
  points: Float32Array,
  strandStart: Uint32Array,
  order: ArrayLike<number>,
): [number[], number[]] | null {
  let lo: number[] | null = null;
  let hi: number[] = [];
  for (let i = 0; i < order.length; i++)
    for (let p = strandStart[order[i]]; p < strandStart[order[i] + 1]; p++) {
      if (!lo) {
        lo = [points[3 * p], points[3 * p + 1], points[3 * p + 2]];
        hi = [...lo];
      }
      for (let c = 0; c < 3; c++) {
        const v = points[3 * p + c];
        if (v < lo[c]) lo[c] = v;
        if (v > hi[c]) hi[c] = v;
      }
    }
  return lo ? [lo, hi] : null;
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

/** One prim's strands: `order[k]` is the exported strand written k-th. */
interface CurvesPrim {
  name: string;
  order: ArrayLike<number>;
  guide: 0 | 1;
}

/** What the groom carries, for the status line. */
export interface GroomSummary {
  strands: number;
  guides: number;
  groups: string[];
  /** Where the root UVs come from: the built-in head's scalp layout, a loaded head's own UV
   *  map, or (a loaded head without UVs) the scalp layout as a projection onto it. */
  rootUv: 'builtin-head' | 'head-uv' | 'projection';
}

/** Indents: a prim's properties, and the lines of a long array. */
const IN = '            ';
const PAD = '                ';

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
  const builtinHead = input.session.head === 'builtin';
  // the built-in head's UVs are the scalp layout itself
  const groom = groomLayout(
    strands,
    input.strands,
    input.session,
    builtinHead ? null : (input.headUv ?? null),
  );
  const nGuides = groom.guides.length;
  let guidePoints = 0;
  for (const g of groom.guides) guidePoints += strandStart[g + 1] - strandStart[g];
  // a loaded head's own UVs on its Mesh (per corner), the map its roots' UVs are read from
  const headCornerUvs =
    head && !builtinHead && groom.rootUvFrom === 'head-uv' && input.headUv
      ? input.headUv.cornerUvs
      : null;
  if (headCornerUvs && headCornerUvs.length !== 2 * headTris * 3)
    throw new Error("the head's UVs do not match its triangles");
  input.onGroom?.({
    strands: nStrands,
    guides: nGuides,
    groups: groom.groupNames,
    rootUv: builtinHead
      ? 'builtin-head'
      : groom.rootUvFrom === 'head-uv'
        ? 'head-uv'
        : 'projection',
  });
  // Progress in numbers written: per strand 16, per point 7 (strands and guides), the head.
  const total =
    16 * (nStrands + nGuides) +
    7 * (nPoints + guidePoints) +
    (head
      ? headTris * 4 +
        headVerts * (head.normals ? 6 : 3) +
        (builtinHead ? 2 * headVerts : 0) +
        (headCornerUvs ? 6 * headTris : 0)
      : 0) +
    1;
  let done = 0;
  const tick = (n: number) => {
    done += n;
    progress.at(done / total);
  };

  /** `decl = [items]` with `perItem(i)` for i < n, BATCH items per drain; one item per line
   *  when `lines`. */
  function* list(
    decl: string,
    n: number,
    perItem: (i: number) => string,
    weight: (i0: number, i1: number) => number,
    interpolation: string | null,
    lines = false,
  ): Generator<Uint8Array> {
    out.write(`${IN}${decl} = [`);
    for (let i0 = 0; i0 < n; i0 += BATCH) {
      const i1 = Math.min(n, i0 + BATCH);
      const parts: string[] = [];
      for (let i = i0; i < i1; i++) parts.push(perItem(i));
      if (lines) out.write(`\n${PAD}${parts.join(`,\n${PAD}`)}${i1 < n ? ',' : ''}`);
      else out.write(i0 > 0 ? `, ${parts.join(', ')}` : parts.join(', '));
      tick(weight(i0, i1));
      yield* out.drain();
    }
    out.write(lines && n > 0 ? `\n${IN}]` : ']');
    out.write(interpolation ? ` (\n${PAD}interpolation = "${interpolation}"\n${IN})\n` : '\n');
  }

  function* curves(prim: CurvesPrim): Generator<Uint8Array> {
    const order = prim.order;
    const n = order.length;
    const pointsOf = (i0: number, i1: number) => {
      let c = 0;
      for (let i = i0; i < i1; i++) c += strandStart[order[i] + 1] - strandStart[order[i]];
      return c;
    };
    const perPoint = (s: number, f: (p: number) => string) => {
      const parts: string[] = [];
      for (let p = strandStart[s]; p < strandStart[s + 1]; p++) parts.push(f(p));
      return parts.join(', ');
    };
    out.write(`\n        def BasisCurves "${prim.name}"\n        {\n`);
    out.write(`${IN}uniform token type = "linear"\n`);
    out.write(`${IN}uniform token wrap = "nonperiodic"\n`);
    yield* list(
      'int[] curveVertexCounts',
      n,
      (i) => String(strandStart[order[i] + 1] - strandStart[order[i]]),
      (i0, i1) => i1 - i0,
      null,
    );
    yield* list(
      'point3f[] points',
      n,
      (i) => perPoint(order[i], (p) => vec3(points, 3 * p)),
      (i0, i1) => 3 * pointsOf(i0, i1),
      null,
      true,
    );
    yield* list(
      'float[] widths',
      n,
      (i) => perPoint(order[i], (p) => formatFloat(widths[p])),
      pointsOf,
      'vertex',
      true,
    );
    // Extent: the points' bounds padded by half the widest strand (as UsdGeomCurves::ComputeExtent).
    const box = boundsOf(points, strandStart, order);
    const pad = box ? Math.max(ROOT_WIDTH, TIP_WIDTH) / 2 : 0;
    const lo = (box ? box[0] : [0, 0, 0]).map((v) => v - pad);
    const hi = (box ? box[1] : [0, 0, 0]).map((v) => v + pad);
    out.write(`${IN}float3[] extent = [${vec3(lo, 0)}, ${vec3(hi, 0)}]\n`);
    yield* list(
      'color3f[] primvars:displayColor',
      n,
      (i) => vec3(colors, 3 * order[i]),
      (i0, i1) => 3 * (i1 - i0),
      'uniform',
    );
    // Unreal's groom attributes (groom_* primvars: int, float, float2, float3, string; uniform
    // per strand, vertex per point), and Blender's root-UV attribute.
    yield* list(
      'int[] primvars:groom_guide',
      n,
      () => String(prim.guide),
      (a, b) => b - a,
      'uniform',
    );
    yield* list(
      'int[] primvars:groom_id',
      n,
      (i) => String(groom.ids[order[i]]),
      (a, b) => b - a,
      'uniform',
    );
    yield* list(
      'int[] primvars:groom_group_id',
      n,
      (i) => String(groom.groupOf[order[i]]),
      (a, b) => b - a,
      'uniform',
    );
    yield* list(
      'string[] primvars:groom_group_name',
      n,
      (i) => usdQuote(groom.groupNames[groom.groupOf[order[i]]]),
      (a, b) => b - a,
      'uniform',
    );
    const uv = (i: number) =>
      `(${formatFloat(groom.rootUv[2 * order[i]])}, ${formatFloat(groom.rootUv[2 * order[i] + 1])})`;
    yield* list('float2[] primvars:groom_root_uv', n, uv, (a, b) => 2 * (b - a), 'uniform');
    yield* list('float2[] primvars:surface_uv_coordinate', n, uv, (a, b) => 2 * (b - a), 'uniform');
    yield* list(
      'float3[] primvars:groom_color',
      n,
      (i) => {
        const c = vec3(colors, 3 * order[i]);
        return perPoint(order[i], () => c);
      },
      (i0, i1) => 3 * pointsOf(i0, i1),
      'vertex',
      true,
    );
    if (!prim.guide) {
      // guide ids are integers below 2^24: exact as floats, written in full
      const triple = (a: Float32Array, i: number, f: (x: number) => string) =>
        `(${f(a[3 * order[i]])}, ${f(a[3 * order[i] + 1])}, ${f(a[3 * order[i] + 2])})`;
      yield* list(
        'float3[] primvars:groom_closest_guides',
        n,
        (i) => triple(groom.closestGuides, i, String),
        (a, b) => 3 * (b - a),
        'uniform',
      );
      yield* list(
        'float3[] primvars:groom_guide_weights',
        n,
        (i) => triple(groom.guideWeights, i, formatFloat),
        (a, b) => 3 * (b - a),
        'uniform',
      );
    }
    out.write('        }\n');
  }

  out.write('#usda 1.0\n(\n    customLayerData = {\n');
  out.write(`        string ${usdQuote(USD_SESSION_KEY)} = `);
  out.write(usdQuote(JSON.stringify(input.session)));
  out.write('\n    }\n');
  out.write('    defaultPrim = "hairsketch"\n');
  out.write(`    metersPerUnit = ${formatFloat(METERS_PER_UNIT)}\n`);
  out.write('    upAxis = "Y"\n)\n\n');
  out.write('def Xform "hairsketch"\n{\n');

  // The groom: Unreal takes an Xform with GroomAPI and every BasisCurves under it as one groom.
  out.write('    def Xform "groom" (\n        prepend apiSchemas = ["GroomAPI"]\n    )\n    {');
  const all = new Uint32Array(nStrands);
  for (let s = 0; s < nStrands; s++) all[s] = s;
  yield* curves({ name: 'hair', order: all, guide: 0 });
  yield* curves({ name: 'guides', order: groom.guides, guide: 1 });
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
    if (builtinHead) {
      // the built-in head's UV layout (scalpUv.ts): the one the roots' UVs are in
      const uv = scalpUvs(head.positions, HEAD_CENTER);
      out.write('        texCoord2f[] primvars:st = [');
      for (let v0 = 0; v0 < headVerts; v0 += ROWS) {
        const v1 = Math.min(headVerts, v0 + ROWS);
        const parts: string[] = [];
        for (let v = v0; v < v1; v++)
          parts.push(`(${formatFloat(uv[2 * v])}, ${formatFloat(uv[2 * v + 1])})`);
        out.write((v0 > 0 ? ', ' : '') + parts.join(', '));
        tick(2 * (v1 - v0));
        yield* out.drain();
      }
      out.write('] (\n            interpolation = "vertex"\n        )\n');
    } else if (headCornerUvs) {
      // the file's UVs as they are (unwrapped), one per face corner: seams stay seams
      out.write('        texCoord2f[] primvars:st = [');
      for (let t0 = 0; t0 < headTris; t0 += ROWS) {
        const t1 = Math.min(headTris, t0 + ROWS);
        const parts: string[] = [];
        for (let i = 3 * t0; i < 3 * t1; i++)
          parts.push(
            `(${formatFloat(headCornerUvs[2 * i])}, ${formatFloat(headCornerUvs[2 * i + 1])})`,
          );
        out.write((t0 > 0 ? ', ' : '') + parts.join(', '));
        tick(6 * (t1 - t0));
        yield* out.drain();
      }
      out.write('] (\n            interpolation = "faceVarying"\n        )\n');
    }
    // A polygonal head: no subdivision (with subdivision the normals would be ignored).
    out.write('        uniform token subdivisionScheme = "none"\n');
    out.write('    }\n');
  }

  out.write('}\n');
  yield* out.end();
  progress.at(1);
}
