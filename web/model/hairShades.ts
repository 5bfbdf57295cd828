// Named hair colours, as a stylist names them: the levels of the colour chart (black … platinum
// blonde), its red tones (strawberry blonde, copper, auburn), salt and pepper and silver. Each is
// the colour model's settings (hairLook.ts) whose hair, drawn, reads as the name: melanin sets the
// level; red hair takes a dye as well, since in the model pheomelanin hardly moves the hue (it
// stays near 33° whatever the redness: red hair would read as brown). Chosen from pictures of the
// bob at 25,000 strands from behind, the hair's body colour (the middle half of its pixels by
// luminance) against each melanin, and adjusted after a colourist named them blind (11 of 13
// first; platinum and silver looked alike, the reds looked dyed); Platinum is ivory and Silver
// cool, 15 % of its strands still dark and a greyer dye (all white, judges saw "stark white, not
// silver" and a crown "clipped to white"). tests/unit/hairColourRender.test.ts checks the named ranges in Fast and High. The Hair panel's "Shade" sets them in one edit, each still editable.
import { DEFAULT_HAIR_LOOK, type HairLook, hasTips } from './hairLook';

export interface HairShade {
  id: string;
  name: string;
  melanin: number;
  /** The pheomelanin share of its melanin. */
  redness: number;
  /** A dye (#rrggbb) for the red tones, or null. */
  dye: string | null;
  /** Share of grey strands, percent. */
  grey: number;
  /** The dye of its lighter tips when it is not the shade's own dye (the reds: lightened red
   *  hair loses its brown first and turns copper-gold), or null. */
  tipDye: string | null;
}

const shade = (
  id: string,
  name: string,
  melanin: number,
  redness: number,
  dye: string | null = null,
  grey = 0,
  tipDye: string | null = null,
): HairShade => ({ id, name, melanin, redness, dye, grey, tipDye });

/** The shades in the panel's order: the levels from dark to light, the reds, the greys. */
export const HAIR_SHADES: readonly HairShade[] = [
  shade('black', 'Black', 0.85, 0.1),
  shade('dark-brown', 'Dark brown', 0.35, 0.25),
  shade('medium-brown', 'Medium brown', 0.22, 0.3),
  shade('light-brown', 'Light brown', 0.13, 0.3),
  shade('dark-blonde', 'Dark blonde', 0.07, 0.35),
  shade('blonde', 'Blonde', 0.035, 0.5),
  shade('light-blonde', 'Light blonde', 0.01, 0.5, '#ffd8a0'),
  shade('platinum', 'Platinum blonde', 0.006, 0.3, '#fff0c8'),
  // the reds' tips lightened with their own dye read "salmon-pink" (auburn; a colourist):
  // copper-gold for auburn, a paler gold for strawberry blonde
  shade('strawberry', 'Strawberry blonde', 0.015, 1, '#ffb0a0', 0, '#ffc898'),
  shade('copper', 'Copper', 0.045, 1, '#ff8250'),
  shade('auburn', 'Auburn', 0.3, 1, '#ff8070', 0, '#ffa868'),
  // 18 % of the strands grey: the white strands are brighter than the black ones by far, so they
  // take over (at 40 % the hair read "an even mid grey"; at 25 %, "a mid pewter grey, far more
  // than 25 %", and a colourist preferred 18 % to 25 % side by side)
  shade('salt-pepper', 'Salt and pepper', 0.85, 0.1, null, 18),
  shade('silver', 'Silver', 0.35, 0.25, '#cdd6ec', 85),
];

/** The shade named `id` (HairShade.id), or null. */
export function shadeById(id: string): HairShade | null {
  return HAIR_SHADES.find((s) => s.id === id) ?? null;
}

/** The dye of a shade's lighter tips when the shade has none of its own: a warm honey, as a
 *  balayage's lightener leaves hair (the melanin alone, lightened four levels, reads ash-olive
 *  at the ends of brown hair). The Light blonde shade's dye. */
export const WARM_TIP_DYE = '#ffd8a0';

/** The look with a shade: its pigment and grey share; lighter tips, variation and roughness
 *  kept (tips then lighten the shade: an eighth of its melanin amount, its tip dye, its dye or
 *  else WARM_TIP_DYE). */
export function withShade(look: HairLook | null, shade: HairShade): HairLook {
  const base = look ?? DEFAULT_HAIR_LOOK;
  const shaded: HairLook = {
    ...base,
    melanin: shade.melanin,
    redness: shade.redness,
    dye: shade.dye,
    grey: shade.grey,
    tipMelanin: shade.melanin,
    tipDye: null,
  };
  return hasTips(base) ? withLighterTips(shaded) : shaded;
}

/** The look with tips lighter than its roots, as a Shade with Tips on gives them (an eighth of
 *  the melanin amount; the tip dye of the shade whose dye the look has, else the look's dye, else
 *  WARM_TIP_DYE), unless its tips are lighter already: turning Tips on shows a balayage at once,
 *  not tips of the roots' colour. */
export function withLighterTips(look: HairLook): HairLook {
  if (look.tipMelanin < look.melanin) return look;
  const ownTips = look.dye ? HAIR_SHADES.find((s) => s.dye === look.dye)?.tipDye : null;
  return {
    ...look,
    tipMelanin: lighterMelanin(look.melanin),
    tipDye: ownTips ?? look.dye ?? WARM_TIP_DYE,
  };
}

/** The shade a look has (its pigment and grey share as the shade sets them), or null. */
export function shadeOf(look: HairLook | null): HairShade | null {
  if (!look) return null;
  return (
    HAIR_SHADES.find(
      (s) =>
        look.melanin === s.melanin &&
        look.redness === s.redness &&
        look.dye === s.dye &&
        look.grey === s.grey,
    ) ?? null
  );
}

/** An eighth of the melanin amount (−ln(1 − m)): tips four levels or so lighter, as a balayage
 *  lifts them (half the amount barely showed on long auburn hair; a quarter, mixed along the
 *  strand in log space as hairLook.ts mixAbsorption does, showed as faintly lighter ends). */
function lighterMelanin(m: number): number {
  return Math.round((1 - (1 - m) ** 0.125) * 1000) / 1000;
}
