// glTF 2.0 binary (`.glb`): mesh "hair" as LINES (mode 1) with uint32 indices, POSITION (with
// min/max), COLOR_0 (float32 VEC3, linear) and the application attribute _WIDTH (float32, the
// diameter); mesh "head" as TRIANGLES (mode 4) with POSITION, NORMAL when given, and indices;
// mesh "band" (the ties' bands, bandExport.ts) as TRIANGLES with POSITION, NORMAL, indices and
// material "band" in the band colour.
// Both hang under a root node "hairsketch" scaled by METERS_PER_UNIT (glTF units are metres; the
// app's unit is 10 cm), so positions and widths stay in app units inside the meshes. The session
// is in asset.extras.hairsketch.session. All lengths are computed first; the BIN chunk is then
// written in pieces.
import { BAND_ROUGHNESS, exportBand } from './bandExport';
import { BinarySink, type Progress, writeStrandFloats } from './chunkSink';
import {
  ARRAY_BUFFER,
  bounds,
  ELEMENT_ARRAY_BUFFER,
  FLOAT,
  LINES,
  TRIANGLES,
  UNSIGNED_INT,
  writeGlbStart,
} from './glbContainer';
import type { ExportStrands } from './strandsForExport';
import { type ExportInput, METERS_PER_UNIT } from './types';

const BATCH = 4096;
const ROWS = 16384;

interface View {
  buffer: 0;
  byteOffset: number;
  byteLength: number;
  target: number;
}

interface Accessor {
  bufferView: number;
  componentType: number;
  count: number;
  type: 'SCALAR' | 'VEC3';
  min?: number[];
  max?: number[];
}

