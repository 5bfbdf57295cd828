// Fuzz target 4: the export writers (writeExport), each file checked by a reader written here.
import fc from 'fast-check';
import { CHUNK_BYTES } from '../../../web/export/chunkSink';
import type { ExportFormat } from '../../../web/export/formats';
import { hairFileSize } from '../../../web/export/hairWriter';
import { readExportedSession } from '../../../web/export/readExport';
import { type ExportHead, MAX_POINTS_PER_STRAND } from '../../../web/export/types';
import { writeExport } from '../../../web/export/writeExport';
import type { StrandArrays } from '../../../web/model/hairArrays';
import type { SessionState } from '../../../web/model/session';
import { parseSession } from '../../../web/model/sessionFile';
import { rng } from '../../support/seededRandom';
import { concat, type FuzzContext } from '../context';
import { show } from '../mutate';
import { check, type FuzzTarget, firstDifference, guard } from '../outcomes';
import {
  acceptedSession,
  makeSession,
  PLAIN_MUTATIONS,
  type SessionCase,
  sessionCase,
} from './session';

// ---- 4. the export writers ---------------------------------------------------------------------

export interface HairCase {
  /** points per strand */
  lengths: number[];
  /** how coordinates are made: small (a head's size), zero-length segments, float32 extremes */
  style: 'small' | 'still' | 'extreme' | 'mixed';
  seed: number;
  specials: number[];
}

const FLOAT32_MAX = 3.4028234663852886e38;

export function makeHair(h: HairCase): StrandArrays {
  const rand = rng(h.seed);
  let total = 0;
  for (const n of h.lengths) total += n;
  const strandStart = new Uint32Array(h.lengths.length + 1);
  const points = new Float32Array(3 * total);
  let p = 0;
  h.lengths.forEach((n, s) => {
    let x = rand() * 2 - 1;
    let y = rand() * 2;
    let z = rand() * 2 - 1;
    for (let i = 0; i < n; i++, p++) {
      const kind = h.style === 'mixed' ? ['small', 'still', 'extreme'][(rand() * 3) | 0] : h.style;
      if (kind === 'small') {
        x += (rand() - 0.5) * 0.05;
        y -= rand() * 0.05;
        z += (rand() - 0.5) * 0.05;
      } else if (kind === 'extreme') {
        const big = () => (rand() - 0.5) * 2 * FLOAT32_MAX * rand() ** 8;
        x = big();
        y = big();
        z = big();
      }
      const sp = h.specials.length > 0 && rand() < 0.1 ? h.specials : null;
      points[3 * p] = sp ? sp[(rand() * sp.length) | 0] : x;
      points[3 * p + 1] = y;
      points[3 * p + 2] = z;
    }
    strandStart[s + 1] = p;
  });
  return { points, strandStart };
}

const hairCase: fc.Arbitrary<HairCase> = fc.record({
  lengths: fc.array(
    fc.oneof(
      { weight: 3, arbitrary: fc.constantFrom(0, 1, 2, 3) },
      { weight: 4, arbitrary: fc.integer({ min: 0, max: 40 }) },
      { weight: 1, arbitrary: fc.constantFrom(254, 255, 256, 257) },
      { weight: 1, arbitrary: fc.integer({ min: 256, max: 700 }) },
    ),
    { maxLength: 12 },
  ),
  style: fc.constantFrom('small', 'small', 'still', 'extreme', 'mixed'),
  seed: fc.nat(),
  specials: fc.array(fc.float({ noNaN: true, noDefaultInfinity: true }), { maxLength: 4 }),
});

export interface HeadCase {
  vertices: number;
  triangles: [number, number, number][];
  normals: boolean;
  seed: number;
}

const headCase: fc.Arbitrary<HeadCase | null> = fc.option(
  fc.integer({ min: 0, max: 12 }).chain((vertices) =>
    fc.record({
      vertices: fc.constant(vertices),
      triangles:
        vertices === 0
          ? fc.constant([])
          : fc.array(fc.tuple(fc.nat(vertices - 1), fc.nat(vertices - 1), fc.nat(vertices - 1)), {
              maxLength: 16,
            }),
      normals: fc.boolean(),
      seed: fc.nat(),
    }),
  ),
  { freq: 2 },
);

function makeHead(h: HeadCase | null): ExportHead | null {
  if (!h) return null;
  const rand = rng(h.seed);
  const positions = Float32Array.from({ length: 3 * h.vertices }, () => rand() * 2 - 1);
  return {
    positions,
    indices: Uint32Array.from(h.triangles.flat()),
    ...(h.normals ? { normals: Float32Array.from(positions, (v) => v / 2) } : {}),
  };
}

export interface ExportCase {
  format: ExportFormat;
  hair: HairCase;
  head: HeadCase | null;
  session: SessionCase;
}

