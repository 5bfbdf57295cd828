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
// The file's texture coordinates, when it has them, stay with the triangles as corner UVs
// (HeadMesh.cornerUvs; the USD export's root UVs). Parts are turned outward, normals are area-weighted, the default scalp is the built-in
// hairline region seen from the centre (outermost triangles only), and the signed distance takes
// its sign from a ray-voting inside test that tolerates holes and separate parts (meshInside.ts).
// Nothing here throws at the caller: every failure is a one-line message.
// The formats are read in headFileFormats.ts and sceneTriangles.ts, the placement is
// headPlacement.ts.
import * as THREE from 'three';
import type { Axis, HeadFormat } from '../model/session';
import type { Vec3 } from '../model/vec3';
import { vertexNormals } from './buildHead';
import type { GltfResources } from './gltfPack';
import { Head, type HeadMesh } from './head';
import { HeadFileError } from './headFileError';
import { detectFormat, parse } from './headFileFormats';
import { bounds, extents, guessUnit, type HeadUnit, place, rotateQuarter } from './headPlacement';
import { type MeshInside, meshInside } from './meshInside';
import { markScalpTriangles } from './scalpRegion';
import { collectTriangles } from './sceneTriangles';
import { type IndexedTriangles, orientPartsOutward, weldByPosition } from './weldMesh';

/** A loader's own message, cut to one short line without anything taken from the file: long
 *  runs of letters and digits (encoded data) and quoted text are left out. */
export function loaderReason(e: unknown): string {
  const text = String(e instanceof Error ? e.message : e).split('\n')[0];
  const plain = text
    .replace(/data:\S*/g, '…')
    .replace(/["'`“][^"'`”]*["'`”]/g, '…')
    .replace(/[A-Za-z0-9+/=_-]{40,}/g, '…')
    .slice(0, 120)
    .trim();
  return plain || 'the reader refused it';
}
export { BUILTIN_CRANIUM, type HeadUnit } from './headPlacement';

/** The most triangles a loaded head may have (a bound on the memory and time of loading). */
export const MAX_HEAD_TRIANGLES = 2_000_000;

export interface LoadHeadOptions {
  /** Triangle cap (default MAX_HEAD_TRIANGLES); injectable for tests. */
  maxTriangles?: number;
  /** Which file axis is up; 'auto' (default) guesses. */
  up?: 'auto' | 'y' | 'z';
  /** Files picked together with a .gltf (its .bin), by name. */
  resources?: GltfResources;
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
  const cornerUvs = loaded.mesh.cornerUvs?.slice();
  const t0 = performance.now();
  const unitScale = loaded.unit === 'unknown' ? null : 1;
  const { scale } = place(positions, unitScale);
  return finish(
    { positions, indices, cornerUvs },
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
  const root = await parse(format, bytes, maxTriangles, options.resources);
  const soup = collectTriangles(root, maxTriangles, format === 'gltf' || format === 'glb');
  const t1 = performance.now();
  const welded = weldByPosition(soup.positions, soup.indices, soup.uvs);
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
  const { unit, unitScale } = guessUnit(longest);

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
    { positions, indices: welded.indices, cornerUvs: welded.cornerUvs },
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
    ...(m.cornerUvs ? { cornerUvs: m.cornerUvs } : {}),
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

function oneLine(name: string, e: unknown): string {
  const why = e instanceof HeadFileError ? e.message : `it could not be read (${loaderReason(e)})`;
  return `Cannot open ${name}: ${why.replace(/\s+/g, ' ').trim()}`;
}
