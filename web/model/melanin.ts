// Hair colour from pigment (d'Eon et al. 2011, as Blender's Principled Hair BSDF and Unreal's
// GetHairColorFromMelanin use it), pure arithmetic:
//   m = −ln(max(1 − melanin, 1e−4))          melanin ∈ [0, 1] (0 white … 1 black)
//   eumelanin = m (1 − redness), pheomelanin = m · redness
//   σa = eumelanin · (0.506, 0.841, 1.653) + pheomelanin · (0.343, 0.733, 1.924)   (RGB, per
//        unit of fibre radius)
// A dye (tint) colour C adds σ(C) = (ln C / D(β))², the inverse of the colour mapping below
// (Chiang et al. 2016), with D(β) = 5.969 − 0.215β + 2.532β² − 10.73β³ + 5.574β⁴ + 0.245β⁵
// (β the azimuthal roughness). The base colour (linear RGB, the multiply scattered albedo a
// head of such hair shows) is exp(−√σa · D(β)); Unreal fixes β = 0.3 (D ≈ 5.888).

export type Rgb = [number, number, number];

/** Absorption of one unit of eumelanin and of pheomelanin (d'Eon et al. 2011), RGB. */
export const EUMELANIN_SIGMA: Readonly<Rgb> = [0.506, 0.841, 1.653];
export const PHEOMELANIN_SIGMA: Readonly<Rgb> = [0.343, 0.733, 1.924];

/** The azimuthal roughness the colour mapping is taken at (Unreal's). */
export const COLOR_BETA = 0.3;

/** Chiang et al. 2016's D(β): ln(colour) = −√σa · D(β). */
export function colorScale(beta: number): number {
  const b = beta;
  return 5.969 - 0.215 * b + 2.532 * b ** 2 - 10.73 * b ** 3 + 5.574 * b ** 4 + 0.245 * b ** 5;
}

/** σa of hair with this melanin (0..1) and redness (0..1, the pheomelanin share). */
export function melaninAbsorption(melanin: number, redness: number): Rgb {
  const m = -Math.log(Math.max(1 - clamp01(melanin), 1e-4));
  const eu = m * (1 - clamp01(redness));
  const pheo = m * clamp01(redness);
  return [0, 1, 2].map((c) => eu * EUMELANIN_SIGMA[c] + pheo * PHEOMELANIN_SIGMA[c]) as Rgb;
}

/** σa of a colour (linear RGB, each in (0, 1]): the absorption whose base colour it is. */
export function colorAbsorption(color: Readonly<Rgb>, beta = COLOR_BETA): Rgb {
  const d = colorScale(beta);
  return color.map((c) => (Math.log(Math.min(1, Math.max(c, 1e-4))) / d) ** 2) as Rgb;
}

/** The base colour (linear RGB) of hair with absorption σa. */
export function absorptionColor(sigma: Readonly<Rgb>, beta = COLOR_BETA): Rgb {
  const d = colorScale(beta);
  return sigma.map((s) => Math.exp(-Math.sqrt(Math.max(0, s)) * d)) as Rgb;
}

/** Unreal's GetHairColorFromMelanin: the base colour (linear RGB) of melanin and redness, with
 *  a dye colour (linear RGB; null: none) adding its absorption. */
export function hairColorFromMelanin(
  melanin: number,
  redness: number,
  dye: Readonly<Rgb> | null = null,
): Rgb {
  const s = melaninAbsorption(melanin, redness);
  if (dye) {
    const d = colorAbsorption(dye);
    for (let c = 0; c < 3; c++) s[c] += d[c];
  }
  return absorptionColor(s);
}

function clamp01(v: number): number {
  return v > 0 ? Math.min(v, 1) : 0;
}
