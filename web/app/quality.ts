// The "Quality" setting (view state: kept in localStorage, not in the session or its history):
// Auto, Fast or High. Fast draws GL lines lit by the worker's precomputed lighting; High adds
// camera-facing tapered strips with alpha-to-coverage and deep opacity maps. Auto is High where
// the unmasked WebGL renderer is a real GPU and Fast on a software rasteriser (SwiftShader,
// llvmpipe), where a High frame costs several times a Fast one.

import { type Store, storage } from './localSettings';

export type QualitySetting = 'auto' | 'fast' | 'high';
export type ActiveQuality = 'fast' | 'high';

export const QUALITY_SETTINGS: readonly QualitySetting[] = ['auto', 'fast', 'high'];
const STORAGE_KEY = 'hairsketch.quality';

export function isQualitySetting(v: unknown): v is QualitySetting {
  return typeof v === 'string' && (QUALITY_SETTINGS as readonly string[]).includes(v);
}

/** The drawing path a setting chooses on this renderer. */
export function activeQuality(setting: QualitySetting, software: boolean): ActiveQuality {
  if (setting === 'auto') return software ? 'fast' : 'high';
  return setting;
}

/** The setting after `s` in the Quality button's cycle: from Auto to the path Auto does not draw
 *  on this renderer (`auto`: the one it draws), then to the other, then back to Auto; on a
 *  software rasteriser Auto → High → Fast → Auto, so the first press changes the drawing (Auto →
 *  Fast changed nothing there, and a new user pressed Q twice to see High). */
export function nextQuality(s: QualitySetting, auto: ActiveQuality): QualitySetting {
  const other: ActiveQuality = auto === 'fast' ? 'high' : 'fast';
  if (s === 'auto') return other;
  return s === other ? auto : 'auto';
}

/** The button's label: "Quality: Auto (Fast)", "Quality: High". */
export function qualityLabel(setting: QualitySetting, active: ActiveQuality): string {
  const name = (q: string) => q[0].toUpperCase() + q.slice(1);
  return setting === 'auto' ? `Quality: Auto (${name(active)})` : `Quality: ${name(setting)}`;
}

/** The saved setting ('auto' when none or unreadable). */
export function loadQualitySetting(store: Store | null = storage()): QualitySetting {
  try {
    const v = store?.getItem(STORAGE_KEY);
    return isQualitySetting(v) ? v : 'auto';
  } catch {
    return 'auto';
  }
}

export function saveQualitySetting(s: QualitySetting, store: Store | null = storage()): void {
  try {
    store?.setItem(STORAGE_KEY, s);
  } catch {
    // not persisted: the setting still applies to this page
  }
}

/** What the Quality setting acts on: the hair view (viewer/hairView.ts). */
export interface QualityTarget {
  setQuality(q: ActiveQuality): void;
  readonly activeQuality: ActiveQuality;
  readonly lightingMs: number | null;
}

/** Where the setting is held (the view store, viewState.ts). */
export interface QualityState {
  readonly state: { readonly quality: QualitySetting };
  update(patch: { quality: QualitySetting }): void;
  listen(listener: (c: { state: { quality: QualitySetting } }) => void): void;
}

/** Applies the view store's setting to the hair view, and keeps it in localStorage. */
export class QualityControl {
  constructor(
    private readonly hair: QualityTarget,
    private readonly renderer: { software: boolean; rendererName: string },
    private readonly store: QualityState,
  ) {
    this.hair.setQuality(activeQuality(store.state.quality, renderer.software));
    store.listen(({ state }) => {
      const active = activeQuality(state.quality, this.renderer.software);
      if (active !== this.hair.activeQuality) this.hair.setQuality(active);
    });
  }

  get setting(): QualitySetting {
    return this.store.state.quality;
  }

  set(s: QualitySetting): void {
    saveQualitySetting(s);
    this.store.update({ quality: s });
  }

  cycle(): void {
    this.set(nextQuality(this.setting, activeQuality('auto', this.renderer.software)));
  }

  label(): string {
    return qualityLabel(this.setting, this.hair.activeQuality);
  }

  /** For the test API: the setting, the path drawing now, and the unmasked renderer. */
  info(): { setting: QualitySetting; active: ActiveQuality; renderer: string } {
    return {
      setting: this.setting,
      active: this.hair.activeQuality,
      renderer: this.renderer.rendererName,
    };
  }

  /** The lighting precompute time of the hair shown (ms in the worker; null: none). */
  lightingMs(): number | null {
    return this.hair.lightingMs;
  }
}
