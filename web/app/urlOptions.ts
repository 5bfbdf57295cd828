// Query options: ?preset=default|empty, ?grid=25k|50k|100k|250k, ?strands=N (cap, for small
// test scenes), ?solver=fast|exact|cg|auto.
import { type GridPreset, isGridPreset } from '../model/grid';
import { isPresetName, type PresetName } from '../model/presets';
import type { SolverName } from '../solver/protocol';

const SOLVERS: readonly SolverName[] = ['fast', 'exact', 'cg', 'auto'];

export interface UrlOptions {
  preset: PresetName;
  grid: GridPreset;
  maxStrands: number; // 0 = no cap
  solver: SolverName;
  warnings: string[]; // unknown or malformed values, reported in the status line
}

export function parseUrlOptions(search: string): UrlOptions {
  const q = new URLSearchParams(search);
  const out: UrlOptions = {
    preset: 'default',
    grid: '25k',
    maxStrands: 0,
    solver: 'fast',
    warnings: [],
  };
  const solver = q.get('solver');
  if (solver !== null) {
    const known = SOLVERS.find((s) => s === solver);
    if (known) out.solver = known;
    else out.warnings.push(`unknown solver "${solver.slice(0, 40)}" (using fast)`);
  }
  const preset = q.get('preset');
  if (preset !== null) {
    if (isPresetName(preset)) out.preset = preset;
    else out.warnings.push(`unknown preset "${preset.slice(0, 40)}" (using default)`);
  }
  const grid = q.get('grid');
  if (grid !== null) {
    if (isGridPreset(grid)) out.grid = grid;
    else out.warnings.push(`unknown grid "${grid.slice(0, 40)}" (using 25k)`);
  }
  const strands = q.get('strands');
  if (strands !== null) {
    const n = Number(strands);
    if (Number.isInteger(n) && n >= 1 && n <= 1_000_000) out.maxStrands = n;
    else out.warnings.push(`strands must be an integer from 1 to 1000000 (ignored)`);
  }
  return out;
}
