// Hair cards (.glb): Khronos' validator reports no errors; the embedded PNGs decode with
// node:zlib to the sizes the material names; and the cards' silhouette matches the strands'
// from the front, the side and the top (intersection over union >= 0.85), each mask rasterised
// here from the two exported files read back with an independent GLB reader.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { inflateRawSync, inflateSync, crc32 as zlibCrc32 } from 'node:zlib';
import { beforeAll, describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { clusterStrands, strandFeatures } from '../../web/export/cardClusters';
import { CARD_COUNT_MAX, DEFAULT_CARD_COUNT } from '../../web/export/cardCount';
import { deflateFixed } from '../../web/export/deflate';
import type { ExportFormat } from '../../web/export/formats';
import { growSessionHair } from '../../web/export/growSession';
import { encodePng } from '../../web/export/png';
import { strandsForExport } from '../../web/export/strandsForExport';
import type { ExportInput } from '../../web/export/types';
import { writeExport } from '../../web/export/writeExport';
import { Head } from '../../web/head/head';
import { gridForPreset } from '../../web/model/grid';
import type { StrandArrays } from '../../web/model/hairArrays';
import type { PresetName } from '../../web/model/presets';
import { loadSolverEngine } from '../../web/solver/wasmEngine';

const validator = createRequire(import.meta.url)('gltf-validator') as {
  validateBytes(
    data: Uint8Array,
    options?: object,
  ): Promise<{
    issues: {
      numErrors: number;
      numWarnings: number;
      messages: { code: string; severity: number; pointer?: string; message: string }[];
    };
  }>;
};

const wasmPath = fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url));
const head = Head.builtin();

async function growPreset(name: PresetName, maxStrands: number): Promise<ExportInput> {
  const session = presetSession(name, head, '25k', maxStrands);
  const engine = await loadSolverEngine({ wasmBinary: new Uint8Array(readFileSync(wasmPath)) });
  try {
    const hair = growSessionHair(engine, session, head.scalpMesh(), {
      grid: gridForPreset('25k'),
      solver: 'fast',
    });
    return { strands: hair.strands, session, head: null };
  } finally {
    engine.dispose();
  }
}

function collect(format: ExportFormat, inp: ExportInput): Uint8Array {
  const chunks = [...writeExport(format, inp)];
  const out = new Uint8Array(chunks.reduce((n, c) => n + c.length, 0));
  let o = 0;
  for (const c of chunks) {
    out.set(c, o);
    o += c.length;
  }
  return out;
}

// ---- an independent GLB reader (glTF 2.0, "Binary glTF Layout" and "Accessors") ---------------

interface Glb {
  json: {
    meshes: {
      name: string;
      primitives: {
        mode: number;
        indices: number;
        attributes: Record<string, number>;
        material?: number;
      }[];
    }[];
    accessors: { bufferView: number; count: number; componentType: number; type: string }[];
    bufferViews: { byteOffset: number; byteLength: number }[];
    images?: { bufferView: number; mimeType: string; name: string }[];
    textures?: { source: number }[];
    materials?: {
      alphaMode: string;
      doubleSided: boolean;
      alphaCutoff?: number;
      pbrMetallicRoughness: { baseColorTexture: { index: number } };
      extras: Record<string, unknown>;
    }[];
    nodes: { scale?: number[] }[];
  };
  bin: Uint8Array;
}

function readGlb(b: Uint8Array): Glb {
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  expect(dv.getUint32(0, true)).toBe(0x46546c67);
  expect(dv.getUint32(8, true)).toBe(b.length);
  const jsonLen = dv.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(b.subarray(20, 20 + jsonLen)));
  const binLen = dv.getUint32(20 + jsonLen, true);
  return { json, bin: b.subarray(28 + jsonLen, 28 + jsonLen + binLen) };
}

function accessorData(g: Glb, index: number): Float32Array | Uint32Array {
  const a = g.json.accessors[index];
  const v = g.json.bufferViews[a.bufferView];
  const comps = { SCALAR: 1, VEC2: 2, VEC3: 3 }[a.type] ?? 0;
  const bytes = g.bin.slice(v.byteOffset, v.byteOffset + 4 * comps * a.count);
  return a.componentType === 5126 ? new Float32Array(bytes.buffer) : new Uint32Array(bytes.buffer);
}

function primitive(g: Glb, mesh: string) {
  const m = g.json.meshes.find((x) => x.name === mesh);
  if (!m) throw new Error(`no mesh ${mesh}`);
  return m.primitives[0];
}

