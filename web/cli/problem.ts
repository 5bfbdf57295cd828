// PROBLEM.json for `hairsketch solve`: a grid box, omega, and steps of constraint edits.
//   {"grid": [nx, ny, nz], "omega": 100, "steps": [{"set": [[i, j, k, cx, cy, cz], ...],
//    "unset": [[i, j, k], ...]}, ...]}
// Grid point (i, j, k) has index p = i + nx * (j + ny * k). Constraints persist between steps.
// Decoding is strict and returns a one-line error instead of throwing.
import { oneLine } from '../model/oneLine';

export interface Problem {
  grid: [number, number, number];
  omega: number;
  steps: Array<{
    set: Array<[number, number, number, number, number, number]>;
    unset: Array<[number, number, number]>;
  }>;
}

export type Decoded<T> = { ok: true; value: T } | { ok: false; error: string };

/** Largest grid accepted (points); the solvers' own memory checks apply below it. */
export const MAX_GRID_POINTS = 4_000_000;

const isObject = (v: unknown): v is Record<string, unknown> =>
  typeof v === 'object' && v !== null && !Array.isArray(v);

function unknownKeys(o: Record<string, unknown>, allowed: string[], where: string): string | null {
  for (const k of Object.keys(o))
    if (!allowed.includes(k)) return `unknown key "${oneLine(k, 40)}" in ${where}`;
  return null;
}

export function decodeProblem(text: string): Decoded<Problem> {
  let raw: unknown;
  try {
    raw = JSON.parse(text);
  } catch (e) {
    return { ok: false, error: `not valid JSON: ${oneLine((e as Error).message)}` };
  }
  if (!isObject(raw)) return { ok: false, error: 'the problem must be a JSON object' };
  const bad = unknownKeys(raw, ['grid', 'omega', 'steps'], 'the problem');
  if (bad) return { ok: false, error: bad };
  const g = raw.grid;
  if (!Array.isArray(g) || g.length !== 3 || !g.every((x) => Number.isInteger(x) && x >= 2))
    return { ok: false, error: '"grid" must be [nx, ny, nz], integers >= 2' };
  const grid = g as [number, number, number];
  const n = grid[0] * grid[1] * grid[2];
  if (n > MAX_GRID_POINTS)
    return {
      ok: false,
      error: `grid of ${n} points is past the memory cap of ${MAX_GRID_POINTS} points`,
    };
  const omega = raw.omega === undefined ? 100 : raw.omega;
  if (typeof omega !== 'number' || !Number.isFinite(omega) || omega <= 0)
    return { ok: false, error: '"omega" must be a finite number > 0' };
  if (!Array.isArray(raw.steps)) return { ok: false, error: '"steps" must be an array' };
  const inGrid = (i: unknown, j: unknown, k: unknown) =>
    Number.isInteger(i) &&
    Number.isInteger(j) &&
    Number.isInteger(k) &&
    (i as number) >= 0 &&
    (j as number) >= 0 &&
    (k as number) >= 0 &&
    (i as number) < grid[0] &&
    (j as number) < grid[1] &&
    (k as number) < grid[2];
  const steps: Problem['steps'] = [];
  for (let s = 0; s < raw.steps.length; s++) {
    const st = raw.steps[s];
    if (!isObject(st)) return { ok: false, error: `step ${s} must be an object` };
    const badKey = unknownKeys(st, ['set', 'unset'], `step ${s}`);
    if (badKey) return { ok: false, error: badKey };
    const set = st.set ?? [];
    const unset = st.unset ?? [];
    if (!Array.isArray(set) || !Array.isArray(unset))
      return { ok: false, error: `step ${s}: "set" and "unset" must be arrays` };
    for (let e = 0; e < set.length; e++) {
      const v = set[e];
      if (!Array.isArray(v) || v.length !== 6)
        return { ok: false, error: `step ${s} set[${e}] must be [i, j, k, cx, cy, cz]` };
      if (!inGrid(v[0], v[1], v[2]))
        return {
          ok: false,
          error: `step ${s} set[${e}]: index (${oneLine(v.slice(0, 3).join(', '), 80)}) is outside the grid`,
        };
      if (!v.slice(3).every((x) => typeof x === 'number' && Number.isFinite(x)))
        return { ok: false, error: `step ${s} set[${e}]: target is not finite` };
    }
    for (let e = 0; e < unset.length; e++) {
      const v = unset[e];
      if (!Array.isArray(v) || v.length !== 3 || !inGrid(v[0], v[1], v[2]))
        return { ok: false, error: `step ${s} unset[${e}] must be [i, j, k] inside the grid` };
    }
    steps.push({
      set: set as Problem['steps'][number]['set'],
      unset: unset as Problem['steps'][number]['unset'],
    });
  }
  return { ok: true, value: { grid, omega, steps } };
}

/** Applies the steps one by one, yielding the constraint map after each (index -> target). */
export function* constraintStates(p: Problem): Generator<Map<number, [number, number, number]>> {
  const [nx, ny] = p.grid;
  const current = new Map<number, [number, number, number]>();
  for (const st of p.steps) {
    for (const [i, j, k] of st.unset) current.delete(i + nx * (j + ny * k));
    for (const [i, j, k, cx, cy, cz] of st.set) current.set(i + nx * (j + ny * k), [cx, cy, cz]);
    yield current;
  }
}
