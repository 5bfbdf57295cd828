// Hair cards as glTF 2.0 binary (`.glb`): the strands clustered into cards (cardClusters.ts),
// each a strip of quads (cardMesh.ts) textured from an atlas drawn from the strands
// (cardAtlas.ts), the three atlas images embedded as PNG (png.ts). Mesh "cards": TRIANGLES with
// POSITION, NORMAL, TEXCOORD_0 and uint32 indices, material "hair cards": the colour atlas as
// baseColorTexture, alphaMode MASK (cutoff 0.5) and doubleSided. MASK, not BLEND: engines draw
// masked cards with depth writes and no sorting (Unreal's and Unity's card materials are masked
// or dithered); blended cards need back-to-front sorting per triangle, which no engine does for
// one mesh, so they flicker. Both sides, since a card seen from behind is hair too. The root–tip
// and depth maps are textures named in the material's extras (glTF has no slot for them).
// Mesh "head" and mesh "band" (the ties' bands, with material "band") as in glbWriter.ts; all
// under a root node scaled to metres; the session in
// asset.extras.hairsketch.session, the card settings in asset.extras.hairsketch.cards.

import { BAND_ROUGHNESS, exportBand } from './bandExport';
import { ATLAS_SIZE, ATLAS_TILES, DEPTH_RANGE, drawCardAtlas, tileRect } from './cardAtlas';
import { clusterStrands, strandFeatures } from './cardClusters';
import { cardCountProblem, DEFAULT_CARD_COUNT } from './cardCount';
import { buildCards, type CardGeometry, cardGeometry } from './cardMesh';
import { BinarySink, type Progress } from './chunkSink';
import {
  ARRAY_BUFFER,
  bounds,
  ELEMENT_ARRAY_BUFFER,
  FLOAT,
  TRIANGLES,
  UNSIGNED_INT,
  writeGlbStart,
} from './glbContainer';
import { encodePng } from './png';
import type { ExportStrands } from './strandsForExport';
import { type ExportInput, METERS_PER_UNIT } from './types';

const LINEAR = 9729;
const LINEAR_MIPMAP_LINEAR = 9987;
const CLAMP_TO_EDGE = 33071;

export interface HairCards {
  geometry: CardGeometry;
  atlas: ReturnType<typeof drawCardAtlas>;
  /** Cards made (clusters with strands: at most the count asked for). */
  cards: number;
}

/** The cards of `strands`: `count` clusters asked for, seeded by `seed`. */
export function makeHairCards(strands: ExportStrands, count: number, seed: number): HairCards {
  const problem = cardCountProblem(count);
  if (problem) throw new Error(problem);
  const clusters = clusterStrands(strandFeatures(strands.points, strands.strandStart), count, seed);
  const cards = buildCards(strands, clusters);
  return {
    geometry: cardGeometry(cards, tileRect),
    atlas: drawCardAtlas(strands, cards, clusters),
    cards: cards.count,
  };
}

