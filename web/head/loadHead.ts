// Loading a user's head mesh ("Open head"): OBJ, glTF/GLB, PLY or STL bytes are read
// with three.js's loaders, every mesh is merged (world transforms applied) into one welded,
// indexed triangle mesh, and the result is normalised the way the built-in head is placed:
//  - units: the longest extent tells mm, cm, dm (the app's own unit, 10 cm) or m (a head with or
//    without neck and shoulders is 12–60 cm); otherwise the head is scaled to the built-in
//    head's width and the message says so;
//  - orientation: Y up, face toward +z. glTF is Y-up by its spec; other files whose z extent is
//    clearly the longest are taken as Z-up (front toward -y, Blender's convention) and turned.
//    `rotateLoadedHead` turns by quarter turns about x, y or z for files in other conventions;
//  - position: the cranium (the top 10 cm of the head, scaled with the head's size) sits where
//    the built-in head's does, so the scalp-parameterisation centre is the origin.
// Parts are turned outward, normals are area-weighted, the default scalp is the built-in
// hairline region seen from the centre (outermost triangles only), and the signed distance takes
// its sign from a ray-voting inside test that tolerates holes and separate parts (meshInside.ts).
// Nothing here throws at the caller: every failure is a one-line message.
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { PLYLoader } from 'three/examples/jsm/loaders/PLYLoader.js';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import type { Vec3 } from '../model/vec3';
import { vertexNormals } from './buildHead';
import { Head, type HeadMesh } from './head';
import { type MeshInside, meshInside } from './meshInside';
import { markScalpTriangles } from './scalpRegion';
import { type IndexedTriangles, orientPartsOutward, weldByPosition } from './weldMesh';

export type HeadFormat = 'obj' | 'gltf' | 'glb' | 'ply' | 'stl';
export type HeadUnit = 'mm' | 'cm' | 'dm' | 'm' | 'unknown';
export type Axis = 'x' | 'y' | 'z';

/** The most triangles a loaded head may have (a bound on the memory and time of loading). */
export const MAX_HEAD_TRIANGLES = 2_000_000;

export interface LoadHeadOptions {
  /** Triangle cap (default MAX_HEAD_TRIANGLES); injectable for tests. */
  maxTriangles?: number;
  /** Which file axis is up; 'auto' (default) guesses. */
  up?: 'auto' | 'y' | 'z';
}

/** A loaded, normalised head, ready to become the app's head. */
export interface LoadedHead {
  /** The app's head (its signedDistance uses the robust inside test below). */
  head: Head;
  mesh: HeadMesh;
  name: string;
  format: HeadFormat;
  /** The unit the file was taken to be in ('unknown': scaled to the built-in head's width). */
  unit: HeadUnit;
  /** App units per file unit. */
  scale: number;
  /** The file's up axis as guessed or told. */
  up: 'y' | 'z';
  /** Quarter turns applied by rotateLoadedHead since loading. */
  turns: { axis: Axis; quarterTurns: number }[];
  /** Connected parts of the mesh, and how many were inside out (and were turned outward). */
  parts: number;
  flippedParts: number;
  /** One line for the status: what was loaded and what was guessed. */
  message: string;
  /** Milliseconds spent reading the file, welding and placing it, building the BVH (with
   *  normals), and marking the default scalp. */
  timings: { parseMs: number; normaliseMs: number; bvhMs: number; scalpMs: number };
  insideHead(p: Vec3): boolean;
  /** Distance to the mesh, negative inside (insideHead); beyond `maxDistance` ±maxDistance. */
  signedDistance(p: Vec3, maxDistance?: number): number;
}

export type LoadHeadResult = { ok: true; head: LoadedHead } | { ok: false; error: string };

// The built-in head's cranium (measured on buildHead(); a unit test keeps these in step): its
// top, and the x width and x/z centre of its vertices within BAND of the top.
export const BUILTIN_CRANIUM = {
  top: 0.9992,
  band: 1.0,
  width: 1.5765,
  centerX: 0.0008,
  centerZ: -0.0142,
} as const;

// A real head (with or without neck and shoulders) measures 12 to 60 cm along its longest side.
const HEAD_CM_MIN = 12;
const HEAD_CM_MAX = 60;
const UNITS: ReadonlyArray<{ unit: HeadUnit; cm: number }> = [
  { unit: 'mm', cm: 0.1 },
  { unit: 'cm', cm: 1 },
  { unit: 'dm', cm: 10 },
  { unit: 'm', cm: 100 },
];
const APP_UNIT_CM = 10;

