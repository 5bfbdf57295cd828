// USD `.usda` (plain text): the hair as a groom as Unreal's USD importer reads one (an Xform with
// GroomAPI holding the strands and the guides as linear BasisCurves, groom_* primvars from
// groomLayout.ts), the head as an optional Mesh, the ties' bands as a Mesh "band" (bandExport.ts),
// the session in the layer's customLayerData
// (docs/export.md, "File layouts"). Numbers with 6 significant digits (formatFloat); the text
// comes out in chunks of at most CHUNK_BYTES.
import { exportBand, usdBand } from './bandExport';
import { formatFloat, type Progress, TextSink } from './chunkSink';
import { type GroomLayout, groomLayout, HEAD_CENTER } from './groomLayout';
import { scalpUvs } from './scalpUv';
import { type ExportStrands, strandsForExport } from './strandsForExport';
import { type ExportHead, type ExportInput, METERS_PER_UNIT, ROOT_WIDTH, TIP_WIDTH } from './types';

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
/** Head triangles or vertices written per batch. */
const HEAD_ROWS = 8192;

/** The text of one .usda being written, and its progress (in numbers written). */
interface UsdOut {
  text: TextSink;
  tick(numbers: number): void;
}

/** The layer header (the session in customLayerData), the groom, the head when there is one. */
export function* writeUsda(
  strands: ExportStrands,
  input: ExportInput,
  progress: Progress,
): Generator<Uint8Array> {
  const head = input.head;
  const builtinHead = input.session.head === 'builtin';
  // the built-in head's UVs are the scalp layout itself
  const groom = groomLayout(
    strands,
    input.strands,
    input.session,
    builtinHead ? null : (input.headUv ?? null),
  );
  const headCornerUvs = headMeshUvs(input, groom);
  // the motion's frames as the writers lay the strands out (skipped strands, point caps)
  const motion = input.motion
    ? {
        ...input.motion,
        points: input.motion.frames.map(
          (f) => strandsForExport({ ...input.strands, points: f }, input.session).points,
        ),
      }
    : null;
  input.onGroom?.(groomSummary(strands, groom, builtinHead));
  const total = numbersToWrite(strands, groom, head, builtinHead, headCornerUvs);
  let done = 0;
  const out: UsdOut = {
    text: new TextSink(),
    tick: (n) => {
      done += n;
      progress.at(done / total);
    },
  };

  writeLayerHeader(out.text, input.session, motion);
  out.text.write('def Xform "hairsketch"\n{\n');
  yield* writeGroom(out, strands, groom, motion);
  if (head) yield* writeHeadMesh(out, head, builtinHead, headCornerUvs, motion);
  const band = exportBand(input);
  // a tail is gathered at the head: its band moves with the head's pose
  if (band) out.text.write(usdBand(band, poseOps(motion)));
  out.text.write('}\n');
  yield* out.text.end();
  progress.at(1);
}

/** A loaded head's own UVs on its Mesh (per corner), the map its roots' UVs are read from; null
 *  for the built-in head, no head, or a head whose UVs the roots do not use. */
function headMeshUvs(input: ExportInput, groom: GroomLayout): Float32Array | null {
  const head = input.head;
  const headCornerUvs =
    head && input.session.head !== 'builtin' && groom.rootUvFrom === 'head-uv' && input.headUv
      ? input.headUv.cornerUvs
      : null;
  if (head && headCornerUvs && headCornerUvs.length !== 2 * head.indices.length)
    throw new Error("the head's UVs do not match its triangles");
  return headCornerUvs;
}

function groomSummary(strands: ExportStrands, groom: GroomLayout, builtinHead: boolean) {
  return {
    strands: strands.strandStart.length - 1,
    guides: groom.guides.length,
    groups: groom.groupNames,
    rootUv: builtinHead
      ? 'builtin-head'
      : groom.rootUvFrom === 'head-uv'
        ? 'head-uv'
        : 'projection',
  } satisfies GroomSummary;
}

