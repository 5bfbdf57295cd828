// Mirror editing is kept in this browser across reloads (localSettings.ts), off by default and
// when storage is blocked or broken.
import { describe, expect, it } from 'vitest';
import { loadMirrorSetting, saveMirrorSetting } from '../../web/app/localSettings';

function memoryStore() {
  const m = new Map<string, string>();
  return {
    getItem: (k: string) => m.get(k) ?? null,
    setItem: (k: string, v: string) => void m.set(k, v),
  };
}

describe('Mirror setting', () => {
  it('is off until set, then what was last saved', () => {
    const store = memoryStore();
    expect(loadMirrorSetting(store)).toBe(false);
    saveMirrorSetting(true, store);
    expect(loadMirrorSetting(store)).toBe(true);
    saveMirrorSetting(false, store);
    expect(loadMirrorSetting(store)).toBe(false);
  });

  it('is off, and saving does not throw, where storage is missing or throws', () => {
    const broken = {
      getItem: (): string | null => {
        throw new Error('blocked');
      },
      setItem: () => {
        throw new Error('full');
      },
    };
    expect(loadMirrorSetting(null)).toBe(false);
    expect(loadMirrorSetting(broken)).toBe(false);
    expect(() => saveMirrorSetting(true, broken)).not.toThrow();
  });
});
