// Settings of the view kept in this browser's localStorage across reloads (not in the session,
// its history or its links): the quality (quality.ts) and Mirror editing.

export type Store = Pick<Storage, 'getItem' | 'setItem'>;

export function storage(): Store | null {
  try {
    return typeof localStorage !== 'undefined' ? localStorage : null;
  } catch {
    return null; // storage blocked (e.g. a sandboxed frame)
  }
}

const MIRROR_KEY = 'hairsketch.mirror';

/** Mirror editing as last left in this browser (off when never set or unreadable): fresh eyes
 *  reloaded from the address bar's link and drew one side only. */
export function loadMirrorSetting(store: Store | null = storage()): boolean {
  try {
    return store?.getItem(MIRROR_KEY) === 'on';
  } catch {
    return false;
  }
}

export function saveMirrorSetting(on: boolean, store: Store | null = storage()): void {
  try {
    store?.setItem(MIRROR_KEY, on ? 'on' : 'off');
  } catch {
    // storage full or blocked: Mirror is simply not kept
  }
}