// ---- masks: orthographic views, a pixel covered when its centre is within half a pixel of a
// primitive (inside a triangle, or near a segment widened by the strand's diameter) ---------------

const RES = 200;
type Axes = [number, number]; // the two world axes the view keeps: front (x, y), side (z, y), top (x, z)
const VIEWS: Record<string, Axes> = { front: [0, 1], side: [2, 1], top: [0, 2] };

interface Frame {
  min: number[];
  px: number; // world units per pixel
}

function frameOf(a: Float32Array, axes: Axes, b: Float32Array): Frame {
  const min = [Infinity, Infinity];
  const max = [-Infinity, -Infinity];
  for (const pts of [a, b])
    for (let i = 0; i < pts.length; i += 3)
      for (let k = 0; k < 2; k++) {
        min[k] = Math.min(min[k], pts[i + axes[k]]);
        max[k] = Math.max(max[k], pts[i + axes[k]]);
      }
  const px = Math.max(max[0] - min[0], max[1] - min[1]) / (RES - 4);
  return { min: [min[0] - 2 * px, min[1] - 2 * px], px };
}

function segmentDistance(px: number, py: number, ax: number, ay: number, bx: number, by: number) {
  const dx = bx - ax;
  const dy = by - ay;
  const l2 = dx * dx + dy * dy;
  const t = l2 > 0 ? Math.min(1, Math.max(0, ((px - ax) * dx + (py - ay) * dy) / l2)) : 0;
  return Math.hypot(px - ax - t * dx, py - ay - t * dy);
}

function strokeSegment(mask: Uint8Array, f: Frame, a: number[], b: number[], half: number) {
  const reach = half + 0.5 * f.px;
  const x0 = Math.max(0, Math.floor((Math.min(a[0], b[0]) - reach - f.min[0]) / f.px));
  const x1 = Math.min(RES - 1, Math.ceil((Math.max(a[0], b[0]) + reach - f.min[0]) / f.px));
  const y0 = Math.max(0, Math.floor((Math.min(a[1], b[1]) - reach - f.min[1]) / f.px));
  const y1 = Math.min(RES - 1, Math.ceil((Math.max(a[1], b[1]) + reach - f.min[1]) / f.px));
  for (let y = y0; y <= y1; y++)
    for (let x = x0; x <= x1; x++) {
      const cx = f.min[0] + (x + 0.5) * f.px;
      const cy = f.min[1] + (y + 0.5) * f.px;
      if (segmentDistance(cx, cy, a[0], a[1], b[0], b[1]) <= reach) mask[x + RES * y] = 1;
    }
}

function fillTriangle(mask: Uint8Array, f: Frame, p: number[][]) {
  for (let e = 0; e < 3; e++) strokeSegment(mask, f, p[e], p[(e + 1) % 3], 0);
  const xs = p.map((q) => (q[0] - f.min[0]) / f.px - 0.5);
  const ys = p.map((q) => (q[1] - f.min[1]) / f.px - 0.5);
  const area = (xs[1] - xs[0]) * (ys[2] - ys[0]) - (xs[2] - xs[0]) * (ys[1] - ys[0]);
  if (area === 0) return;
  for (
    let y = Math.max(0, Math.floor(Math.min(...ys)));
    y <= Math.min(RES - 1, Math.ceil(Math.max(...ys)));
    y++
  )
    for (
      let x = Math.max(0, Math.floor(Math.min(...xs)));
      x <= Math.min(RES - 1, Math.ceil(Math.max(...xs)));
      x++
    ) {
      let inside = true;
      for (let e = 0; e < 3 && inside; e++) {
        const a = e;
        const b = (e + 1) % 3;
        const c = (xs[b] - xs[a]) * (y - ys[a]) - (x - xs[a]) * (ys[b] - ys[a]);
        inside = c * area >= 0;
      }
      if (inside) mask[x + RES * y] = 1;
    }
}

const pick = (pts: Float32Array, i: number, axes: Axes) => [
  pts[3 * i + axes[0]],
  pts[3 * i + axes[1]],
];

