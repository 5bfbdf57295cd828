// The head store (web/head/headStore.ts) and the content hash that names a head: SHA-256 against
// the FIPS 180-4 example digests and node:crypto, in the platform's crypto.subtle and in the
// JavaScript fallback; the memory store; the IndexedDB store's fallbacks (no IndexedDB here in
// Node, one that will not open, one whose transactions fail, one that works); loadHeadRef applies
// the reference's up axis and turns as loadHeadFile + rotateLoadedHead do.
import { createHash } from 'node:crypto';
import { describe, expect, it } from 'vitest';
import { buildHead } from '../../web/head/buildHead';
import {
  hashHeadBytes,
  indexedDbHeadStore,
  loadHeadRef,
  memoryHeadStore,
  type StoredHead,
} from '../../web/head/headStore';
import { loadHeadFile, rotateLoadedHead } from '../../web/head/loadHead';
import { sha256Hex, sha256HexPortable } from '../../web/model/bytes';
import type { HeadRef } from '../../web/model/session';

const text = (s: string) => new TextEncoder().encode(s);
const buf = (b: Uint8Array) => b.slice().buffer as ArrayBuffer;

// FIPS 180-4 / NIST examples
const ABC = 'ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad';
const EMPTY = 'e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855';
const TWO_BLOCKS = '248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1';
const TWO_BLOCKS_TEXT = 'abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq';

function bytesOf(n: number, seed: number): Uint8Array {
  const b = new Uint8Array(n);
  let x = seed >>> 0;
  for (let i = 0; i < n; i++) {
    x = (Math.imul(x, 1664525) + 1013904223) >>> 0;
    b[i] = x >>> 24;
  }
  return b;
}

describe('hashHeadBytes: SHA-256 as hex', () => {
  it('gives the standard digests', async () => {
    expect(await hashHeadBytes(buf(text('abc')))).toBe(ABC);
    expect(await hashHeadBytes(new ArrayBuffer(0))).toBe(EMPTY);
    expect(await hashHeadBytes(buf(text(TWO_BLOCKS_TEXT)))).toBe(TWO_BLOCKS);
  });

  it('the JavaScript fallback gives the same digests as node:crypto at every padding length', () => {
    expect(sha256HexPortable(text('abc'))).toBe(ABC);
    expect(sha256HexPortable(new Uint8Array(0))).toBe(EMPTY);
    expect(sha256HexPortable(text(TWO_BLOCKS_TEXT))).toBe(TWO_BLOCKS);
    for (const n of [1, 55, 56, 57, 63, 64, 65, 119, 120, 127, 128, 129, 1000, 65_537]) {
      const b = bytesOf(n, n);
      expect(sha256HexPortable(b), `${n} bytes`).toBe(createHash('sha256').update(b).digest('hex'));
    }
  });

  it('a view into a larger buffer hashes only its bytes', async () => {
    const big = bytesOf(300, 3);
    const view = big.subarray(100, 203);
    const want = createHash('sha256').update(view).digest('hex');
    expect(await sha256Hex(view)).toBe(want);
    expect(sha256HexPortable(view)).toBe(want);
  });
});

const head = (name: string, s: string): StoredHead => ({
  hash: createHash('sha256').update(s).digest('hex'),
  name,
  bytes: buf(text(s)),
});

describe('memoryHeadStore', () => {
  it('finds what was put by its hash, and nothing else', async () => {
    const store = memoryHeadStore();
    const a = head('a.obj', 'v 0 0 0');
    const b = head('b.stl', 'solid b');
    expect(await store.get(a.hash)).toBeNull();
    await store.put(a);
    await store.put(b);
    expect(await store.get(a.hash)).toEqual(a);
    expect(await store.get(b.hash)).toEqual(b);
    expect(await store.get(EMPTY)).toBeNull();
    // putting the same hash again replaces it
    await store.put({ ...a, name: 'renamed.obj' });
    expect((await store.get(a.hash))?.name).toBe('renamed.obj');
  });
});

// ---- a small IndexedDB stand-in (the store's only use of it: open, one object store, put, get)

type Handler = (() => void) | null;
interface FakeRequest<T> {
  result: T;
  onsuccess: Handler;
  onerror: Handler;
}

