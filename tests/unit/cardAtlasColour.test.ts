// The cards atlas keeps the strands' colour: the mean colour (linear light) of the atlas's covered
// pixels against the base colour that the colour model gives the preset's hairLook (its melanin,
// redness and dye), computed here from melanin.ts alone (Unreal's GetHairColorFromMelanin). Synthetic hanging strands (no solver),
// so the test costs a fraction of a second beside the atlas's drawing.
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { makeHairCards } from '../../web/export/cardsWriter';
import { srgbToLinear, strandsForExport } from '../../web/export/strandsForExport';
import { Head } from '../../web/head/head';
import { hexToLinear } from '../../web/model/hairLook';
import { hairColorFromMelanin } from '../../web/model/melanin';
import type { PresetName } from '../../web/model/presets';

/** n strands hanging from a ring around the crown, `np` points each, 2 units (20 cm) long. */
function hangingStrands(n: number, np: number) {
  const points = new Float32Array(3 * n * np);
  const strandStart = new Uint32Array(n + 1);
  for (let s = 0; s < n; s++) {
    strandStart[s + 1] = (s + 1) * np;
    const a = (2 * Math.PI * s) / n;
    const r = 0.9 + (0.1 * ((s * 7919) % 13)) / 13;
    for (let k = 0; k < np; k++) {
      const p = 3 * (s * np + k);
      const t = k / (np - 1);
      points[p] = r * Math.cos(a) * (1 + 0.2 * t);
      points[p + 1] = 1 - 2 * t;
      points[p + 2] = r * Math.sin(a) * (1 + 0.2 * t);
    }
  }
  return { points, strandStart };
}

describe('cards atlas colour', () => {
  const head = Head.builtin();
  for (const preset of ['bob', 'curly', 'braid'] as PresetName[]) {
    it(`${preset}: the atlas's mean colour is the colour model's (within 12 % a channel)`, () => {
      const session = presetSession(preset, head);
      const look = session.hairLook;
      if (!look) throw new Error('preset without a hairLook');
      expect(look.tipLength).toBe(0); // no lighter tips: one colour from root to tip
      expect(look.tipStart).toBeUndefined();
      // with its dye (curly's copper has one)
      const dye = look.dye ? hexToLinear(look.dye) : null;
      const want = hairColorFromMelanin(look.melanin, look.redness, dye);
      const exported = strandsForExport(hangingStrands(600, 16), session);
      const { atlas } = makeHairCards(exported, 100, session.growth.seed);
      const sum = [0, 0, 0];
      let weight = 0;
      for (let i = 0; i < atlas.size * atlas.size; i++) {
        const a = atlas.colour[4 * i + 3] / 255;
        if (a < 0.5) continue; // what the alpha test keeps
        for (let q = 0; q < 3; q++) sum[q] += srgbToLinear(atlas.colour[4 * i + q] / 255);
        weight++;
      }
      expect(weight).toBeGreaterThan(10_000);
      for (let q = 0; q < 3; q++) {
        const got = sum[q] / weight;
        // 12 %, or an sRGB byte's step near black (one byte near 0 is 0.0003 in linear)
        const tolerance = Math.max(0.12 * want[q], 0.001);
        expect(Math.abs(got - want[q]), `channel ${q}: ${got} vs ${want[q]}`).toBeLessThan(
          tolerance,
        );
      }
    });
  }
});
