// Session version 3: a loaded head (HeadRef), scalp brush strokes and a mirror plane.
// A session file embeds the head file and reads back the same session and the same bytes
// (checked by their SHA-256, computed here with node:crypto); a link carries the head's
// reference, the strokes and the plane and reopens the same session; version 2 sessions and
// links open unchanged on the built-in head; every new field is refused by name when wrong; an
// export of a session on a loaded head still carries the session.
import { createHash } from 'node:crypto';
import { deflateRawSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { readExportedSession } from '../../web/export/readExport';
import { writeExport } from '../../web/export/writeExport';
import { Head } from '../../web/head/head';
import { quantizeSession } from '../../web/model/quantize';
import type { HeadRef, ScalpStroke, SessionState } from '../../web/model/session';
import {
  SESSION_LIMITS as L,
  MAX_HEAD_FILE_BYTES,
  parseSession,
  readSessionFile,
  writeSessionFile,
} from '../../web/model/sessionFile';
import { decodeSessionLink, encodeSessionLink, packSession } from '../../web/model/sessionLink';
import { SESSION_MIGRATIONS, SESSION_VERSION } from '../../web/model/sessionMigrations';
import type { Vec3 } from '../../web/model/vec3';

const head = Head.builtin();
const base = presetSession('default', head, '25k', 0);

/** Pseudo-random bytes (a fixed LCG: the same bytes every run). */
function bytesOf(n: number, seed = 7): Uint8Array {
  const b = new Uint8Array(n);
  let x = seed >>> 0;
  for (let i = 0; i < n; i++) {
    x = (Math.imul(x, 1664525) + 1013904223) >>> 0;
    b[i] = x >>> 24;
  }
  return b;
}

/** A head file's text: compressible, as a real OBJ is. */
const objText = (n: number) =>
  Array.from({ length: n }, (_, i) => `v ${i * 0.5} ${(i * 7) % 13} ${-i}`).join('\n');
const FILE = new TextEncoder().encode(objText(4000));
const sha256 = (b: Uint8Array) => createHash('sha256').update(b).digest('hex');
const buf = (b: Uint8Array) => b.slice().buffer as ArrayBuffer;

const REF: HeadRef = {
  kind: 'mesh',
  name: 'my head.obj',
  hash: sha256(FILE),
  format: 'obj',
  up: 'z',
  turns: [
    { axis: 'x', quarterTurns: 3 },
    { axis: 'y', quarterTurns: 1 },
  ],
};

/** Points along an arc over the head (world units), as a brush leaves them. */
function arc(n: number, phase: number): Vec3[] {
  return Array.from({ length: n }, (_, i) => {
    const t = phase + (i / Math.max(1, n - 1)) * 1.2;
    return [0.93 * Math.sin(t), 0.2 + 0.93 * Math.cos(t), -0.3 + 0.01 * i] as Vec3;
  });
}

const STROKES: ScalpStroke[] = [
  { erase: false, radius: 0.12, points: arc(40, -0.6) },
  { erase: true, radius: 0.05, points: [[0.1, 0.95, -0.2]] },
  { erase: false, radius: 2, points: arc(3, 0.4) },
];
const PLANE = { normal: [0.9986295347545738, 0.05233595624294383, 0] as Vec3, offset: 0.0123 };

/** A session on a loaded head with strokes and a plane, on the grid (as the editor keeps it). */
const loaded: SessionState = quantizeSession({
  ...base,
  head: REF,
  scalpPaint: STROKES,
  symmetry: PLANE,
});

function read(v: unknown): SessionState {
  const r = parseSession(v);
  if (!r.ok) throw new Error(r.error);
  return r.value;
}

describe('session files with the head', () => {
  it('embed the head file and read back the same session and the same bytes', async () => {
    const text = await writeSessionFile(loaded, {
      headBytes: buf(FILE),
      camera: base.curves[0].viewpoint,
    });
    const json = JSON.parse(text);
    expect(Object.keys(json).at(-1)).toBe('headFile');
    expect(json.headFile).toMatchObject({
      name: 'my head.obj',
      hash: REF.hash,
      encoding: 'deflate-base64',
    });
    // the data is the raw deflate of the file (inflated here by zlib)
    const { inflateRawSync } = await import('node:zlib');
    expect(new Uint8Array(inflateRawSync(Buffer.from(json.headFile.data, 'base64')))).toEqual(FILE);
    expect(json.headFile.data.length).toBeLessThan(FILE.length); // compressed
    const r = await readSessionFile(json);
    if (!r.ok) throw new Error(r.error);
    expect(r.value.session).toEqual(loaded);
    expect(r.value.headFile?.name).toBe('my head.obj');
    expect(r.value.headFile?.hash).toBe(REF.hash);
    const back = new Uint8Array(r.value.headFile?.bytes ?? new ArrayBuffer(0));
    expect(back).toEqual(FILE);
    expect(sha256(back)).toBe(REF.hash);
    // written again from what was read: the same file
    const again = await writeSessionFile(r.value.session, {
      headBytes: r.value.headFile?.bytes,
      camera: base.curves[0].viewpoint,
    });
    expect(again).toBe(text);
  });

  it('incompressible bytes round-trip too', async () => {
    const bin = bytesOf(100_003);
    const s = { ...loaded, head: { ...REF, name: 'h.glb', format: 'glb', hash: sha256(bin) } };
    const r = await readSessionFile(
      JSON.parse(await writeSessionFile(s as SessionState, { headBytes: buf(bin) })),
    );
    expect(r.ok && new Uint8Array(r.value.headFile?.bytes ?? [])).toEqual(bin);
  });

  it('a session on a loaded head without its file reads fine (the app asks for the head)', async () => {
    const text = await writeSessionFile(loaded);
    expect(JSON.parse(text)).not.toHaveProperty('headFile');
    const r = await readSessionFile(JSON.parse(text));
    expect(r).toEqual({ ok: true, value: { session: loaded } });
    // and parseSession ignores an embedded file (it is beside the session, not in it)
    const withFile = JSON.parse(await writeSessionFile(loaded, { headBytes: buf(FILE) }));
    expect(read(withFile)).toEqual(loaded);
  });

  it('the built-in head: no head file, whatever bytes are given', async () => {
    const text = await writeSessionFile(base, { headBytes: buf(FILE) });
    expect(text).toBe(JSON.stringify(base));
  });

  it('the writer refuses bytes that are not the head', async () => {
    await expect(writeSessionFile(loaded, { headBytes: buf(bytesOf(10)) })).rejects.toThrow(
      /SHA-256 .* is not the session head's/,
    );
  });

  describe('the reader refuses a bad head file, naming the field', () => {
    const good = async () => JSON.parse(await writeSessionFile(loaded, { headBytes: buf(FILE) }));
    const errorOf = async (edit: (j: Record<string, Record<string, unknown>>) => void) => {
      const j = await good();
      edit(j);
      const r = await readSessionFile(j);
      return r.ok ? 'accepted' : r.error;
    };

    it('fields', async () => {
      expect(await errorOf(() => {})).toBe('accepted');
      expect(await errorOf((j) => (j.headFile.extra = 1))).toBe(
        'session.headFile.extra: is not a field hairsketch knows',
      );
      expect(await errorOf((j) => (j.headFile = 'x' as never))).toBe(
        'session.headFile: must be an object',
      );
      expect(await errorOf((j) => (j.headFile.encoding = 'gzip'))).toBe(
        'session.headFile.encoding: must be "deflate-base64"',
      );
      expect(await errorOf((j) => (j.headFile.hash = 'ABC'))).toBe(
        'session.headFile.hash: must be a SHA-256 as 64 lowercase hex digits',
      );
      expect(await errorOf((j) => (j.headFile.name = ''))).toBe(
        'session.headFile.name: must be a file name (1 to 255 characters)',
      );
      expect(await errorOf((j) => (j.headFile.data = 5))).toBe(
        'session.headFile.data: must be base64 text',
      );
      expect(await errorOf((j) => (j.headFile.data = 'a*b='))).toBe(
        'session.headFile.data: must be base64 text',
      );
    });

    it('against the session head', async () => {
      expect(await errorOf((j) => (j.head = 'builtin' as never))).toBe(
        'session.headFile: the session is on the built-in head (session.head), so it carries no head file',
      );
      const other = sha256(bytesOf(3));
      expect(await errorOf((j) => (j.headFile.hash = other))).toBe(
        `session.headFile.hash: must be the hash of the session's head (session.head.hash ${REF.hash})`,
      );
      expect(await errorOf((j) => (j.headFile.name = 'other.obj'))).toBe(
        `session.headFile.name: must be the name of the session's head (session.head.name "my head.obj")`,
      );
    });

    it('data that is damaged, not the hashed bytes, or a deflate bomb', async () => {
      expect(await errorOf((j) => (j.headFile.data = 'AAAAAAAA'))).toBe(
        'session.headFile.data: does not inflate (damaged deflate data)',
      );
      const forged = deflateRawSync(bytesOf(500)).toString('base64');
      expect(await errorOf((j) => (j.headFile.data = forged))).toMatch(
        /^session\.headFile\.hash: does not match the data \(the SHA-256 of the data is [0-9a-f]{64}\): the file is damaged$/,
      );
      // a stream that inflates past the cap is refused while inflating
      const bomb = deflateRawSync(Buffer.alloc(MAX_HEAD_FILE_BYTES + 1), { level: 9 });
      expect(bomb.length).toBeLessThan(1 << 20);
      const t0 = performance.now();
      expect(await errorOf((j) => (j.headFile.data = bomb.toString('base64')))).toBe(
        'session.headFile.data: inflates to more than 256 MiB (the cap)',
      );
      console.log(
        `head file deflate bomb (${bomb.length} bytes → 256 MiB + 1): refused in ${(performance.now() - t0).toFixed(0)} ms`,
      );
    });
  });
});

describe('links with a head, scalp strokes and a mirror plane', () => {
  it('reopen the same session (the strokes on the position grid, the plane exact)', async () => {
    const r = await decodeSessionLink(`#${await encodeSessionLink(loaded)}`);
    if (!r.ok) throw new Error(r.error);
    expect(r.value).toEqual(loaded);
    expect(r.value.symmetry?.normal).toEqual(PLANE.normal); // already unit: kept bit for bit
    // and each part alone
    for (const part of [
      { head: REF },
      { scalpPaint: STROKES },
      { symmetry: PLANE },
      { head: { ...REF, turns: [], up: 'y' as const, format: 'stl' as const } },
      { head: { ...REF, name: 'tête 😀.obj' } },
    ]) {
      const s = quantizeSession({ ...base, ...part });
      const back = await decodeSessionLink(`#${await encodeSessionLink(s)}`);
      expect(back.ok && back.value).toEqual(s);
    }
  });

  it('carry no mesh, and the strokes compactly; without them a link is what it was', async () => {
    // without the fields added since version 2 (the head, strokes, plane; natural fall, sections,
    // finished edges, the bust, the colour model, hair detail and its locks)
    const {
      fall: _fall,
      sections: _sections,
      finish: _finish,
      bust: _bust,
      hairLook: _look,
      detail: _detail,
      locks: _locks,
      ...v2Fields
    } = base;
    const plain = packSession(v2Fields);
    const withHead = packSession({ ...v2Fields, head: REF });
    // the mask, 32 hash bytes, the name, format, up, the turns
    expect(withHead.length - plain.length).toBe(1 + 32 + 1 + REF.name.length + 2 + 1 + 2);
    // with version 3 fields absent, the body ends as a version 2 body did: the avoid slot (0),
    // the tail length (0) and the CRC
    expect(Array.from(plain.subarray(plain.length - 6, plain.length - 4))).toEqual([0, 0]);
    const many = quantizeSession({
      ...base,
      scalpPaint: Array.from({ length: 20 }, (_, i) => ({
        erase: i % 3 === 0,
        radius: 0.08,
        points: arc(50, i * 0.1),
      })),
    });
    const link = await encodeSessionLink(many);
    const baseLink = await encodeSessionLink(base);
    console.log(
      `default preset link ${baseLink.length + 1} characters; with 20 strokes of 50 points ${link.length + 1}`,
    );
    expect(link.length - baseLink.length).toBeLessThan(20 * 50 * 3);
    expect((await decodeSessionLink(`#${link}`)).ok).toBe(true);
  });

  it('a head reference the reader refuses is refused in a link too', async () => {
    const bad = { ...base, head: { ...REF, name: 'a\nb.obj' } };
    const r = await decodeSessionLink(`#${await encodeSessionLink(bad)}`);
    expect(r).toEqual({
      ok: false,
      error:
        'the session link is invalid: session.head.name: must be a file name without control characters',
    });
    const far = { ...base, symmetry: { normal: [0, 0, 2] as Vec3, offset: 0 } };
    const f = await decodeSessionLink(`#${await encodeSessionLink(far)}`);
    expect(f.ok ? 'accepted' : f.error).toMatch(/session\.symmetry\.normal: must be a unit vector/);
  });
});

describe('quantizeSession: strokes and the plane', () => {
  it('strokes on the position grid, the plane a unit normal and an offset on the grid', () => {
    const s = quantizeSession({
      ...base,
      scalpPaint: [{ erase: false, radius: 0.123456, points: [[0.100004, 0.99996, -0.2000001]] }],
      symmetry: { normal: [2, 0, -0], offset: 0.0123456 },
    });
    expect(s.scalpPaint).toEqual([{ erase: false, radius: 0.1235, points: [[0.1, 1, -0.2]] }]);
    expect(s.symmetry).toEqual({ normal: [1, 0, 0], offset: 0.0123 });
    expect(Object.is(s.symmetry?.normal[2], -0)).toBe(false);
    // on the grid already: the very same objects
    expect(quantizeSession(s)).toBe(s);
    expect(quantizeSession(loaded)).toBe(loaded);
  });
});

describe('v2-to-v3: version 2 sessions are on the built-in head', () => {
  const v2 = JSON.parse(JSON.stringify({ ...base, version: 2 }));

  it('a version 2 session opens as version 3 on the built-in head, nothing else changed', () => {
    const r = read(v2);
    expect(r.version).toBe(SESSION_VERSION);
    expect(r).toEqual(base);
    const { head: _h, ...noHead } = v2;
    expect(read(noHead)).toEqual(base);
  });

  it('the step is pure, names itself and gives version 3', () => {
    const step = SESSION_MIGRATIONS.find((m) => m.from === 2);
    expect(step?.name).toMatch(/^v2-to-v3: /);
    if (!step) return;
    const input = Object.freeze(JSON.parse('{"version": 2, "curves": []}'));
    const out = step.migrate(input);
    expect(input).toEqual({ version: 2, curves: [] });
    expect(out).toEqual({ version: 3, curves: [], head: 'builtin' });
  });
});

describe('the reader checks every new field', () => {
  const json = JSON.stringify(loaded);
  // biome-ignore lint/suspicious/noExplicitAny: edits arbitrary JSON to break it
  const errorOf = (edit: (j: any) => void) => {
    const j = JSON.parse(json);
    edit(j);
    const r = parseSession(j);
    return r.ok ? 'accepted' : r.error;
  };

  it('accepts the session, in a canonical form', () => {
    expect(errorOf(() => {})).toBe('accepted');
    expect(read(JSON.parse(json))).toEqual(loaded);
    // absent turns are none; an empty scalpPaint is none
    const { turns: _t, ...noTurns } = REF;
    expect(read({ ...JSON.parse(json), head: noTurns }).head).toEqual({ ...REF, turns: [] });
    expect(read({ ...JSON.parse(json), scalpPaint: [] })).not.toHaveProperty('scalpPaint');
  });

  it('head', () => {
    expect(errorOf((j) => (j.head = 7))).toBe(
      'session.head: must be "builtin" or a head mesh ({"kind": "mesh", "name", "hash", …})',
    );
    expect(errorOf((j) => (j.head.kind = 'sdf'))).toBe('session.head.kind: must be "mesh"');
    expect(errorOf((j) => (j.head.size = 1))).toBe(
      'session.head.size: is not a field hairsketch knows',
    );
    expect(errorOf((j) => (j.head.hash = REF.hash.toUpperCase()))).toBe(
      'session.head.hash: must be a SHA-256 as 64 lowercase hex digits',
    );
    expect(errorOf((j) => (j.head.hash = REF.hash.slice(1)))).toBe(
      'session.head.hash: must be a SHA-256 as 64 lowercase hex digits',
    );
    expect(errorOf((j) => delete j.head.hash)).toBe(
      'session.head.hash: must be a SHA-256 as 64 lowercase hex digits',
    );
    expect(errorOf((j) => (j.head.name = 'x'.repeat(256)))).toBe(
      'session.head.name: must be a file name (1 to 255 characters)',
    );
    expect(errorOf((j) => (j.head.name = 'x'.repeat(255)))).toBe('accepted');
    expect(errorOf((j) => (j.head.name = 'a\u0000.obj'))).toBe(
      'session.head.name: must be a file name without control characters',
    );
    expect(errorOf((j) => (j.head.name = 'a\ud800.obj'))).toBe(
      'session.head.name: must be a file name in well-formed Unicode (a lone surrogate)',
    );
    expect(errorOf((j) => (j.head.name = '\udc00a.obj'))).toBe(
      'session.head.name: must be a file name in well-formed Unicode (a lone surrogate)',
    );
    expect(errorOf((j) => (j.head.name = 'tête 😀.obj'))).toBe('accepted');
    expect(errorOf((j) => (j.head.format = 'fbx'))).toBe(
      'session.head.format: must be one of "obj", "gltf", "glb", "ply", "stl"',
    );
    expect(errorOf((j) => (j.head.up = 'x'))).toBe('session.head.up: must be "y" or "z"');
    expect(errorOf((j) => (j.head.turns = {}))).toBe(
      'session.head.turns: must be an array of turns',
    );
    expect(errorOf((j) => (j.head.turns[1].axis = 'w'))).toBe(
      'session.head.turns[1].axis: must be "x", "y" or "z"',
    );
    expect(errorOf((j) => (j.head.turns[0].quarterTurns = 4))).toBe(
      'session.head.turns[0].quarterTurns: must be between 0 and 3',
    );
    expect(errorOf((j) => (j.head.turns[0].quarterTurns = 1.5))).toBe(
      'session.head.turns[0].quarterTurns: must be a whole number (between 0 and 3)',
    );
    expect(
      errorOf((j) => (j.head.turns = Array(L.maxTurns + 1).fill({ axis: 'x', quarterTurns: 1 }))),
    ).toBe(`session.head.turns: has ${L.maxTurns + 1} turns, more than ${L.maxTurns} (the cap)`);
  });

  it('scalpPaint', () => {
    expect(errorOf((j) => (j.scalpPaint = {}))).toBe(
      'session.scalpPaint: must be an array of scalp strokes',
    );
    expect(errorOf((j) => (j.scalpPaint[1].erase = 'yes'))).toBe(
      'session.scalpPaint[1].erase: must be true or false',
    );
    expect(errorOf((j) => (j.scalpPaint[1].colour = 1))).toBe(
      'session.scalpPaint[1].colour: is not a field hairsketch knows',
    );
    expect(errorOf((j) => (j.scalpPaint[0].radius = 0))).toBe(
      'session.scalpPaint[0].radius: must be greater than 0 (at least 0.00005, at most 2)',
    );
    expect(errorOf((j) => (j.scalpPaint[0].radius = 2.0001))).toBe(
      'session.scalpPaint[0].radius: must be between 0 and 2',
    );
    expect(errorOf((j) => (j.scalpPaint[0].radius = -1))).toBe(
      'session.scalpPaint[0].radius: must be between 0 and 2',
    );
    expect(errorOf((j) => (j.scalpPaint[0].radius = null))).toBe(
      'session.scalpPaint[0].radius: must be a finite number',
    );
    expect(errorOf((j) => (j.scalpPaint[2].points = []))).toBe(
      'session.scalpPaint[2].points: needs at least 1 point',
    );
    expect(errorOf((j) => (j.scalpPaint[0].points[3][1] = 'NaN'))).toBe(
      'session.scalpPaint[0].points[3][1]: must be a finite number',
    );
    expect(errorOf((j) => (j.scalpPaint[0].points[3] = [0, 1e3, 0]))).toMatch(
      /^session\.scalpPaint\[0\]\.points\[3\]: must be within the bounding volume \(±25\)/,
    );
  });

  it('scalpPaint caps: strokes, and points of all strokes together', () => {
    const dab = { erase: false, radius: 0.1, points: [[0, 1, 0]] };
    expect(errorOf((j) => (j.scalpPaint = Array(L.maxStrokes).fill(dab)))).toBe('accepted');
    expect(errorOf((j) => (j.scalpPaint = Array(L.maxStrokes + 1).fill(dab)))).toBe(
      `session.scalpPaint: has ${L.maxStrokes + 1} strokes, more than ${L.maxStrokes} (the cap)`,
    );
    const long = (n: number) => ({ erase: false, radius: 0.1, points: Array(n).fill([0, 1, 0]) });
    // one stroke may hold them all (they are not curve points: no 5,000-point polyline cap)
    expect(errorOf((j) => (j.scalpPaint = [long(L.maxStrokePoints)]))).toBe('accepted');
    expect(
      errorOf(
        (j) => (j.scalpPaint = [long(L.maxStrokePoints / 2), long(L.maxStrokePoints / 2 + 1)]),
      ),
    ).toBe(
      `session.scalpPaint[1].points: brings the scalp strokes over ${L.maxStrokePoints} points in all (the cap)`,
    );
    expect(errorOf((j) => (j.scalpPaint = [long(L.maxStrokePoints + 1)]))).toBe(
      `session.scalpPaint[0].points: has ${L.maxStrokePoints + 1} points, more than ${L.maxStrokePoints} (the cap)`,
    );
  });

  it('symmetry', () => {
    expect(errorOf((j) => (j.symmetry = [1, 0, 0]))).toBe('session.symmetry: must be an object');
    expect(errorOf((j) => (j.symmetry.normal = [1, 0]))).toBe(
      'session.symmetry.normal: must be [x, y, z]',
    );
    expect(errorOf((j) => (j.symmetry.normal = [1.01, 0, 0]))).toBe(
      'session.symmetry.normal: must be a unit vector (its length is 1.01, must be 1 ± 0.001)',
    );
    expect(errorOf((j) => (j.symmetry.normal = [0, 0, 0]))).toMatch(
      /^session\.symmetry\.normal: must be a unit vector/,
    );
    expect(errorOf((j) => (j.symmetry.offset = 11))).toBe(
      'session.symmetry.offset: must be between -10 and 10',
    );
    expect(errorOf((j) => delete j.symmetry.offset)).toBe(
      'session.symmetry.offset: must be a finite number',
    );
    expect(errorOf((j) => (j.symmetry.tilt = 0))).toBe(
      'session.symmetry.tilt: is not a field hairsketch knows',
    );
    // a normal within the tolerance is made a unit vector, once and for all
    const s = read({ ...JSON.parse(json), symmetry: { normal: [1.0005, 0, -0], offset: 0 } });
    expect(s.symmetry).toEqual({ normal: [1, 0, 0], offset: 0 });
    const tilted = read({ ...JSON.parse(json), symmetry: { normal: [0.6, 0.8004, 0], offset: 0 } });
    const n = tilted.symmetry?.normal ?? [0, 0, 0];
    expect(Math.abs(Math.hypot(...n) - 1)).toBeLessThan(1e-15);
    expect(read(JSON.parse(JSON.stringify(tilted)))).toEqual(tilted);
  });
});

describe('exports of a session on a loaded head', () => {
  it('carry the session (not the head file) and read back', () => {
    const strands = {
      points: new Float32Array([0, 1, 0, 0, 0.9, 0.1]),
      strandStart: new Uint32Array([0, 2]),
    };
    for (const format of ['usda', 'glb'] as const) {
      const chunks = [...writeExport(format, { strands, session: loaded, head: null })];
      const bytes = new Uint8Array(chunks.reduce((n, c) => n + c.length, 0));
      let at = 0;
      for (const c of chunks) {
        bytes.set(c, at);
        at += c.length;
      }
      const r = readExportedSession(bytes);
      if (!r?.ok) throw new Error(`${format}: ${r ? r.error : 'no session'}`);
      expect(read(r.session)).toEqual(loaded);
    }
  });
});
