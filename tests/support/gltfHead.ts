// A head in the layout of Blender's glTF exporter ("glTF Separate": Head.gltf + Head.bin + its
// texture; embedded: one .gltf with the buffer and the image each as a data: URI, as several
// tools write it, where Blender 5.0 keeps the image inside the buffer): metres, Y up, a node with
// the mesh, POSITION / NORMAL / TEXCOORD_0 and unsigned-short indices, a material with a
// base-colour texture. Written by hand from the glTF 2.0 specification, for the loader's unit
// tests of variants and broken files; tests/support/blenderGltf.ts has Blender write real ones.
import type { Soup } from './generatedHead';

/** A 1 x 1 PNG (a texture the head does not need, as a real export carries one). */
export const TINY_PNG = Uint8Array.from(
  atob(
    'iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg==',
  ),
  (c) => c.charCodeAt(0),
);

export interface GltfFiles {
  /** The .gltf JSON text. */
  gltf: string;
  /** The buffer files it names (none when embedded), by name. */
  files: Map<string, Uint8Array>;
}

const pad4 = (n: number) => Math.ceil(n / 4) * 4;
const base64 = (b: Uint8Array) => Buffer.from(b).toString('base64');

/** `m` (app units, 10 cm) as Blender writes it. `split`: positions and indices in two buffer
 *  files (as some tools write them); `embedded`: data: URIs instead of files. */
export function blenderGltf(
  m: Soup,
  name: string,
  o: { embedded?: boolean; split?: boolean } = {},
): GltfFiles {
  if (m.positions.length / 3 > 65535) throw new Error('too many vertices for unsigned short');
  const P = m.positions.map((v) => v * 0.1); // metres
  const n = P.length / 3;
  const normals = new Float32Array(3 * n);
  const uv = new Float32Array(2 * n);
  for (let i = 0; i < n; i++) {
    const [x, y, z] = [P[3 * i], P[3 * i + 1], P[3 * i + 2]];
    const l = Math.hypot(x, y, z) || 1;
    normals.set([x / l, y / l, z / l], 3 * i);
    uv.set([0.5 + Math.atan2(x, z) / (2 * Math.PI), 0.5 + y], 2 * i);
  }
  const indices = Uint16Array.from(m.indices);
  const min = [0, 1, 2].map((a) => Math.min(...P.filter((_, i) => i % 3 === a)));
  const max = [0, 1, 2].map((a) => Math.max(...P.filter((_, i) => i % 3 === a)));
  const parts = [P, normals, uv, indices].map((a) => new Uint8Array(a.buffer, 0, a.byteLength));
  // one buffer (Blender), or vertex data and indices apart
  const groups = o.split ? [[0, 1, 2], [3]] : [[0, 1, 2, 3]];
  const bufferViews: Record<string, number>[] = [];
  const buffers: { byteLength: number; uri: string }[] = [];
  const files = new Map<string, Uint8Array>();
  groups.forEach((members, b) => {
    let at = 0;
    const chunks: Uint8Array[] = [];
    for (const k of members) {
      bufferViews[k] = {
        buffer: b,
        byteOffset: at,
        byteLength: parts[k].byteLength,
        target: k === 3 ? 34963 : 34962,
      };
      const padded = new Uint8Array(pad4(parts[k].byteLength));
      padded.set(parts[k]);
      chunks.push(padded);
      at += padded.byteLength;
    }
    const bytes = new Uint8Array(at);
    let w = 0;
    for (const c of chunks) {
      bytes.set(c, w);
      w += c.byteLength;
    }
    const file = groups.length > 1 ? `${name}_${b}.bin` : `${name}.bin`;
    const uri = o.embedded ? `data:application/octet-stream;base64,${base64(bytes)}` : file;
    if (!o.embedded) files.set(file, bytes);
    buffers.push({ byteLength: at, uri });
  });
  const image = o.embedded
    ? { mimeType: 'image/png', name: 'skin', uri: `data:image/png;base64,${base64(TINY_PNG)}` }
    : { mimeType: 'image/png', name: 'skin', uri: 'skin.png' };
  const json = {
    asset: { generator: 'Khronos glTF Blender I/O v4.2.69', version: '2.0' },
    scene: 0,
    scenes: [{ name: 'Scene', nodes: [0] }],
    nodes: [{ mesh: 0, name }],
    materials: [
      {
        name: 'Skin',
        pbrMetallicRoughness: { baseColorTexture: { index: 0 }, metallicFactor: 0 },
      },
    ],
    meshes: [
      {
        name,
        primitives: [
          { attributes: { POSITION: 0, NORMAL: 1, TEXCOORD_0: 2 }, indices: 3, material: 0 },
        ],
      },
    ],
    textures: [{ sampler: 0, source: 0 }],
    images: [image],
    accessors: [
      { bufferView: 0, componentType: 5126, count: n, max, min, type: 'VEC3' },
      { bufferView: 1, componentType: 5126, count: n, type: 'VEC3' },
      { bufferView: 2, componentType: 5126, count: n, type: 'VEC2' },
      { bufferView: 3, componentType: 5123, count: indices.length, type: 'SCALAR' },
    ],
    bufferViews,
    samplers: [{ magFilter: 9729, minFilter: 9987 }],
    buffers,
  };
  return { gltf: JSON.stringify(json, null, 2), files };
}