function strandMask(g: Glb, axes: Axes, f: Frame): Uint8Array {
  const prim = primitive(g, 'hair');
  expect(prim.mode).toBe(1);
  const pos = accessorData(g, prim.attributes.POSITION) as Float32Array;
  const width = accessorData(g, prim.attributes._WIDTH) as Float32Array;
  const idx = accessorData(g, prim.indices) as Uint32Array;
  const mask = new Uint8Array(RES * RES);
  for (let i = 0; i < idx.length; i += 2)
    strokeSegment(
      mask,
      f,
      pick(pos, idx[i], axes),
      pick(pos, idx[i + 1], axes),
      Math.max(width[idx[i]], width[idx[i + 1]]) / 2,
    );
  return mask;
}

function cardMask(g: Glb, axes: Axes, f: Frame): Uint8Array {
  const prim = primitive(g, 'cards');
  expect(prim.mode).toBe(4);
  const pos = accessorData(g, prim.attributes.POSITION) as Float32Array;
  const idx = accessorData(g, prim.indices) as Uint32Array;
  const mask = new Uint8Array(RES * RES);
  for (let i = 0; i < idx.length; i += 3)
    fillTriangle(mask, f, [
      pick(pos, idx[i], axes),
      pick(pos, idx[i + 1], axes),
      pick(pos, idx[i + 2], axes),
    ]);
  return mask;
}

function iou(a: Uint8Array, b: Uint8Array): number {
  let both = 0;
  let either = 0;
  for (let i = 0; i < a.length; i++) {
    both += a[i] & b[i];
    either += a[i] | b[i];
  }
  return either > 0 ? both / either : 1;
}

/** An independent PNG reader: chunk CRCs (node:zlib's crc32), IHDR, and the IDAT stream inflated
 *  by node:zlib to exactly the rows IHDR promises. */
