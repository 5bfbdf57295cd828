// The grids every number of a session is kept on (quantize.ts puts a session on them): the
// integers per unit of each kind of number, and the rounding to and from those integers. A leaf
// module (it imports nothing), so the readers and the curve kinds can use it without a cycle.

/** Integers per world unit for positions (1e-4 world units = 10 µm). */
export const POSITION_SCALE = 1e4;
/** Integers per unit for direction components (normals, axes, avoid targets). */
export const DIRECTION_SCALE = 1e4;
/** Integers per radian for curve angles (their rows' quantum, 1e-5). */
export const ANGLE_SCALE = 1e5;
/** Integers per unit for the other curve parameters (sigma, h, tightness: quantum 1e-4). */
export const PARAM_SCALE = 1e4;
/** Numbers are clamped to ±LIMIT before quantising (keeps every integer far below 2^53). */
export const LIMIT = 1e6;

/** The integer a number is stored as: round(clamp(x) * scale), never -0. */
export function toGridInt(x: number, scale: number): number {
  const c = Math.min(LIMIT, Math.max(-LIMIT, x));
  return Math.round(c * scale) + 0;
}

/** The number on the grid an integer stands for. */
export function fromGridInt(k: number, scale: number): number {
  return k / scale + 0;
}

/** x on the grid of `scale`. */
export function quantize(x: number, scale: number): number {
  return fromGridInt(toGridInt(x, scale), scale);
}
