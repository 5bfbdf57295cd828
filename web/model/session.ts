// The session model: everything the user made, as plain immutable JSON-able data.
import type { GrowthParams } from '../solver/protocol';
import type { GridPreset } from './grid';
import type { Vec3 } from './vec3';

export interface Viewpoint {
  position: Vec3; // camera position when the curve was drawn
  target: Vec3; // orbit target
}

export interface StreamCurve {
  id: string;
  type: 'stream';
  points: Vec3[]; // world units, consecutive distance = grid step d
  extend: boolean; // append fading extrapolated segments (S4.1)
  viewpoint: Viewpoint;
}

export type StyleCurve = StreamCurve;

export interface SessionState {
  version: 1;
  head: 'builtin';
  grid: GridPreset;
  curves: readonly StyleCurve[];
  growth: GrowthParams;
  hairColor: string; // CSS hex colour
}

export const DEFAULT_GROWTH: GrowthParams = {
  thetaStepDeg: 1.0,
  phiStepDeg: 1.0,
  jitter: 0.8,
  seed: 20070807,
  stepFraction: 0.5,
  minMagnitude: 0.05,
  maxLength: 3.2,
  maxSegments: 120,
  maxStrands: 0,
};

export function emptySession(
  grid: GridPreset,
  growth: GrowthParams = DEFAULT_GROWTH,
): SessionState {
  return { version: 1, head: 'builtin', grid, curves: [], growth, hairColor: '#5a3825' };
}

export function addCurve(s: SessionState, c: StyleCurve): SessionState {
  return { ...s, curves: [...s.curves, c] };
}

export function deleteCurve(s: SessionState, id: string): SessionState {
  const curves = s.curves.filter((c) => c.id !== id);
  return curves.length === s.curves.length ? s : { ...s, curves };
}

/** Curve ids are unique within a session: a counter past the largest id in use. */
export function nextCurveId(s: SessionState): string {
  let max = 0;
  for (const c of s.curves) {
    const m = /^c(\d+)$/.exec(c.id);
    if (m) max = Math.max(max, Number(m[1]));
  }
  return `c${max + 1}`;
}
