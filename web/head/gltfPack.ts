// A glTF head as one self-contained GLB for three.js's loader, whatever form it came in: a .gltf
// with its buffers embedded as data: URIs (as many exporters write it), a .gltf whose .bin the
// user picked with it, or a GLB. Buffers are decoded here, never fetched (the page's CSP allows
// the loader no data: or blob: fetch, and a fetch would reach beyond the files given), and are
// joined into the GLB's one binary chunk. Images, textures, samplers and materials are dropped:
// the app draws a head with its own material, so a head's textures are accepted and unused.
import { HeadFileError } from './headFileError';

/** Files picked together with a .gltf, by file name. */
export type GltfResources = ReadonlyMap<string, ArrayBuffer>;

interface GltfJson {
  buffers?: { uri?: unknown; byteLength?: unknown }[];
  bufferViews?: { buffer?: unknown; byteOffset?: unknown }[];
  meshes?: { primitives?: { material?: unknown; extensions?: Record<string, unknown> }[] }[];
  extensionsRequired?: unknown[];
  extensionsUsed?: unknown[];
  extensions?: Record<string, unknown>;
  [key: string]: unknown;
}

const GLB_MAGIC = 0x46546c67; // "glTF"
const JSON_CHUNK = 0x4e4f534a; // "JSON"
const BIN_CHUNK = 0x004e4942; // "BIN\0"

/** Extensions about looks only (materials, textures, lights): dropped with the materials. */
const LOOKS = /^(KHR_materials_|KHR_texture_|EXT_texture_|KHR_lights_|MSFT_texture_)/;

/** `bytes` (a .gltf's JSON or a GLB) as a GLB with one binary chunk, no URIs and no materials;
 *  `resources` are the files picked with it (a .gltf's .bin). One-sentence HeadFileError when
 *  it cannot be. */
export function selfContainedGlb(
  format: 'gltf' | 'glb',
  bytes: ArrayBuffer,
  resources: GltfResources = new Map(),
): ArrayBuffer {
  const { text, bin } = format === 'glb' ? glbChunks(bytes) : { text: utf8(bytes), bin: null };
  let json: GltfJson;
  try {
    json = JSON.parse(text);
  } catch {
    throw new HeadFileError('not a readable glTF file (bad JSON)');
  }
  if (typeof json !== 'object' || json === null || Array.isArray(json))
    throw new HeadFileError('not a readable glTF file');
  const compressed = (Array.isArray(json.extensionsRequired) ? json.extensionsRequired : []).filter(
    (e) => e === 'KHR_draco_mesh_compression' || e === 'EXT_meshopt_compression',
  );
  if (compressed.length > 0)
    throw new HeadFileError(`it is compressed with ${compressed.join(', ')}: save it uncompressed`);
  const buffers = Array.isArray(json.buffers) ? json.buffers : [];
  const data = buffers.map((b, i) => bufferBytes(b, i, bin, resources));

  // one binary chunk: each buffer at a 4-byte aligned offset, the views moved with it
  const offsets: number[] = [];
  let total = 0;
  for (const d of data) {
    offsets.push(total);
    total += Math.ceil(d.byteLength / 4) * 4;
  }
  const joined = new Uint8Array(total);
  for (let i = 0; i < data.length; i++) joined.set(data[i], offsets[i]);
  const views = Array.isArray(json.bufferViews) ? json.bufferViews : [];
  for (const v of views) {
    const b = v?.buffer;
    if (typeof b !== 'number' || !Number.isInteger(b) || b < 0 || b >= data.length)
      throw new HeadFileError('not a readable glTF file (a buffer view names no buffer)');
    v.buffer = 0;
    v.byteOffset = offsets[b] + (typeof v.byteOffset === 'number' ? v.byteOffset : 0);
  }
  const out: GltfJson = { ...json, buffers: total > 0 ? [{ byteLength: total }] : [] };
  for (const k of ['images', 'textures', 'samplers', 'materials']) delete out[k];
  for (const m of Array.isArray(json.meshes) ? json.meshes : [])
    for (const p of Array.isArray(m?.primitives) ? m.primitives : []) {
      if (!p || typeof p !== 'object') continue;
      delete p.material;
      if (p.extensions && typeof p.extensions === 'object')
        for (const k of Object.keys(p.extensions)) if (LOOKS.test(k)) delete p.extensions[k];
    }
  for (const k of ['extensionsRequired', 'extensionsUsed'] as const)
    if (Array.isArray(json[k]))
      out[k] = (json[k] as unknown[]).filter((e) => typeof e === 'string' && !LOOKS.test(e));
  if (json.extensions && typeof json.extensions === 'object') {
    const kept = Object.fromEntries(
      Object.entries(json.extensions).filter(([k]) => !LOOKS.test(k)),
    );
    out.extensions = kept;
  }
  return writeGlb(JSON.stringify(out), joined);
}

