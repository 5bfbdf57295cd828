// The session schema (web/model/sessionSchema.ts) is the one list of a session's fields: every
// field a session holds is in it, a change needs a solve exactly when a field that shapes the
// request changes, and the result cache key (curveSet.ts hairRequestKey) covers every field of a
// request, with no list of its own to keep.
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import { hairRequestKey, packCurves, packHairOptions } from '../../web/model/curveSet';
import { X_PLANE } from '../../web/model/mirror';
import type { SessionState } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';
import {
  changesHair,
  engineSettings,
  needsSolve,
  REQUEST_FIELDS,
  SESSION_FIELD_NAMES,
  SESSION_FIELDS,
  SETTING_NAMES,
} from '../../web/model/sessionSchema';

const head = Head.builtin();

/** A session with every optional field present. */
function full(): SessionState {
  const s = presetSession('fig1', head);
  return {
    ...s,
    avoidScalp: true,
    fall: true,
    sections: true,
    finish: true,
    shape: true,
    volume: 0.12,
    ties: true,
    hairline: true,
    curlVolume: true,
    nape: true,
    coilVolume: true,
    roundPlaits: true,
    tieVolume: true,
    compactBun: true,
    clumpAll: true,
    faceClear: true,
    locks: true,
    bandColor: '#d02060',
    detail: { lengthJitter: 0.2 },
    scalpPaint: [{ erase: true, radius: 0.3, points: [[0, 1, 0]] }],
    symmetry: X_PLANE,
    references: [
      {
        name: 'front.png',
        hash: 'a'.repeat(64),
        format: 'png',
        width: 40,
        height: 60,
        view: 'front',
        opacity: 0.5,
        scale: 3,
        offset: [0, 0.1],
      },
    ],
  };
}

describe('session schema', () => {
  it('lists every field a session holds, in the order the reader writes them', () => {
    const r = parseSession(JSON.parse(JSON.stringify(full())));
    if (!r.ok) throw new Error(r.error);
    expect(Object.keys(r.value)).toEqual(SESSION_FIELD_NAMES);
    for (const k of SETTING_NAMES) expect(SESSION_FIELDS[k].link).toBe('tail');
  });

  it('asks for a solve exactly when a field of the request changes', () => {
    const s = full();
    expect(REQUEST_FIELDS).toEqual([
      'curves',
      'growth',
      'avoidScalp',
      'fall',
      'sections',
      'finish',
      'bust',
      'shape',
      'volume',
      'ties',
      'hairline',
      'curlVolume',
      'nape',
      'coilVolume',
      'roundPlaits',
      'tieVolume',
      'compactBun',
      'clumpAll',
      'faceClear',
      'locks',
      'detail',
    ]);
    expect(needsSolve(s, { ...s })).toBe(false);
    expect(needsSolve(s, { ...s, hairColor: '#000000' })).toBe(false);
    expect(needsSolve(s, { ...s, symmetry: { normal: [1, 0, 0], offset: 0.1 } })).toBe(false);
    expect(needsSolve(s, { ...s, curves: s.curves.slice(1) })).toBe(true);
    expect(needsSolve(s, { ...s, growth: { ...s.growth, seed: 1 } })).toBe(true);
    expect(needsSolve(s, { ...s, avoidScalp: false })).toBe(true);
    const { fall: _f, ...noFall } = s;
    expect(needsSolve(s, noFall)).toBe(true);
    const { sections: _s, ...noSections } = s;
    expect(needsSolve(s, noSections)).toBe(true);
    expect(needsSolve(s, { ...s, detail: { lengthJitter: 0.3 } })).toBe(true);
    // reference pictures are drawn, never solved: placing, hiding or removing one is no solve
    expect(needsSolve(s, { ...s, references: [] })).toBe(false);
    const { references: _r, ...noPictures } = s;
    expect(needsSolve(s, noPictures)).toBe(false);
    // and no new hair is on its way after them (the view does not wait for one)
    expect(changesHair(s, noPictures)).toBe(false);
    expect(changesHair(s, { ...s, hairColor: '#000000' })).toBe(false);
    expect(changesHair(s, { ...s, curves: s.curves.slice(1) })).toBe(true);
    expect(changesHair(s, { ...s, scalpPaint: [] })).toBe(true);
    expect(changesHair(s, { ...s, head: 'builtin' as const })).toBe(false); // the same value
  });

  it('gives every setting that shapes the hair to each solve, defaults spelled out', () => {
    const s = presetSession('fig7', head);
    const o = packHairOptions({}, s.curves);
    expect(o.avoidScalp).toBe(false);
    expect(o.fall).toBe(false);
    const on = packHairOptions({ avoidScalp: true, fall: true }, s.curves);
    expect(on.avoidScalp && on.fall).toBe(true);
  });

  it('keys a request by every field it has, a field it did not have before included', () => {
    const s = full();
    const curves = packCurves(s.curves, null, true);
    const options = packHairOptions(s, s.curves);
    const key = hairRequestKey(curves, s.growth, options);
    expect(hairRequestKey(curves, { ...s.growth }, packHairOptions(s, s.curves))).toBe(key);
    // the pictures are not part of the request: its key is that of the session without them
    const { references: _r, ...noPictures } = s;
    expect(hairRequestKey(curves, s.growth, packHairOptions(noPictures, s.curves))).toBe(key);
    expect(hairRequestKey(curves, s.growth, { ...options, avoidScalp: false })).not.toBe(key);
    expect(hairRequestKey(curves, s.growth, { ...options, fall: false })).not.toBe(key);
    expect(hairRequestKey(curves, { ...s.growth, maxStrands: 9 }, options)).not.toBe(key);
    const more = { ...options, futureSetting: 0.5 } as typeof options;
    expect(hairRequestKey(curves, s.growth, more)).not.toBe(key);
    const params = curves.params.slice();
    params[0] += 1e-4;
    expect(hairRequestKey({ ...curves, params }, s.growth, options)).not.toBe(key);
  });
});

describe('engine settings', () => {
  it("pack every 'request' setting in table order, flags as 0 or 1 (engine_settings.hpp)", () => {
    expect([
      ...engineSettings({
        avoidScalp: true,
        fall: false,
        sections: false,
        finish: true,
        bust: false,
        shape: true,
        volume: 0.12,
        ties: false,
        hairline: true,
        curlVolume: false,
        nape: true,
        coilVolume: true,
        roundPlaits: false,
        tieVolume: true,
        compactBun: false,
        clumpAll: true,
        faceClear: false,
        locks: true,
      }),
    ]).toEqual([1, 0, 0, 1, 0, 1, 0.12, 0, 1, 0, 1, 1, 0, 1, 0, 1, 0, 1]);
    expect([
      ...engineSettings({
        avoidScalp: false,
        fall: true,
        sections: true,
        finish: false,
        bust: true,
        shape: false,
        volume: 0,
        ties: true,
        hairline: false,
        curlVolume: true,
        nape: false,
        coilVolume: false,
        roundPlaits: true,
        tieVolume: false,
        compactBun: true,
        clumpAll: false,
        faceClear: true,
        locks: false,
      }),
    ]).toEqual([0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1, 0, 1, 0, 1, 0]);
  });
});