/** Progress in numbers written: per strand 16, per point 7 (strands and guides), the head. */
function numbersToWrite(
  strands: ExportStrands,
  groom: GroomLayout,
  head: ExportHead | null,
  builtinHead: boolean,
  headCornerUvs: Float32Array | null,
): number {
  const { strandStart, widths } = strands;
  const nStrands = strandStart.length - 1;
  const nGuides = groom.guides.length;
  let guidePoints = 0;
  for (const g of groom.guides) guidePoints += strandStart[g + 1] - strandStart[g];
  const headVerts = head ? head.positions.length / 3 : 0;
  const headTris = head ? head.indices.length / 3 : 0;
  // the colour model's pigment: 1 number per point (melanin), 4 per strand (redness, tint)
  const pigment = strands.pigment ? 4 * (nStrands + nGuides) + widths.length + guidePoints : 0;
  return (
    16 * (nStrands + nGuides) +
    7 * (widths.length + guidePoints) +
    pigment +
    (head
      ? headTris * 4 +
        headVerts * (head.normals ? 6 : 3) +
        (builtinHead ? 2 * headVerts : 0) +
        (headCornerUvs ? 6 * headTris : 0)
      : 0) +
    1
  );
}

/** A motion's frames as written: each frame's points in the writers' strand layout. */
type MotionOut = { points: Float32Array[]; poses: Float32Array[]; frameRate: number } | null;

function writeLayerHeader(
  text: TextSink,
  session: ExportInput['session'],
  motion: MotionOut = null,
): void {
  text.write('#usda 1.0\n(\n    customLayerData = {\n');
  text.write(`        string ${usdQuote(USD_SESSION_KEY)} = `);
  text.write(usdQuote(JSON.stringify(session)));
  text.write('\n    }\n');
  text.write('    defaultPrim = "hairsketch"\n');
  if (motion) {
    text.write(`    startTimeCode = 0\n    endTimeCode = ${motion.points.length - 1}\n`);
    text.write(`    timeCodesPerSecond = ${motion.frameRate}\n`);
    text.write(`    framesPerSecond = ${motion.frameRate}\n`);
  }
  text.write(`    metersPerUnit = ${formatFloat(METERS_PER_UNIT)}\n`);
  text.write('    upAxis = "Y"\n)\n\n');
}

/** The groom: Unreal takes an Xform with GroomAPI and every BasisCurves under it as one groom. */
function* writeGroom(
  out: UsdOut,
  strands: ExportStrands,
  groom: GroomLayout,
  motion: MotionOut = null,
): Generator<Uint8Array> {
  const nStrands = strands.strandStart.length - 1;
  out.text.write(
    '    def Xform "groom" (\n        prepend apiSchemas = ["GroomAPI"]\n    )\n    {',
  );
  const all = new Uint32Array(nStrands);
  for (let s = 0; s < nStrands; s++) all[s] = s;
  yield* writeCurves(out, strands, groom, { name: 'hair', order: all, guide: 0 }, motion);
  yield* writeCurves(
    out,
    strands,
    groom,
    { name: 'guides', order: groom.guides, guide: 1 },
    motion,
  );
  out.text.write('    }\n');
}

/** `decl = [items]` with `perItem(i)` for i < n, BATCH items per drain; one item per line
 *  when `lines`. */
function* list(
  out: UsdOut,
  decl: string,
  n: number,
  perItem: (i: number) => string,
  weight: (i0: number, i1: number) => number,
  interpolation: string | null,
  lines = false,
): Generator<Uint8Array> {
  const { text } = out;
  text.write(`${IN}${decl} = [`);
  for (let i0 = 0; i0 < n; i0 += BATCH) {
    const i1 = Math.min(n, i0 + BATCH);
    const parts: string[] = [];
    for (let i = i0; i < i1; i++) parts.push(perItem(i));
    if (lines) text.write(`\n${PAD}${parts.join(`,\n${PAD}`)}${i1 < n ? ',' : ''}`);
    else text.write(i0 > 0 ? `, ${parts.join(', ')}` : parts.join(', '));
    out.tick(weight(i0, i1));
    yield* text.drain();
  }
  text.write(lines && n > 0 ? `\n${IN}]` : ']');
  text.write(interpolation ? ` (\n${PAD}interpolation = "${interpolation}"\n${IN})\n` : '\n');
}

