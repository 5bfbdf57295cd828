// Heads exported by Blender's own glTF exporter at test time (tests/support/blenderGltf.ts: a
// skull and neck with a textured material, as "glTF Separate" and "glTF Embedded") open through
// the app's loader as the mesh Blender held: its triangle count, and its extent on each axis in
// metres (glTF is Y up) times the app's 10 per metre; the unit is found to be metres. The
// embedded file is decoded in code: the loader never fetches (the page's CSP would refuse a
// data: URI). The separate .gltf alone is refused naming its .bin; picked with its .bin and
// texture it opens.
import { afterEach, beforeAll, describe, expect, it, vi } from 'vitest';
import { headFromPicked, type PickedFile } from '../../web/head/headFiles';
import { type LoadedHead, loadHeadFile } from '../../web/head/loadHead';
import { type BlenderHeads, blenderHeads } from '../support/blenderGltf';

const buf = (b: Buffer): ArrayBuffer => new Uint8Array(b).buffer as ArrayBuffer;

let heads: BlenderHeads;
beforeAll(async () => {
  heads = await blenderHeads();
  console.log(
    `Blender ${heads.blender} exported ${heads.triangles} triangles as ${[...heads.files.separate, ...heads.files.embedded].join(', ')} in ${Math.round(heads.ms)} ms`,
  );
}, 120_000);

afterEach(() => {
  vi.unstubAllGlobals();
});

/** The mesh Blender held: same triangles, same extents (metres × 10 app units), in metres. */
function expectBlenderHead(h: LoadedHead): void {
  expect(h.mesh.indices.length / 3).toBe(heads.triangles);
  expect(h.unit).toBe('m');
  expect(h.scale).toBe(10);
  expect(h.up).toBe('y');
  expect(h.parts).toBe(2); // the skull and the neck, as joined in Blender
  for (let a = 0; a < 3; a++)
    expect(h.mesh.bounds.max[a] - h.mesh.bounds.min[a]).toBeCloseTo(
      10 * (heads.max[a] - heads.min[a]),
      4,
    );
}

describe('glTF heads exported by Blender', () => {
  it('"glTF Embedded": the buffer (texture included) as a data: URI, opened without a fetch', async () => {
    expect(heads.files.embedded).toEqual(['Embedded.gltf']);
    const bytes = heads.read('Embedded.gltf');
    const json = JSON.parse(bytes.toString('utf8'));
    expect(json.asset.generator).toMatch(/Blender/);
    expect(json.buffers.map((b: { uri: string }) => b.uri.slice(0, 37))).toEqual([
      'data:application/octet-stream;base64,',
    ]);
    // Blender keeps the texture in the buffer, not as a URI of its own: a PNG in a buffer view
    const image = json.images[0];
    expect(image).toMatchObject({ mimeType: 'image/png' });
    expect(image.uri).toBeUndefined();
    const data = Buffer.from(json.buffers[0].uri.split(',')[1], 'base64');
    const view = json.bufferViews[image.bufferView];
    expect([...data.subarray(view.byteOffset, view.byteOffset + 8)]).toEqual([
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a,
    ]);
    // as in a page (three's loader reads `self`), so that only the fetch stands in its way
    vi.stubGlobal('self', globalThis);
    const fetched: string[] = [];
    vi.stubGlobal('fetch', (input: unknown) => {
      fetched.push((input instanceof Request ? input.url : String(input)).slice(0, 40));
      return Promise.reject(new Error('no fetch in a head load'));
    });
    const r = await loadHeadFile('Embedded.gltf', buf(bytes));
    expect(fetched).toEqual([]);
    if (!r.ok) throw new Error(r.error);
    expectBlenderHead(r.head);
    expect(r.head.message).toMatch(/in m\b/);
  });

  it('"glTF Separate": alone it names its .bin; picked with its .bin and texture it opens', async () => {
    expect(heads.files.separate).toEqual(['Head.bin', 'Head.gltf', 'skin.png']);
    const json = JSON.parse(heads.read('Head.gltf').toString('utf8'));
    expect(json.buffers.map((b: { uri: string }) => b.uri)).toEqual(['Head.bin']);
    expect(json.images.map((i: { uri: string }) => i.uri)).toEqual(['skin.png']);

    const alone = await loadHeadFile('Head.gltf', buf(heads.read('Head.gltf')));
    expect(alone.ok).toBe(false);
    if (!alone.ok) expect(alone.error).toMatch(/\(“Head\.bin”\): pick the \.gltf together/);

    const picked: PickedFile[] = heads.files.separate.map((name) => ({
      name,
      bytes: buf(heads.read(name)),
    }));
    const h = headFromPicked(picked);
    if (!h.ok) throw new Error(h.error);
    expect(h.head.name).toBe('Head.gltf');
    const r = await loadHeadFile(h.head.name, h.head.bytes);
    if (!r.ok) throw new Error(r.error);
    expectBlenderHead(r.head);
  });
});
