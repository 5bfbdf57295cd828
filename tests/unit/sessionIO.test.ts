// Opening sessions in the app (web/app/sessionIO.ts) with a head store: a session file's embedded
// head is stored before the session is applied; a link, a file without its head or an export on
// a head the store lacks is applied and reported as `needsHead` (the status sentence names the
// head); a bad file or link changes nothing. "Save" embeds the stored head file. The editor is a
// stand-in that records the commands it is given.
import { createHash } from 'node:crypto';
import { describe, expect, it } from 'vitest';
import {
  needsHeadMessage,
  openSessionFile,
  openSessionFileOutcome,
  openSessionLink,
  openSessionLinkOutcome,
  sessionFileText,
} from '../../web/app/sessionIO';
import { presetSession } from '../../web/cli/presetSession';
import type { Editor } from '../../web/editor/editor';
import { writeExport } from '../../web/export/writeExport';
import { Head } from '../../web/head/head';
import { type HeadStore, memoryHeadStore, type StoredHead } from '../../web/head/headStore';
import { quantizeSession } from '../../web/model/quantize';
import type { HeadRef, SessionState } from '../../web/model/session';
import { readSessionFile, writeSessionFile } from '../../web/model/sessionFile';
import { encodeSessionLink } from '../../web/model/sessionLink';

const base = presetSession('default', Head.builtin(), '25k', 0);
const FILE = new TextEncoder().encode('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n'.repeat(50));
const REF: HeadRef = {
  kind: 'mesh',
  name: 'mine.obj',
  hash: createHash('sha256').update(FILE).digest('hex'),
  format: 'obj',
  up: 'y',
  turns: [],
};
const onHead: SessionState = quantizeSession({
  ...base,
  head: REF,
  scalpPaint: [{ erase: true, radius: 0.1, points: [[0, 1, 0]] }],
});
const camera = base.curves[0].viewpoint;

type Event = { put: string } | { run: string; session: SessionState; resetHistory: boolean };

/** A store and an editor that log what happens to them, in order. */
function harness(store: HeadStore = memoryHeadStore()) {
  const log: Event[] = [];
  const heads: HeadStore = {
    async put(h) {
      log.push({ put: h.hash });
      await store.put(h);
    },
    get: (hash) => store.get(hash),
  };
  const editor = {
    run(c: { kind: string; session: SessionState; resetHistory: boolean }) {
      log.push({ run: c.kind, session: c.session, resetHistory: c.resetHistory });
    },
  } as unknown as Editor;
  return { log, heads, editor, store };
}

const fileOf = (name: string, text: string) => new File([text], name);

describe('opening a session file', () => {
  it('stores the embedded head, then applies the session', async () => {
    const h = harness();
    const text = await writeSessionFile(onHead, {
      camera,
      headBytes: FILE.slice().buffer as ArrayBuffer,
    });
    const r = await openSessionFileOutcome(h.editor, fileOf('s.json', text), h.heads);
    expect(r).toEqual({ kind: 'opened', message: null });
    expect(h.log).toEqual([
      { put: REF.hash },
      { run: 'loadSession', session: onHead, resetHistory: false },
    ]);
    const stored = await h.store.get(REF.hash);
    expect(stored?.name).toBe('mine.obj');
    expect(new Uint8Array(stored?.bytes ?? [])).toEqual(FILE);
  });

  it('without its head, and the head not stored: applied, and the head is asked for', async () => {
    const h = harness();
    const r = await openSessionFileOutcome(
      h.editor,
      fileOf('s.json', await writeSessionFile(onHead)),
      h.heads,
    );
    expect(r).toEqual({
      kind: 'needsHead',
      needsHead: { name: 'mine.obj', hash: REF.hash },
      message: 'This session needs the head “mine.obj”; Open head to load it.',
    });
    expect(h.log).toEqual([{ run: 'loadSession', session: onHead, resetHistory: false }]);
    // the sentence-returning form says the same
    expect(
      await openSessionFile(h.editor, fileOf('s.json', await writeSessionFile(onHead)), h.heads),
    ).toBe(r.message);
  });

  it('without its head, the head stored: opened', async () => {
    const h = harness();
    await h.store.put({ hash: REF.hash, name: 'mine.obj', bytes: FILE.slice().buffer });
    const r = await openSessionFileOutcome(
      h.editor,
      fileOf('s.json', await writeSessionFile(onHead)),
      h.heads,
    );
    expect(r.kind).toBe('opened');
  });

  it('an export on a loaded head (it carries the session, never the head)', async () => {
    const h = harness();
    const strands = {
      points: new Float32Array([0, 1, 0, 0, 0.9, 0]),
      strandStart: new Uint32Array([0, 2]),
    };
    const chunks = [...writeExport('glb', { strands, session: onHead, head: null })];
    const r = await openSessionFileOutcome(
      h.editor,
      new File(chunks as BlobPart[], 'hair.glb'),
      h.heads,
    );
    expect(r.kind).toBe('needsHead');
    expect(h.log).toEqual([{ run: 'loadSession', session: onHead, resetHistory: false }]);
  });

  it('a bad head file changes nothing and stores nothing', async () => {
    const h = harness();
    const json = JSON.parse(
      await writeSessionFile(onHead, { headBytes: FILE.slice().buffer as ArrayBuffer }),
    );
    json.headFile.data = json.headFile.data.slice(0, -8);
    const r = await openSessionFileOutcome(
      h.editor,
      fileOf('cut.json', JSON.stringify(json)),
      h.heads,
    );
    expect(r.kind).toBe('failed');
    expect(r.message).toMatch(
      /^Could not open cut\.json: session\.headFile\.(data|hash): .*\. Nothing changed\.$/,
    );
    expect(h.log).toEqual([]);
  });

  it('the built-in head needs nothing; no store to ask: opened', async () => {
    const h = harness();
    const text = await writeSessionFile(base, { camera });
    expect(await openSessionFileOutcome(h.editor, fileOf('b.json', text), h.heads)).toEqual({
      kind: 'opened',
      message: null,
    });
    expect(
      await openSessionFile(h.editor, fileOf('s.json', await writeSessionFile(onHead))),
    ).toBeNull();
  });
});