function readPng(b: Uint8Array) {
  expect([...b.subarray(0, 8)]).toEqual([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  let o = 8;
  const idat: Uint8Array[] = [];
  let w = 0;
  let h = 0;
  let type = -1;
  for (;;) {
    const len = dv.getUint32(o);
    const name = new TextDecoder().decode(b.subarray(o + 4, o + 8));
    expect(dv.getUint32(o + 8 + len), `${name} CRC`).toBe(
      zlibCrc32(b.subarray(o + 4, o + 8 + len)),
    );
    if (name === 'IHDR') {
      w = dv.getUint32(o + 8);
      h = dv.getUint32(o + 12);
      type = b[o + 17];
    } else if (name === 'IDAT') idat.push(b.subarray(o + 8, o + 8 + len));
    o += 12 + len;
    if (name === 'IEND') break;
  }
  expect(o).toBe(b.length);
  const channels = type === 6 ? 4 : type === 0 ? 1 : 0;
  const raw = inflateSync(Buffer.concat(idat));
  expect(raw.length).toBe(h * (1 + w * channels));
  return { w, h, channels, raw };
}

// ---- the tests --------------------------------------------------------------------------------

describe('deflate', () => {
  it('compresses what node:zlib inflates back exactly: empty, short, runs, noise, long matches', () => {
    const noise = new Uint8Array(100_000);
    let x = 12345;
    for (let i = 0; i < noise.length; i++) {
      x = (Math.imul(x, 1103515245) + 12345) >>> 0;
      noise[i] = x >>> 24;
    }
    const runs = new Uint8Array(300_000);
    for (let i = 0; i < runs.length; i++) runs[i] = i % 4 === 3 ? 0 : [90, 56, 37][i % 4];
    const mixed = new Uint8Array(200_000);
    for (let i = 0; i < mixed.length; i++)
      mixed[i] = (i >> 9) % 3 === 0 ? noise[i % 5000] : (i * 7) & 15;
    const cases: Record<string, Uint8Array> = {
      empty: new Uint8Array(0),
      'two bytes': new Uint8Array([1, 2]),
      'one run of 100K zeros': new Uint8Array(100_000),
      'RGBA runs': runs,
      noise,
      'repeats 5,000 bytes back and small values': mixed,
    };
    for (const [name, data] of Object.entries(cases)) {
      const packed = deflateFixed(data);
      const back = inflateRawSync(packed);
      expect(Buffer.compare(back, data), name).toBe(0);
      if (name === 'RGBA runs') expect(packed.length).toBeLessThan(data.length / 50);
    }
  });
});

describe('PNG encoder', () => {
  it('writes a PNG that node:zlib inflates to the same pixels', () => {
    const px = new Uint8Array(70_000 * 4).map((_, i) => (i * 7) & 255);
    const png = readPng(encodePng(350, 200, 4, px));
    expect([png.w, png.h, png.channels]).toEqual([350, 200, 4]);
    for (let y = 0; y < 200; y++) {
      expect(png.raw[y * 1401]).toBe(0);
      expect(
        Buffer.compare(
          png.raw.subarray(y * 1401 + 1, (y + 1) * 1401),
          px.subarray(y * 1400, (y + 1) * 1400),
        ),
      ).toBe(0);
    }
  });
});

describe('card clusters', () => {
  it('are seeded: the same seed gives the same clusters, every strand in one, none empty', () => {
    const strands: number[] = [];
    const start = [0];
    for (let s = 0; s < 3000; s++) {
      const a = (s * 2.399) % 6.283;
      const r = 1 + (s % 7) * 0.01;
      for (let i = 0; i < 10; i++) strands.push(r * Math.cos(a), 1 - 0.1 * i, r * Math.sin(a));
      start.push(start[start.length - 1] + 10);
    }
    const f = strandFeatures(new Float32Array(strands), new Uint32Array(start));
    const a = clusterStrands(f, 200, 7);
    const b = clusterStrands(f, 200, 7);
    expect(Buffer.from(a.of.buffer).equals(Buffer.from(b.of.buffer))).toBe(true);
    expect(a.count).toBeLessThanOrEqual(200);
    expect(a.count).toBeGreaterThan(150);
    for (let c = 0; c < a.count; c++) expect(a.start[c + 1]).toBeGreaterThan(a.start[c]);
    expect(a.start[a.count]).toBe(3000);
    // a cluster's strands lie together: the brute-force nearest centre of most strands is their own
    const centres = new Float64Array(12 * a.count);
    for (let s = 0; s < 3000; s++)
      for (let q = 0; q < 12; q++)
        centres[12 * a.of[s] + q] += f[12 * s + q] / (a.start[a.of[s] + 1] - a.start[a.of[s]]);
    let own = 0;
    for (let s = 0; s < 3000; s++) {
      let best = -1;
      let bestD = Infinity;
      for (let c = 0; c < a.count; c++) {
        let d = 0;
        for (let q = 0; q < 12; q++) d += (f[12 * s + q] - centres[12 * c + q]) ** 2;
        if (d < bestD) [best, bestD] = [c, d];
      }
      if (best === a.of[s]) own++;
    }
    expect(own / 3000).toBeGreaterThan(0.95);
  });
});

describe('hair cards (.glb)', () => {
  const inputs: Record<string, ExportInput> = {};
  beforeAll(async () => {
    inputs.bob = await growPreset('bob', 8000);
    inputs.long = await growPreset('long', 8000);
  }, 120_000);

  for (const preset of ['bob', 'long'])
    it(`${preset}: valid, with its textures, and the cards' silhouette is the strands'`, async () => {
      const inp = inputs[preset];
      const cardsBytes = collect('cards', {
        ...inp,
        head: {
          positions: head.mesh.positions,
          indices: head.mesh.indices,
          normals: head.mesh.normals,
        },
      });
      const report = await validator.validateBytes(cardsBytes);
      const notes = report.issues.messages.map(
        (m) => `${m.severity} ${m.code} ${m.pointer ?? ''}: ${m.message}`,
      );
      expect(report.issues.numErrors, notes.join('\n')).toBe(0);

      const cards = readGlb(cardsBytes);
      const prim = primitive(cards, 'cards');
      const triangles = cards.json.accessors[prim.indices].count / 3;
      const material = cards.json.materials?.[prim.material ?? -1];
      expect(material?.alphaMode).toBe('MASK');
      expect(material?.doubleSided).toBe(true);
      const texImage = (t: number) => cards.json.images?.[cards.json.textures?.[t]?.source ?? -1];
      const named = {
        colour: texImage(material?.pbrMetallicRoughness.baseColorTexture.index ?? -1),
        'root-tip': texImage(material?.extras.rootTipTexture as number),
        depth: texImage(material?.extras.depthTexture as number),
      };
      const sizes: string[] = [];
      for (const [what, image] of Object.entries(named)) {
        expect(image?.mimeType, what).toBe('image/png');
        const v = cards.json.bufferViews[image?.bufferView ?? -1];
        const png = readPng(cards.bin.subarray(v.byteOffset, v.byteOffset + v.byteLength));
        expect(png.channels).toBe(what === 'colour' ? 4 : 1);
        sizes.push(
          `${what} ${png.w}×${png.h}×${png.channels} (${(v.byteLength / 1048576).toFixed(1)} MB)`,
        );
        if (what === 'colour') {
          // some pixels are hair (opaque) and some are not (the mask cuts them)
          let opaque = 0;
          for (let y = 0; y < png.h; y++)
            for (let x = 0; x < png.w; x++)
              if (png.raw[y * (1 + 4 * png.w) + 1 + 4 * x + 3] >= 128) opaque++;
          expect(opaque).toBeGreaterThan(0.01 * png.w * png.h);
          expect(opaque).toBeLessThan(0.9 * png.w * png.h);
        }
      }
      const strands = strandsForExport(inp.strands, inp.session).strandStart.length - 1;
      const strandsBytes = collect('glb', inp);
      const lines = readGlb(strandsBytes);
      const linePos = accessorData(
        lines,
        primitive(lines, 'hair').attributes.POSITION,
      ) as Float32Array;
      const cardPos = accessorData(cards, prim.attributes.POSITION) as Float32Array;
      const scores: string[] = [];
      for (const [view, axes] of Object.entries(VIEWS)) {
        const f = frameOf(linePos, axes, cardPos);
        const score = iou(strandMask(lines, axes, f), cardMask(cards, axes, f));
        scores.push(`${view} ${score.toFixed(3)}`);
        expect(score, `${preset} ${view}`).toBeGreaterThanOrEqual(0.85);
      }
      console.log(
        `hair cards, ${preset}: ${strands} strands → ${(cards.json as unknown as { asset: { extras: { hairsketch: { cards: { made: number } } } } }).asset.extras.hairsketch.cards.made} cards (asked ${DEFAULT_CARD_COUNT}), ${triangles} triangles; ${sizes.join(', ')}; ${(cardsBytes.length / 1048576).toFixed(1)} MB; IoU ${scores.join(', ')}`,
      );
    }, 240_000);

  it('takes the count it is given, and refuses one out of range with a sentence', () => {
    const inp = inputs.bob;
    const few = readGlb(collect('cards', { ...inp, cards: 100 }));
    const made = (
      few.json as unknown as { asset: { extras: { hairsketch: { cards: { made: number } } } } }
    ).asset.extras.hairsketch.cards.made;
    expect(made).toBeLessThanOrEqual(100);
    expect(made).toBeGreaterThan(80);
    expect(() => collect('cards', { ...inp, cards: CARD_COUNT_MAX + 1 })).toThrow(
      /card count must be a whole number from 100 to 5,000/,
    );
    expect(() => collect('cards', { ...inp, cards: 99.5 })).toThrow(/card count/);
  });

  it('stays valid on degenerate hair: one strand, identical strands, zero-length strands, straight out', async () => {
    const pack = (strands: number[][]): StrandArrays => {
      const strandStart = new Uint32Array(strands.length + 1);
      strands.forEach((st, i) => {
        strandStart[i + 1] = strandStart[i] + st.length / 3;
      });
      return { points: new Float32Array(strands.flat()), strandStart };
    };
    const still = [0.2, 1, 0.1, 0.2, 1, 0.1, 0.2, 1, 0.1];
    const down = [0, 1, 0.5, 0, 0.5, 0.6, 0, 0, 0.7];
    const out = [0, 1.2, 0, 0, 1.5, 0, 0, 1.8, 0]; // along the line from the roots' centroid
    const cases: Record<string, number[][]> = {
      'one strand': [down],
      'identical strands': Array.from({ length: 300 }, () => down),
      'zero-length strands': Array.from({ length: 200 }, () => still),
      'straight out and down': [
        ...Array.from({ length: 150 }, () => out),
        ...Array.from({ length: 150 }, () => down),
      ],
    };
    for (const [name, strands] of Object.entries(cases)) {
      const bytes = collect('cards', { ...inputs.bob, strands: pack(strands), cards: 100 });
      const report = await validator.validateBytes(bytes);
      const notes = report.issues.messages.map((m) => `${m.code} ${m.pointer ?? ''}: ${m.message}`);
      expect(report.issues.numErrors, `${name}: ${notes.join('; ')}`).toBe(0);
      const g = readGlb(bytes);
      const pos = accessorData(g, primitive(g, 'cards').attributes.POSITION);
      expect(pos.every(Number.isFinite), name).toBe(true);
    }
  });

  it('writes a valid file from no strands', async () => {
    const empty: ExportInput = {
      ...inputs.bob,
      strands: { points: new Float32Array(0), strandStart: new Uint32Array([0]) } as StrandArrays,
    };
    const report = await validator.validateBytes(collect('cards', empty));
    expect(report.issues.numErrors).toBe(0);
  });
});