/** One prim's strands as linear BasisCurves: their geometry, then the groom attributes. */
function* writeCurves(
  out: UsdOut,
  strands: ExportStrands,
  groom: GroomLayout,
  prim: CurvesPrim,
  motion: MotionOut = null,
): Generator<Uint8Array> {
  out.text.write(`\n        def BasisCurves "${prim.name}"\n        {\n`);
  out.text.write(`${IN}uniform token type = "linear"\n`);
  out.text.write(`${IN}uniform token wrap = "nonperiodic"\n`);
  const strandsOf = new PrimStrands(strands.strandStart, prim.order);
  yield* writeCurvesGeometry(out, strands, strandsOf);
  if (motion) yield* writePointSamples(out, strandsOf, motion);
  yield* writeGroomPrimvars(out, strands, groom, prim, strandsOf);
  out.text.write('        }\n');
}

/** The points of a prim's strands at every frame of a motion: `points.timeSamples`. */
function* writePointSamples(
  out: UsdOut,
  prim: PrimStrands,
  motion: NonNullable<MotionOut>,
): Generator<Uint8Array> {
  const { order } = prim;
  out.text.write(`${IN}point3f[] points.timeSamples = {\n`);
  for (let f = 0; f < motion.points.length; f++) {
    const pts = motion.points[f];
    out.text.write(`${PAD}${f}: [`);
    for (let i0 = 0; i0 < order.length; i0 += BATCH) {
      const i1 = Math.min(order.length, i0 + BATCH);
      const parts: string[] = [];
      for (let i = i0; i < i1; i++) parts.push(prim.perPoint(order[i], (p) => vec3(pts, 3 * p)));
      out.text.write(i0 > 0 ? `, ${parts.join(', ')}` : parts.join(', '));
      yield* out.text.drain();
    }
    out.text.write('],\n');
  }
  out.text.write(`${IN}}\n`);
}

/** A head pose (R row-major, then t: world = R * p + t) as a USD matrix4d (row vectors:
 *  p' = p * M, so M's rows are R's columns and t is the last row). */
function usdMatrix(pose: Float32Array): string {
  const f = (x: number) => formatFloat(x);
  const rows: string[] = [];
  for (let c = 0; c < 3; c++) rows.push(`(${f(pose[c])}, ${f(pose[3 + c])}, ${f(pose[6 + c])}, 0)`);
  rows.push(`(${f(pose[9])}, ${f(pose[10])}, ${f(pose[11])}, 1)`);
  return `( ${rows.join(', ')} )`;
}

/** The points of a prim's strands: `order[k]` is the exported strand written k-th. */
class PrimStrands {
  constructor(
    readonly strandStart: Uint32Array,
    readonly order: ArrayLike<number>,
  ) {}

  /** Points of the prim's strands i0..i1-1. */
  readonly pointsOf = (i0: number, i1: number): number => {
    const { strandStart, order } = this;
    let c = 0;
    for (let i = i0; i < i1; i++) c += strandStart[order[i] + 1] - strandStart[order[i]];
    return c;
  };

  /** `f(p)` for every point p of exported strand s, joined by ', '. */
  perPoint(s: number, f: (p: number) => string): string {
    const parts: string[] = [];
    for (let p = this.strandStart[s]; p < this.strandStart[s + 1]; p++) parts.push(f(p));
    return parts.join(', ');
  }
}

