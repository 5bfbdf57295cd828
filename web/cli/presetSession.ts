// A preset's session as the app builds it on load (app/app.ts): the preset's curves sketched on
// the built-in head at the grid's step, from the viewer's default camera. For tests and
// measurements of `hairsketch grow` (write it to a file with JSON.stringify, as "Save" does).
import type { Head } from '../head/head';
import { type GridPreset, gridForPreset } from '../model/grid';
import { applyPreset, type PresetName } from '../model/presets';
import { DEFAULT_GROWTH, emptySession, type SessionState } from '../model/session';
import { DEFAULT_CAMERA } from '../viewer/defaultCamera';

export function presetSession(
  name: PresetName,
  head: Head,
  grid: GridPreset = '25k',
  maxStrands = 0,
): SessionState {
  return applyPreset(emptySession(grid, { ...DEFAULT_GROWTH, maxStrands }), name, {
    head,
    step: gridForPreset(grid).step,
    viewpoint: { position: [...DEFAULT_CAMERA.position], target: [...DEFAULT_CAMERA.target] },
  });
}
