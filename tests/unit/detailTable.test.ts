// The detail table (model/detail.ts DETAIL_PARAMS) is the one statement of every detail block: the
// Hair panel builds its rows from it, the session reader checks against it and packDetailGroup
// lays it out for the engine. These check that the three agree on each block (the flyaway
// included), in the order solver-cpp/src/hair_engine.cpp detailFromArray reads.
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import {
  DETAIL_BLOCKS,
  DETAIL_GROUP_STRIDE,
  DETAIL_PARAMS,
  type DetailParamSpec,
  defaultBlock,
  detailIsOn,
  type HairDetail,
  packDetailGroup,
} from '../../web/model/detail';
import { parseSession } from '../../web/model/sessionFile';

/** hair_engine.cpp detailFromArray, index by index. */
const ENGINE_ORDER = [
  'curl.radius',
  'curl.frequency',
  'curl.start',
  'curl.randomOffset',
  'clump.factor',
  'clump.shape',
  'clump.tipSpread',
  'clump.guideDistance',
  'frizz.distance',
  'frizz.shape',
  'flyaway.share',
  'flyaway.distance',
  'flyaway.start',
  'lengthJitter',
];

const base = presetSession('default', Head.builtin(), '25k', 0);
const read = (detail: unknown) =>
  parseSession(JSON.parse(JSON.stringify({ ...base, detail })) as unknown);

describe('the detail table, the reader and the packing agree', () => {
  it('the flyaway block: share of strands 0..0.2 (1 %), distance 1.2 cm, start 0.55 of the length', () => {
    expect(DETAIL_BLOCKS).toEqual(['curl', 'clump', 'frizz', 'flyaway']);
    const rows = DETAIL_PARAMS.flyaway.map((p: DetailParamSpec) => [
      p.key,
      p.default,
      p.min,
      p.max,
    ]);
    expect(rows).toEqual([
      ['share', 0.01, 0, 0.2],
      ['distance', 0.12, 0, 0.5],
      ['start', 0.55, 0, 0.95],
    ]);
    // the Hair panel's rows: "Flyaway share", "Flyaway distance" (in cm), "Flyaway start"
    const labels = DETAIL_PARAMS.flyaway.map((p) => `Flyaway ${p.label.toLowerCase()}`);
    expect(labels).toEqual(['Flyaway share', 'Flyaway distance', 'Flyaway start']);
    expect(DETAIL_PARAMS.flyaway.map((p: DetailParamSpec) => p.unit)).toEqual([
      'of strands',
      'cm',
      'of length',
    ]);
    expect(detailIsOn({ flyaway: defaultBlock('flyaway') })).toBe(true);
  });

  it("packs every block's numbers where the engine reads them", () => {
    expect(DETAIL_GROUP_STRIDE).toBe(ENGINE_ORDER.length);
    const d: Record<string, Record<string, number>> = {};
    let v = 1;
    const want = new Float64Array(DETAIL_GROUP_STRIDE);
    for (const b of DETAIL_BLOCKS) {
      d[b] = {};
      for (const p of DETAIL_PARAMS[b] as readonly DetailParamSpec[]) {
        d[b][p.key] = v / 1000;
        want[ENGINE_ORDER.indexOf(`${b}.${p.key}`)] = v / 1000;
        v++;
      }
    }
    want[ENGINE_ORDER.indexOf('lengthJitter')] = 0.125;
    const out = new Float64Array(DETAIL_GROUP_STRIDE + 2);
    packDetailGroup({ ...d, lengthJitter: 0.125 } as HairDetail, out, 1);
    expect(Array.from(out.subarray(1, 1 + DETAIL_GROUP_STRIDE))).toEqual(Array.from(want));
    expect([out[0], out[DETAIL_GROUP_STRIDE + 1]]).toEqual([0, 0]); // nothing outside the group
  });

  it('a detail saved before flyaways (no block) packs the flyaway off', () => {
    const out = new Float64Array(DETAIL_GROUP_STRIDE);
    packDetailGroup({ clump: defaultBlock('clump'), lengthJitter: 0.2 }, out, 0);
    expect(out[ENGINE_ORDER.indexOf('flyaway.share')]).toBe(0);
    expect(out[ENGINE_ORDER.indexOf('lengthJitter')]).toBe(0.2);
  });

  it('the reader takes each block at its defaults and refuses what the table does not allow', () => {
    for (const b of DETAIL_BLOCKS) {
      const r = read({ [b]: defaultBlock(b) });
      expect(r.ok && r.value.detail).toEqual({ [b]: defaultBlock(b) });
    }
    const bad = (flyaway: Record<string, unknown>) => {
      const r = read({ flyaway: { ...defaultBlock('flyaway'), ...flyaway } });
      return r.ok ? 'accepted' : r.error;
    };
    expect(bad({ share: 0.2, start: 0 })).toBe('accepted'); // the ends of the ranges
    expect(bad({ share: 0.25 })).toBe('session.detail.flyaway.share: must be between 0 and 0.2');
    expect(bad({ distance: -0.01 })).toBe(
      'session.detail.flyaway.distance: must be between 0 and 0.5',
    );
    expect(bad({ start: 1 })).toBe('session.detail.flyaway.start: must be between 0 and 0.95');
    expect(bad({ spread: 1 })).toBe(
      'session.detail.flyaway.spread: is not a field hairsketch knows',
    );
    const missing = read({ flyaway: { share: 0.01, distance: 0.12 } });
    expect(missing.ok ? 'accepted' : missing.error).toBe(
      'session.detail.flyaway.start: must be a finite number',
    );
  });
});
