// The hair export writers, each checked against an independent reader written here from the
// formats' published layouts (docs/export.md; for glTF, Khronos' validator), never against
// numbers printed once.
import { createRequire } from 'node:module';
import { describe, expect, it } from 'vitest';
import { CHUNK_BYTES, formatFloat } from '../../web/export/chunkSink';
import {
  EXPORT_FORMAT_IDS,
  EXPORT_FORMATS,
  type ExportFormat,
  exportFileName,
  exportFormatsWith,
  exportMenuLabel,
  extensionsInWords,
  formatFromFileName,
} from '../../web/export/formats';
import { readExportedSession } from '../../web/export/readExport';
import { strandsForExport } from '../../web/export/strandsForExport';
import {
  type ExportHead,
  type ExportInput,
  MAX_POINTS_PER_STRAND,
  ROOT_WIDTH,
  TIP_WIDTH,
} from '../../web/export/types';
import { usdQuote } from '../../web/export/usdWriter';
import { writeExport } from '../../web/export/writeExport';
import type { StrandArrays } from '../../web/model/hairArrays';
import { emptySession, type SessionState } from '../../web/model/session';

// ---- fixtures ----------------------------------------------------------------------------------

/** Strands: 0) 5 uneven points, 1) 300 points on a straight line with uneven spacing (y = 3 u²),
 *  2) 1 point (skipped), 3) 0 points (skipped), 4) 2 points, 5) a 300-point helix, 6) 24 points. */
function syntheticHair(): StrandArrays {
  const strands: number[][] = [];
  strands.push([0, 1, 0, 0.1, 1.1, 0, 0.15, 1.3, 0.05, 0.4, 1.35, 0.1, 0.45, 1.2, 0.3]);
  const line: number[] = [];
  for (let i = 0; i < 300; i++) line.push(0.5, 3 * (i / 299) ** 2, -0.25);
  strands.push(line);
  strands.push([1, 1, 1]);
  strands.push([]);
  strands.push([-0.5, 0.8, 0.2, -0.6, 0.5, 0.25]);
  const helix: number[] = [];
  for (let i = 0; i < 300; i++) {
    const a = i * 0.31;
    helix.push(0.2 * Math.cos(a), 1 - i * 0.01, 0.2 * Math.sin(a) + 0.1);
  }
  strands.push(helix);
  const wavy: number[] = [];
  for (let i = 0; i < 24; i++)
    wavy.push(-0.3 + 0.01 * Math.sin(i), 1.2 - 0.05 * i, 0.7 + 0.002 * i);
  strands.push(wavy);
  return pack(strands);
}

function pack(strands: number[][]): StrandArrays {
  const strandStart = new Uint32Array(strands.length + 1);
  let p = 0;
  strands.forEach((s, i) => {
    p += s.length / 3;
    strandStart[i + 1] = p;
  });
  return { points: new Float32Array(strands.flat()), strandStart };
}

/** A tetrahedron, counter-clockwise from outside, unit normals along the vertex directions. */
function tinyHead(): ExportHead {
  const v = [
    [1, 1, 1],
    [1, -1, -1],
    [-1, 1, -1],
    [-1, -1, 1],
  ];
  const positions = new Float32Array(v.flat().map((x) => 0.5 * x));
  const normals = new Float32Array(v.flat().map((x) => x / Math.sqrt(3)));
  const indices = new Uint32Array([0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2]);
  return { positions, normals, indices };
}

function trickySession(): SessionState {
  const s = emptySession('25k');
  return {
    ...s,
    hairColor: '#a0522d',
    growth: { ...s.growth, seed: 12345 },
    curves: [
      {
        id: 'quote " backslash \\ newline \n tab \t unicode ✂ ü 𝄞 \u0001 \u007f \'',
        type: 'stream',
        points: [
          [0, 1, 0],
          [0.1, 1.1, 0.05],
        ],
        extend: true,
        viewpoint: { position: [0, 0, 6], target: [0, 0, 0] },
      },
    ],
    avoidScalp: true,
    detail: {
      curl: { radius: 0.05, frequency: 3, start: 0.15, randomOffset: 1 },
      clump: { factor: 0.5, shape: -0.3, tipSpread: 0.02, guideDistance: 0.12 },
      lengthJitter: 0.15,
    },
  };
}

