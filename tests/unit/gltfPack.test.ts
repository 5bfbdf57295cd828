// glTF heads as other tools write them (tests/support/gltfHead.ts, Blender's layout): a .gltf
// with data: URI buffers, and a .gltf picked with its .bin (one or two buffer files), open as the
// same head as the same mesh written as OBJ (read by another loader); a .gltf without its .bin,
// bad embedded data and a loader's message holding file data are refused in one short sentence
// that never carries the file's content.
import { describe, expect, it } from 'vitest';
import { decodeDataUri, selfContainedGlb } from '../../web/head/gltfPack';
import { headFromPicked, type PickedFile } from '../../web/head/headFiles';
import { type LoadedHead, loaderReason, loadHeadFile } from '../../web/head/loadHead';
import { ellipsoidHead, toObj } from '../support/generatedHead';
import { blenderGltf, TINY_PNG } from '../support/gltfHead';

const soup = ellipsoidHead(24);
const triangles = soup.indices.length / 3;
const buf = (b: Uint8Array | string): ArrayBuffer => {
  const bytes = typeof b === 'string' ? new TextEncoder().encode(b) : b;
  return bytes.slice().buffer as ArrayBuffer;
};

async function load(name: string, bytes: ArrayBuffer): Promise<LoadedHead> {
  const r = await loadHeadFile(name, bytes);
  if (!r.ok) throw new Error(r.error);
  return r.head;
}

/** Same triangles, same placed bounds (to float precision) as the OBJ reference. */
function expectSameHead(a: LoadedHead, ref: LoadedHead): void {
  expect(a.mesh.indices.length / 3).toBe(triangles);
  expect(a.unit).toBe('m');
  for (const k of ['min', 'max'] as const)
    for (let i = 0; i < 3; i++) expect(a.mesh.bounds[k][i]).toBeCloseTo(ref.mesh.bounds[k][i], 4);
}

// the reference: the same mesh as an OBJ in metres, through three's OBJ loader
const metres = { positions: soup.positions.map((v) => v * 0.1), indices: soup.indices };
const ref = await load('head.obj', toObj(metres));

describe('glTF heads from other tools', () => {
  it('a .gltf with its buffers and texture as data: URIs opens', async () => {
    const { gltf, files } = blenderGltf(soup, 'Head', { embedded: true });
    expect(files.size).toBe(0);
    expect(gltf).toContain('data:application/octet-stream;base64,');
    expectSameHead(await load('Head.gltf', buf(gltf)), ref);
  });

  for (const split of [false, true])
    it(`a .gltf picked with its ${split ? 'two buffer files' : '.bin'} and texture opens`, async () => {
      const { gltf, files } = blenderGltf(soup, 'Head', { split });
      const picked: PickedFile[] = [
        { name: 'skin.png', bytes: buf(TINY_PNG) },
        { name: 'Head.gltf', bytes: buf(gltf) },
        ...[...files].map(([name, b]) => ({ name, bytes: buf(b) })),
      ];
      const h = headFromPicked(picked);
      if (!h.ok) throw new Error(h.error);
      expect(h.head.name).toBe('Head.gltf');
      // one self-contained GLB: a binary chunk, no URI left, no material
      const text = new TextDecoder().decode(h.head.bytes);
      expect(text.startsWith('glTF')).toBe(true);
      expect(text).not.toContain('"uri"');
      expect(text).not.toContain('"materials"');
      expectSameHead(await load(h.head.name, h.head.bytes), ref);
      // the same files give the same bytes (the head store names a head by their hash)
      const again = headFromPicked([...picked].reverse());
      expect(again.ok && Buffer.from(again.head.bytes).equals(Buffer.from(h.head.bytes))).toBe(
        true,
      );
    });

  it('a .gltf without its .bin, or with bad embedded data, is refused in one sentence', async () => {
    const { gltf } = blenderGltf(soup, 'Head');
    const alone = await loadHeadFile('Head.gltf', buf(gltf));
    expect(alone.ok).toBe(false);
    if (!alone.ok) {
      expect(alone.error).toMatch(/separate file \(“Head\.bin”\): pick the \.gltf together/);
      expect(alone.error).not.toMatch(/\n/);
    }
    const picked = headFromPicked([
      { name: 'Head.gltf', bytes: buf(gltf) },
      { name: 'other.bin', bytes: buf(new Uint8Array(8)) },
    ]);
    expect(picked.ok).toBe(false);
    if (!picked.ok) expect(picked.error).toMatch(/^Cannot open Head\.gltf: .*“Head\.bin”/);

    const embedded = blenderGltf(soup, 'Head', { embedded: true }).gltf;
    const blob = /data:application\/octet-stream;base64,([^"]+)/.exec(embedded)?.[1] ?? '';
    const broken = embedded.replace(blob, `${blob.slice(0, 100)}!!!${blob.slice(103)}`);
    const bad = await loadHeadFile('Head.gltf', buf(broken));
    expect(bad.ok).toBe(false);
    if (!bad.ok) {
      expect(bad.error).toBe(
        'Cannot open Head.gltf: one of its embedded buffers is not valid data',
      );
      expect(bad.error).not.toContain(blob.slice(0, 20));
    }
    const short = embedded.replace(blob, blob.slice(0, 400));
    const cut = await loadHeadFile('Head.gltf', buf(short));
    expect(cut.ok).toBe(false);
    if (!cut.ok) expect(cut.error).toMatch(/shorter than it says/);
  });

  it('picking two heads, or no head, says so', () => {
    const two = headFromPicked([
      { name: 'a.obj', bytes: buf('v 0 0 0') },
      { name: 'b.glb', bytes: buf('glTF') },
    ]);
    expect(two).toMatchObject({ ok: false, error: expect.stringMatching(/one head file/) });
    const none = headFromPicked([
      { name: 'a.bin', bytes: buf('x') },
      { name: 'b.png', bytes: buf(TINY_PNG) },
    ]);
    expect(none).toMatchObject({ ok: false, error: expect.stringMatching(/none of the files/) });
  });

  it('decodes data: URIs as RFC 2397 writes them', () => {
    expect([...(decodeDataUri('data:,A%20b') ?? [])]).toEqual([65, 32, 98]);
    expect([...(decodeDataUri('data:application/octet-stream;base64,AAEC/w==') ?? [])]).toEqual([
      0, 1, 2, 255,
    ]);
    expect(decodeDataUri('data:;base64,A$==')).toBeNull();
    expect(decodeDataUri('data:%zz')).toBeNull();
  });

  it('keeps a GLB as it is, but for the materials', async () => {
    const { gltf, files } = blenderGltf(soup, 'Head');
    const glb = selfContainedGlb(
      'gltf',
      buf(gltf),
      new Map([...files].map(([k, v]) => [k, buf(v)])),
    );
    // a GLB through it again: the same bytes
    expect(Buffer.from(selfContainedGlb('glb', glb)).equals(Buffer.from(glb))).toBe(true);
  });

  it("a loader's message loses the file's data before it is shown", () => {
    const said = loaderReason(
      new Error(
        `Failed to fetch "data:application/octet-stream;base64,${'QUJD'.repeat(40)}"\nmore`,
      ),
    );
    expect(said).not.toMatch(/QUJD|base64|\n/);
    expect(said.length).toBeLessThanOrEqual(120);
  });
});