/** Every number in `text` read as a float32 is finite. */
function finiteNumbers(text: string): boolean {
  for (const m of text.matchAll(/-?\d+(\.\d+)?([eE][-+]?\d+)?|\b(inf|nan)\b/gi))
    if (!Number.isFinite(Math.fround(Number(m[0])))) return false;
  return true;
}

function listOf(text: string, decl: string): string | null {
  const i = text.indexOf(decl);
  if (i < 0) return null;
  const open = text.indexOf('= [', i) + 2;
  const close = text.indexOf(']', open);
  return text.slice(open + 1, close);
}

function checkUsda(bytes: Uint8Array, n: number, p: number, lengths: number[]): void {
  const text = new TextDecoder().decode(bytes);
  check(text.startsWith('#usda 1.0\n'), () => 'the .usda does not start with #usda 1.0');
  const hair = text.slice(text.indexOf('def BasisCurves "hair"'));
  const counts = (listOf(hair, 'int[] curveVertexCounts') ?? '')
    .split(',')
    .map((s) => s.trim())
    .filter((s) => s !== '')
    .map(Number);
  check(counts.length === n, () => `the .usda has ${counts.length} curves, not ${n}`);
  check(
    counts.every((c, i) => c === lengths[i]),
    () => `the .usda's curve counts ${show(counts)} are not ${show(lengths)}`,
  );
  const sum = counts.reduce((a, b) => a + b, 0);
  const pts = listOf(hair, 'point3f[] points') ?? '';
  const tuples = pts.match(/\(([^)]*)\)/g) ?? [];
  check(
    tuples.length === sum && sum === p,
    () => `the .usda's counts sum to ${sum}, it lists ${tuples.length} points, expected ${p}`,
  );
  check(
    tuples.every((t) => t.split(',').length === 3),
    () => 'a .usda point is not (x, y, z)',
  );
  check(finiteNumbers(pts), () => 'a .usda point is not a finite float');
  const widths = (listOf(hair, 'float[] widths') ?? '').split(',').filter((s) => s.trim() !== '');
  check(widths.length === p, () => `the .usda has ${widths.length} widths for ${p} points`);
  const colours = listOf(hair, 'color3f[] primvars:displayColor')?.match(/\(/g)?.length ?? 0;
  check(colours === n, () => `the .usda has ${colours} colours for ${n} curves`);
  check(
    finiteNumbers(listOf(hair, 'float3[] extent') ?? ''),
    () => 'the .usda extent is not finite',
  );
}

function u32(b: Uint8Array, at: number): number {
  return new DataView(b.buffer, b.byteOffset, b.byteLength).getUint32(at, true);
}

function checkGlb(bytes: Uint8Array, n: number, p: number): void {
  check(bytes.length >= 20, () => 'the .glb is shorter than its header');
  check(u32(bytes, 0) === 0x46546c67 && u32(bytes, 4) === 2, () => 'not a glTF 2 binary');
  check(
    u32(bytes, 8) === bytes.length,
    () => `the .glb header says ${u32(bytes, 8)} bytes, the file has ${bytes.length}`,
  );
  check(bytes.length % 4 === 0, () => 'the .glb length is not a multiple of 4');
  const jsonLength = u32(bytes, 12);
  check(u32(bytes, 16) === 0x4e4f534a, () => 'the .glb does not start with its JSON chunk');
  const gltf = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLength)));
  const binAt = 20 + jsonLength;
  const binLength = binAt < bytes.length ? u32(bytes, binAt) : 0;
  check(
    binAt === bytes.length || (binAt + 8 + binLength === bytes.length && binLength % 4 === 0),
    () => 'the .glb chunks do not add up to the file',
  );
  const declared = gltf.buffers?.[0]?.byteLength ?? 0;
  check(
    declared <= binLength && binLength - declared < 4,
    () => `buffer 0 is ${declared} bytes in a BIN chunk of ${binLength}`,
  );
  const hair = (gltf.meshes ?? []).find((m: { name: string }) => m.name === 'hair');
  check(!!hair === n > 0, () => `${n} strands, hair mesh ${hair ? 'present' : 'absent'}`);
  if (hair) {
    const prim = hair.primitives[0];
    const count = (a: number) => gltf.accessors[a].count;
    check(count(prim.attributes.POSITION) === p, () => `POSITION count is not ${p}`);
    check(count(prim.indices) === 2 * (p - n), () => `LINES index count is not ${2 * (p - n)}`);
    const pos = gltf.accessors[prim.attributes.POSITION];
    check(
      [...pos.min, ...pos.max].every((v: unknown) => typeof v === 'number' && Number.isFinite(v)),
      () => `POSITION bounds ${show([pos.min, pos.max])}`,
    );
  }
}

