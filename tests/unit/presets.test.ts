// The paper's presets, sketched in code: the kinds and counts of curves of each figure, every
// curve well formed (segments of one grid step, finite, on or above the head), and packable.
import { describe, expect, it } from 'vitest';
import { Head } from '../../web/head/head';
import { headSdf } from '../../web/head/headSdf';
import { packCurves } from '../../web/model/curveSet';
import { gridForPreset } from '../../web/model/grid';
import { CURLY_DETAIL, NEW_SESSION_DETAIL } from '../../web/model/presetDetail';
import { applyPreset, PRESET_NAMES, type PresetName, presetCurves } from '../../web/model/presets';
import { emptySession } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';
import { distance, type Vec3 } from '../../web/model/vec3';

const head = Head.builtin();
const step = gridForPreset('25k').step;
const ctx = {
  head,
  step,
  viewpoint: { position: [0, 0, 7] as Vec3, target: [0, 0, 0] as Vec3 },
};

const EXPECTED: Record<string, { stream: number; dividing: number; ponytail: number }> = {
  fig6: { stream: 10, dividing: 0, ponytail: 0 },
  fig7: { stream: 7, dividing: 1, ponytail: 0 },
  // two ponytails, curves combing each half (front, crown, occiput, nape) to its ponytail
  fig8: { stream: 8, dividing: 0, ponytail: 2 },
  // the back combed up from the nape into the ponytail (three curves where one lock was)
  fig1: { stream: 13, dividing: 4, ponytail: 1 },
};

describe('presets', () => {
  for (const [name, want] of Object.entries(EXPECTED)) {
    it(`${name}: the figure's curves, each well formed`, () => {
      const curves = presetCurves(name as PresetName, ctx);
      const count = (t: string) => curves.filter((c) => c.type === t).length;
      expect({
        stream: count('stream'),
        dividing: count('dividing'),
        ponytail: count('ponytail'),
      }).toEqual(want);
      expect(new Set(curves.map((c) => c.id)).size).toBe(curves.length);
      for (const c of curves) {
        expect(c.points.length).toBeGreaterThan(2);
        for (let i = 1; i < c.points.length - 1; i++)
          expect(distance(c.points[i - 1], c.points[i])).toBeCloseTo(step, 6);
        // on the head (dividing) or not inside it (a little slack for the mesh)
        for (const p of c.points) expect(headSdf(...p)).toBeGreaterThan(-0.03);
        if (c.type === 'dividing') {
          expect(c.normals.length).toBe(c.points.length);
          for (const p of c.points) expect(Math.abs(headSdf(...p))).toBeLessThan(0.03);
        }
        if (c.type === 'ponytail') {
          expect(c.circles.length).toBeGreaterThan(2);
          // gathered at C1, wider below
          const r = c.circles.map((k) => k.radius);
          expect(Math.max(...r)).toBeGreaterThan(1.2 * r[0]);
        }
      }
      const set = packCurves(curves);
      expect(set.kinds.length).toBe(curves.length);
      expect(set.params.every(Number.isFinite)).toBe(true);
    });
  }

  it('curly: the default curves with curl, clumps, frizz and length jitter, and the rules for loose hair round the face; other presets drop a detail', () => {
    const curly = applyPreset(emptySession('25k'), 'curly', ctx);
    expect(curly.curves).toEqual(applyPreset(emptySession('25k'), 'default', ctx).curves);
    expect(curly.detail).toEqual({
      curl: { radius: 0.08, frequency: 3.4, start: 0.12, randomOffset: 1 },
      clump: { factor: 0.92, shape: 0.15, tipSpread: 0.01, guideDistance: 0.12 },
      frizz: { distance: 0.003, shape: 0.5 },
      lengthJitter: 0.25,
    });
    // a new session's rules for loose hair round the face; the default preset (its strokes) not
    const rules = ['hairline', 'curlVolume', 'nape', 'clumpAll', 'faceClear'] as const;
    const plain = applyPreset(emptySession('25k'), 'default', ctx);
    for (const k of rules) expect([k, curly[k], plain[k]]).toEqual([k, true, undefined]);
    const read = parseSession(JSON.parse(JSON.stringify(curly)));
    expect(read.ok && read.value).toEqual(curly);
    const fig6 = applyPreset(curly, 'fig6', ctx);
    expect(Object.keys(fig6)).not.toContain('detail');
  });

  it('a new session (empty) and the styles it opens with have natural detail: locks, uneven ends, a few flyaways; the paper figures none, curly its own', () => {
    const fresh = applyPreset(emptySession('25k'), 'empty', ctx);
    expect(fresh.detail).toEqual(NEW_SESSION_DETAIL);
    const d = fresh.detail ?? {};
    expect(d.curl).toBeUndefined();
    expect(d.frizz).toBeUndefined();
    // locks: strands most of the way onto clumps 2–3 cm apart towards the tips, a little tip
    // spread (half-way onto clumps 1.5 cm apart read as a smooth tube from behind)
    expect(d.clump?.factor).toBeGreaterThanOrEqual(0.6);
    expect(d.clump?.factor).toBeLessThanOrEqual(0.9);
    expect(d.clump?.shape).toBeGreaterThanOrEqual(0.5); // none at the root: no parting at the crown
    expect(d.clump?.guideDistance).toBeGreaterThanOrEqual(0.2);
    expect(d.clump?.guideDistance).toBeLessThanOrEqual(0.3);
    expect(d.clump?.tipSpread).toBeGreaterThan(0);
    expect(d.lengthJitter).toBeGreaterThan(0);
    expect(d.lengthJitter).toBeLessThanOrEqual(0.15);
    expect(d.flyaway).toEqual({ share: 0.01, distance: 0.12, start: 0.55 });
    // the reader keeps it as it is
    const read = parseSession(JSON.parse(JSON.stringify(fresh)));
    expect(read.ok && read.value).toEqual(fresh);
    // every other preset: the same, but the paper's figures (smooth, as the paper draws them)
    // and the curly preset (its own)
    const paper: readonly string[] = ['fig6', 'fig7', 'fig8', 'fig1'];
    for (const name of PRESET_NAMES.filter((n) => n !== 'empty')) {
      const s = applyPreset(emptySession('25k'), name, ctx);
      const want =
        name === 'curly' ? CURLY_DETAIL : paper.includes(name) ? undefined : fresh.detail;
      expect([name, s.detail]).toEqual([name, want]);
    }
  });
});
