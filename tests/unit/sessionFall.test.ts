// Session version 4: natural fall (`fall`) is a session setting. The v3-to-v4 step adds nothing,
// so a session made before it opens without fall (the paper's method: the hair it had); the
// reader takes fall as true or false (false written as absent); links carry it in the JSON tail;
// new sessions and the non-paper presets have it on, the paper's figures do not.
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import { packHairOptions } from '../../web/model/curveSet';
import { gridForPreset } from '../../web/model/grid';
import { applyPreset, type PresetName } from '../../web/model/presets';
import { quantizeSession } from '../../web/model/quantize';
import { emptySession, newCurveExtends, type SessionState } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';
import {
  decodeSessionLink,
  encodeSessionLink,
  encodeSessionLinkV1,
  packSession,
  unpackSession,
} from '../../web/model/sessionLink';
import {
  migrateSession,
  type PlainRecord,
  SESSION_MIGRATIONS,
  SESSION_VERSION,
} from '../../web/model/sessionMigrations';
import { DEFAULT_CAMERA } from '../../web/viewer/defaultCamera';

const head = Head.builtin();

const plain = (o: object) => JSON.parse(JSON.stringify(o)) as PlainRecord;

function read(v: unknown): SessionState {
  const r = parseSession(v);
  if (!r.ok) throw new Error(r.error);
  return r.value;
}

async function linkRoundTrip(s: SessionState): Promise<SessionState> {
  const link = await encodeSessionLink(s);
  expect(link).toMatch(/^s=3\.[A-Za-z0-9_-]+$/);
  const r = await decodeSessionLink(`#${link}`);
  if (!r.ok) throw new Error(r.error);
  return r.value;
}

/** The default preset as a version 3 hairsketch saved it: no fall, its curves extended. */
function v3Default(): PlainRecord {
  const { fall: _fall, ...s } = presetSession('default', head);
  return plain({
    ...s,
    version: 3,
    curves: s.curves.map((c) => (c.type === 'dividing' ? c : { ...c, extend: true })),
  });
}

describe('v3-to-v4: natural fall is a setting; sessions made before it stay without it', () => {
  const step = SESSION_MIGRATIONS.find((m) => m.from === 3);

  it('the step is pure, names itself, gives version 4 and adds no field', () => {
    expect(step?.name).toBe(
      'v3-to-v4: natural fall is a setting; sessions made before it stay without it',
    );
    if (!step) return;
    for (const input of [
      Object.freeze(plain({ version: 3, curves: [] })),
      Object.freeze(plain({ version: 3, head: 'builtin', curves: [], avoidScalp: true })),
      Object.freeze(v3Default()),
    ]) {
      const before = JSON.stringify(input);
      const out = step.migrate(input);
      expect(JSON.stringify(input)).toBe(before); // the input is untouched
      expect(out).not.toBe(input);
      expect(out.version).toBe(4);
      expect(Object.keys(out)).toEqual(Object.keys(input)); // no field added or dropped
      expect(out).not.toHaveProperty('fall');
      expect(out).toEqual({ ...input, version: 4 });
      expect(step.migrate(input)).toEqual(out); // deterministic
    }
  });

  it('a version 3 session runs only this step', () => {
    const input = Object.freeze(plain({ version: 3, curves: [] }));
    const r = migrateSession(input);
    expect(r).toMatchObject({ ok: true, applied: [step?.name] });
    expect(r.ok && r.value).toEqual({ version: 4, curves: [] });
    // the current version runs none
    expect(migrateSession(plain({ version: SESSION_VERSION, curves: [] }))).toMatchObject({
      ok: true,
      applied: [],
    });
  });

  it('a version 3 session (without fall) reads as version 4 without fall: the hair it had', () => {
    const v3 = v3Default();
    const back = read(v3);
    expect(back.version).toBe(4);
    expect(back.version).toBe(SESSION_VERSION);
    expect(Object.keys(back)).not.toContain('fall');
    // nothing else changed: the curves keep their extension past the end (the paper's)
    expect(back).toEqual(read({ ...v3, version: SESSION_VERSION }));
    expect(back).toEqual({ ...v3, version: SESSION_VERSION });
    expect(back.curves.length).toBeGreaterThan(0);
    for (const c of back.curves) if (c.type !== 'dividing') expect(c.extend).toBe(true);
    // and the solver is asked for the paper's method
    expect(packHairOptions(back, back.curves).fall).toBe(false);
    // its next curve extends, as the version 3 app's did
    expect(newCurveExtends(back)).toBe(true);
    // versions 1 and 2 open without fall too
    for (const version of [1, 2]) expect(read({ ...v3, version })).toEqual(back);
  });
});