class HeadFileError extends Error {}

/** Read and normalise a head file. Never throws: a bad file gives `{ ok: false, error }`. */
export async function loadHeadFile(
  name: string,
  bytes: ArrayBuffer,
  options: LoadHeadOptions = {},
): Promise<LoadHeadResult> {
  try {
    return { ok: true, head: await load(name, bytes, options) };
  } catch (e) {
    return { ok: false, error: oneLine(name, e) };
  }
}

/** The head turned by `quarterTurns` × 90° (counter-clockwise looking down the axis) about
 *  `axis`, then placed and scalp-marked again. */
export function rotateLoadedHead(loaded: LoadedHead, axis: Axis, quarterTurns: number): LoadedHead {
  const q = (((Math.round(quarterTurns) % 4) + 4) % 4) as 0 | 1 | 2 | 3;
  const positions = loaded.mesh.positions.slice();
  rotateQuarter(positions, axis, q);
  const indices = loaded.mesh.indices.slice();
  const t0 = performance.now();
  const unitScale = loaded.unit === 'unknown' ? null : 1;
  const { scale } = place(positions, unitScale);
  return finish(
    { positions, indices },
    {
      name: loaded.name,
      format: loaded.format,
      unit: loaded.unit,
      scale: loaded.scale * scale,
      up: loaded.up,
      turns: [...loaded.turns, { axis, quarterTurns: q }],
      parts: loaded.parts,
      flippedParts: loaded.flippedParts,
      message: `${loaded.name}: turned ${q * 90}° about ${axis}`,
      timings: { parseMs: 0, normaliseMs: performance.now() - t0, bvhMs: 0, scalpMs: 0 },
    },
  );
}

async function load(
  name: string,
  bytes: ArrayBuffer,
  options: LoadHeadOptions,
): Promise<LoadedHead> {
  const maxTriangles = options.maxTriangles ?? MAX_HEAD_TRIANGLES;
  if (!(bytes instanceof ArrayBuffer) || bytes.byteLength === 0)
    throw new HeadFileError('the file is empty');
  const t0 = performance.now();
  const format = detectFormat(name, bytes);
  const root = await parse(format, bytes, maxTriangles);
  const soup = collectTriangles(root, maxTriangles);
  const t1 = performance.now();
  const welded = weldByPosition(soup.positions, soup.indices);
  if (welded.indices.length === 0) throw new HeadFileError('its triangles all have zero size');
  const { parts, flipped } = orientPartsOutward(welded);

  // units from the longest extent (orientation does not change it)
  const ext = extents(welded.positions);
  const longest = Math.max(ext[0], ext[1], ext[2]);
  const shortest = Math.min(ext[0], ext[1], ext[2]);
  if (!(longest > 0) || !Number.isFinite(longest))
    throw new HeadFileError('it has no size (all vertices at one point)');
  if (shortest < 0.01 * longest)
    throw new HeadFileError('it is flat (a plane or a line), not a head');
  const guess = UNITS.find((u) => longest * u.cm >= HEAD_CM_MIN && longest * u.cm < HEAD_CM_MAX);
  const unit: HeadUnit = guess ? guess.unit : 'unknown';
  const unitScale = guess ? guess.cm / APP_UNIT_CM : null;

  // up axis: glTF is Y-up by its spec; otherwise Z-up when z is clearly the longest extent
  let up: 'y' | 'z' = 'y';
  if (options.up === 'y' || options.up === 'z') up = options.up;
  else if (format !== 'gltf' && format !== 'glb' && ext[2] > 1.1 * ext[1] && ext[2] >= ext[0])
    up = 'z';
  const positions = welded.positions;
  if (up === 'z') rotateQuarter(positions, 'x', 3); // (x, y, z) → (x, z, -y): front -y → +z

  const { scale } = place(positions, unitScale);
  const notes: string[] = [`${(welded.indices.length / 3).toLocaleString('en-US')} triangles`];
  notes.push(
    unit === 'unknown'
      ? "size not recognised as mm, cm or m: scaled to the built-in head's width"
      : `in ${unit}`,
  );
  if (up === 'z') notes.push('Z-up turned to Y-up');
  if (parts > 1) notes.push(`${parts} parts`);
  if (flipped > 0) notes.push(`${flipped} inside-out part${flipped > 1 ? 's' : ''} turned outward`);
  return finish(
    { positions, indices: welded.indices },
    {
      name,
      format,
      unit,
      scale,
      up,
      turns: [],
      parts,
      flippedParts: flipped,
      message: `${name}: ${notes.join(', ')}`,
      timings: { parseMs: t1 - t0, normaliseMs: performance.now() - t1, bvhMs: 0, scalpMs: 0 },
    },
  );
}

