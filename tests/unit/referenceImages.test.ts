// Reference pictures (web/model/referenceImage.ts): the picture checks before any decoder runs
// (format, size in pixels, a PNG's chunks against Node's zlib CRC-32), the session field through
// the reader, a saved file (the picture embedded, checked by hash), a link (named by hash) and
// the editor (one undoable edit that asks for no solve).
import { createHash } from 'node:crypto';
import { describe, expect, it } from 'vitest';
import { Editor } from '../../web/editor/editor';
import { nearestView, type ReferenceImage, viewFade } from '../../web/model/referenceImage';
import { emptySession, type SessionState } from '../../web/model/session';
import { parseSession, readSessionFile, writeSessionFile } from '../../web/model/sessionFile';
import { decodeSessionLink, encodeSessionLink } from '../../web/model/sessionLink';
import { needsSolve } from '../../web/model/sessionSchema';
import { checkPictureFile, crc32 } from '../../web/reference/pictureFile';
import { jpegHeader, pngFile, pngHeaderOnly, webpHeader } from '../support/pictureFiles';

const sha = (b: Uint8Array) => createHash('sha256').update(b).digest('hex');
const bytesOf = (b: Buffer) => new Uint8Array(b.buffer, b.byteOffset, b.byteLength);

const red = pngFile(40, 60, () => [220, 20, 60]);
const green = pngFile(30, 30, (x) => (x < 15 ? [0, 200, 0] : [0, 100, 0]));

function picture(over: Partial<ReferenceImage> = {}): ReferenceImage {
  return {
    name: 'front.png',
    hash: sha(red),
    format: 'png',
    width: 40,
    height: 60,
    view: 'front',
    opacity: 0.6,
    scale: 3.2,
    offset: [0, 0],
    ...over,
  };
}

function withPictures(refs: ReferenceImage[]): SessionState {
  return { ...emptySession('25k'), references: refs };
}

describe('picture files', () => {
  it('computes the CRC-32 PNG uses (the standard check value)', () => {
    expect(crc32(new TextEncoder().encode('123456789'))).toBe(0xcbf43926);
  });

  it('reads the format and size of a PNG, a JPEG and a WebP from their headers', () => {
    expect(checkPictureFile(bytesOf(red))).toEqual({
      ok: true,
      value: { format: 'png', width: 40, height: 60 },
    });
    expect(checkPictureFile(bytesOf(jpegHeader(1024, 768)))).toEqual({
      ok: true,
      value: { format: 'jpeg', width: 1024, height: 768 },
    });
    expect(checkPictureFile(bytesOf(webpHeader(300, 200)))).toEqual({
      ok: true,
      value: { format: 'webp', width: 300, height: 200 },
    });
  });

  it('refuses what is not a picture, a picture over 50 megapixels and a damaged PNG', () => {
    const no = (b: Buffer) => {
      const r = checkPictureFile(bytesOf(b));
      if (r.ok) throw new Error('accepted');
      expect(r.error).not.toContain('\n');
      return r.error;
    };
    expect(no(Buffer.from('hello, not a picture'))).toBe('it is not a PNG, JPEG or WebP picture');
    // 50,000,000 pixels open; one row more does not
    expect(checkPictureFile(bytesOf(pngHeaderOnly(10_000, 5_000))).ok).toBe(true);
    expect(no(pngHeaderOnly(10_000, 5_001))).toContain('more than the 50 megapixels');
    expect(no(jpegHeader(9000, 6000))).toContain('54.0 megapixels');
    const flipped = Buffer.from(red);
    flipped[60] ^= 0xff; // inside IDAT
    expect(no(flipped)).toBe('it is a damaged PNG: its "IDAT" chunk fails its checksum');
    expect(no(red.subarray(0, red.length - 12))).toBe(
      'it is a damaged PNG: it ends before its IEND chunk',
    );
    expect(no(red.subarray(0, 50))).toContain('runs past the end of the file');
  });
});