function checkHair(bytes: Uint8Array, n: number, p: number, lengths: number[]): void {
  check(
    bytes.length === hairFileSize(n, p),
    () => `the .hair is ${bytes.length} bytes, the format says ${hairFileSize(n, p)}`,
  );
  check(
    String.fromCharCode(...bytes.subarray(0, 4)) === 'HAIR' &&
      u32(bytes, 4) === n &&
      u32(bytes, 8) === p,
    () => 'the .hair header is wrong',
  );
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  for (let s = 0; s < n; s++)
    check(
      view.getUint16(128 + 2 * s, true) === lengths[s] - 1,
      () => `.hair strand ${s} has ${view.getUint16(128 + 2 * s, true)} segments`,
    );
  for (let i = 0; i < 3 * p; i++)
    check(Number.isFinite(view.getFloat32(128 + 2 * n + 4 * i, true)), () => '.hair point');
}

function checkObj(bytes: Uint8Array, n: number, p: number, head: ExportHead | null): void {
  const lines = new TextDecoder().decode(bytes).split('\n');
  const verts = lines.filter((l) => l.startsWith('v '));
  const strands = lines.filter((l) => l.startsWith('l '));
  const faces = lines.filter((l) => l.startsWith('f '));
  const hv = head ? head.positions.length / 3 : 0;
  const ht = head ? head.indices.length / 3 : 0;
  check(verts.length === p + hv, () => `the .obj has ${verts.length} v lines, not ${p + hv}`);
  check(strands.length === n, () => `the .obj has ${strands.length} l lines, not ${n}`);
  check(faces.length === ht, () => `the .obj has ${faces.length} f lines, not ${ht}`);
  let next = 1;
  for (const l of strands) {
    const idx = l.slice(2).split(' ').map(Number);
    check(
      idx.length >= 2 && idx.length <= MAX_POINTS_PER_STRAND && idx.every((v, i) => v === next + i),
      () => `the .obj line "${l.slice(0, 60)}" does not continue at ${next}`,
    );
    next += idx.length;
  }
  for (const f of faces)
    check(
      f
        .slice(2)
        .split(' ')
        .map(Number)
        .every((v) => v > p && v <= p + hv),
      () => `the .obj face "${f}" is not on the head`,
    );
  check(finiteNumbers(verts.join(' ')), () => 'an .obj vertex is not a finite float');
}

/** The session an export carries, read back: the input session, deep-equal. */
function checkCarries(bytes: Uint8Array, session: SessionState, format: string): void {
  const r = guard('readExportedSession', () => readExportedSession(bytes));
  check(r?.ok === true, () => `the .${format} carries no session: ${show(r)}`);
  const parsed = guard('parseSession', () => parseSession(r.ok ? r.session : null));
  check(parsed.ok, () => `the .${format} session is refused: ${show(parsed)}`);
  const d = firstDifference(session, parsed.ok ? parsed.value : null, 'session');
  check(d === null, () => `the .${format} session differs at ${d}`);
}

export function exportTarget(ctx: FuzzContext): FuzzTarget<ExportCase> {
  return {
    name: 'export writers',
    arbitrary: fc.record({
      format: fc.constantFrom<ExportFormat>('usda', 'hair', 'obj', 'glb'),
      hair: hairCase,
      head: headCase,
      session: sessionCase(ctx, PLAIN_MUTATIONS),
    }),
    explain: (c) =>
      `${c.format}: hair ${show(c.hair, 300)}; head ${show(c.head, 200)}; session ${makeSession(ctx, c.session, PLAIN_MUTATIONS).log.join('; ')}`,
    run(c) {
      const session = acceptedSession(ctx, c.session);
      const strands = makeHair(c.hair);
      const head = makeHead(c.head);
      const kept = c.hair.lengths.filter((k) => k >= 2).map((k) => Math.min(k, 255));
      const n = kept.length;
      const p = kept.reduce((a, b) => a + b, 0);
      {
        const format = c.format;
        const progress: number[] = [];
        const chunks = guard(`writeExport(${format})`, () => [
          ...writeExport(format, { strands, session, head }, (f) => progress.push(f)),
        ]);
        check(
          chunks.every((k) => k instanceof Uint8Array && k.length <= CHUNK_BYTES),
          () => `a .${format} chunk is over ${CHUNK_BYTES} bytes`,
        );
        check(
          progress.every((f, i) => f >= 0 && f <= 1 && (i === 0 || f >= progress[i - 1])) &&
            progress[progress.length - 1] === 1,
          () => `.${format} progress ${show(progress)}`,
        );
        const bytes = concat(chunks);
        if (format === 'usda') {
          checkUsda(bytes, n, p, kept);
          checkCarries(bytes, session, format);
        } else if (format === 'glb') {
          checkGlb(bytes, n, p);
          checkCarries(bytes, session, format);
        } else if (format === 'hair') checkHair(bytes, n, p, kept);
        else checkObj(bytes, n, p, head);
      }
      return 'accepted';
    },
  };
}