type Info = Omit<LoadedHead, 'head' | 'mesh' | 'insideHead' | 'signedDistance'>;

function finish(m: IndexedTriangles, info: Info): LoadedHead {
  const { positions, indices } = m;
  const t0 = performance.now();
  const normals = vertexNormals(positions, indices);
  const ext = bounds(positions);
  const center: Vec3 = [0, 0, 0];
  const mesh: HeadMesh = {
    positions,
    normals,
    indices,
    scalp: new Uint8Array(indices.length / 3),
    center,
    bounds: ext,
  };
  let inside: MeshInside | null = null;
  const signed = (x: number, y: number, z: number) =>
    (inside as MeshInside).signedDistance([x, y, z]);
  const head = new Head(mesh, signed);
  inside = meshInside(head.bvh, ext);
  const t1 = performance.now();
  mesh.scalp = markScalpTriangles({ positions, indices }, center);
  keepOutermostScalp(head);
  const probe = inside;
  return {
    ...info,
    timings: { ...info.timings, bvhMs: t1 - t0, scalpMs: performance.now() - t1 },
    head,
    mesh,
    insideHead: (p) => probe.inside(p),
    signedDistance: (p, maxDistance) => probe.signedDistance(p, maxDistance),
  };
}

/** Unmark scalp triangles that something else covers as seen from the centre (inner shells,
 *  the inside of a cap): the ray from just outside the centroid, away from the centre, must
 *  leave the head without another hit. */
function keepOutermostScalp(head: Head): void {
  const { positions: P, indices: I, scalp, center } = head.mesh;
  const ray = new THREE.Ray();
  const size = Math.max(...[0, 1, 2].map((a) => head.mesh.bounds.max[a] - head.mesh.bounds.min[a]));
  const eps = 1e-4 * size;
  for (let t = 0; t < scalp.length; t++) {
    if (!scalp[t]) continue;
    let cx = 0;
    let cy = 0;
    let cz = 0;
    for (let k = 0; k < 3; k++) {
      const v = 3 * I[3 * t + k];
      cx += P[v] / 3;
      cy += P[v + 1] / 3;
      cz += P[v + 2] / 3;
    }
    const dx = cx - center[0];
    const dy = cy - center[1];
    const dz = cz - center[2];
    const len = Math.hypot(dx, dy, dz);
    if (!(len > 0)) continue;
    ray.direction.set(dx / len, dy / len, dz / len);
    ray.origin.set(cx, cy, cz).addScaledVector(ray.direction, eps);
    if (head.bvh.raycastFirst(ray, THREE.DoubleSide)) scalp[t] = 0;
  }
}

// ---------------------------------------------------------------------------------------------
// Formats

