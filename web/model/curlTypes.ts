// Curl types a stylist names: the hair typing stylists use (1 straight, 2A–2C wavy, 3A–3C curly,
// 4A–4C coily), each as the detail that makes it (model/detail.ts): a curl of the type's radius
// and turns, ramping in over the first 12 % of the hair (a curl rolling from the very root
// makes barrel rolls across the crown, a stylist saw), wound in locks (a clump per lock, the
// curly types' held tight: lockHold; with finished edges each lock's radius and frequency vary
// by a seeded factor and half the locks wind the other way, docs/natural-fall.md "Ringlets"),
// and no frizz (a wiry halo is not a curl type). Radii and turns are for a curl's helix: the diameter a lock winds round (a 3A curl
// round sidewalk chalk, 3C a pencil, 4A a crochet needle) and its pitch, about three diameters
// for springy curls and longer for waves.
import type { HairDetail } from './detail';

export interface CurlType {
  /** '1', '2A' … '4C'. */
  id: string;
  /** What the Hair panel's "Curl type" lists. */
  label: string;
  /** Helix radius, world units (1 = 10 cm): the type's range, its middle is what it sets. */
  radius: [number, number];
  /** Turns per world unit of length (turns per 10 cm): range. */
  frequency: [number, number];
  /** The lock spacing on the scalp (clump guide distance, world units). */
  lock: number;
  /** The Volume it brings (world units: the hair's lift at the roots, sessions with the shape
   *  rules): curly and coily hair stands off the head at its roots, a spring of hair on hair,
   *  where straight and wavy hair lies on it; none for waves. */
  rootLift?: number;
  /** How far a lock's strands are drawn onto it (its clump factor; 0.7 when absent): curly
   *  types hold theirs tight, each lock one spiral ringlet (at 0.7, loose bundles of curls read
   *  as "rows of flat scallops, like fish scales"). */
  lockHold?: number;
}

export const CURL_TYPES: readonly CurlType[] = [
  {
    id: '2A',
    label: '2A wavy: loose waves',
    radius: [0.02, 0.04],
    frequency: [0.9, 1.3],
    lock: 0.3,
  },
  { id: '2B', label: '2B wavy: S-waves', radius: [0.04, 0.06], frequency: [1.3, 1.8], lock: 0.25 },
  {
    id: '2C',
    label: '2C wavy: deep waves',
    radius: [0.06, 0.08],
    frequency: [1.8, 2.4],
    lock: 0.2,
  },
  {
    id: '3A',
    label: '3A curly: loose curls',
    radius: [0.09, 0.12],
    frequency: [2.2, 2.8],
    lock: 0.18,
    rootLift: 0.1,
    lockHold: 0.92,
  },
  {
    id: '3B',
    label: '3B curly: springy curls',
    radius: [0.07, 0.09],
    frequency: [3, 3.8],
    lock: 0.15,
    rootLift: 0.1,
    lockHold: 0.92,
  },
  {
    id: '3C',
    label: '3C curly: tight curls',
    radius: [0.05, 0.065],
    frequency: [4.2, 5.4],
    lock: 0.12,
    rootLift: 0.1,
    lockHold: 0.92,
  },
  {
    id: '4A',
    label: '4A coily: tight coils',
    radius: [0.03, 0.045],
    frequency: [6, 8],
    lock: 0.1,
    rootLift: 0.25,
  },
  {
    id: '4B',
    label: '4B coily: zig-zag coils',
    radius: [0.022, 0.03],
    frequency: [8.5, 10.5],
    lock: 0.08,
    rootLift: 0.25,
  },
  {
    id: '4C',
    label: '4C coily: densest coils',
    radius: [0.015, 0.022],
    frequency: [11, 13],
    lock: 0.07,
    rootLift: 0.25,
  },
];

const mid = (r: [number, number]) => (r[0] + r[1]) / 2;

/** The detail a curl type makes, keeping the rest of `d` (length jitter); '1' (straight): `d`
 *  without its curl. */
export function detailForCurlType(id: string, d: HairDetail | undefined): HairDetail {
  const t = CURL_TYPES.find((c) => c.id === id);
  if (!t) {
    const { curl: _, ...straight } = d ?? {};
    return straight;
  }
  const { curl: _c, clump: _k, frizz: _f, ...rest } = d ?? {};
  return {
    ...rest,
    curl: { radius: mid(t.radius), frequency: mid(t.frequency), start: 0.12, randomOffset: 1 },
    // locks: strands drawn most of the way onto their lock, loosening towards the tips
    clump: { factor: t.lockHold ?? 0.7, shape: 0.3, tipSpread: 0.01, guideDistance: t.lock },
  };
}

/** The Volume (world units) choosing curl type `id` brings, or undefined: none. */
export function rootLiftOf(id: string): number | undefined {
  return CURL_TYPES.find((c) => c.id === id)?.rootLift;
}

/** The curl type a detail matches (its curl's radius and frequency in a type's ranges), '1' for
 *  no curl, or null (a curl of its own). */
export function curlTypeOf(d: HairDetail | undefined): string | null {
  const c = d?.curl;
  if (!c || c.radius === 0) return '1';
  const eps = 1e-9;
  const t = CURL_TYPES.find(
    (k) =>
      c.radius >= k.radius[0] - eps &&
      c.radius <= k.radius[1] + eps &&
      c.frequency >= k.frequency[0] - eps &&
      c.frequency <= k.frequency[1] + eps,
  );
  return t ? t.id : null;
}