function input(head = true): ExportInput {
  return { strands: syntheticHair(), session: trickySession(), head: head ? tinyHead() : null };
}

function collect(format: ExportFormat, inp: ExportInput, onProgress?: (f: number) => void) {
  const chunks = [...writeExport(format, inp, onProgress)];
  const total = chunks.reduce((n, c) => n + c.length, 0);
  const bytes = new Uint8Array(total);
  let o = 0;
  for (const c of chunks) {
    bytes.set(c, o);
    o += c.length;
  }
  return { chunks, bytes };
}

const text = (b: Uint8Array) => new TextDecoder('utf-8', { fatal: true }).decode(b);

/** Independent arc-length fractions of a polyline's points. */
function arcFractions(pts: ArrayLike<number>): number[] {
  const cum = [0];
  for (let i = 3; i < pts.length; i += 3)
    cum.push(
      cum[cum.length - 1] +
        Math.hypot(pts[i] - pts[i - 3], pts[i + 1] - pts[i - 2], pts[i + 2] - pts[i - 1]),
    );
  const L = cum[cum.length - 1];
  return cum.map((c) => c / L);
}

function srgbToLinearRef(c: number): number {
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
}

// ---- strandsForExport ----------------------------------------------------------------------------

describe('strandsForExport', () => {
  const hair = syntheticHair();
  const session = trickySession();
  const out = strandsForExport(hair, session);
  const counts = [...out.strandStart.slice(1)].map((e, i) => e - out.strandStart[i]);

  it('skips strands of fewer than 2 points and caps the rest at 255', () => {
    expect(counts).toEqual([5, 255, 2, 255, 24]);
    expect(out.widths.length).toBe(5 + 255 + 2 + 255 + 24);
    expect(out.points.length).toBe(3 * out.widths.length);
    expect(out.colors.length).toBe(3 * 5);
  });

  it('keeps short strands exactly and tapers their widths by arc length', () => {
    const src = hair.points.subarray(0, 15);
    expect([...out.points.subarray(0, 15)]).toEqual([...src]);
    const t = arcFractions(src);
    for (let i = 0; i < 5; i++)
      expect(out.widths[i]).toBeCloseTo(ROOT_WIDTH + (TIP_WIDTH - ROOT_WIDTH) * t[i], 9);
  });

  it('resamples a long strand evenly by arc length, root and tip exact', () => {
    // Strand 1 is the straight line y = 3 u², x = 0.5, z = -0.25: point k must be at y = 3k/254.
    const a = out.strandStart[1];
    for (let k = 0; k < 255; k++) {
      const o = 3 * (a + k);
      expect(out.points[o]).toBe(Math.fround(0.5));
      expect(out.points[o + 2]).toBe(Math.fround(-0.25));
      expect(out.points[o + 1]).toBeCloseTo((3 * k) / 254, 5);
      expect(out.widths[a + k]).toBeCloseTo(ROOT_WIDTH + ((TIP_WIDTH - ROOT_WIDTH) * k) / 254, 9);
    }
    expect(out.points[3 * a + 1]).toBe(0);
    expect(out.points[3 * (a + 254) + 1]).toBe(3);
    // The helix (input strand 5, exported strand 3): root and tip bit-exact, spacing even.
    const h = out.strandStart[3];
    const src = hair.points.subarray(3 * hair.strandStart[5], 3 * hair.strandStart[6]);
    expect([...out.points.subarray(3 * h, 3 * h + 3)]).toEqual([...src.subarray(0, 3)]);
    expect([...out.points.subarray(3 * (h + 254), 3 * (h + 255))]).toEqual([
      ...src.subarray(897, 900),
    ]);
    expect(out.widths[h]).toBeCloseTo(ROOT_WIDTH, 9);
    expect(out.widths[h + 254]).toBeCloseTo(TIP_WIDTH, 9);
  });

  it('colours each strand from the session colour (linear) within ±4 % value, not all equal', () => {
    const base = [0xa0, 0x52, 0x2d].map((c) => c / 255);
    for (let s = 0; s < 5; s++)
      for (let c = 0; c < 3; c++) {
        const v = out.colors[3 * s + c];
        expect(v).toBeGreaterThanOrEqual(Math.fround(srgbToLinearRef(base[c] * 0.96)) - 1e-7);
        expect(v).toBeLessThanOrEqual(Math.fround(srgbToLinearRef(base[c] * 1.04)) + 1e-7);
      }
    const reds = new Set([...Array(5).keys()].map((s) => out.colors[3 * s]));
    expect(reds.size).toBeGreaterThan(1);
    expect([...strandsForExport(hair, session).colors]).toEqual([...out.colors]);
  });

  it('bounds hold every point', () => {
    for (let i = 0; i < out.points.length; i += 3)
      for (let c = 0; c < 3; c++) {
        expect(out.points[i + c]).toBeGreaterThanOrEqual(out.min[c]);
        expect(out.points[i + c]).toBeLessThanOrEqual(out.max[c]);
      }
  });
});

