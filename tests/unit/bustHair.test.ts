// Hair rests on the bust (issue 37), through the whole pipeline with the real wasm solver: the
// `long` preset at 60 cm with natural fall, its strokes extended leaves no strand point more than 1 mm inside the bust
// (measured with the bust's own signed distance, head/bodySdf.ts, not the solver's grid of it);
// strands keep their length within 1 % of the same hair without the bust; the same session
// grows the same bytes. (Without `bust` the hair is the head-alone hair: old sessions' fixtures.)
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { bodySdf } from '../../web/head/bodySdf';
import { Head } from '../../web/head/head';
import type { StrandArrays } from '../../web/model/hairArrays';
import type { SessionState } from '../../web/model/session';
import { growOnBuiltinHead } from '../support/growOnBuiltinHead';

const head = Head.builtin();
// the long preset with its strokes' hair growing on past their ends ("Extend past the end"):
// the maximum length ends every strand, over the shoulders
// without its natural detail, whose length jitter ends strands short of the maximum length
const { detail: _detail, ...long } = presetSession('long', head, '25k', 0);
const session: SessionState = {
  ...long,
  growth: { ...long.growth, maxLength: 6 },
  curves: long.curves.map((c) => ('extend' in c ? { ...c, extend: true } : c)),
};

const grow = (s: SessionState): Promise<StrandArrays> => growOnBuiltinHead(s, 3000);

const lengths = (h: StrandArrays): number[] => {
  const out: number[] = [];
  for (let k = 0; k + 1 < h.strandStart.length; k++) {
    let l = 0;
    for (let p = h.strandStart[k] + 1; p < h.strandStart[k + 1]; p++)
      l += Math.hypot(
        h.points[3 * p] - h.points[3 * p - 3],
        h.points[3 * p + 1] - h.points[3 * p - 2],
        h.points[3 * p + 2] - h.points[3 * p - 1],
      );
    out.push(l);
  }
  return out;
};

describe('long hair on the bust', () => {
  it('no point more than 1 mm inside the bust; lengths kept within 1 %; the same bytes again', async () => {
    expect(session.bust).toBe(true);
    const on = await grow(session);
    const { bust: _, ...headAlone } = session;
    const off = await grow(headAlone);
    // inside the bust: the bust's signed distance (negative inside) below -1 mm
    let inside = 0;
    let onBody = 0;
    for (let p = 0; p < on.points.length; p += 3) {
      const d = bodySdf(on.points[p], on.points[p + 1], on.points[p + 2]);
      if (d < -0.01) inside++;
      if (d < 0.03) onBody++;
    }
    // hair reaches the bust at all (it would pass through it without the collider)
    let throughBody = 0;
    for (let p = 0; p < off.points.length; p += 3)
      if (bodySdf(off.points[p], off.points[p + 1], off.points[p + 2]) < -0.01) throughBody++;
    // lengths: the same roots (the same scalp and seed), strand by strand, of the strands the
    // maximum length ends (a strand that ends where its stroke says ends at a place, and one
    // that goes round a shoulder to get there is longer)
    expect(on.strandStart.length).toBe(off.strandStart.length);
    const a = lengths(on);
    const b = lengths(off);
    const max = session.growth.maxLength;
    const ratios: number[] = [];
    for (let k = 0; k < a.length; k++)
      if (b[k] > 0.99 * max) ratios.push(Math.abs(a[k] / b[k] - 1));
    ratios.sort((x, y) => x - y);
    const median = ratios[Math.floor(ratios.length / 2)];
    const within = ratios.filter((r) => r <= 0.01).length / ratios.length;
    console.log(
      `[bust] long, extended, 60 cm, ${a.length} strands: points > 1 mm inside the bust ${inside} (without the collider ${throughBody}); points within 3 mm of it ${onBody}; strands at the maximum length ${ratios.length}, their length change vs head alone: median ${(100 * median).toFixed(2)} %, ${(100 * within).toFixed(1)} % of strands within 1 %`,
    );
    expect(throughBody).toBeGreaterThan(0);
    expect(inside).toBe(0);
    expect(ratios.length).toBeGreaterThan(100);
    expect(median).toBeLessThanOrEqual(0.01);
    expect(within).toBeGreaterThanOrEqual(0.9);
    const again = await grow(session);
    expect(Buffer.from(again.points.buffer).equals(Buffer.from(on.points.buffer))).toBe(true);
  });
});
