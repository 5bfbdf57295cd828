// The reference picture files the browser keeps, by SHA-256, as it keeps loaded heads: a link
// names a picture only by its hash, so every picture opened (or read from a session file) is
// kept in IndexedDB (database "hairsketch-pictures") and found again there. Pictures never leave
// the browser: nothing here, or anywhere else in the app, sends them anywhere.
import { type HeadStore, indexedDbHeadStore, memoryHeadStore } from '../head/headStore';

/** A store of files by hash (the head store's shape: {hash, name, bytes}). */
export type PictureStore = HeadStore;

export const indexedDbPictureStore = (): PictureStore => indexedDbHeadStore('hairsketch-pictures');
export const memoryPictureStore = (): PictureStore => memoryHeadStore();
