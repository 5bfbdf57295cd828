// The melanin → absorption → colour mapping against values worked out by hand (Python, from
// the published coefficients: d'Eon et al. 2011's eumelanin (0.506, 0.841, 1.653) and
// pheomelanin (0.343, 0.733, 1.924), Chiang et al. 2016's D(β) polynomial at β = 0.3), not from
// this code.
import { describe, expect, it } from 'vitest';
import {
  absorptionColor,
  colorAbsorption,
  colorScale,
  hairColorFromMelanin,
  melaninAbsorption,
} from '../../web/model/melanin';

function close(a: readonly number[], b: readonly number[], digits = 5): void {
  for (const [i, v] of a.entries()) expect(v).toBeCloseTo(b[i], digits);
}

describe('melanin mapping (d’Eon 2011, Chiang 2016)', () => {
  it('D(0.3) is 5.888415', () => {
    expect(colorScale(0.3)).toBeCloseTo(5.888415, 5);
  });

  it('absorption of melanin and redness', () => {
    // m = −ln(1 − 0.5) = 0.693147, all eumelanin
    close(melaninAbsorption(0.5, 0), [0.350732, 0.582937, 1.145772]);
    close(melaninAbsorption(0.25, 0), [0.145567, 0.241941, 0.475538]);
    // m = −ln(0.2) = 1.609438, half of it pheomelanin
    close(melaninAbsorption(0.8, 0.5), [0.683206, 1.266628, 2.87848]);
    // melanin 1 is capped at m = −ln(1e−4)
    close(melaninAbsorption(1, 0), [4.660432, 7.745896, 15.224693]);
    close(melaninAbsorption(0, 0.7), [0, 0, 0]);
  });

  it('base colour exp(−√σa · D(0.3))', () => {
    close(hairColorFromMelanin(0.5, 0), [0.030584, 0.011156, 0.001831]);
    close(hairColorFromMelanin(0.25, 0), [0.105756, 0.055224, 0.017239]);
    close(hairColorFromMelanin(0.8, 0.5), [0.007695, 0.001324, 0.000046]);
    close(hairColorFromMelanin(0, 0), [1, 1, 1]);
  });

  it('a dye adds (ln C / D)²; a colour maps back to itself', () => {
    close(colorAbsorption([0.8, 0.2, 0.1]), [0.001436, 0.074705, 0.15291]);
    close(absorptionColor(colorAbsorption([0.8, 0.2, 0.1])), [0.8, 0.2, 0.1]);
    // no melanin, only the dye: the dye's own colour
    close(hairColorFromMelanin(0, 0, [0.8, 0.2, 0.1]), [0.8, 0.2, 0.1]);
    // melanin 0.25 dyed: the absorptions add
    const s = [0.145567 + 0.001436, 0.241941 + 0.074705, 0.475538 + 0.15291];
    close(
      hairColorFromMelanin(0.25, 0, [0.8, 0.2, 0.1]),
      s.map((v) => Math.exp(-Math.sqrt(v) * 5.888415)),
    );
  });
});
