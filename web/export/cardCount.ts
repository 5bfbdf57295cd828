// How many hair cards the hair is cut into: the setting the Export menu, the Cards view and
// `hairsketch grow --cards` share.

/** Cards a hairstyle is cut into unless told: about 20K triangles for the default preset, the
 *  budget of a game character's hair at its closest level of detail. */
export const DEFAULT_CARD_COUNT = 1000;
export const CARD_COUNT_MIN = 100;
export const CARD_COUNT_MAX = 5000;

/** Null when `n` is a whole number in CARD_COUNT_MIN..CARD_COUNT_MAX, else the sentence saying
 *  what is wrong. */
export function cardCountProblem(n: number): string | null {
  return Number.isInteger(n) && n >= CARD_COUNT_MIN && n <= CARD_COUNT_MAX
    ? null
    : `the card count must be a whole number from ${CARD_COUNT_MIN} to ${CARD_COUNT_MAX.toLocaleString('en-US')}, got ${n}`;
}
