// How wide hair strands are drawn (method S6.1): each drawn strand stands for several of a head's
// hairs, so together they cover what a head's hairs cover (representedWidth), and each strand's
// width varies by a seeded hash of its random values (strandWidthFactor; the shaders' widthOf).
import type * as THREE from 'three';

/** Each strand's width is strandWidth times 1 ± WIDTH_VARIATION, from a hash of its four random
 *  bytes (uniform, so the mean width is strandWidth): some strands read finer, some coarser. */
export const WIDTH_VARIATION = 0.4;
export const WIDTH_HASH = [0.4142136, 0.7320508, 0.236068, 0.6457513] as const;
export const WIDTH_HASH_SCALE = 113.17;

/** The width factor the shaders give a strand of random values `rnd` (each 0..1, as the
 *  normalised `strandRandom` attribute reads): what `widthOf` computes, for tests. */
export function strandWidthFactor(rnd: readonly [number, number, number, number]): number {
  const d = rnd.reduce((a, v, i) => a + v * WIDTH_HASH[i], 0) * WIDTH_HASH_SCALE;
  return 1 + WIDTH_VARIATION * (2 * (d - Math.floor(d)) - 1);
}

/** A hair's width, world units (1 unit = 10 cm): 75 µm, a medium human hair. */
export const HAIR_WIDTH = 0.00075;
/** Hairs on a head: about 100,000 (90,000 to 150,000 by colour). */
export const HAIRS_ON_A_HEAD = 100_000;
/** The widest a drawn strand gets (world units, 1.2 mm): a sparse sample stays strands, not
 *  ribbons. */
const MAX_STRAND_WIDTH = 0.012;

/** The width each of `drawn` strands is drawn at (world units, at the root): together they
 *  cover what a head's hairs cover, so the hair's density does not depend on how many strands
 *  are grown or, while the view moves, on how sparse a sample of them is drawn (Unreal widens
 *  a decimated groom's strands the same way). At least one hair's width, at most
 *  MAX_STRAND_WIDTH. */
export function representedWidth(drawn: number): number {
  const hairs = HAIRS_ON_A_HEAD / Math.max(drawn, 1);
  return Math.min(MAX_STRAND_WIDTH, HAIR_WIDTH * Math.max(1, hairs));
}

/** Strands a draw of `geometry` (a strand geometry: userData.strands, lodCounts) covers: its
 *  draw range's share of the index (prefixes are even samples of the strands), or all of them
 *  when the draw is a slice of the whole hair's frame (userData.sliceOfWhole: progressiveHair.ts),
 *  whose strands are as wide as in the frame drawn in one pass. */
export function drawnStrands(geometry: THREE.BufferGeometry): number {
  const strands = (geometry.userData.strands as number | undefined) ?? 0;
  const all = geometry.index?.count ?? 0;
  if (all === 0 || geometry.userData.sliceOfWhole) return strands;
  return (strands * Math.min(geometry.drawRange.count, all)) / all;
}
