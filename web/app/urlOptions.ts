// Query options: ?preset=default|empty, ?grid=25k|50k, ?strands=N (cap, for small test scenes).
import { type GridPreset, isGridPreset } from '../model/grid';
import { isPresetName, type PresetName } from '../model/presets';

export interface UrlOptions {
  preset: PresetName;
  grid: GridPreset;
  maxStrands: number; // 0 = no cap
  warnings: string[]; // unknown or malformed values, reported in the status line
}

export function parseUrlOptions(search: string): UrlOptions {
  const q = new URLSearchParams(search);
  const out: UrlOptions = { preset: 'default', grid: '25k', maxStrands: 0, warnings: [] };
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