describe('the reader and session.fall', () => {
  const base = (): PlainRecord => {
    const { fall: _fall, ...s } = presetSession('default', head);
    return plain(s);
  };

  it('accepts fall: true and keeps it, in its place beside avoidScalp', () => {
    const s = read({ ...base(), fall: true });
    expect(s.fall).toBe(true);
    expect(packHairOptions(s, s.curves).fall).toBe(true);
    expect(read(JSON.parse(JSON.stringify(s)))).toEqual(s);
    // one key order, whatever the input's: avoidScalp, fall, sections, finish, bust, (the
    // default preset's) locks, then detail
    const all = read({
      detail: { lengthJitter: 0.1 },
      sections: true,
      fall: true,
      avoidScalp: true,
      ...base(),
    });
    const keys = Object.keys(all);
    expect(keys.slice(keys.indexOf('avoidScalp'))).toEqual([
      'avoidScalp',
      'fall',
      'sections',
      'finish',
      'bust',
      'locks',
      'detail',
    ]);
  });

  it('accepts fall: false, written as absent', () => {
    const s = read({ ...base(), fall: false });
    expect(Object.keys(s)).not.toContain('fall');
    expect(JSON.stringify(s)).not.toContain('fall');
    expect(s).toEqual(read(base()));
    expect(packHairOptions(s, s.curves).fall).toBe(false);
  });

  it('refuses a fall that is not true or false, naming session.fall', () => {
    for (const fall of [1, 0, 'yes', 'true', null, [], {}])
      expect(parseSession({ ...base(), fall })).toEqual({
        ok: false,
        error: 'session.fall: must be true or false',
      });
    // in an older session too (its steps leave a fall in place for the reader to refuse)
    expect(parseSession({ ...base(), version: 3, fall: 'yes' })).toEqual({
      ok: false,
      error: 'session.fall: must be true or false',
    });
  });
});

describe('share links and fall', () => {
  it('a session with fall: true round-trips with fall (in the JSON tail)', async () => {
    const s = presetSession('default', head);
    expect(s.fall).toBe(true);
    const data = unpackSession(packSession(s));
    expect(data.fall).toBe(true);
    const back = await linkRoundTrip(s);
    expect(back.fall).toBe(true);
    expect(back.version).toBe(SESSION_VERSION);
    expect(back).toEqual(quantizeSession(s));
    // also a new, empty session
    expect(await linkRoundTrip(emptySession('50k'))).toEqual(emptySession('50k'));
  });

  it('a session without fall decodes without fall (false too)', async () => {
    const { fall: _fall, ...noFall } = presetSession('default', head);
    const sessions: SessionState[] = [
      noFall,
      { ...noFall, fall: false },
      presetSession('fig7', head),
    ];
    for (const s of sessions) {
      // absent: nothing in the tail (false travels as written; the reader drops it)
      const data = unpackSession(packSession(s));
      if (s.fall === undefined) expect(data).not.toHaveProperty('fall');
      else expect(data.fall).toBe(false);
      const back = await linkRoundTrip(s);
      expect(back.version).toBe(SESSION_VERSION);
      expect(Object.keys(back)).not.toContain('fall');
      const { fall: _f, ...expected } = quantizeSession(s);
      expect(back).toEqual(expected);
    }
    // the link of a session with fall differs from the one without
    expect(await encodeSessionLink(noFall)).not.toBe(
      await encodeSessionLink({ ...noFall, fall: true }),
    );
  });

  it('version 1 links (the session JSON) keep fall, and one of version 3 opens without it', async () => {
    const withFall = presetSession('curly', head);
    const r = await decodeSessionLink(`#${await encodeSessionLinkV1(withFall)}`);
    if (!r.ok) throw new Error(r.error);
    expect(r.value.fall).toBe(true);
    const v3 = v3Default();
    const o = await decodeSessionLink(
      `#${await encodeSessionLinkV1(v3 as unknown as SessionState)}`,
    );
    if (!o.ok) throw new Error(o.error);
    expect(o.value.version).toBe(SESSION_VERSION);
    expect(Object.keys(o.value)).not.toContain('fall');
  });
});

describe('the preset sessions and fall', () => {
  const WITH_FALL: PresetName[] = ['default', 'empty', 'curly'];
  const PAPER: PresetName[] = ['fig6', 'fig7', 'fig8', 'fig1'];
  const ctx = {
    head,
    step: gridForPreset('25k').step,
    viewpoint: { position: [...DEFAULT_CAMERA.position], target: [...DEFAULT_CAMERA.target] },
  } as Parameters<typeof applyPreset>[2];

  it.each(WITH_FALL)('%s has fall on, and its stream curves do not extend', (name) => {
    const s = presetSession(name, head);
    expect(s.fall).toBe(true);
    expect(s.version).toBe(SESSION_VERSION);
    const streams = s.curves.filter((c) => c.type === 'stream');
    if (name !== 'empty') expect(streams.length).toBeGreaterThan(0);
    for (const c of s.curves) if (c.type !== 'dividing') expect(c.extend).toBe(false);
    // whether or not the session it is applied to had fall
    const { fall: _f, ...without } = emptySession('25k');
    const again = applyPreset(without, name, ctx);
    expect(again.fall).toBe(true);
    expect(again).toEqual(s);
    expect(newCurveExtends(s)).toBe(false);
  });

  it.each(PAPER)('%s (a paper figure) has no fall, and its curves extend', (name) => {
    const s = presetSession(name, head);
    expect(Object.keys(s)).not.toContain('fall');
    expect(s.curves.filter((c) => c.type === 'stream').length).toBeGreaterThan(0);
    for (const c of s.curves) if (c.type !== 'dividing') expect(c.extend).toBe(true);
    // applied over a session with fall (a new one), the figure drops it
    const over = applyPreset({ ...emptySession('25k'), fall: true }, name, ctx);
    expect(Object.keys(over)).not.toContain('fall');
    expect(over).toEqual(s);
    expect(newCurveExtends(s)).toBe(true);
  });
});
