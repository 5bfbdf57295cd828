// The hair's colour model: pigment (melanin, redness), a dye, a share of grey (unpigmented)
// strands, lighter tips (a balayage: the tip colour fades in over a length measured from each
// strand's tip, so short and long strands of one style lighten over the same last centimetres), a
// seeded per-strand spread of melanin and roughness, and the roughness itself. A session without
// one (older sessions, or a colour picked in the colour box) shows its direct colour: the
// absorption whose base colour it is (melanin.ts), varied per strand a little. Pure arithmetic: the strand shader (viewer/strandShaders.ts) takes
// lookUniforms(), the exports strandLookColor() (linear RGB).
import { absorptionColor, colorAbsorption, melaninAbsorption, type Rgb } from './melanin';
import { smoothstep } from './smoothstep';

export interface HairLook {
  /** Melanin 0 (white) … 1 (black). */
  melanin: number;
  /** Redness 0 … 1: the pheomelanin share. */
  redness: number;
  /** A dye (tint) colour, #rrggbb (sRGB), or null for none. */
  dye: string | null;
  /** Share of strands without pigment, percent (0 … 100). */
  grey: number;
  /** The tips' melanin (the lighter tips' colour; the same redness). */
  tipMelanin: number;
  /** The tips' dye, or null. */
  tipDye: string | null;
  /** Lighter tips: the length from each strand's tip over which the tip colour fades in, world
   *  units (a smoothstep: the tip colour at the tip, the root colour from this far up); 0: none. */
  tipLength: number;
  /** Sessions saved before tipLength: where along each strand (0 root … 1 tip) the blend
   *  towards the tips started, a fraction of the strand (so short and long strands faded over
   *  different lengths). Read and drawn as before; absent in new looks (1 reads as absent), and
   *  never set together with tipLength: setting a length replaces it. */
  tipStart?: number;
  /** Seeded per-strand spread of melanin (and half of it of roughness), 0 … 1. */
  variation: number;
  /** Longitudinal roughness β of the BSDF (radians-like, 0.1 … 0.8). */
  roughness: number;
}

/** A natural mid brown. */
export const DEFAULT_HAIR_LOOK: HairLook = {
  melanin: 0.4,
  redness: 0.25,
  dye: null,
  grey: 0,
  tipMelanin: 0.4,
  tipDye: null,
  tipLength: 0,
  variation: 0.2,
  roughness: 0.3,
};

/** The colour of a tie's band (tieBands.ts) when the session names none: a dark elastic. */
export const DEFAULT_BAND_COLOR = '#1c1c1f';

/** Grey strands: hardly any pigment, a trace of keratin's own yellow: silver-white (base colour
 *  sRGB about (0.88, 0.85, 0.79), HSV saturation 0.1; 0.04 and 0.5 read as champagne blonde,
 *  saturation 0.31). */
export const GREY_MELANIN = 0.005;
export const GREY_REDNESS = 0.2;
/** A direct colour's per-strand spread of absorption (about ±7 % of its value). */
export const DIRECT_VARIATION = 0.15;
/** The roughness of a direct colour's hair. */
export const DIRECT_ROUGHNESS = 0.3;

/** What the strand shader takes (strandMaterial.ts uniforms of the same names). */
export interface LookUniformValues {
  rootSigma: Rgb;
  tipSigma: Rgb;
  greySigma: Rgb;
  /** grey share (0 … 1), an older session's tip start along the strand (≥ 1: none; see
   *  HairLook.tipStart), melanin variation, roughness variation. */
  shares: [number, number, number, number];
  /** Lighter tips' length from the tip, world units (0: none; HairLook.tipLength). */
  tipLength: number;
  roughness: number;
}

/** Whether the look has lighter tips: a length, or an older session's fraction. */
export function hasTips(look: HairLook): boolean {
  return look.tipLength > 0 || (look.tipStart ?? 1) < 1;
}