describe('opening a link', () => {
  it('on a head the store lacks: applied (a new history), and the head is asked for', async () => {
    const h = harness();
    const link = `#${await encodeSessionLink(onHead)}`;
    const r = await openSessionLinkOutcome(h.editor, link, h.heads);
    expect(r).toEqual({
      kind: 'needsHead',
      needsHead: { name: 'mine.obj', hash: REF.hash },
      message: needsHeadMessage({ name: 'mine.obj', hash: REF.hash }, 'link'),
    });
    expect(r.message).toBe('This link needs the head “mine.obj”; Open head to load it.');
    expect(h.log).toEqual([{ run: 'loadSession', session: onHead, resetHistory: true }]);
    expect(await openSessionLink(h.editor, link, h.heads)).toBe(r.message);
  });

  it('on a stored head, or the built-in one: opened', async () => {
    const h = harness();
    await h.store.put({ hash: REF.hash, name: 'mine.obj', bytes: FILE.slice().buffer });
    const link = `#${await encodeSessionLink(onHead)}`;
    expect(await openSessionLinkOutcome(h.editor, link, h.heads)).toEqual({
      kind: 'opened',
      message: null,
    });
    expect(
      await openSessionLink(h.editor, `#${await encodeSessionLink(base)}`, h.heads),
    ).toBeNull();
  });

  it('a bad link changes nothing', async () => {
    const h = harness();
    const r = await openSessionLinkOutcome(h.editor, '#s=2.@@', h.heads);
    expect(r).toEqual({
      kind: 'failed',
      message:
        'Could not open the link: the session link is damaged (not base64url). Showing the preset instead.',
    });
    expect(h.log).toEqual([]);
  });

  it('a store that fails holds nothing (the head is asked for), and does not throw', async () => {
    const broken: HeadStore = {
      put: () => Promise.reject(new Error('quota')),
      get: () => Promise.reject(new Error('gone')),
    };
    const h = harness(broken);
    const link = `#${await encodeSessionLink(onHead)}`;
    expect((await openSessionLinkOutcome(h.editor, link, h.heads)).kind).toBe('needsHead');
    const text = await writeSessionFile(onHead, { headBytes: FILE.slice().buffer as ArrayBuffer });
    expect((await openSessionFileOutcome(h.editor, fileOf('s.json', text), h.heads)).kind).toBe(
      'needsHead',
    );
  });
});

describe('Save', () => {
  it('embeds the stored head file; says when it cannot', async () => {
    const store = memoryHeadStore();
    const missing = await sessionFileText(onHead, camera, store);
    expect(missing.headMissing).toEqual({ name: 'mine.obj', hash: REF.hash });
    expect(JSON.parse(missing.text)).not.toHaveProperty('headFile');
    const stored: StoredHead = { hash: REF.hash, name: 'mine.obj', bytes: FILE.slice().buffer };
    await store.put(stored);
    const saved = await sessionFileText(onHead, camera, store);
    expect(saved.headMissing).toBeNull();
    const back = await readSessionFile(JSON.parse(saved.text));
    if (!back.ok) throw new Error(back.error);
    expect(back.value.session).toEqual(onHead);
    expect(new Uint8Array(back.value.headFile?.bytes ?? [])).toEqual(FILE);
    expect(JSON.parse(saved.text).camera).toEqual(camera);
    // bytes in the store that are not the head's (a damaged store): saved without them
    const wrong = memoryHeadStore();
    await wrong.put({ ...stored, bytes: new ArrayBuffer(3) });
    expect((await sessionFileText(onHead, camera, wrong)).headMissing).toEqual({
      name: 'mine.obj',
      hash: REF.hash,
    });
    // the built-in head: as before, the session and the camera
    expect((await sessionFileText(base, camera, store)).text).toBe(
      JSON.stringify({ ...base, camera }),
    );
  });
});