// ---- number format and names ---------------------------------------------------------------------

describe('formatFloat and file names', () => {
  it('writes 6 significant digits, no trailing zeros', () => {
    expect(formatFloat(0.0008)).toBe('0.0008');
    expect(formatFloat(1 / 3)).toBe('0.333333');
    expect(formatFloat(-2 / 3)).toBe('-0.666667');
    expect(formatFloat(123456.7)).toBe('123457');
    expect(formatFloat(1234567)).toBe('1.23457e+6');
    expect(formatFloat(1.5e-7)).toBe('1.5e-7');
    expect(formatFloat(-0)).toBe('0');
    expect(formatFloat(100)).toBe('100');
    expect(formatFloat(Math.fround(0.1))).toBe('0.1');
    expect(formatFloat(2.5)).toBe('2.5');
    let seed = 7;
    for (let i = 0; i < 2000; i++) {
      seed = (Math.imul(seed, 1103515245) + 12345) >>> 0;
      const x = ((seed / 2 ** 32) * 2 - 1) * 10 ** ((i % 14) - 7);
      const s = formatFloat(x);
      const digits = s.replace(/e.*$/, '').replace(/[-.]/g, '').replace(/^0+/, '');
      expect(digits.length).toBeLessThanOrEqual(6);
      expect(Math.abs(Number(s) - x)).toBeLessThanOrEqual(Math.abs(x) * 5.0001e-6);
    }
  });

  it('maps file names to formats', () => {
    expect(formatFromFileName('hairstyle.usda')).toBe('usda');
    expect(formatFromFileName('A.USDA')).toBe('usda');
    expect(formatFromFileName('x.hair')).toBe('hair');
    expect(formatFromFileName('x.obj')).toBe('obj');
    expect(formatFromFileName('x.glb')).toBe('glb');
    expect(formatFromFileName('x.usd')).toBeNull();
    expect(formatFromFileName('x.gltf')).toBeNull();
    expect(formatFromFileName('usda')).toBeNull();
  });

  it('names each format as the menu, the downloads and the CLI always have', () => {
    const row = (f: ExportFormat) => {
      const x = EXPORT_FORMATS[f];
      return [exportMenuLabel(f), exportFileName(f), x.mime, x.headByDefault, x.statusName];
    };
    expect(EXPORT_FORMAT_IDS.map(row)).toEqual([
      ['USD (.usda)', 'hairstyle.usda', 'text/plain', true, 'USD'],
      ['Cem Yuksel (.hair)', 'hairstyle.hair', 'application/octet-stream', false, '.hair'],
      ['OBJ (.obj)', 'hairstyle.obj', 'text/plain', false, 'OBJ'],
      ['glTF (.glb)', 'hairstyle.glb', 'model/gltf-binary', true, 'glTF'],
      ['Hair cards (.glb)', 'hairstyle-cards.glb', 'model/gltf-binary', true, 'hair cards'],
    ]);
    expect(extensionsInWords(exportFormatsWith('byExtension'))).toBe('.usda, .hair, .obj or .glb');
  });

  it('carries the session in exactly the formats that say so (read back by readExportedSession)', () => {
    const inp = input(false);
    for (const f of EXPORT_FORMAT_IDS) {
      const back = readExportedSession(collect(f, inp).bytes);
      expect(back?.ok ?? false, f).toBe(EXPORT_FORMATS[f].carriesSession);
    }
  });

  it('quotes USD strings as Sdf does', () => {
    expect(usdQuote('a"b\\c\nd\te\r✂\u0001')).toBe('"a\\"b\\\\c\\nd\\te\\r✂\\x01"');
  });
});

