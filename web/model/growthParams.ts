// The session's growth settings (method S5): one table gives each its default, its accepted range
// and whether it is a whole number; the session reader and the share link follow it, and the
// solver's GROWTH_INPUT struct (solver/protocol.ts, mirrored in wasm-build/binding.cpp) carries it.

/** Hair growth settings (method S5). */
export interface GrowthParams {
  thetaStepDeg: number; // sampling step of θ ∈ [0, 180)
  phiStepDeg: number; // sampling step of φ ∈ [0, 360)
  jitter: number; // random offset as a fraction of a step, 0..1
  seed: number; // uint32: the same seed grows the same roots
  stepFraction: number; // l / d (paper: 0.5)
  minMagnitude: number; // stop when |v(p)| falls below this (paper: 0.05)
  maxLength: number; // world units: stop a strand at this length
  maxSegments: number; // stop a strand after this many segments
  maxStrands: number; // cap on the number of roots used (0 = no cap)
}

export interface GrowthFieldSpec {
  readonly default: number;
  readonly min: number;
  readonly max: number;
  /** A whole number (a count or a seed). */
  readonly integer?: boolean;
}

/** Per strand: at most this many segments; per session at most this many strands (0 = no cap). */
export const MAX_SEGMENTS = 2000;
export const MAX_STRANDS = 1_000_000;

/** Every growth setting, in the order links store them (a link's growth mask has bit i for the
 *  i-th row: add rows at the end only). Growth values are exact (not quantised). A session
 *  without a field (made before it) takes its default. */
export const GROWTH_FIELDS = {
  thetaStepDeg: { default: 1.0, min: 0.1, max: 30 },
  phiStepDeg: { default: 1.0, min: 0.1, max: 30 },
  jitter: { default: 0.8, min: 0, max: 1 },
  seed: { default: 20070807, min: 0, max: 2 ** 32 - 1, integer: true },
  stepFraction: { default: 0.5, min: 0.05, max: 4 },
  minMagnitude: { default: 0.05, min: 0, max: 1 },
  maxLength: { default: 3.2, min: 0.01, max: 100 },
  maxSegments: { default: 120, min: 1, max: MAX_SEGMENTS, integer: true },
  maxStrands: { default: 0, min: 0, max: MAX_STRANDS, integer: true },
} as const satisfies Record<keyof GrowthParams, GrowthFieldSpec>;

/** The growth settings in table order. */
export const GROWTH_KEYS = Object.keys(GROWTH_FIELDS) as (keyof GrowthParams)[];

export const DEFAULT_GROWTH: GrowthParams = Object.fromEntries(
  GROWTH_KEYS.map((k) => [k, GROWTH_FIELDS[k].default]),
) as unknown as GrowthParams;

/** Root directions the engine samples for these steps (solver-cpp scalp_roots.cpp). */
export function rootSamples(thetaStepDeg: number, phiStepDeg: number): number {
  const nT = Math.max(1, Math.ceil(180 / thetaStepDeg - 1e-9));
  const nP = Math.max(1, Math.ceil(360 / phiStepDeg - 1e-9));
  return nT * nP;
}
