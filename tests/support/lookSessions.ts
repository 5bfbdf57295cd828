// Sessions the look is judged on, shared by the look pictures (scripts/look-pictures.ts) and the
// colour checks that draw the same styles (tests/unit/hairColourRender.test.ts): a preset or a
// library style as a new session draws it today.
import { readFileSync } from 'node:fs';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import { NEW_SESSION_DETAIL } from '../../web/model/presetDetail';
import type { PresetName } from '../../web/model/presets';
import type { SessionState } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';

const head = Head.builtin();

/** A preset at `strands` strands on the 25K grid. */
export const lookPreset = (name: PresetName, strands: number): SessionState =>
  presetSession(name, head, '25k', strands);

/** A preset as a new session draws it: a new session's soft hairline, low nape, tie volume,
 *  compact bun and clumps (the presets keep the hair they had without them: the bun's hair ended
 *  in a line above the nape, a judge's "swim cap") and natural detail. */
export function newSessionLook(s: SessionState): SessionState {
  const fresh = lookPreset('empty', 0);
  return {
    ...s,
    hairline: fresh.hairline,
    nape: fresh.nape,
    tieVolume: fresh.tieVolume,
    compactBun: fresh.compactBun,
    clumpAll: fresh.clumpAll,
    detail: s.detail ?? NEW_SESSION_DETAIL,
  };
}

/** The library's style `id` (public/styles) at `strands` strands. */
export function libraryStyle(id: string, strands: number): SessionState {
  const r = parseSession(JSON.parse(readFileSync(`public/styles/${id}.json`, 'utf8')));
  if (!r.ok) throw new Error(`public/styles/${id}.json: ${r.error}`);
  return { ...r.value, growth: { ...r.value.growth, maxStrands: strands } };
}

/** A library style as a new session draws it today: its strokes and settings with a new
 *  session's look (newSessionLook), its natural detail rather than the style's, and the rules
 *  its locks need (locks, the face kept clear). */
export function drawnToday(id: string, strands: number): SessionState {
  const fresh = lookPreset('empty', 0);
  return {
    ...newSessionLook({ ...libraryStyle(id, strands), detail: NEW_SESSION_DETAIL }),
    faceClear: fresh.faceClear,
    locks: fresh.locks,
  };
}