// ---- .hair -------------------------------------------------------------------------------------

/** An independent .hair reader from the layout in docs/export.md. */
function parseHair(b: Uint8Array) {
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  const magic = String.fromCharCode(b[0], b[1], b[2], b[3]);
  const n = dv.getUint32(4, true);
  const p = dv.getUint32(8, true);
  const bits = dv.getUint32(12, true);
  const info = text(b.subarray(40, 128)).replace(/\0+$/, '');
  let o = 128;
  const segments: number[] = [];
  if (bits & 1) for (let i = 0; i < n; i++, o += 2) segments.push(dv.getUint16(o, true));
  const f32 = (count: number) => {
    const a: number[] = [];
    for (let i = 0; i < count; i++, o += 4) a.push(dv.getFloat32(o, true));
    return a;
  };
  const points = bits & 2 ? f32(3 * p) : [];
  const thickness = bits & 4 ? f32(p) : [];
  const transparency = bits & 8 ? f32(p) : [];
  const colors = bits & 16 ? f32(3 * p) : [];
  return { magic, n, p, bits, info, segments, points, thickness, transparency, colors, end: o };
}

describe('.hair writer', () => {
  it('matches the docs/export.md layout exactly', () => {
    const inp = input();
    const ref = strandsForExport(inp.strands, inp.session);
    const { bytes } = collect('hair', inp);
    const h = parseHair(bytes);
    const N = ref.strandStart.length - 1;
    const P = ref.widths.length;
    expect(h.magic).toBe('HAIR');
    expect(h.n).toBe(N);
    expect(h.p).toBe(P);
    expect(h.bits).toBe(1 | 2 | 4 | 16);
    expect(h.info).toBe('hairsketch');
    expect(bytes.length).toBe(128 + 2 * N + 12 * P + 4 * P + 12 * P);
    expect(h.end).toBe(bytes.length);
    expect(h.segments.reduce((a, s) => a + s + 1, 0)).toBe(P);
    expect(h.segments).toEqual([4, 254, 1, 254, 23]);
    expect(h.points).toEqual([...ref.points]);
    expect(h.thickness).toEqual([...ref.widths]);
    let q = 0;
    h.segments.forEach((seg, s) => {
      for (let k = 0; k <= seg; k++, q++)
        expect(h.colors.slice(3 * q, 3 * q + 3)).toEqual([
          ...ref.colors.subarray(3 * s, 3 * s + 3),
        ]);
    });
    expect(readExportedSession(bytes)).toBeNull();
  });
});

// ---- OBJ ---------------------------------------------------------------------------------------

describe('OBJ writer', () => {
  it('writes v / l / f lines with indices in range', () => {
    const inp = input();
    const ref = strandsForExport(inp.strands, inp.session);
    const P = ref.widths.length;
    const lines = text(collect('obj', inp).bytes).split('\n');
    const v = lines.filter((l) => l.startsWith('v '));
    const l = lines.filter((x) => x.startsWith('l '));
    const f = lines.filter((x) => x.startsWith('f '));
    expect(lines.filter((x) => x.startsWith('o ')).map((x) => x.slice(2))).toEqual([
      'hair',
      'head',
    ]);
    expect(v.length).toBe(P + 4);
    expect(l.length).toBe(5);
    expect(f.length).toBe(4);
    const lineCounts = l.map((x) => {
      const idx = x.slice(2).split(' ').map(Number);
      for (const i of idx) {
        expect(Number.isInteger(i)).toBe(true);
        expect(i).toBeGreaterThanOrEqual(1);
        expect(i).toBeLessThanOrEqual(P);
      }
      return idx.length;
    });
    expect(lineCounts).toEqual([5, 255, 2, 255, 24]);
    for (const x of f)
      for (const i of x.slice(2).split(' ').map(Number)) {
        expect(i).toBeGreaterThan(P);
        expect(i).toBeLessThanOrEqual(P + 4);
      }
    // The hair's v lines carry the exported points to 6 significant digits.
    v.slice(0, P).forEach((x, i) => {
      const c = x.slice(2).split(' ').map(Number);
      for (let k = 0; k < 3; k++)
        expect(Math.abs(c[k] - ref.points[3 * i + k])).toBeLessThanOrEqual(
          Math.abs(ref.points[3 * i + k]) * 5.0001e-6,
        );
    });
    // Without the head: no head object.
    const noHead = text(collect('obj', input(false)).bytes);
    expect(noHead.includes('o head')).toBe(false);
    expect(noHead.split('\n').filter((x) => x.startsWith('f ')).length).toBe(0);
  });
});