export function* writeGlb(
  strands: ExportStrands,
  input: ExportInput,
  progress: Progress,
): Generator<Uint8Array> {
  const { strandStart, widths } = strands;
  const n = strandStart.length - 1;
  const p = widths.length;
  const head = input.head && input.head.indices.length >= 3 ? input.head : null;
  const headVerts = head ? head.positions.length / 3 : 0;
  const headTris = head ? Math.floor(head.indices.length / 3) : 0;

  const views: View[] = [];
  const accessors: Accessor[] = [];
  const meshes: object[] = [];
  const nodes: { name: string; mesh?: number; children?: number[]; scale?: number[] }[] = [
    { name: 'hairsketch', scale: [METERS_PER_UNIT, METERS_PER_UNIT, METERS_PER_UNIT] },
  ];
  let offset = 0;
  const view = (byteLength: number, target: number): number => {
    views.push({ buffer: 0, byteOffset: offset, byteLength, target });
    offset += byteLength; // every element is 4 bytes: views stay 4-byte aligned
    return views.length - 1;
  };
  const accessor = (a: Accessor): number => {
    accessors.push(a);
    return accessors.length - 1;
  };

  if (n > 0) {
    const position = accessor({
      bufferView: view(12 * p, ARRAY_BUFFER),
      componentType: FLOAT,
      count: p,
      type: 'VEC3',
      min: [...strands.min],
      max: [...strands.max],
    });
    const color = accessor({
      bufferView: view(12 * p, ARRAY_BUFFER),
      componentType: FLOAT,
      count: p,
      type: 'VEC3',
    });
    const width = accessor({
      bufferView: view(4 * p, ARRAY_BUFFER),
      componentType: FLOAT,
      count: p,
      type: 'SCALAR',
    });
    const indices = accessor({
      bufferView: view(8 * (p - n), ELEMENT_ARRAY_BUFFER),
      componentType: UNSIGNED_INT,
      count: 2 * (p - n),
      type: 'SCALAR',
    });
    meshes.push({
      name: 'hair',
      primitives: [
        {
          mode: LINES,
          indices,
          attributes: { POSITION: position, COLOR_0: color, _WIDTH: width },
        },
      ],
    });
    nodes.push({ name: 'hair', mesh: meshes.length - 1 });
  }
  if (head) {
    const position = accessor({
      bufferView: view(12 * headVerts, ARRAY_BUFFER),
      componentType: FLOAT,
      count: headVerts,
      type: 'VEC3',
      ...bounds(head.positions),
    });
    const attributes: Record<string, number> = { POSITION: position };
    if (head.normals)
      attributes.NORMAL = accessor({
        bufferView: view(12 * headVerts, ARRAY_BUFFER),
        componentType: FLOAT,
        count: headVerts,
        type: 'VEC3',
      });
    const indices = accessor({
      bufferView: view(12 * headTris, ELEMENT_ARRAY_BUFFER),
      componentType: UNSIGNED_INT,
      count: 3 * headTris,
      type: 'SCALAR',
    });
    meshes.push({ name: 'head', primitives: [{ mode: TRIANGLES, indices, attributes }] });
    nodes.push({ name: 'head', mesh: meshes.length - 1 });
  }
  const band = exportBand(input);
  const materials: object[] = [];
  if (band) {
    const { positions, indices } = band.mesh;
    const count = positions.length / 3;
    const vec3 = (min?: number[], max?: number[]) => ({
      bufferView: view(12 * count, ARRAY_BUFFER),
      componentType: FLOAT,
      count,
      type: 'VEC3' as const,
      ...(min && max ? { min, max } : {}),
    });
    const { min, max } = bounds(positions);
    const attributes = { POSITION: accessor(vec3(min, max)), NORMAL: accessor(vec3()) };
    const index = accessor({
      bufferView: view(4 * indices.length, ELEMENT_ARRAY_BUFFER),
      componentType: UNSIGNED_INT,
      count: indices.length,
      type: 'SCALAR',
    });
    materials.push({
      name: 'band',
      pbrMetallicRoughness: {
        baseColorFactor: [...band.linear, 1],
        metallicFactor: 0,
        roughnessFactor: BAND_ROUGHNESS,
      },
    });
    const material = materials.length - 1;
    meshes.push({
      name: 'band',
      primitives: [{ mode: TRIANGLES, indices: index, attributes, material }],
    });
    nodes.push({ name: 'band', mesh: meshes.length - 1 });
  }
  if (nodes.length > 1) nodes[0].children = nodes.slice(1).map((_, i) => i + 1);
  const binLength = offset;

  const gltf: Record<string, unknown> = {
    asset: {
      version: '2.0',
      generator: 'hairsketch',
      extras: { hairsketch: { session: input.session } },
    },
    scene: 0,
    scenes: [{ name: 'hairsketch', nodes: [0] }],
    nodes,
  };
  if (meshes.length > 0) {
    gltf.meshes = meshes;
    gltf.accessors = accessors;
    gltf.bufferViews = views;
    gltf.buffers = [{ byteLength: binLength }];
  }
  if (materials.length > 0) gltf.materials = materials;
  const out = new BinarySink();
  const total = writeGlbStart(out, gltf, binLength);
  const report = () => progress.at(out.bytes / total);
  report();
  yield* out.drain();
  if (binLength === 0) {
    yield* out.end();
    progress.at(1);
    return;
  }

  if (n > 0) {
    yield* writeStrandFloats(out, strands, 'points', report);
    yield* writeStrandFloats(out, strands, 'colors', report);
    yield* writeStrandFloats(out, strands, 'widths', report);
    for (let s0 = 0; s0 < n; s0 += BATCH) {
      const s1 = Math.min(n, s0 + BATCH);
      for (let s = s0; s < s1; s++)
        for (let q = strandStart[s]; q + 1 < strandStart[s + 1]; q++) {
          out.u32(q);
          out.u32(q + 1);
        }
      report();
      yield* out.drain();
    }
  }
  if (head) {
    for (let v0 = 0; v0 < headVerts; v0 += ROWS) {
      out.f32s(head.positions, 3 * v0, 3 * Math.min(headVerts, v0 + ROWS));
      report();
      yield* out.drain();
    }
    const normals = head.normals;
    if (normals)
      for (let v0 = 0; v0 < headVerts; v0 += ROWS) {
        out.f32s(normals, 3 * v0, 3 * Math.min(headVerts, v0 + ROWS));
        report();
        yield* out.drain();
      }
    for (let t0 = 0; t0 < headTris; t0 += ROWS) {
      out.u32s(head.indices, 3 * t0, 3 * Math.min(headTris, t0 + ROWS));
      report();
      yield* out.drain();
    }
  }
  if (band) {
    const { positions, normals, indices } = band.mesh;
    out.f32s(positions, 0, positions.length);
    out.f32s(normals, 0, normals.length);
    out.u32s(indices, 0, indices.length);
    report();
    yield* out.drain();
  }
  out.zeros(((binLength + 3) & ~3) - binLength);
  yield* out.end();
  progress.at(1);
}
