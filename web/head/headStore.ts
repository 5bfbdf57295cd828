// The head files the browser keeps: a share link names a loaded head only by the
// SHA-256 of its file, so the app keeps every head file it opened (or read from a session file)
// by that hash, in IndexedDB, and finds it again when a link or an undo names it.
//
// The store never throws at the caller: where IndexedDB is missing (Node, some private modes) or
// will not open, or a transaction fails (quota), it keeps the heads in memory for this page
// instead, so the app still works within the page.
import type { HeadRef } from '../model/session';
import { hashBytes } from '../model/sessionFile';
import { type LoadedHead, type LoadHeadResult, loadHeadFile, rotateLoadedHead } from './loadHead';

/** A head file as the user opened it. */
export interface StoredHead {
  /** SHA-256 of `bytes`, 64 lowercase hex digits. */
  hash: string;
  name: string;
  bytes: ArrayBuffer;
}

export interface HeadStore {
  /** Keeps a head file (by its hash; storing one again replaces it). */
  put(h: StoredHead): Promise<void>;
  /** The head file with this hash, or null. */
  get(hash: string): Promise<StoredHead | null>;
}

/** The SHA-256 of a head file's bytes as 64 lowercase hex digits: the name a session gives the
 *  head (crypto.subtle where there is one, else computed in JavaScript). */
export function hashHeadBytes(bytes: ArrayBuffer): Promise<string> {
  return hashBytes(bytes);
}

/** The head a session's HeadRef names, from its file's bytes: loadHeadFile with the ref's name
 *  and up axis, then each of its quarter turns in order (what the app showed when the session
 *  was made). The caller checks the hash (hashHeadBytes) when the bytes come from outside. */
/** The session's name for a head file just loaded (no turns yet). */
export function headRefOf(name: string, hash: string, loaded: LoadedHead): HeadRef {
  return { kind: 'mesh', name, hash, format: loaded.format, up: loaded.up, turns: [] };
}

export async function loadHeadRef(ref: HeadRef, bytes: ArrayBuffer): Promise<LoadHeadResult> {
  const r = await loadHeadFile(ref.name, bytes, { up: ref.up });
  if (!r.ok) return r;
  let head = r.head;
  for (const t of ref.turns) head = rotateLoadedHead(head, t.axis, t.quarterTurns);
  return { ok: true, head };
}

/** Heads kept in this page's memory. */
export function memoryHeadStore(): HeadStore {
  const heads = new Map<string, StoredHead>();
  return {
    async put(h) {
      heads.set(h.hash, { hash: h.hash, name: h.name, bytes: h.bytes });
    },
    async get(hash) {
      const h = heads.get(hash);
      return h ? { ...h } : null;
    },
  };
}

const STORE = 'heads';

/** Heads kept in IndexedDB database `dbName` (object store "heads", key: the hash), with a
 *  memory store as a fallback: a head whose put failed (no IndexedDB, quota) is still found in
 *  this page. */
export function indexedDbHeadStore(dbName = 'hairsketch-heads'): HeadStore {
  const memory = memoryHeadStore();
  let db: Promise<IDBDatabase | null> | null = null;
  const open = (): Promise<IDBDatabase | null> => {
    db ??= new Promise<IDBDatabase | null>((resolve) => {
      try {
        const factory = globalThis.indexedDB;
        if (!factory) {
          resolve(null);
          return;
        }
        const req = factory.open(dbName, 1);
        req.onupgradeneeded = () => {
          if (!req.result.objectStoreNames.contains(STORE)) req.result.createObjectStore(STORE);
        };
        req.onsuccess = () => resolve(req.result);
        req.onerror = () => resolve(null);
        req.onblocked = () => resolve(null);
      } catch {
        resolve(null);
      }
    });
    return db;
  };
  const run = <T>(
    mode: IDBTransactionMode,
    work: (store: IDBObjectStore) => IDBRequest<T>,
  ): Promise<{ ok: true; value: T } | { ok: false }> =>
    open().then(
      (d) =>
        new Promise((resolve) => {
          if (!d) {
            resolve({ ok: false });
            return;
          }
          try {
            const tx = d.transaction(STORE, mode);
            const req = work(tx.objectStore(STORE));
            let value: T;
            req.onsuccess = () => {
              value = req.result;
            };
            tx.oncomplete = () => resolve({ ok: true, value });
            tx.onerror = () => resolve({ ok: false });
            tx.onabort = () => resolve({ ok: false });
          } catch {
            resolve({ ok: false });
          }
        }),
    );
  return {
    async put(h) {
      const record: StoredHead = { hash: h.hash, name: h.name, bytes: h.bytes };
      const r = await run('readwrite', (s) => s.put(record, h.hash));
      if (!r.ok) await memory.put(h); // found in this page at least
    },
    async get(hash) {
      const r = await run('readonly', (s) => s.get(hash) as IDBRequest<unknown>);
      if (r.ok && isStoredHead(r.value, hash)) return r.value;
      return memory.get(hash);
    },
  };
}

function isStoredHead(v: unknown, hash: string): v is StoredHead {
  if (typeof v !== 'object' || v === null) return false;
  const o = v as Record<string, unknown>;
  return o.hash === hash && typeof o.name === 'string' && o.bytes instanceof ArrayBuffer;
}
