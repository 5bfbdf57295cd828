// Head file formats: which format a file is (by name and first bytes), and reading it into a
// three.js scene with three.js's loaders, after checks that turn what the loaders would do with a
// bad or oversized file (cryptic messages, fetches, huge allocations) into a plain refusal. glTF
// goes through gltfPack.ts first (its buffers decoded here, never fetched).
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { PLYLoader } from 'three/examples/jsm/loaders/PLYLoader.js';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import type { HeadFormat } from '../model/session';
import { type GltfResources, selfContainedGlb } from './gltfPack';
import { capCheck, HeadFileError } from './headFileError';

export function detectFormat(name: string, bytes: ArrayBuffer): HeadFormat {
  const ext = /\.([a-z0-9]+)$/i.exec(name.trim())?.[1]?.toLowerCase() ?? '';
  const head = new Uint8Array(bytes, 0, Math.min(bytes.byteLength, 256));
  const text = String.fromCharCode(...head);
  if (text.startsWith('glTF')) return 'glb';
  if (ext === 'glb') throw new HeadFileError('not a GLB file (no glTF header)');
  if (ext === 'gltf') return 'gltf';
  if (ext === 'ply' || /^ply\r?\n/.test(text)) return 'ply';
  if (ext === 'stl') return 'stl';
  if (ext === 'obj') return 'obj';
  if (/^\s*\{/.test(text) && text.includes('"asset"')) return 'gltf';
  if (/^solid\s/.test(text) && text.includes('facet')) return 'stl';
  if (/^\s*(#|v |o |g |mtllib)/m.test(text)) return 'obj';
  throw new HeadFileError(
    `unsupported file type${ext ? ` .${ext}` : ''}: open an OBJ, glTF/GLB, PLY or STL file`,
  );
}

export async function parse(
  format: HeadFormat,
  bytes: ArrayBuffer,
  maxTriangles: number,
  /** Files picked with a .gltf (its .bin), by name. */
  resources?: GltfResources,
): Promise<THREE.Object3D> {
  switch (format) {
    case 'obj': {
      const text = new TextDecoder().decode(bytes);
      if (text.includes('\u0000')) throw new HeadFileError('not an OBJ file (binary data)');
      // cheap cap before the loader allocates: each face line is at least one triangle
      let faces = 0;
      for (let i = text.indexOf('\nf '); i >= 0; i = text.indexOf('\nf ', i + 3)) faces++;
      if (text.startsWith('f ')) faces++;
      capCheck(faces, maxTriangles);
      return new OBJLoader().parse(text);
    }
    case 'gltf':
    case 'glb': {
      // buffers decoded here, so the loader fetches nothing (gltfPack.ts)
      const glb = selfContainedGlb(format, bytes, resources);
      const gltf = await new GLTFLoader().parseAsync(glb, '');
      return gltf.scene;
    }
    case 'ply': {
      const faces = plyFaceCount(bytes);
      capCheck(faces, maxTriangles);
      const geometry = new PLYLoader().parse(bytes);
      return new THREE.Mesh(geometry);
    }
    case 'stl': {
      const text = new TextDecoder().decode(
        new Uint8Array(bytes, 0, Math.min(bytes.byteLength, 512)),
      );
      const n = bytes.byteLength >= 84 ? new DataView(bytes).getUint32(80, true) : -1;
      if (n >= 0 && 84 + 50 * n === bytes.byteLength) capCheck(n, maxTriangles);
      else if (!/^\s*solid/.test(text) && !(n >= 0 && 84 + 50 * n <= bytes.byteLength))
        throw new HeadFileError('not a readable STL file (truncated, or not STL)');
      const geometry = new STLLoader().parse(bytes);
      return new THREE.Mesh(geometry);
    }
  }
}

function plyFaceCount(bytes: ArrayBuffer): number {
  const head = new TextDecoder().decode(new Uint8Array(bytes, 0, Math.min(bytes.byteLength, 4096)));
  if (!/^ply\r?\n/.test(head)) throw new HeadFileError('not a PLY file (no "ply" header)');
  const end = head.indexOf('end_header');
  if (end < 0) throw new HeadFileError('not a readable PLY file (its header has no end)');
  const m = /element\s+face\s+(\d+)/.exec(head.slice(0, end));
  const faces = m ? Number(m[1]) : 0;
  if (faces === 0) throw new HeadFileError('it has no faces (a point cloud, not a mesh)');
  return faces;
}
