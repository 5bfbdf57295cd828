// Placing a loaded head where the built-in one is: its unit guessed from its size, quarter turns
// about an axis, and a scale and shift that put its cranium on the built-in head's.
import type { Axis } from '../model/session';
import type { Vec3 } from '../model/vec3';

export type HeadUnit = 'mm' | 'cm' | 'dm' | 'm' | 'unknown';

// The built-in head's cranium (measured on buildHead(); a unit test keeps these in step): its
// top, and the x width and x/z centre of its vertices within BAND of the top.
export const BUILTIN_CRANIUM = {
  top: 0.9992,
  band: 1.0,
  width: 1.5765,
  centerX: 0.0008,
  centerZ: -0.0142,
} as const;

// A real head (with or without neck and shoulders) measures 12 to 60 cm along its longest side.
const HEAD_CM_MIN = 12;
const HEAD_CM_MAX = 60;
const UNITS: ReadonlyArray<{ unit: HeadUnit; cm: number }> = [
  { unit: 'mm', cm: 0.1 },
  { unit: 'cm', cm: 1 },
  { unit: 'dm', cm: 10 },
  { unit: 'm', cm: 100 },
];
const APP_UNIT_CM = 10;

/** The unit a head whose longest extent is `longest` (file units) is in, and app units per file
 *  unit (null when no unit gives a head's size: the head is then scaled to the built-in one). */
export function guessUnit(longest: number): { unit: HeadUnit; unitScale: number | null } {
  const guess = UNITS.find((u) => longest * u.cm >= HEAD_CM_MIN && longest * u.cm < HEAD_CM_MAX);
  return { unit: guess ? guess.unit : 'unknown', unitScale: guess ? guess.cm / APP_UNIT_CM : null };
}

export function extents(P: Float32Array): Vec3 {
  const b = bounds(P);
  return [b.max[0] - b.min[0], b.max[1] - b.min[1], b.max[2] - b.min[2]];
}

export function bounds(P: Float32Array): { min: Vec3; max: Vec3 } {
  const min: Vec3 = [Infinity, Infinity, Infinity];
  const max: Vec3 = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < P.length; i += 3) {
    for (let a = 0; a < 3; a++) {
      const x = P[i + a];
      if (x < min[a]) min[a] = x;
      if (x > max[a]) max[a] = x;
    }
  }
  return { min, max };
}

/** Rotate positions in place by q quarter turns about the axis (right-handed). */
export function rotateQuarter(P: Float32Array, axis: Axis, q: 0 | 1 | 2 | 3): void {
  if (q === 0) return;
  const [i, j] = axis === 'x' ? [1, 2] : axis === 'y' ? [2, 0] : [0, 1];
  for (let v = 0; v < P.length; v += 3) {
    const a = P[v + i];
    const b = P[v + j];
    if (q === 1) {
      P[v + i] = -b;
      P[v + j] = a;
    } else if (q === 2) {
      P[v + i] = -a;
      P[v + j] = -b;
    } else {
      P[v + i] = b;
      P[v + j] = -a;
    }
  }
}

/** Scale (by `unitScale`, or to the built-in head's cranium width when null) and translate the
 *  positions in place so the cranium sits where the built-in head's does. Returns the scale. */
export function place(P: Float32Array, unitScale: number | null): { scale: number } {
  let scale = unitScale ?? 1;
  if (unitScale === null) {
    // no unit: first bring the longest side to the built-in head's height, then fit the width
    const e = extents(P);
    scale = 3.6 / Math.max(e[0], e[1], e[2]);
  }
  for (let i = 0; i < P.length; i++) P[i] *= scale;
  let cranium = craniumOf(P, 1);
  // the band is 10 cm on the built-in head: scale it with the head (two refinements)
  for (let k = 0; k < 2; k++)
    cranium = craniumOf(P, clampSize(cranium.width / BUILTIN_CRANIUM.width));
  if (unitScale === null) {
    const s = BUILTIN_CRANIUM.width / cranium.width;
    for (let i = 0; i < P.length; i++) P[i] *= s;
    scale *= s;
    cranium = craniumOf(P, 1);
  }
  const size = clampSize(cranium.width / BUILTIN_CRANIUM.width);
  const shift: Vec3 = [
    BUILTIN_CRANIUM.centerX * size - cranium.centerX,
    BUILTIN_CRANIUM.top * size - cranium.top,
    BUILTIN_CRANIUM.centerZ * size - cranium.centerZ,
  ];
  for (let i = 0; i < P.length; i += 3) {
    P[i] += shift[0];
    P[i + 1] += shift[1];
    P[i + 2] += shift[2];
  }
  return { scale };
}

const clampSize = (s: number) => Math.min(2, Math.max(0.5, Number.isFinite(s) ? s : 1));

/** Top, and x width and x/z centre of the vertices within `size` × BAND of the top. */
function craniumOf(P: Float32Array, size: number) {
  let top = -Infinity;
  for (let i = 1; i < P.length; i += 3) if (P[i] > top) top = P[i];
  const floor = top - BUILTIN_CRANIUM.band * size;
  let x0 = Infinity;
  let x1 = -Infinity;
  let z0 = Infinity;
  let z1 = -Infinity;
  for (let i = 0; i < P.length; i += 3) {
    if (P[i + 1] < floor) continue;
    if (P[i] < x0) x0 = P[i];
    if (P[i] > x1) x1 = P[i];
    if (P[i + 2] < z0) z0 = P[i + 2];
    if (P[i + 2] > z1) z1 = P[i + 2];
  }
  return { top, width: x1 - x0, centerX: (x0 + x1) / 2, centerZ: (z0 + z1) / 2 };
}