/** Curve vertex counts, points, widths, extent and display colour. */
function* writeCurvesGeometry(
  out: UsdOut,
  { points, strandStart, widths, colors }: ExportStrands,
  prim: PrimStrands,
): Generator<Uint8Array> {
  const { order, pointsOf } = prim;
  const n = order.length;
  yield* list(
    out,
    'int[] curveVertexCounts',
    n,
    (i) => String(strandStart[order[i] + 1] - strandStart[order[i]]),
    (i0, i1) => i1 - i0,
    null,
  );
  yield* list(
    out,
    'point3f[] points',
    n,
    (i) => prim.perPoint(order[i], (p) => vec3(points, 3 * p)),
    (i0, i1) => 3 * pointsOf(i0, i1),
    null,
    true,
  );
  yield* list(
    out,
    'float[] widths',
    n,
    (i) => prim.perPoint(order[i], (p) => formatFloat(widths[p])),
    pointsOf,
    'vertex',
    true,
  );
  // Extent: the points' bounds padded by half the widest strand (as UsdGeomCurves::ComputeExtent).
  const box = boundsOf(points, strandStart, order);
  const pad = box ? Math.max(ROOT_WIDTH, TIP_WIDTH) / 2 : 0;
  const lo = (box ? box[0] : [0, 0, 0]).map((v) => v - pad);
  const hi = (box ? box[1] : [0, 0, 0]).map((v) => v + pad);
  out.text.write(`${IN}float3[] extent = [${vec3(lo, 0)}, ${vec3(hi, 0)}]\n`);
  yield* list(
    out,
    'color3f[] primvars:displayColor',
    n,
    (i) => vec3(colors, 3 * order[i]),
    (i0, i1) => 3 * (i1 - i0),
    'uniform',
  );
}

/** Unreal's groom attributes (groom_* primvars: int, float, float2, float3, string; uniform
 *  per strand, vertex per point), and Blender's root-UV attribute. */
function* writeGroomPrimvars(
  out: UsdOut,
  { colors, pointColors, pigment }: ExportStrands,
  groom: GroomLayout,
  { guide }: CurvesPrim,
  prim: PrimStrands,
): Generator<Uint8Array> {
  const { order, pointsOf } = prim;
  const n = order.length;
  /** One value of `k` numbers per strand. */
  const uniform = (decl: string, item: (i: number) => string, k = 1) =>
    list(out, decl, n, item, (a, b) => k * (b - a), 'uniform');
  yield* uniform('int[] primvars:groom_guide', () => String(guide));
  yield* uniform('int[] primvars:groom_id', (i) => String(groom.ids[order[i]]));
  yield* uniform('int[] primvars:groom_group_id', (i) => String(groom.groupOf[order[i]]));
  yield* uniform('string[] primvars:groom_group_name', (i) =>
    usdQuote(groom.groupNames[groom.groupOf[order[i]]]),
  );
  const uv = (i: number) =>
    `(${formatFloat(groom.rootUv[2 * order[i]])}, ${formatFloat(groom.rootUv[2 * order[i] + 1])})`;
  yield* uniform('float2[] primvars:groom_root_uv', uv, 2);
  yield* uniform('float2[] primvars:surface_uv_coordinate', uv, 2);
  yield* list(
    out,
    'float3[] primvars:groom_color',
    n,
    (i) => {
      if (pointColors) return prim.perPoint(order[i], (p) => vec3(pointColors, 3 * p));
      const c = vec3(colors, 3 * order[i]);
      return prim.perPoint(order[i], () => c);
    },
    (i0, i1) => 3 * pointsOf(i0, i1),
    'vertex',
    true,
  );
  if (pigment) {
    // the colour model's pigment for Blender (each primvar becomes an attribute that an
    // Attribute node feeds into the Principled Hair BSDF's melanin parametrisation)
    yield* list(
      out,
      'float[] primvars:melanin',
      n,
      (i) => prim.perPoint(order[i], (p) => formatFloat(pigment.melanin[p])),
      pointsOf,
      'vertex',
      true,
    );
    yield* uniform('float[] primvars:redness', (i) => formatFloat(pigment.redness[order[i]]));
    yield* uniform('color3f[] primvars:tint', (i) => vec3(pigment.tint, 3 * order[i]), 3);
  }
  if (!guide) {
    // guide ids are integers below 2^24: exact as floats, written in full
    const triple = (a: Float32Array, i: number, f: (x: number) => string) =>
      `(${f(a[3 * order[i]])}, ${f(a[3 * order[i] + 1])}, ${f(a[3 * order[i] + 2])})`;
    yield* uniform(
      'float3[] primvars:groom_closest_guides',
      (i) => triple(groom.closestGuides, i, String),
      3,
    );
    yield* uniform(
      'float3[] primvars:groom_guide_weights',
      (i) => triple(groom.guideWeights, i, formatFloat),
      3,
    );
  }
}

/** `open`, then `n` rows (triangles or vertices) HEAD_ROWS per batch, the items `row(r, items)`
 *  adds all joined by ', ', `weight` numbers per row; then `close`. */