describe('session.references', () => {
  it('reads back what it wrote, from JSON and from a link', async () => {
    const s = withPictures([
      picture(),
      picture({
        name: 'side.png',
        hash: sha(green),
        width: 30,
        height: 30,
        view: 'side',
        hidden: true,
        offset: [0.25, -0.5],
      }),
    ]);
    const r = parseSession(JSON.parse(JSON.stringify(s)));
    if (!r.ok) throw new Error(r.error);
    expect(r.value).toEqual(s);
    const link = await encodeSessionLink(r.value);
    const back = await decodeSessionLink(link);
    if (!back.ok) throw new Error(back.error);
    expect(back.value.references).toEqual(s.references);
    // the link names the pictures by hash: their bytes are not in it
    expect(link.length).toBeLessThan(1000);
  });

  it('refuses a bad picture entry, naming the field', () => {
    const bad = (over: Partial<ReferenceImage> | Record<string, unknown>) => {
      const r = parseSession(withPictures([{ ...picture(), ...over } as ReferenceImage]));
      return r.ok ? 'accepted' : r.error;
    };
    expect(bad({ view: 'top' })).toBe(
      'session.references[0].view: must be one of "front", "side", "back"',
    );
    expect(bad({ opacity: 1.5 })).toBe('session.references[0].opacity: must be between 0 and 1');
    expect(bad({ hash: 'abc' })).toBe(
      'session.references[0].hash: must be a SHA-256 as 64 lowercase hex digits',
    );
    expect(bad({ width: 10_000, height: 5_001 })).toBe(
      'session.references[0].height: 10000 × 5001 is more than 50 megapixels (the cap)',
    );
    expect(bad({ format: 'gif' })).toContain('session.references[0].format');
    expect(bad({ url: 'https://example.com/a.png' })).toBe(
      'session.references[0].url: is not a field hairsketch knows',
    );
    const twice = parseSession(withPictures([picture(), picture({ name: 'again.png' })]));
    expect(twice.ok ? '' : twice.error).toBe(
      'session.references[1].hash: names the same picture file as an earlier picture',
    );
    const nine = Array.from({ length: 9 }, (_, i) =>
      picture({ hash: i.toString(16).padStart(64, '0') }),
    );
    const many = parseSession(withPictures(nine));
    expect(many.ok ? '' : many.error).toBe(
      'session.references: has more than 8 pictures (the cap)',
    );
  });

  it('a saved file embeds each picture, checked by its SHA-256', async () => {
    const s = withPictures([
      picture(),
      picture({ name: 'side.png', hash: sha(green), view: 'side' }),
    ]);
    const pictureBytes = new Map([
      [sha(red), bytesOf(red).slice().buffer],
      [sha(green), bytesOf(green).slice().buffer],
    ]);
    const text = await writeSessionFile(s, { pictureBytes });
    const r = await readSessionFile(JSON.parse(text));
    if (!r.ok) throw new Error(r.error);
    expect(r.value.session).toEqual(s);
    expect(r.value.pictureFiles?.map((p) => p.name)).toEqual(['front.png', 'side.png']);
    for (const p of r.value.pictureFiles ?? []) expect(sha(new Uint8Array(p.bytes))).toBe(p.hash);
    expect(Buffer.from(r.value.pictureFiles?.[0].bytes ?? new ArrayBuffer(0)).equals(red)).toBe(
      true,
    );

    const data = JSON.parse(text);
    data.pictureFiles[1].data = data.pictureFiles[0].data;
    const damaged = await readSessionFile(data);
    expect(damaged.ok ? '' : damaged.error).toMatch(
      /^session\.pictureFiles\[1\]\.hash: does not match the data/,
    );
    const foreign = JSON.parse(text);
    foreign.references = [foreign.references[0]];
    const f = await readSessionFile(foreign);
    expect(f.ok ? '' : f.error).toBe(
      'session.pictureFiles: has 2 files for 1 pictures (session.references)',
    );
  });
});

describe('placing pictures', () => {
  it('is one undoable edit that asks for no solve, its numbers on their grids', () => {
    const editor = new Editor(emptySession('25k'));
    const before = editor.session;
    editor.run({
      kind: 'setReferences',
      references: [picture({ opacity: 0.123456, offset: [0.123456, -0.5] })],
      what: 'Placed',
    });
    const placed = editor.session.references?.[0];
    expect(placed?.opacity).toBe(0.123);
    expect(placed?.offset).toEqual([0.1235, -0.5]);
    expect(needsSolve(before, editor.session)).toBe(false);
    editor.undo();
    expect(editor.session).toBe(before);
    expect(editor.session.references).toBeUndefined();
  });

  it('places for the nearest named view and fades away from it', () => {
    expect(nearestView([0.3, 0.1, 1])).toBe('front');
    expect(nearestView([1, 0.1, -0.2])).toBe('side');
    expect(nearestView([0.2, 0.1, -1])).toBe('back');
    expect(viewFade('front', [0, 0, 1])).toBe(1);
    const at = (deg: number) =>
      viewFade('front', [Math.sin((deg * Math.PI) / 180), 0, Math.cos((deg * Math.PI) / 180)]);
    expect(at(10)).toBe(1);
    // halfway in cosine between 15° and 40°: cos 30° = 0.8660 ≈ (cos 15° + cos 40°) / 2
    expect(at(30)).toBeCloseTo(0.5, 2);
    expect(at(45)).toBe(0);
    expect(viewFade('side', [0, 0, 1])).toBe(0);
  });
});