// ---- GLB ---------------------------------------------------------------------------------------

interface ValidationReport {
  issues: {
    numErrors: number;
    numWarnings: number;
    numInfos: number;
    numHints: number;
    messages: { code: string; message: string; severity: number; pointer?: string }[];
  };
}
const validator = createRequire(import.meta.url)('gltf-validator') as {
  validateBytes(data: Uint8Array, options?: object): Promise<ValidationReport>;
  version(): string;
};

/** An independent GLB container reader (glTF 2.0 spec, "Binary glTF Layout"). */
function parseGlb(b: Uint8Array) {
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  expect(dv.getUint32(0, true)).toBe(0x46546c67);
  expect(dv.getUint32(4, true)).toBe(2);
  expect(dv.getUint32(8, true)).toBe(b.length);
  const jsonLen = dv.getUint32(12, true);
  expect(jsonLen % 4).toBe(0);
  expect(dv.getUint32(16, true)).toBe(0x4e4f534a);
  const json = JSON.parse(text(b.subarray(20, 20 + jsonLen)));
  const binAt = 20 + jsonLen;
  const binLen = dv.getUint32(binAt, true);
  expect(binLen % 4).toBe(0);
  expect(dv.getUint32(binAt + 4, true)).toBe(0x004e4942);
  expect(binAt + 8 + binLen).toBe(b.length);
  return { json, bin: new DataView(b.buffer, b.byteOffset + binAt + 8, binLen) };
}

describe('GLB writer', () => {
  it("passes Khronos' validator with 0 errors and has the right accessor counts", async () => {
    const inp = input();
    const ref = strandsForExport(inp.strands, inp.session);
    const N = ref.strandStart.length - 1;
    const P = ref.widths.length;
    const { bytes } = collect('glb', inp);
    const report = await validator.validateBytes(new Uint8Array(bytes));
    console.log(
      `gltf-validator ${validator.version()}: ${report.issues.numErrors} errors, ` +
        `${report.issues.numWarnings} warnings, ${report.issues.numInfos} infos, ` +
        `${report.issues.numHints} hints`,
      report.issues.messages.map((m) => `${m.severity} ${m.code} ${m.pointer ?? ''}: ${m.message}`),
    );
    expect(report.issues.numErrors).toBe(0);

    const { json, bin } = parseGlb(bytes);
    expect(json.asset.version).toBe('2.0');
    expect(json.asset.generator).toBe('hairsketch');
    const meshes = Object.fromEntries(json.meshes.map((m: { name: string }) => [m.name, m]));
    const hair = meshes.hair.primitives[0];
    const head = meshes.head.primitives[0];
    expect(hair.mode).toBe(1);
    expect(head.mode).toBe(4);
    const acc = json.accessors;
    expect(acc[hair.attributes.POSITION].count).toBe(P);
    expect(acc[hair.attributes.COLOR_0].count).toBe(P);
    expect(acc[hair.attributes._WIDTH].count).toBe(P);
    expect(acc[hair.indices].count).toBe(2 * (P - N));
    expect(acc[hair.indices].componentType).toBe(5125);
    expect(acc[head.attributes.POSITION].count).toBe(4);
    expect(acc[head.attributes.NORMAL].count).toBe(4);
    expect(acc[head.indices].count).toBe(12);
    // POSITION data equals the exported points; _WIDTH the widths.
    const view = (a: { bufferView: number }) => json.bufferViews[a.bufferView];
    const pv = view(acc[hair.attributes.POSITION]);
    for (let i = 0; i < 3 * P; i++)
      expect(bin.getFloat32(pv.byteOffset + 4 * i, true)).toBe(ref.points[i]);
    const wv = view(acc[hair.attributes._WIDTH]);
    for (let i = 0; i < P; i++)
      expect(bin.getFloat32(wv.byteOffset + 4 * i, true)).toBe(ref.widths[i]);
  });

  it('is valid without the head too', async () => {
    const { bytes } = collect('glb', input(false));
    const report = await validator.validateBytes(new Uint8Array(bytes));
    expect(report.issues.numErrors).toBe(0);
    expect(parseGlb(bytes).json.meshes.map((m: { name: string }) => m.name)).toEqual(['hair']);
  });
});