function detectFormat(name: string, bytes: ArrayBuffer): HeadFormat {
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

async function parse(
  format: HeadFormat,
  bytes: ArrayBuffer,
  maxTriangles: number,
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
      if (format === 'gltf') checkGltfJson(new TextDecoder().decode(bytes));
      else checkGlb(bytes);
      const gltf = await new GLTFLoader().parseAsync(bytes, '');
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

function capCheck(triangles: number, maxTriangles: number): void {
  if (triangles > maxTriangles)
    throw new HeadFileError(
      `it has ${triangles.toLocaleString('en-US')} triangles, over the limit of ${maxTriangles.toLocaleString('en-US')}: decimate it first`,
    );
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

function checkGlb(bytes: ArrayBuffer): void {
  const view = new DataView(bytes);
  if (bytes.byteLength < 20) throw new HeadFileError('not a readable GLB file (truncated)');
  const jsonLength = view.getUint32(12, true);
  if (view.getUint32(16, true) !== 0x4e4f534a || 20 + jsonLength > bytes.byteLength)
    throw new HeadFileError('not a readable GLB file (bad JSON chunk)');
  checkGltfJson(new TextDecoder().decode(new Uint8Array(bytes, 20, jsonLength)));
}

/** glTF refusals the loader would give cryptic messages (or fetches) for. */
function checkGltfJson(text: string): void {
  let json: {
    buffers?: { uri?: string }[];
    extensionsRequired?: string[];
  };
  try {
    json = JSON.parse(text);
  } catch {
    throw new HeadFileError('not a readable glTF file (bad JSON)');
  }
  if (typeof json !== 'object' || json === null)
    throw new HeadFileError('not a readable glTF file');
  for (const b of json.buffers ?? [])
    if (typeof b.uri === 'string' && !b.uri.startsWith('data:'))
      throw new HeadFileError(
        `it refers to a separate file (${b.uri.slice(0, 60)}): save it as .glb`,
      );
  const unsupported = (json.extensionsRequired ?? []).filter(
    (e) => e === 'KHR_draco_mesh_compression' || e === 'EXT_meshopt_compression',
  );
  if (unsupported.length > 0)
    throw new HeadFileError(
      `it is compressed with ${unsupported.join(', ')}: save it uncompressed`,
    );
}

// ---------------------------------------------------------------------------------------------
// Geometry

/** Every mesh's triangles in world space, one vertex per source vertex (welding comes after). */
function collectTriangles(root: THREE.Object3D, maxTriangles: number): IndexedTriangles {
  root.updateMatrixWorld(true);
  const meshes: { geometry: THREE.BufferGeometry; matrices: THREE.Matrix4[] }[] = [];
  let triangles = 0;
  let vertices = 0;
  root.traverse((o) => {
    const mesh = o as THREE.Mesh;
    if (!mesh.isMesh || !mesh.geometry?.getAttribute('position')) return;
    const geometry = mesh.geometry;
    const position = geometry.getAttribute('position');
    const count = geometry.index ? geometry.index.count : position.count;
    const matrices: THREE.Matrix4[] = [];
    const instanced = o as THREE.InstancedMesh;
    if (instanced.isInstancedMesh) {
      for (let i = 0; i < instanced.count; i++) {
        const m = new THREE.Matrix4();
        instanced.getMatrixAt(i, m);
        matrices.push(m.premultiply(o.matrixWorld));
      }
    } else matrices.push(o.matrixWorld.clone());
    meshes.push({ geometry, matrices });
    triangles += Math.floor(count / 3) * matrices.length;
    vertices += position.count * matrices.length;
  });
  capCheck(triangles, maxTriangles);
  if (triangles === 0)
    throw new HeadFileError('it contains no triangles (not a mesh, or an empty one)');
  const positions = new Float32Array(3 * vertices);
  const indices = new Uint32Array(3 * triangles);
  let v0 = 0;
  let t = 0;
  const p = new THREE.Vector3();
  for (const { geometry, matrices } of meshes) {
    const position = geometry.getAttribute('position');
    const index = geometry.index;
    const count = Math.floor((index ? index.count : position.count) / 3) * 3;
    for (const matrix of matrices) {
      for (let v = 0; v < position.count; v++) {
        p.fromBufferAttribute(position, v).applyMatrix4(matrix);
        if (!Number.isFinite(p.x) || !Number.isFinite(p.y) || !Number.isFinite(p.z))
          throw new HeadFileError(`vertex ${v + 1} has a non-finite coordinate (NaN or infinity)`);
        positions[3 * (v0 + v)] = p.x;
        positions[3 * (v0 + v) + 1] = p.y;
        positions[3 * (v0 + v) + 2] = p.z;
      }
      const mirrored = matrix.determinant() < 0;
      for (let k = 0; k < count; k += 3) {
        const a = index ? index.getX(k) : k;
        let b = index ? index.getX(k + 1) : k + 1;
        let c = index ? index.getX(k + 2) : k + 2;
        if (mirrored) [b, c] = [c, b];
        if (a >= position.count || b >= position.count || c >= position.count)
          throw new HeadFileError('a triangle refers to a vertex that does not exist');
        indices[t++] = v0 + a;
        indices[t++] = v0 + b;
        indices[t++] = v0 + c;
      }
      v0 += position.count;
    }
  }
  return { positions, indices: indices.subarray(0, t) };
}

function extents(P: Float32Array): Vec3 {
  const b = bounds(P);
  return [b.max[0] - b.min[0], b.max[1] - b.min[1], b.max[2] - b.min[2]];
}

function bounds(P: Float32Array): { min: Vec3; max: Vec3 } {
  const min: Vec3 = [Infinity, Infinity, Infinity];
  const max: Vec3 = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < P.length; i += 3) {
    for (let a = 0; a < 3; a++) {
      const x = P[i + a];
      if (x < min[a]) min[a] = x;
      if (x > max[a]) max[a] = x;
    }
  }
  return { min, max };
}

/** Rotate positions in place by q quarter turns about the axis (right-handed). */
function rotateQuarter(P: Float32Array, axis: Axis, q: 0 | 1 | 2 | 3): void {
  if (q === 0) return;
  const [i, j] = axis === 'x' ? [1, 2] : axis === 'y' ? [2, 0] : [0, 1];
  for (let v = 0; v < P.length; v += 3) {
    const a = P[v + i];
    const b = P[v + j];
    if (q === 1) {
      P[v + i] = -b;
      P[v + j] = a;
    } else if (q === 2) {
      P[v + i] = -a;
      P[v + j] = -b;
    } else {
      P[v + i] = b;
      P[v + j] = -a;
    }
  }
}

/** Scale (by `unitScale`, or to the built-in head's cranium width when null) and translate the
 *  positions in place so the cranium sits where the built-in head's does. Returns the scale. */
function place(P: Float32Array, unitScale: number | null): { scale: number } {
  let scale = unitScale ?? 1;
  if (unitScale === null) {
    // no unit: first bring the longest side to the built-in head's height, then fit the width
    const e = extents(P);
    scale = 3.6 / Math.max(e[0], e[1], e[2]);
  }
  for (let i = 0; i < P.length; i++) P[i] *= scale;
  let cranium = craniumOf(P, 1);
  // the band is 10 cm on the built-in head: scale it with the head (two refinements)
  for (let k = 0; k < 2; k++)
    cranium = craniumOf(P, clampSize(cranium.width / BUILTIN_CRANIUM.width));
  if (unitScale === null) {
    const s = BUILTIN_CRANIUM.width / cranium.width;
    for (let i = 0; i < P.length; i++) P[i] *= s;
    scale *= s;
    cranium = craniumOf(P, 1);
  }
  const size = clampSize(cranium.width / BUILTIN_CRANIUM.width);
  const shift: Vec3 = [
    BUILTIN_CRANIUM.centerX * size - cranium.centerX,
    BUILTIN_CRANIUM.top * size - cranium.top,
    BUILTIN_CRANIUM.centerZ * size - cranium.centerZ,
  ];
  for (let i = 0; i < P.length; i += 3) {
    P[i] += shift[0];
    P[i + 1] += shift[1];
    P[i + 2] += shift[2];
  }
  return { scale };
}

const clampSize = (s: number) => Math.min(2, Math.max(0.5, Number.isFinite(s) ? s : 1));

/** Top, and x width and x/z centre of the vertices within `size` × BAND of the top. */
function craniumOf(P: Float32Array, size: number) {
  let top = -Infinity;
  for (let i = 1; i < P.length; i += 3) if (P[i] > top) top = P[i];
  const floor = top - BUILTIN_CRANIUM.band * size;
  let x0 = Infinity;
  let x1 = -Infinity;
  let z0 = Infinity;
  let z1 = -Infinity;
  for (let i = 0; i < P.length; i += 3) {
    if (P[i + 1] < floor) continue;
    if (P[i] < x0) x0 = P[i];
    if (P[i] > x1) x1 = P[i];
    if (P[i + 2] < z0) z0 = P[i + 2];
    if (P[i + 2] > z1) z1 = P[i + 2];
  }
  return { top, width: x1 - x0, centerX: (x0 + x1) / 2, centerZ: (z0 + z1) / 2 };
}

function oneLine(name: string, e: unknown): string {
  const why =
    e instanceof HeadFileError
      ? e.message
      : `it could not be read (${String(e instanceof Error ? e.message : e)
          .split('\n')[0]
          .slice(0, 160)})`;
  return `Cannot open ${name}: ${why.replace(/\s+/g, ' ').trim()}`;
}