function fakeIndexedDb(mode: 'works' | 'cannot open' | 'open throws' | 'transactions fail') {
  const data = new Map<string, unknown>();
  let stores = 0;
  const later = (f: () => void) => setTimeout(f, 0);
  const db = {
    objectStoreNames: { contains: () => stores > 0 },
    createObjectStore: () => {
      stores++;
    },
    transaction: (_name: string, _mode: string) => {
      const tx = {
        oncomplete: null as Handler,
        onerror: null as Handler,
        onabort: null as Handler,
      };
      const request = <T>(work: () => T): FakeRequest<T> => {
        const r: FakeRequest<T> = { result: undefined as T, onsuccess: null, onerror: null };
        later(() => {
          if (mode === 'transactions fail') {
            r.onerror?.();
            tx.onerror?.();
            return;
          }
          r.result = work();
          r.onsuccess?.();
          tx.oncomplete?.();
        });
        return r;
      };
      return Object.assign(tx, {
        objectStore: () => ({
          put: (v: unknown, k: string) => request(() => data.set(k, structuredClone(v)) && k),
          get: (k: string) => request(() => structuredClone(data.get(k))),
        }),
      });
    },
  };
  const factory = {
    open: (_name: string, _version: number) => {
      if (mode === 'open throws') throw new Error('SecurityError');
      const req = {
        result: db,
        onupgradeneeded: null as Handler,
        onsuccess: null as Handler,
        onerror: null as Handler,
        onblocked: null as Handler,
      };
      later(() => {
        if (mode === 'cannot open') req.onerror?.();
        else {
          if (stores === 0) req.onupgradeneeded?.();
          req.onsuccess?.();
        }
      });
      return req;
    },
  };
  return { factory, data };
}

async function withIndexedDb<T>(factory: unknown, run: () => Promise<T>): Promise<T> {
  const g = globalThis as { indexedDB?: unknown };
  const had = 'indexedDB' in g;
  const before = g.indexedDB;
  g.indexedDB = factory;
  try {
    return await run();
  } finally {
    if (had) g.indexedDB = before;
    else delete g.indexedDB;
  }
}

describe('indexedDbHeadStore', () => {
  const a = head('a.obj', 'v 1 2 3\n');

  it('without IndexedDB (Node) keeps heads in memory and never throws', async () => {
    expect('indexedDB' in globalThis).toBe(false);
    const store = indexedDbHeadStore();
    expect(await store.get(a.hash)).toBeNull();
    await store.put(a);
    expect(await store.get(a.hash)).toEqual(a);
  });

  it('keeps heads in the database when it works (another store on it finds them)', async () => {
    const fake = fakeIndexedDb('works');
    await withIndexedDb(fake.factory, async () => {
      await indexedDbHeadStore('t').put(a);
      expect(fake.data.size).toBe(1);
      const other = indexedDbHeadStore('t'); // as a page opened later
      expect(await other.get(a.hash)).toEqual(a);
      expect(await other.get(EMPTY)).toBeNull();
    });
  });

  for (const mode of ['cannot open', 'open throws', 'transactions fail'] as const)
    it(`falls back to memory when the database ${mode}`, async () => {
      const fake = fakeIndexedDb(mode);
      await withIndexedDb(fake.factory, async () => {
        const store = indexedDbHeadStore('t');
        expect(await store.get(a.hash)).toBeNull();
        await store.put(a);
        expect(await store.get(a.hash)).toEqual(a);
        expect(fake.data.size).toBe(0);
      });
    });
});

describe('loadHeadRef', () => {
  it("is loadHeadFile with the ref's up axis, then its turns in order", async () => {
    // the built-in head's mesh in mm as an OBJ, Z-up
    const m = buildHead();
    const lines: string[] = [];
    for (let i = 0; i < m.positions.length; i += 3)
      lines.push(
        `v ${m.positions[i] * 100} ${-m.positions[i + 2] * 100} ${m.positions[i + 1] * 100}`,
      );
    for (let t = 0; t < m.indices.length; t += 3)
      lines.push(`f ${m.indices[t] + 1} ${m.indices[t + 1] + 1} ${m.indices[t + 2] + 1}`);
    const bytes = buf(text(`${lines.join('\n')}\n`));
    const ref: HeadRef = {
      kind: 'mesh',
      name: 'zup.obj',
      hash: await hashHeadBytes(bytes),
      format: 'obj',
      up: 'y', // told Y-up (wrongly), then turned back by hand
      turns: [
        { axis: 'x', quarterTurns: 3 },
        { axis: 'y', quarterTurns: 2 },
      ],
    };
    const r = await loadHeadRef(ref, bytes);
    if (!r.ok) throw new Error(r.error);
    const direct = await loadHeadFile('zup.obj', bytes, { up: 'y' });
    if (!direct.ok) throw new Error(direct.error);
    const want = rotateLoadedHead(rotateLoadedHead(direct.head, 'x', 3), 'y', 2);
    expect(r.head.mesh.positions).toEqual(want.mesh.positions);
    expect(r.head.mesh.scalp).toEqual(want.mesh.scalp);
    expect(r.head.turns).toEqual(ref.turns);
    const bad = await loadHeadRef({ ...ref, name: 'x.stl' }, buf(text('nothing')));
    expect(bad.ok).toBe(false);
  });
});