describe('no strands', () => {
  it('writes every format from an empty hair, and the GLB stays valid', async () => {
    const empty: ExportInput = {
      strands: { points: new Float32Array(0), strandStart: new Uint32Array([0]) },
      session: trickySession(),
      head: tinyHead(),
    };
    for (const f of ['usda', 'hair', 'obj'] as const)
      expect(collect(f, empty).bytes.length).toBeGreaterThan(0);
    expect(collect('hair', empty).bytes.length).toBe(128);
    for (const head of [tinyHead(), null]) {
      const { bytes } = collect('glb', { ...empty, head });
      const report = await validator.validateBytes(new Uint8Array(bytes));
      expect(report.issues.numErrors).toBe(0);
      expect(readExportedSession(bytes)).toEqual({ ok: true, session: empty.session });
    }
    const usd = text(collect('usda', empty).bytes);
    expect(usd).toMatch(/int\[\] curveVertexCounts = \[\]/);
    expect(readExportedSession(new TextEncoder().encode(usd))).toEqual({
      ok: true,
      session: empty.session,
    });
  });
});

// ---- USD ---------------------------------------------------------------------------------------

/** The numbers inside `name = [ ... ]` within `block`. */
function usdArray(block: string, decl: string): number[] {
  const head = `${decl} = [`;
  const at = block.indexOf(head);
  expect(at).toBeGreaterThanOrEqual(0);
  const open = at + head.length;
  const close = block.indexOf(']', open);
  const body = block.slice(open, close).replace(/[()]/g, ' ');
  return body
    .split(/[\s,]+/)
    .filter((x) => x.length > 0)
    .map(Number);
}