/** A buffer's bytes: the GLB's binary chunk, an embedded data: URI, or a file picked with it. */
function bufferBytes(
  b: { uri?: unknown; byteLength?: unknown },
  index: number,
  bin: Uint8Array | null,
  resources: GltfResources,
): Uint8Array {
  const length = typeof b?.byteLength === 'number' ? b.byteLength : Number.NaN;
  if (!(Number.isInteger(length) && length >= 0))
    throw new HeadFileError('not a readable glTF file (a buffer has no length)');
  let bytes: Uint8Array;
  if (b.uri === undefined) {
    if (index !== 0 || !bin)
      throw new HeadFileError('not a readable glTF file (a buffer has no data)');
    bytes = bin;
  } else if (typeof b.uri !== 'string') {
    throw new HeadFileError('not a readable glTF file (a buffer URI is not text)');
  } else if (b.uri.startsWith('data:')) {
    const decoded = decodeDataUri(b.uri);
    if (!decoded) throw new HeadFileError('one of its embedded buffers is not valid data');
    bytes = decoded;
  } else {
    const file = findResource(b.uri, resources);
    if (!file)
      throw new HeadFileError(
        `it keeps its data in a separate file (${fileLabel(b.uri)}): pick the .gltf together with it, or save as .glb`,
      );
    bytes = new Uint8Array(file);
  }
  if (bytes.byteLength < length)
    throw new HeadFileError('not a readable glTF file (a buffer is shorter than it says)');
  return bytes.subarray(0, length);
}

/** A data: URI's bytes (base64 or percent-encoded); null when it is not one. */
export function decodeDataUri(uri: string): Uint8Array | null {
  const comma = uri.indexOf(',');
  if (!uri.startsWith('data:') || comma < 0) return null;
  const meta = uri.slice(5, comma);
  const body = uri.slice(comma + 1);
  if (/;base64$/i.test(meta)) {
    const clean = body.replace(/\s+/g, '');
    if (!/^[A-Za-z0-9+/]*={0,2}$/.test(clean) || clean.length % 4 === 1) return null;
    try {
      const s = atob(clean);
      const out = new Uint8Array(s.length);
      for (let i = 0; i < s.length; i++) out[i] = s.charCodeAt(i);
      return out;
    } catch {
      return null;
    }
  }
  const out: number[] = [];
  for (let i = 0; i < body.length; i++) {
    if (body[i] === '%') {
      const h = Number.parseInt(body.slice(i + 1, i + 3), 16);
      if (!/^[0-9a-f]{2}$/i.test(body.slice(i + 1, i + 3))) return null;
      out.push(h);
      i += 2;
    } else out.push(...new TextEncoder().encode(body[i]));
  }
  return Uint8Array.from(out);
}

/** The picked file a relative URI names (its last path part, URI-decoded; letter case
 *  ignored when nothing matches exactly). */
function findResource(uri: string, resources: GltfResources): ArrayBuffer | null {
  let name = uri.split(/[?#]/)[0].split('/').pop() ?? '';
  try {
    name = decodeURIComponent(name);
  } catch {
    // a name with a stray %: as written
  }
  const exact = resources.get(name);
  if (exact) return exact;
  for (const [k, v] of resources) if (k.toLowerCase() === name.toLowerCase()) return v;
  return null;
}

/** A file name from the file, as the message may show it: short, plain characters only. */
function fileLabel(uri: string): string {
  const name = uri.split(/[?#]/)[0].split('/').pop() ?? '';
  return /^[\w .()+-]{1,60}$/.test(name) ? `“${name}”` : 'a file it names';
}

function utf8(bytes: ArrayBuffer | Uint8Array): string {
  return new TextDecoder().decode(bytes);
}

function glbChunks(bytes: ArrayBuffer): { text: string; bin: Uint8Array | null } {
  const view = new DataView(bytes);
  if (bytes.byteLength < 20 || view.getUint32(0, true) !== GLB_MAGIC)
    throw new HeadFileError('not a readable GLB file (truncated)');
  const jsonLength = view.getUint32(12, true);
  if (view.getUint32(16, true) !== JSON_CHUNK || 20 + jsonLength > bytes.byteLength)
    throw new HeadFileError('not a readable GLB file (bad JSON chunk)');
  const text = utf8(new Uint8Array(bytes, 20, jsonLength));
  let bin: Uint8Array | null = null;
  const at = 20 + jsonLength;
  if (at + 8 <= bytes.byteLength && view.getUint32(at + 4, true) === BIN_CHUNK) {
    const length = view.getUint32(at, true);
    if (at + 8 + length > bytes.byteLength)
      throw new HeadFileError('not a readable GLB file (truncated binary chunk)');
    bin = new Uint8Array(bytes, at + 8, length);
  }
  return { text, bin };
}

function writeGlb(jsonText: string, bin: Uint8Array): ArrayBuffer {
  const json = new TextEncoder().encode(jsonText);
  const jsonLength = Math.ceil(json.length / 4) * 4;
  const binLength = Math.ceil(bin.length / 4) * 4;
  const total = 12 + 8 + jsonLength + (binLength > 0 ? 8 + binLength : 0);
  const out = new ArrayBuffer(total);
  const view = new DataView(out);
  const bytes = new Uint8Array(out);
  view.setUint32(0, GLB_MAGIC, true);
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, JSON_CHUNK, true);
  bytes.fill(0x20, 20, 20 + jsonLength);
  bytes.set(json, 20);
  if (binLength > 0) {
    const at = 20 + jsonLength;
    view.setUint32(at, binLength, true);
    view.setUint32(at + 4, BIN_CHUNK, true);
    bytes.set(bin, at + 8);
  }
  return out;
}