/** Lighter tips are painted as a balayage is, in pieces: each strand's own fade length is
 *  tipLength × (BALAYAGE_LENGTH[0] + BALAYAGE_LENGTH[1] · piece) and its own strength
 *  BALAYAGE_STRENGTH[0] … 1 (piece in [0, 1), shared by the two, so the pieces painted higher
 *  are the lighter ones: in the view, the strand's section, a few centimetres wide and lighter
 *  round the face, colourPlacement.ts). One length and one
 *  strength for every strand read as an even gradient that the hair's own shading hides; from
 *  0.6 … 1 strong and 0.8 … 1.6 × tipLength long, on sections a lock wide, as "an even
 *  top-to-bottom ombré, no separate painted lighter pieces" (a judge). */
export const BALAYAGE_LENGTH: readonly [number, number] = [0.6, 1.3];
export const BALAYAGE_STRENGTH: readonly [number, number] = [0.4, 0.6];
/** A piece has its full strength over the last BALAYAGE_FULL of its fade length and fades to the
 *  root colour over the rest (painted ends). Faded over the whole length, the share reached half
 *  strength only halfway along it, and a colourist saw "the ends lighten only slightly more than
 *  the plain hair does from lighting alone". */
export const BALAYAGE_FULL = 0.35;

/** The absorption (or melanin amount, which it is proportional to) a share `t` of the way from
 *  the root's `a` to the tips' `b`: mixed in log space, a · (b / a)^t, so the colour lightens
 *  evenly along the fade (mixed linearly, the strand stays near the root's colour until the last
 *  fifth of the fade: lighter tips read as lighter ends only). An older session's fraction
 *  (tipStart < 1) mixes linearly. The strand shader mixes alike. */
export function mixAbsorption(a: number, b: number, t: number, tipStart = 1): number {
  // an older session's fraction (tipStart < 1) mixes linearly, as it always did
  if (tipStart < 0.999) return a + (b - a) * t;
  const la = Math.log(Math.max(a, 1e-4));
  return Math.exp(la + (Math.log(Math.max(b, 1e-4)) - la) * t);
}

/** The share of the tip colour (0 root colour … 1 tip colour) at a point `tipDistance` world
 *  units from its strand's tip: strength × (1 − smoothstep(BALAYAGE_FULL · length, length,
 *  tipDistance)), the strand's length and strength by its `piece` (BALAYAGE_LENGTH,
 *  BALAYAGE_STRENGTH). An older
 *  session's fraction (tipStart < 1) instead blends by the point's place along the strand,
 *  `along` (0 root … 1 tip): smoothstep(tipStart, 1, along), as it always did. The strand
 *  shader's tipShare() is the same arithmetic. */
export function tipShare(
  tipStart: number,
  tipLength: number,
  along: number,
  tipDistance: number,
  piece: number,
): number {
  if (tipStart < 0.999) return smoothstep(tipStart, 1, along);
  if (tipLength <= 0) return 0;
  const length = tipLength * (BALAYAGE_LENGTH[0] + BALAYAGE_LENGTH[1] * piece);
  const strength = BALAYAGE_STRENGTH[0] + BALAYAGE_STRENGTH[1] * piece;
  return strength * (1 - smoothstep(BALAYAGE_FULL * length, length, tipDistance));
}

/** #rrggbb (sRGB) → linear RGB; null when it is not #rrggbb. */
export function hexToLinear(hex: string): Rgb | null {
  const m = /^#([0-9a-fA-F]{6})$/.exec(hex);
  if (!m) return null;
  const v = Number.parseInt(m[1], 16);
  return [(v >> 16) & 255, (v >> 8) & 255, v & 255].map((b) => {
    const c = b / 255;
    return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
  }) as Rgb;
}

const add = (a: Rgb, b: Rgb | null): Rgb => (b ? [a[0] + b[0], a[1] + b[1], a[2] + b[2]] : a);
const dyeSigma = (hex: string | null): Rgb | null => {
  const c = hex ? hexToLinear(hex) : null;
  return c ? colorAbsorption(c) : null;
};