describe('USD writer', () => {
  it('writes a header and a BasisCurves whose arrays agree', () => {
    const inp = input();
    const ref = strandsForExport(inp.strands, inp.session);
    const usd = text(collect('usda', inp).bytes);
    expect(usd.startsWith('#usda 1.0\n')).toBe(true);
    const header = usd.slice(0, usd.indexOf('def Xform'));
    expect(header).toMatch(/\n\s*metersPerUnit = 0\.1\n/);
    expect(header).toMatch(/\n\s*upAxis = "Y"\n/);
    expect(header).toMatch(/\n\s*defaultPrim = "hairsketch"\n/);
    expect(header).toMatch(/customLayerData = \{\s*string "hairsketch:session" = "/);
    expect(usd).toMatch(
      /def Xform "hairsketch"\n\{\n\s*def Xform "groom" \(\n\s*prepend apiSchemas = \["GroomAPI"\]\n\s*\)\n\s*\{\n\s*def BasisCurves "hair"/,
    );

    const curves = usd.slice(
      usd.indexOf('def BasisCurves "hair"'),
      usd.indexOf('def BasisCurves "guides"'),
    );
    expect(usd.indexOf('def BasisCurves "guides"')).toBeLessThan(usd.indexOf('def Mesh "head"'));
    expect(curves).toMatch(/uniform token type = "linear"/);
    expect(curves).toMatch(/uniform token wrap = "nonperiodic"/);
    const counts = usdArray(curves, 'int[] curveVertexCounts');
    const pts = usdArray(curves, 'point3f[] points');
    const widths = usdArray(curves, 'float[] widths');
    const extent = usdArray(curves, 'float3[] extent');
    const colors = usdArray(curves, 'color3f[] primvars:displayColor');
    const nPoints = pts.length / 3;
    expect(counts.reduce((a, c) => a + c, 0)).toBe(nPoints);
    for (const c of counts) {
      expect(c).toBeGreaterThanOrEqual(2);
      expect(c).toBeLessThanOrEqual(MAX_POINTS_PER_STRAND);
    }
    expect(counts.length).toBe(5);
    expect(nPoints).toBe(ref.widths.length);
    expect(widths.length).toBe(nPoints);
    expect(colors.length).toBe(3 * counts.length);
    expect(extent.length).toBe(6);
    for (let i = 0; i < pts.length; i += 3)
      for (let c = 0; c < 3; c++) {
        expect(pts[i + c]).toBeGreaterThanOrEqual(extent[c]);
        expect(pts[i + c]).toBeLessThanOrEqual(extent[3 + c]);
      }
    expect(curves).toMatch(/float\[\] widths = \[[^\]]*\] \(\s*interpolation = "vertex"\s*\)/);
    expect(curves).toMatch(
      /color3f\[\] primvars:displayColor = \[[^\]]*\] \(\s*interpolation = "uniform"\s*\)/,
    );
    for (const w of widths) {
      expect(w).toBeGreaterThanOrEqual(TIP_WIDTH);
      expect(w).toBeLessThanOrEqual(ROOT_WIDTH);
    }

    const mesh = usd.slice(usd.indexOf('def Mesh "head"'));
    const fvc = usdArray(mesh, 'int[] faceVertexCounts');
    const fvi = usdArray(mesh, 'int[] faceVertexIndices');
    const mp = usdArray(mesh, 'point3f[] points');
    const mn = usdArray(mesh, 'normal3f[] primvars:normals');
    expect(fvc).toEqual([3, 3, 3, 3]);
    expect(fvi).toEqual([...tinyHead().indices]);
    expect(mp.length).toBe(12);
    expect(mn.length).toBe(12);
    expect(mesh).toMatch(/uniform token orientation = "rightHanded"/);
    // Braces balance (outside strings).
    const body = usd.slice(usd.indexOf('def Xform'));
    expect(body.split('{').length).toBe(body.split('}').length);

    const noHead = text(collect('usda', input(false)).bytes);
    expect(noHead.includes('def Mesh')).toBe(false);
  });
});

// ---- round trip, determinism, chunks -------------------------------------------------------------

describe('reading the session back', () => {
  it('returns the session from the USD and the GLB, escapes included', () => {
    const inp = input();
    for (const f of ['usda', 'glb'] as const) {
      const r = readExportedSession(collect(f, inp).bytes);
      expect(r).toEqual({ ok: true, session: inp.session });
    }
  });

  it('names what is wrong, and ignores other files', () => {
    const enc = new TextEncoder();
    expect(
      readExportedSession(enc.encode('#usda 1.0\n(\n  upAxis = "Y"\n)\ndef Xform "x" {}\n')),
    ).toEqual({ ok: false, error: 'the USD file carries no hairsketch session' });
    const bad = readExportedSession(
      enc.encode(
        '#usda 1.0\n(\n customLayerData = {\n string "hairsketch:session" = "{oops"\n }\n)\n',
      ),
    );
    expect(bad?.ok).toBe(false);
    expect(bad && !bad.ok && bad.error).toMatch(/not valid JSON/);
    // Single quotes, as usdcat writes a string holding double quotes.
    const single = readExportedSession(
      enc.encode(
        `#usda 1.0\n(\n customLayerData = {\n string "hairsketch:session" = '{"a":"\\\\\\\\ \\x41 ✂"}'\n }\n)\n`,
      ),
    );
    expect(single).toEqual({ ok: true, session: { a: '\\ A ✂' } });
    expect(readExportedSession(enc.encode('o hair\nv 0 0 0\n'))).toBeNull();
    expect(readExportedSession(new Uint8Array([1, 2, 3]))).toBeNull();
    expect(readExportedSession(new Uint8Array([0x67, 0x6c, 0x54, 0x46, 2, 0, 0, 0]))).toEqual({
      ok: false,
      error: 'the GLB file is truncated (no JSON chunk)',
    });
  });
});

describe('determinism and chunks', () => {
  it('writes the same bytes twice, with or without progress, every chunk <= 1 MiB', () => {
    for (const f of ['usda', 'hair', 'obj', 'glb'] as const) {
      const a = collect(f, input());
      const seen: number[] = [];
      const b = collect(f, input(), (x) => seen.push(x));
      expect(Buffer.from(b.bytes).equals(Buffer.from(a.bytes))).toBe(true);
      expect(seen[seen.length - 1]).toBe(1);
      for (let i = 1; i < seen.length; i++) expect(seen[i]).toBeGreaterThanOrEqual(seen[i - 1]);
      for (const c of a.chunks) expect(c.length).toBeLessThanOrEqual(CHUNK_BYTES);
    }
  });

  it('splits a multi-megabyte file into chunks that join to the same text (UTF-8 intact)', () => {
    // A 2 MB-plus session string of 3-byte characters forces chunk boundaries inside it.
    const big = trickySession();
    const session = {
      ...big,
      curves: [{ ...big.curves[0], id: `✂${'ü✂'.repeat(700_000)}"\\` }],
    } as SessionState;
    const inp: ExportInput = { strands: syntheticHair(), session, head: tinyHead() };
    for (const f of ['usda', 'glb'] as const) {
      const { chunks, bytes } = collect(f, inp);
      expect(chunks.length).toBeGreaterThan(2);
      for (const c of chunks) expect(c.length).toBeLessThanOrEqual(CHUNK_BYTES);
      expect(readExportedSession(bytes)).toEqual({ ok: true, session });
      const again = collect(f, inp).bytes;
      expect(Buffer.from(again).equals(Buffer.from(bytes))).toBe(true);
    }
  });
});

// ---- 20K strands -----------------------------------------------------------------------------------

describe('20K strands × 24 points', () => {
  // npm run bench:export measures the export of a whole head of hair; this checks the chunking
  it('exports every format in chunks of at most 1 MiB (times and sizes printed)', () => {
    const N = 20_000;
    const K = 24;
    const points = new Float32Array(3 * N * K);
    const strandStart = new Uint32Array(N + 1);
    let seed = 1;
    const rnd = () => {
      seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
      return seed / 2 ** 32;
    };
    for (let s = 0; s < N; s++) {
      const th = rnd() * Math.PI;
      const ph = rnd() * 2 * Math.PI;
      let x = Math.sin(th) * Math.cos(ph);
      let y = Math.cos(th) + 0.3;
      let z = Math.sin(th) * Math.sin(ph);
      for (let k = 0; k < K; k++) {
        const o = 3 * (s * K + k);
        points[o] = x;
        points[o + 1] = y;
        points[o + 2] = z;
        x += 0.02 * (rnd() - 0.5);
        y -= 0.05;
        z += 0.02 * (rnd() - 0.5);
      }
      strandStart[s + 1] = (s + 1) * K;
    }
    const inp: ExportInput = {
      strands: { points, strandStart },
      session: trickySession(),
      head: tinyHead(),
    };
    const rows: string[] = [];
    for (const f of ['usda', 'hair', 'obj', 'glb'] as const) {
      const t0 = performance.now();
      let size = 0;
      let count = 0;
      let largest = 0;
      for (const c of writeExport(f, inp)) {
        size += c.length;
        count++;
        largest = Math.max(largest, c.length);
      }
      const ms = performance.now() - t0;
      expect(largest).toBeLessThanOrEqual(CHUNK_BYTES);
      if (f === 'hair') expect(size).toBe(128 + 2 * N + 28 * N * K);
      rows.push(
        `${f.padEnd(5)} ${(size / 1e6).toFixed(1).padStart(6)} MB  ${ms.toFixed(0).padStart(6)} ms  ${count} chunks (largest ${largest} B)`,
      );
    }
    console.log(`export of ${N} strands × ${K} points:\n${rows.join('\n')}`);
  }, 300_000);
});
