// A session's loaded head for the embed, from this browser's head store: loaded only for a
// session on a loaded head (it brings the head file readers). A page framed by another site
// usually has its own, empty storage, so the head is often missing there.
import { hashHeadBytes, indexedDbHeadStore, loadHeadRef } from '../head/headStore';
import type { LoadedHead } from '../head/loadHead';
import type { HeadRef } from '../model/session';

/** The head `ref` names, or the sentence saying why it cannot be shown. */
export async function storedHead(ref: HeadRef): Promise<LoadedHead | string> {
  const missing = `This hairstyle was made on the head “${ref.name}”, which this page has not stored; shown on the built-in head.`;
  let stored: Awaited<ReturnType<ReturnType<typeof indexedDbHeadStore>['get']>> = null;
  try {
    stored = await indexedDbHeadStore().get(ref.hash);
  } catch {
    return missing;
  }
  if (!stored) return missing;
  const r = await loadHeadRef(ref, stored.bytes);
  return r.ok ? r.head : `The head “${ref.name}” could not be read; shown on the built-in head.`;
}

/** Keeps a head file in this browser's head store (the bytes must be the named ones). */
export async function storeHeadFile(name: string, hash: string, bytes: Uint8Array): Promise<void> {
  const buffer = bytes.slice().buffer as ArrayBuffer;
  if ((await hashHeadBytes(buffer)) !== hash) throw new Error('the head file is not the one named');
  await indexedDbHeadStore().put({ name, hash, bytes: buffer });
}