export function* writeCardsGlb(
  strands: ExportStrands,
  input: ExportInput,
  progress: Progress,
): Generator<Uint8Array> {
  const count = input.cards ?? DEFAULT_CARD_COUNT;
  const problem = cardCountProblem(count);
  if (problem) throw new Error(problem);
  const hasHair = strands.strandStart.length > 1;
  const made = hasHair ? makeHairCards(strands, count, input.session.growth.seed) : null;
  progress.at(0.6);
  const head = input.head && input.head.indices.length >= 3 ? input.head : null;

  const parts: Uint8Array[] = [];
  const views: object[] = [];
  const accessors: object[] = [];
  const meshes: object[] = [];
  const nodes: { name: string; mesh?: number; children?: number[]; scale?: number[] }[] = [
    { name: 'hairsketch', scale: [METERS_PER_UNIT, METERS_PER_UNIT, METERS_PER_UNIT] },
  ];
  let offset = 0;
  const view = (bytes: Uint8Array, target?: number): number => {
    views.push({
      buffer: 0,
      byteOffset: offset,
      byteLength: bytes.length,
      ...(target ? { target } : {}),
    });
    parts.push(bytes);
    const pad = (4 - (bytes.length % 4)) % 4;
    if (pad) parts.push(new Uint8Array(pad));
    offset += bytes.length + pad;
    return views.length - 1;
  };
  const le = (a: Float32Array | Uint32Array) => {
    const out = new Uint8Array(4 * a.length);
    const dv = new DataView(out.buffer);
    if (a instanceof Float32Array)
      for (let i = 0; i < a.length; i++) dv.setFloat32(4 * i, a[i], true);
    else for (let i = 0; i < a.length; i++) dv.setUint32(4 * i, a[i], true);
    return out;
  };
  const accessor = (a: object): number => {
    accessors.push(a);
    return accessors.length - 1;
  };

  const gltf: Record<string, unknown> = {
    asset: {
      version: '2.0',
      generator: 'hairsketch',
      extras: {
        hairsketch: {
          session: input.session,
          cards: { asked: count, made: made?.cards ?? 0, triangles: made?.geometry.triangles ?? 0 },
        },
      },
    },
    scene: 0,
    scenes: [{ name: 'hairsketch', nodes: [0] }],
    nodes,
  };

  if (made && made.geometry.triangles > 0) {
    const g = made.geometry;
    const vertices = g.positions.length / 3;
    const position = accessor({
      bufferView: view(le(g.positions), ARRAY_BUFFER),
      componentType: FLOAT,
      count: vertices,
      type: 'VEC3',
      ...bounds(g.positions),
    });
    const normal = accessor({
      bufferView: view(le(g.normals), ARRAY_BUFFER),
      componentType: FLOAT,
      count: vertices,
      type: 'VEC3',
    });
    const uv = accessor({
      bufferView: view(le(g.uvs), ARRAY_BUFFER),
      componentType: FLOAT,
      count: vertices,
      type: 'VEC2',
    });
    const indices = accessor({
      bufferView: view(le(g.indices), ELEMENT_ARRAY_BUFFER),
      componentType: UNSIGNED_INT,
      count: g.indices.length,
      type: 'SCALAR',
    });
    meshes.push({
      name: 'cards',
      primitives: [
        {
          mode: TRIANGLES,
          indices,
          material: 0,
          attributes: { POSITION: position, NORMAL: normal, TEXCOORD_0: uv },
        },
      ],
    });
    nodes.push({ name: 'cards', mesh: meshes.length - 1 });
    const a = made.atlas;
    const image = (name: string, png: Uint8Array) => ({
      name,
      mimeType: 'image/png',
      bufferView: view(png),
    });
    gltf.images = [
      image('hair colour', encodePng(a.size, a.size, 4, a.colour)),
      image('hair root-tip', encodePng(a.size, a.size, 1, a.rootTip)),
      image('hair depth', encodePng(a.size, a.size, 1, a.depth)),
    ];
    progress.at(0.9);
    gltf.samplers = [
      {
        magFilter: LINEAR,
        minFilter: LINEAR_MIPMAP_LINEAR,
        wrapS: CLAMP_TO_EDGE,
        wrapT: CLAMP_TO_EDGE,
      },
    ];
    gltf.textures = [
      { name: 'hair colour', source: 0, sampler: 0 },
      { name: 'hair root-tip', source: 1, sampler: 0 },
      { name: 'hair depth', source: 2, sampler: 0 },
    ];
    gltf.materials = [
      {
        name: 'hair cards',
        pbrMetallicRoughness: {
          baseColorTexture: { index: 0 },
          metallicFactor: 0,
          roughnessFactor: 0.6,
        },
        alphaMode: 'MASK',
        alphaCutoff: 0.5,
        doubleSided: true,
        extras: {
          rootTipTexture: 1,
          depthTexture: 2,
          depthRange: Number((DEPTH_RANGE * METERS_PER_UNIT).toPrecision(6)), // metres
          atlas: { size: ATLAS_SIZE, tiles: ATLAS_TILES },
        },
      },
    ];
  }
  if (head) {
    const attributes: Record<string, number> = {
      POSITION: accessor({
        bufferView: view(le(head.positions), ARRAY_BUFFER),
        componentType: FLOAT,
        count: head.positions.length / 3,
        type: 'VEC3',
        ...bounds(head.positions),
      }),
    };
    if (head.normals)
      attributes.NORMAL = accessor({
        bufferView: view(le(head.normals), ARRAY_BUFFER),
        componentType: FLOAT,
        count: head.normals.length / 3,
        type: 'VEC3',
      });
    const tris = Math.floor(head.indices.length / 3);
    const indices = accessor({
      bufferView: view(le(head.indices.subarray(0, 3 * tris)), ELEMENT_ARRAY_BUFFER),
      componentType: UNSIGNED_INT,
      count: 3 * tris,
      type: 'SCALAR',
    });
    meshes.push({ name: 'head', primitives: [{ mode: TRIANGLES, indices, attributes }] });
    nodes.push({ name: 'head', mesh: meshes.length - 1 });
  }
  const band = exportBand(input);
  if (band) {
    const { positions, normals, indices } = band.mesh;
    const vec3 = (a: Float32Array) => ({
      bufferView: view(le(a), ARRAY_BUFFER),
      componentType: FLOAT,
      count: a.length / 3,
      type: 'VEC3',
    });
    const attributes = {
      POSITION: accessor({ ...vec3(positions), ...bounds(positions) }),
      NORMAL: accessor(vec3(normals)),
    };
    const index = accessor({
      bufferView: view(le(indices), ELEMENT_ARRAY_BUFFER),
      componentType: UNSIGNED_INT,
      count: indices.length,
      type: 'SCALAR',
    });
    const materials = (gltf.materials as object[] | undefined) ?? [];
    materials.push({
      name: 'band',
      pbrMetallicRoughness: {
        baseColorFactor: [...band.linear, 1],
        metallicFactor: 0,
        roughnessFactor: BAND_ROUGHNESS,
      },
    });
    gltf.materials = materials;
    meshes.push({
      name: 'band',
      primitives: [{ mode: TRIANGLES, indices: index, attributes, material: materials.length - 1 }],
    });
    nodes.push({ name: 'band', mesh: meshes.length - 1 });
  }
  if (nodes.length > 1) nodes[0].children = nodes.slice(1).map((_, i) => i + 1);
  if (meshes.length > 0) {
    gltf.meshes = meshes;
    gltf.accessors = accessors;
    gltf.bufferViews = views;
    gltf.buffers = [{ byteLength: offset }];
  }

  // every part is padded to 4 bytes (view()), so the BIN chunk needs no padding of its own
  const out = new BinarySink();
  writeGlbStart(out, gltf, offset);
  if (offset > 0) {
    for (const p of parts) {
      out.raw(p);
      yield* out.drain();
    }
  }
  yield* out.end();
  progress.at(1);
}