function* headArray(
  out: UsdOut,
  open: string,
  n: number,
  row: (r: number, items: string[]) => void,
  weight: number,
  close: string,
  drain = true,
): Generator<Uint8Array> {
  out.text.write(open);
  for (let r0 = 0; r0 < n; r0 += HEAD_ROWS) {
    const r1 = Math.min(n, r0 + HEAD_ROWS);
    const items: string[] = [];
    for (let r = r0; r < r1; r++) row(r, items);
    out.text.write((r0 > 0 ? ', ' : '') + items.join(', '));
    out.tick(weight * (r1 - r0));
    if (drain) yield* out.text.drain();
  }
  out.text.write(close);
}

const VERTEX = '] (\n            interpolation = "vertex"\n        )\n';

/** The head's animated transform, for the head's prim and the bands' (the hair's points are in
 *  world space already); '' without a motion. */
function poseOps(motion: MotionOut): string {
  if (!motion) return '';
  const samples = motion.poses.map((pose, f) => `${PAD}${f}: ${usdMatrix(pose)},\n`).join('');
  return `        matrix4d xformOp:transform.timeSamples = {\n${samples}        }\n        uniform token[] xformOpOrder = ["xformOp:transform"]\n`;
}

/** The head as a Mesh: topology, points, normals, and the UVs its roots' UVs are in. */
function* writeHeadMesh(
  out: UsdOut,
  head: ExportHead,
  builtinHead: boolean,
  headCornerUvs: Float32Array | null,
  motion: MotionOut = null,
): Generator<Uint8Array> {
  const headVerts = head.positions.length / 3;
  const headTris = head.indices.length / 3;
  out.text.write('\n    def Mesh "head"\n    {\n');
  out.text.write(poseOps(motion));
  const [hlo, hhi] = extentOf(head.positions);
  out.text.write(`        float3[] extent = [${vec3(hlo, 0)}, ${vec3(hhi, 0)}]\n`);
  // the counts are drained with the indices
  const three = (_: number, items: string[]) => items.push('3');
  yield* headArray(out, '        int[] faceVertexCounts = [', headTris, three, 1, '', false);
  const corners = (t: number, items: string[]) => {
    for (let i = 3 * t; i < 3 * t + 3; i++) items.push(String(head.indices[i]));
  };
  yield* headArray(out, ']\n        int[] faceVertexIndices = [', headTris, corners, 3, ']\n');
  out.text.write('        uniform token orientation = "rightHanded"\n');
  const point = (v: number, items: string[]) => items.push(vec3(head.positions, 3 * v));
  yield* headArray(out, '        point3f[] points = [', headVerts, point, 3, ']\n');
  const normals = head.normals;
  if (normals) {
    const normal = (v: number, items: string[]) => items.push(vec3(normals, 3 * v));
    yield* headArray(out, '        normal3f[] primvars:normals = [', headVerts, normal, 3, VERTEX);
  }
  if (builtinHead) {
    // the built-in head's UV layout (scalpUv.ts): the one the roots' UVs are in
    const uv = scalpUvs(head.positions, HEAD_CENTER);
    const st = (v: number, items: string[]) =>
      items.push(`(${formatFloat(uv[2 * v])}, ${formatFloat(uv[2 * v + 1])})`);
    yield* headArray(out, '        texCoord2f[] primvars:st = [', headVerts, st, 2, VERTEX);
  } else if (headCornerUvs) {
    // the file's UVs as they are (unwrapped), one per face corner: seams stay seams
    const st = (t: number, items: string[]) => {
      for (let i = 3 * t; i < 3 * t + 3; i++)
        items.push(
          `(${formatFloat(headCornerUvs[2 * i])}, ${formatFloat(headCornerUvs[2 * i + 1])})`,
        );
    };
    const faceVarying = '] (\n            interpolation = "faceVarying"\n        )\n';
    yield* headArray(out, '        texCoord2f[] primvars:st = [', headTris, st, 6, faceVarying);
  }
  // A polygonal head: no subdivision (with subdivision the normals would be ignored).
  out.text.write('        uniform token subdivisionScheme = "none"\n');
  out.text.write('    }\n');
}
