// session.hairLook (hairLook.ts) in files and links: the strict reader's part (known keys,
// numbers within their ranges, dyes #rrggbb or null; a key left out takes the default) and the
// grid its numbers are kept on. Absent: the session shows its direct colour (hairColor), as
// every session made before the colour model does. Lighter tips are a length from each strand's
// tip (tipLength, world units); a session saved before it holds a fraction of the strand
// (tipStart), read and kept as it was so the session keeps its look: 1 (its "no tips") reads as
// absent, and the two are never set together.
import { DEFAULT_HAIR_LOOK, type HairLook } from './hairLook';
import { fail } from './readFailure';
import { num, record } from './readValues';
import type { Plain } from './sessionMigrations';

type NumberKey = Exclude<keyof HairLook, 'dye' | 'tipDye'>;

/** Each number of the colour model: its range and the grid it is kept on. */
export const HAIR_LOOK_NUMBERS: Readonly<
  Record<NumberKey, { min: number; max: number; quantum: number }>
> = {
  melanin: { min: 0, max: 1, quantum: 1e-3 },
  redness: { min: 0, max: 1, quantum: 1e-3 },
  grey: { min: 0, max: 100, quantum: 0.1 },
  tipMelanin: { min: 0, max: 1, quantum: 1e-3 },
  // up to the longest hair a session grows (SESSION_LIMITS: 10 units, 100 cm)
  tipLength: { min: 0, max: 10, quantum: 1e-3 },
  tipStart: { min: 0, max: 1, quantum: 1e-3 },
  variation: { min: 0, max: 1, quantum: 1e-3 },
  roughness: { min: 0.05, max: 1, quantum: 1e-3 },
};

const NUMBER_KEYS = Object.keys(HAIR_LOOK_NUMBERS) as NumberKey[];
const KEYS: readonly (keyof HairLook)[] = [
  ...(Object.keys(DEFAULT_HAIR_LOOK) as (keyof HairLook)[]),
  'tipStart', // sessions saved before tipLength only
];

/** An older session's tipStart of 1 meant no tips: the look without it. */
function withoutUnusedTipStart(look: HairLook): HairLook {
  if (look.tipStart === undefined || look.tipStart < 1) return look;
  const { tipStart: _, ...rest } = look;
  return rest;
}

function dye(v: Plain | undefined, path: string): string | null {
  if (v === undefined || v === null) return null;
  if (typeof v !== 'string' || !/^#[0-9a-fA-F]{6}$/.test(v))
    fail(path, 'must be a colour like #a04020, or null for none');
  return v.toLowerCase();
}

/** session.hairLook as the session holds it ({} when absent). */
export function readHairLook(v: Plain | undefined, path: string): { hairLook?: HairLook } {
  if (v === undefined) return {};
  const o = record(v, path, KEYS);
  const read: HairLook = { ...DEFAULT_HAIR_LOOK };
  for (const k of NUMBER_KEYS) {
    const { min, max } = HAIR_LOOK_NUMBERS[k];
    if (o[k] !== undefined) read[k] = num(o[k], `${path}.${k}`, min, max);
  }
  read.dye = dye(o.dye, `${path}.dye`);
  read.tipDye = dye(o.tipDye, `${path}.tipDye`);
  const look = withoutUnusedTipStart(read);
  if (look.tipStart !== undefined && look.tipLength > 0)
    fail(
      `${path}.tipStart`,
      'cannot be set with tipLength (a length from the tip replaces the older fraction)',
    );
  return { hairLook: look };
}

/** session.bandColor: #rrggbb, kept in lowercase ({} when absent: the default band). */
export function readBandColor(v: Plain | undefined, path: string): { bandColor?: string } {
  if (v === undefined) return {};
  if (typeof v !== 'string' || !/^#[0-9a-fA-F]{6}$/.test(v))
    fail(path, 'must be a colour like #1c1c1f');
  return { bandColor: v.toLowerCase() };
}

/** The look with its numbers on their grids (the same look when they are already). */
export function quantizeHairLook(look: HairLook): HairLook {
  let same = true;
  const out = { ...look };
  for (const k of NUMBER_KEYS) {
    const given = look[k];
    if (given === undefined) continue; // tipStart, absent in new looks
    const { min, max, quantum } = HAIR_LOOK_NUMBERS[k];
    const v = Math.min(max, Math.max(min, Math.round(given / quantum) * quantum));
    const q = Number(v.toFixed(6));
    if (q !== given) same = false;
    out[k] = q;
  }
  return same ? look : withoutUnusedTipStart(out);
}
