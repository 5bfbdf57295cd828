// Hair detail (curl, clump, frizz, flyaway, length jitter), applied to grown strands by the solver's growth
// step (solver-cpp/src/strand_detail.hpp). Parameter names and defaults are Blender's
// (docs/user-guide.md "Detail"), in world units (1 unit = 10 cm). One table states every parameter: the
// session reader, the Detail panel and the packing for the wasm engine all read it.

export interface CurlDetail {
  radius: number; // helix radius
  frequency: number; // turns per world unit of strand length
  start: number; // fraction of the strand over which the curl ramps in from the root
  randomOffset: number; // phase randomisation per strand, as a fraction of a turn
}
export interface ClumpDetail {
  factor: number; // 0..1: how far strands are pulled onto their clump's guide
  shape: number; // -1..1: falloff along the strand (0 = the whole strand, 0.5 = linear to the tip)
  tipSpread: number; // random spread of the tips around the guide
  guideDistance: number; // spacing of clump guides on the scalp
}
export interface FrizzDetail {
  distance: number; // size of the random offsets
  shape: number; // -1..1: falloff along the strand
}
export interface FlyawayDetail {
  share: number; // 0..0.2: fraction of strands that fly away
  distance: number; // how far a flyaway's tip leaves the groom
  start: number; // fraction of the length where a flyaway starts to leave the groom
}
/** A block present is on; absent blocks are off. */
export interface HairDetail {
  curl?: CurlDetail;
  clump?: ClumpDetail;
  frizz?: FrizzDetail;
  flyaway?: FlyawayDetail;
  lengthJitter?: number; // 0..1: each strand's length times (1 - lengthJitter · u), u in [0, 1)
}

export type DetailBlock = 'curl' | 'clump' | 'frizz' | 'flyaway';

export interface DetailParamSpec {
  key: string;
  label: string;
  /** How the Hair panel shows it: 'cm' a length in world units shown in centimetres (× 10);
   *  'turns per 10 cm' per world unit; 'of length', 'of a turn', 'of strands' fractions; absent:
   *  a plain number. */
  unit?: 'cm' | 'turns per 10 cm' | 'of length' | 'of a turn' | 'of strands';
  default: number;
  min: number;
  max: number;
  step: number;
}

export const DETAIL_PARAMS = {
  curl: [
    { key: 'radius', label: 'Radius', unit: 'cm', default: 0.1, min: 0, max: 0.5, step: 0.005 },
    {
      key: 'frequency',
      label: 'Frequency',
      unit: 'turns per 10 cm',
      default: 1,
      min: 0,
      max: 20,
      step: 0.1,
    },
    { key: 'start', label: 'Start', unit: 'of length', default: 0.1, min: 0, max: 1, step: 0.01 },
    {
      key: 'randomOffset',
      label: 'Random offset',
      unit: 'of a turn',
      default: 0.25,
      min: 0,
      max: 1,
      step: 0.01,
    },
  ],
  clump: [
    { key: 'factor', label: 'Factor', default: 1, min: 0, max: 1, step: 0.01 },
    { key: 'shape', label: 'Shape', default: 0.5, min: -1, max: 1, step: 0.01 },
    { key: 'tipSpread', label: 'Tip spread', unit: 'cm', default: 0, min: 0, max: 1, step: 0.005 },
    {
      key: 'guideDistance',
      label: 'Guide distance',
      unit: 'cm',
      default: 0.1,
      min: 0.01,
      max: 2,
      step: 0.01,
    },
  ],
  frizz: [
    {
      key: 'distance',
      label: 'Distance',
      unit: 'cm',
      default: 0.01,
      min: 0,
      max: 0.5,
      step: 0.002,
    },
    { key: 'shape', label: 'Shape', default: 0.5, min: -1, max: 1, step: 0.01 },
  ],
  // not Blender's: a few stray hairs leaving the groom (strand_detail.hpp "Flyaway")
  flyaway: [
    {
      key: 'share',
      label: 'Share',
      unit: 'of strands',
      default: 0.01,
      min: 0,
      max: 0.2,
      step: 0.005,
    },
    { key: 'distance', label: 'Distance', unit: 'cm', default: 0.12, min: 0, max: 0.5, step: 0.01 },
    {
      key: 'start',
      label: 'Start',
      unit: 'of length',
      default: 0.55,
      min: 0,
      max: 0.95,
      step: 0.01,
    },
  ],
} as const satisfies Record<DetailBlock, readonly DetailParamSpec[]>;

export const DETAIL_BLOCKS: readonly DetailBlock[] = ['curl', 'clump', 'frizz', 'flyaway'];
export const LENGTH_JITTER: DetailParamSpec = {
  key: 'lengthJitter',
  label: 'Length jitter',
  default: 0.2,
  min: 0,
  max: 1,
  step: 0.01,
};

/** Numbers per detail group (hairArrays.ts DetailArrays; solver-cpp/src/strand_detail.hpp): every
 *  block's parameters in DETAIL_PARAMS order, then lengthJitter. */
export const DETAIL_GROUP_STRIDE: number =
  DETAIL_BLOCKS.reduce((n, b) => n + DETAIL_PARAMS[b].length, 0) + 1;

/** A block with Blender's defaults (flyaway: its own). */
export function defaultBlock<B extends DetailBlock>(b: B): NonNullable<HairDetail[B]> {
  const out: Record<string, number> = {};
  for (const p of DETAIL_PARAMS[b]) out[p.key] = p.default;
  return out as unknown as NonNullable<HairDetail[B]>;
}

/** Writes one detail group (hairArrays.ts DetailArrays, DETAIL_GROUP_STRIDE numbers) at `at`:
 *  curl radius, frequency, start, randomOffset; clump factor, shape, tipSpread, guideDistance;
 *  frizz distance, shape; flyaway share, distance, start; lengthJitter. An absent block is written
 *  as off (radius, factor, distance, share 0). */
export function packDetailGroup(d: HairDetail | undefined, out: Float64Array, at: number): void {
  let k = at;
  for (const b of DETAIL_BLOCKS) {
    const block = d?.[b] as Record<string, number> | undefined;
    for (const p of DETAIL_PARAMS[b]) out[k++] = block ? block[p.key] : p.default;
    if (!block) out[k - DETAIL_PARAMS[b].length] = 0; // the block's first parameter turns it off
  }
  out[k] = d?.lengthJitter ?? 0;
}

/** Whether block `b` is present and turned on: its first parameter (curl radius, clump factor,
 *  frizz distance, flyaway share) above 0 (packDetailGroup writes 0 there for an absent block). */
export function blockIsOn(d: HairDetail, b: DetailBlock): boolean {
  const block = d[b] as Record<string, number> | undefined;
  return !!block && block[DETAIL_PARAMS[b][0].key] > 0;
}

/** True when the detail changes any strand. */
export function detailIsOn(d: HairDetail | undefined): boolean {
  return !!d && (!!d.curl || !!d.clump || !!d.frizz || !!d.flyaway || (d.lengthJitter ?? 0) > 0);
}
