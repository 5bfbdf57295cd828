// Curl types (model/curlTypes.ts) through the whole pipeline with the real wasm solver: each
// type's detail grows hair whose curls, measured from the strands alone, have the type's radius
// and turns: the curl's axis is each strand's moving average over one of the type's turns, the
// radius the median distance from it, the turns the unwrapped angle of that offset about the
// axis. Also: the type a detail reads back as, and "straight" keeping clump and length jitter.
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import { CURL_TYPES, curlTypeOf, detailForCurlType } from '../../web/model/curlTypes';
import type { StrandArrays } from '../../web/model/hairArrays';
import type { SessionState } from '../../web/model/session';
import { growOnBuiltinHead } from '../support/growOnBuiltinHead';

const head = Head.builtin();
const long = presetSession('long', head, '25k', 0);

const grow = (s: SessionState): Promise<StrandArrays> => growOnBuiltinHead(s, 400);

type P = [number, number, number];
const sub = (a: P, b: P): P => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: P, b: P) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: P, b: P): P => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
const norm = (a: P) => Math.hypot(a[0], a[1], a[2]);
const median = (v: number[]) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];

/** Radius and turns per world unit of one strand's curl, measured over its middle 80 %; `period`
 *  is the arc length of the curled strand over about one turn. */
function measure(pts: P[], period: number): { radius: number; frequency: number } | null {
  const s = [0];
  for (let i = 1; i < pts.length; i++) s.push(s[i - 1] + norm(sub(pts[i], pts[i - 1])));
  const L = s[s.length - 1];
  if (L < 4 * period) return null;
  // the axis: the mean of the points within half a turn either side (by arc length)
  const axis: P[] = pts.map((_, i) => {
    const acc: P = [0, 0, 0];
    let n = 0;
    for (let j = 0; j < pts.length; j++)
      if (Math.abs(s[j] - s[i]) <= period / 2) {
        for (let c = 0; c < 3; c++) acc[c] += pts[j][c];
        n++;
      }
    return acc.map((v) => v / n) as P;
  });
  const radii: number[] = [];
  let angle = 0;
  let prev: P | null = null;
  let axisLength = 0;
  for (let i = 1; i + 1 < pts.length; i++) {
    if (s[i] < 0.1 * L + period / 2 || s[i] > 0.9 * L - period / 2) continue;
    const t = sub(axis[i + 1], axis[i - 1]);
    const tl = norm(t);
    if (!(tl > 0)) continue;
    const T = t.map((v) => v / tl) as P;
    const off = sub(pts[i], axis[i]);
    const o = sub(off, T.map((v) => v * dot(off, T)) as P);
    radii.push(norm(o));
    if (prev) {
      angle += Math.atan2(dot(cross(prev, o), T), dot(prev, o));
      axisLength += norm(sub(axis[i], axis[i - 1]));
    }
    prev = o;
  }
  if (axisLength <= 0) return null;
  return { radius: median(radii), frequency: Math.abs(angle) / (2 * Math.PI) / axisLength };
}

describe('curl types', () => {
  it('read back as themselves; straight takes the curl off and keeps the rest', () => {
    for (const t of CURL_TYPES) expect(curlTypeOf(detailForCurlType(t.id, undefined))).toBe(t.id);
    const d = detailForCurlType('3B', { lengthJitter: 0.2, frizz: { distance: 0.05, shape: 0.5 } });
    expect(d.frizz).toBeUndefined(); // no frizz halo
    expect(d.lengthJitter).toBe(0.2);
    const straight = detailForCurlType('1', d);
    expect(straight.curl).toBeUndefined();
    expect(straight.clump).toEqual(d.clump);
    expect(curlTypeOf(straight)).toBe('1');
    expect(curlTypeOf({ curl: { radius: 0.3, frequency: 0.5, start: 0, randomOffset: 0 } })).toBe(
      null,
    );
  });

  it('grow hair whose measured curl radius and turns are the type’s', async () => {
    for (const id of ['2B', '3A', '3C', '4A']) {
      const t = CURL_TYPES.find((c) => c.id === id);
      if (!t) throw new Error(id);
      const s: SessionState = { ...long, detail: detailForCurlType(id, long.detail) };
      const h = await grow(s);
      const nominal = (t.frequency[0] + t.frequency[1]) / 2;
      // one turn of a helix of the type's middle radius and frequency, along the curled hair
      const r0 = (t.radius[0] + t.radius[1]) / 2;
      const turn = Math.hypot(1, 2 * Math.PI * r0 * nominal) / nominal;
      const radii: number[] = [];
      const freqs: number[] = [];
      for (let k = 0; k + 1 < h.strandStart.length; k++) {
        const pts: P[] = [];
        for (let p = h.strandStart[k]; p < h.strandStart[k + 1]; p++)
          pts.push([h.points[3 * p], h.points[3 * p + 1], h.points[3 * p + 2]]);
        const m = measure(pts, turn);
        if (m) {
          radii.push(m.radius);
          freqs.push(m.frequency);
        }
      }
      const r = median(radii);
      const f = median(freqs);
      console.log(
        `${id}: ${radii.length} strands; curl radius ${(10 * r).toFixed(2)} cm (type ${(10 * t.radius[0]).toFixed(2)}-${(10 * t.radius[1]).toFixed(2)}), ${f.toFixed(2)} turns per 10 cm (type ${t.frequency[0]}-${t.frequency[1]})`,
      );
      expect(radii.length).toBeGreaterThan(100);
      expect(r).toBeGreaterThanOrEqual(t.radius[0] * 0.85);
      expect(r).toBeLessThanOrEqual(t.radius[1] * 1.15);
      expect(f).toBeGreaterThanOrEqual(t.frequency[0] * 0.9);
      expect(f).toBeLessThanOrEqual(t.frequency[1] * 1.1);
    }
  });
});