/** The shader's inputs for a look (null: the direct colour `hairColor`, #rrggbb). */
export function lookUniforms(look: HairLook | null, hairColor: string): LookUniformValues {
  if (!look) {
    const s = colorAbsorption(hexToLinear(hairColor) ?? [0.1, 0.04, 0.02]);
    return {
      rootSigma: s,
      tipSigma: s,
      greySigma: s,
      shares: [0, 1, DIRECT_VARIATION, 0.5 * DIRECT_VARIATION],
      tipLength: 0,
      roughness: DIRECT_ROUGHNESS,
    };
  }
  const dye = dyeSigma(look.dye);
  const tips = hasTips(look);
  const tipStart = look.tipStart ?? 1;
  const root = add(melaninAbsorption(look.melanin, look.redness), dye);
  const tip = tips
    ? add(melaninAbsorption(look.tipMelanin, look.redness), dyeSigma(look.tipDye))
    : root;
  return {
    rootSigma: root,
    tipSigma: tip,
    greySigma: add(melaninAbsorption(GREY_MELANIN, GREY_REDNESS), dye),
    shares: [
      Math.min(1, Math.max(0, look.grey / 100)),
      tipStart,
      look.variation,
      0.5 * look.variation,
    ],
    tipLength: look.tipLength,
    roughness: look.roughness,
  };
}

/** The hair's colour at its roots (linear RGB): the base colour of its root pigment, with its
 *  grey share's; what the scalp under the hair shows (viewer/headMaterial.ts). */
export function rootColor(look: HairLook | null, hairColor: string): Rgb {
  const v = lookUniforms(look, hairColor);
  const root = absorptionColor(v.rootSigma);
  const grey = absorptionColor(v.greySigma);
  const g = v.shares[0];
  return [0, 1, 2].map((c) => root[c] + (grey[c] - root[c]) * g) as Rgb;
}

/** Linear RGB base colour of one strand at a point `along` it (0 root … 1 tip, by point) and
 *  `tipDistance` from its tip (world units, by arc length): u = its seeded random values in
 *  [0, 1) (u[0] grey pick, u[1] melanin spread, u[2] balayage piece), as the shader does it. */
export function strandLookColor(
  values: LookUniformValues,
  u: readonly [number, number, number],
  along: number,
  tipDistance: number,
): Rgb {
  const [grey, tipStart, spread] = values.shares;
  let s: Rgb;
  if (u[0] < grey) s = values.greySigma;
  else {
    const t = tipShare(tipStart, values.tipLength, along, tipDistance, u[2]);
    s = [0, 1, 2].map((c) =>
      mixAbsorption(values.rootSigma[c], values.tipSigma[c], t, tipStart),
    ) as Rgb;
  }
  const k = 1 + spread * (2 * u[1] - 1);
  return absorptionColor([s[0] * k, s[1] * k, s[2] * k]);
}

/** One strand's pigment at a point (`along`, `tipDistance` as for strandLookColor) as Blender's
 *  Principled Hair BSDF takes it (melanin parametrisation): melanin (its spread and the lighter
 *  tips applied to the amount −ln(1 − melanin)), redness, and the dye as tint (linear RGB;
 *  white: none). u as for strandLookColor. */
export function strandPigment(
  look: HairLook,
  u: readonly [number, number, number],
  along: number,
  tipDistance: number,
): { melanin: number; redness: number; tint: Rgb } {
  const dye = look.dye ? hexToLinear(look.dye) : null;
  const tint: Rgb = dye ?? [1, 1, 1];
  if (u[0] < look.grey / 100) return { melanin: GREY_MELANIN, redness: GREY_REDNESS, tint };
  const amount = (m: number) => -Math.log(Math.max(1 - Math.min(1, Math.max(0, m)), 1e-4));
  const t = tipShare(look.tipStart ?? 1, look.tipLength, along, tipDistance, u[2]);
  const m =
    mixAbsorption(amount(look.melanin), amount(look.tipMelanin), t, look.tipStart ?? 1) *
    (1 + look.variation * (2 * u[1] - 1));
  return { melanin: 1 - Math.exp(-m), redness: look.redness, tint };
}
