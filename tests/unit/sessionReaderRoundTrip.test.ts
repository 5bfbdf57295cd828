// The strict reader writes back what it accepts: read → JSON → read is the identity, the value
// has one key order (the same session gives the same bytes), and every preset session — built
// as web/cli/presetSession.ts builds it, on every grid — passes. Plus the version migrations.
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import { GRID_PRESETS, type GridPreset } from '../../web/model/grid';
import { PRESET_NAMES } from '../../web/model/presets';
import { emptySession, type SessionState } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';
import {
  migrateSession,
  type PlainRecord,
  SESSION_MIGRATIONS,
  SESSION_VERSION,
  type SessionMigration,
} from '../../web/model/sessionMigrations';

const head = Head.builtin();

const plain = (o: object) => JSON.parse(JSON.stringify(o)) as PlainRecord;

function read(v: unknown): SessionState {
  const r = parseSession(v);
  if (!r.ok) throw new Error(r.error);
  return r.value;
}

/** Key paths in order, so two values with the same keys in another order differ. */
function keyOrder(v: unknown, path = ''): string[] {
  if (Array.isArray(v)) return v.flatMap((x, i) => keyOrder(x, `${path}[${i}]`));
  if (typeof v === 'object' && v !== null)
    return Object.entries(v).flatMap(([k, x]) => [`${path}.${k}`, ...keyOrder(x, `${path}.${k}`)]);
  return [];
}

/** The same object with its keys in reverse order, at every level. */
function shuffled(v: unknown): unknown {
  if (Array.isArray(v)) return v.map(shuffled);
  if (typeof v === 'object' && v !== null)
    return Object.fromEntries(
      Object.entries(v)
        .reverse()
        .map(([k, x]) => [k, shuffled(x)]),
    );
  return v;
}

function expectRoundTrip(s: unknown): SessionState {
  const once = read(s);
  const json = JSON.stringify(once);
  const twice = read(JSON.parse(json));
  expect(twice).toEqual(once);
  expect(JSON.stringify(twice)).toBe(json); // byte-stable
  expect(keyOrder(twice)).toEqual(keyOrder(once));
  // the order of the input's keys does not reach the output
  expect(JSON.stringify(read(shuffled(JSON.parse(json))))).toBe(json);
  return once;
}

describe('every preset session passes the reader and round-trips', () => {
  for (const name of PRESET_NAMES)
    for (const grid of Object.keys(GRID_PRESETS) as GridPreset[])
      it(`${name} on ${grid}`, () => {
        const s = presetSession(name, head, grid, 0);
        const back = expectRoundTrip(JSON.parse(JSON.stringify(s)));
        // nothing of the preset is lost or changed: only the defaults are spelled out
        expect(back).toEqual(s);
        // the in-memory session (not through JSON) reads the same, as the exporter reads it
        expect(read(s)).toEqual(back);
      });

  it('a Save file (session + camera + selected) reads as the session alone', () => {
    const s = presetSession('fig1', head, '25k', 5000);
    const file = { ...s, camera: { position: [1, 2, 3], target: [0, 0, 0] }, selected: 'c2' };
    const back = expectRoundTrip(JSON.parse(JSON.stringify(file)));
    expect(back).toEqual(s);
    // the paper's figures keep the paper's method (no fall, sections or finished edges) on the bust
    expect(Object.keys(back)).toEqual([
      'version',
      'head',
      'grid',
      'curves',
      'growth',
      'hairColor',
      'hairLook',
      'bust',
    ]);
  });

  it('spells out the defaults of a minimal session, and keeps them on the next read', () => {
    // a session made before version 4 has no natural fall, sections, finished edges, bust or
    // shape rules, ties from any hand, soft hairline, curl volume, low nape or coil volume (new
    // sessions have them on)
    const {
      fall,
      sections,
      finish,
      bust,
      shape,
      ties,
      hairline,
      curlVolume,
      nape,
      coilVolume,
      roundPlaits,
      tieVolume,
      compactBun,
      clumpAll,
      faceClear,
      locks,
      ...beforeFall
    } = emptySession('25k');
    expect(roundPlaits).toBe(true);
    expect(tieVolume).toBe(true);
    expect(compactBun).toBe(true);
    expect(clumpAll).toBe(true);
    expect(faceClear).toBe(true);
    expect(locks).toBe(true);
    expect(coilVolume).toBe(true);
    expect(nape).toBe(true);
    expect(curlVolume).toBe(true);
    expect(hairline).toBe(true);
    expect(shape).toBe(true);
    expect(ties).toBe(true);
    expect(fall).toBe(true);
    expect(sections).toBe(true);
    expect(finish).toBe(true);
    expect(bust).toBe(true);
    const back = expectRoundTrip({ version: 2, curves: [] });
    expect(back).toEqual(beforeFall);
    // a minimal version 1 session reads as the same session
    expect(expectRoundTrip({ version: 1, curves: [] })).toEqual(beforeFall);
    // and a minimal current one with fall, sections, finished edges and the shape rules on as a
    // new session
    expect(
      expectRoundTrip({
        version: SESSION_VERSION,
        curves: [],
        fall: true,
        sections: true,
        finish: true,
        bust: true,
        shape: true,
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
      }),
    ).toEqual(emptySession('25k'));
  });

  it('writes -0 as 0 (JSON cannot say -0)', () => {
    const s = presetSession('default', head, '25k', 0);
    const j = JSON.parse(JSON.stringify(s));
    j.curves[0].viewpoint.target = [-0, -0.55, -0];
    const back = expectRoundTrip(j);
    expect(Object.is(back.curves[0].viewpoint.target[0], 0)).toBe(true);
  });

  it('returns a fresh value: nothing of the input is shared or frozen in', () => {
    const s = presetSession('fig7', head, '25k', 0);
    const back = read(s);
    expect(back.curves[0]).not.toBe(s.curves[0]);
    expect(back.curves[0].points[0]).not.toBe(s.curves[0].points[0]);
    expect(back.growth).not.toBe(s.growth);
  });
});

describe('hair detail and avoid scalp round-trip byte-stable', () => {
  const detail = {
    curl: { radius: 0.05, frequency: 3, start: 0.15, randomOffset: 1 },
    clump: { factor: 0.5, shape: -0.3, tipSpread: 0.02, guideDistance: 0.12 },
    frizz: { distance: 0.006, shape: 0.5 },
    lengthJitter: 0.15,
  };

  it('a session-wide detail with every block, and avoidScalp', () => {
    const s = { ...presetSession('fig7', head, '25k', 0), avoidScalp: true, detail };
    const back = expectRoundTrip(JSON.parse(JSON.stringify(s)));
    expect(back.avoidScalp).toBe(true);
    expect(back.detail).toEqual(detail);
    expect(back).toEqual(s);
    // a canonical key order: the blocks and their numbers in the table's order
    expect(Object.keys(back.detail ?? {})).toEqual(['curl', 'clump', 'frizz', 'lengthJitter']);
    expect(Object.keys(back.detail?.clump ?? {})).toEqual([
      'factor',
      'shape',
      'tipSpread',
      'guideDistance',
    ]);
  });

  it('single blocks and an empty detail', () => {
    for (const d of [{ frizz: detail.frizz }, { lengthJitter: 0 }, {}]) {
      const s = { ...presetSession('default', head, '25k', 0), detail: d };
      expect(expectRoundTrip(JSON.parse(JSON.stringify(s))).detail).toEqual(d);
    }
  });

  it("each curve kind's own detail", () => {
    const s = presetSession('fig1', head, '25k', 0); // a ponytail, dividing and stream curves
    const kinds = new Set<string>();
    const curves = s.curves.map((c, i) => {
      if (kinds.has(c.type)) return c;
      kinds.add(c.type);
      return { ...c, detail: i % 2 ? { clump: detail.clump } : detail };
    });
    expect([...kinds].sort()).toEqual(['dividing', 'ponytail', 'stream']);
    const withDetail = { ...s, curves };
    const back = expectRoundTrip(JSON.parse(JSON.stringify(withDetail)));
    expect(back).toEqual(withDetail);
  });
});

describe('v1-to-v2: stored scalp-avoidance constraints become the avoidScalp setting', () => {
  const v2 = JSON.parse(JSON.stringify(presetSession('fig6', head, '25k', 0)));
  const v1 = (avoid: unknown) => ({ ...v2, version: 1, avoid });

  it('a version 1 session with constraints opens as the version 2 session with avoidScalp on', () => {
    const r = parseSession(v1({ index: [3, 7], target: [0, 0.3, 0, 0.3, 0, 0] }));
    expect(r.ok).toBe(true);
    if (!r.ok) return;
    expect(r.value.version).toBe(SESSION_VERSION);
    expect(r.value.avoidScalp).toBe(true);
    expect(Object.keys(r.value)).not.toContain('avoid');
    // exactly what the reader gives for the same session written as version 2
    expect(r.value).toEqual(read({ ...v2, avoidScalp: true }));
    expectRoundTrip(r.value);
  });

  it('no constraints (null, empty or absent) opens with avoid scalp off', () => {
    for (const avoid of [null, { index: [], target: [] }, undefined]) {
      const r = parseSession(v1(avoid));
      expect(r.ok).toBe(true);
      if (!r.ok) return;
      expect(Object.keys(r.value)).not.toContain('avoidScalp');
      expect(Object.keys(r.value)).not.toContain('avoid');
      expect(r.value).toEqual(read(v2));
    }
  });

  it('a malformed avoid is refused by name', () => {
    for (const avoid of [5, 'all', [1, 2], { target: [0, 0.3, 0] }, { index: 3, target: [] }])
      expect(parseSession(v1(avoid))).toEqual({
        ok: false,
        error: 'session.avoid: is not a field hairsketch knows',
      });
  });

  it('the step is pure, names itself and gives version 2', () => {
    const step = SESSION_MIGRATIONS.find((m) => m.from === 1);
    expect(step?.name).toMatch(/^v1-to-v2: /);
    if (!step) return;
    const input = Object.freeze(
      plain({ version: 1, curves: [], avoid: { index: [1], target: [0, 0, 1] } }),
    );
    const before = JSON.stringify(input);
    const out = step.migrate(input);
    expect(JSON.stringify(input)).toBe(before);
    expect(out).toEqual({ version: 2, curves: [], avoidScalp: true });
    // the chain goes on to the current version, each later step named
    expect(migrateSession(input)).toMatchObject({
      ok: true,
      value: { version: 4, curves: [], avoidScalp: true },
      applied: [step.name, SESSION_MIGRATIONS[1].name, SESSION_MIGRATIONS[2].name],
    });
    const r = migrateSession(input);
    expect(r.ok && r.applied.map((n) => n.slice(0, 9))).toEqual([
      'v1-to-v2:',
      'v2-to-v3:',
      'v3-to-v4:',
    ]);
  });
});

describe('session versions (sessionMigrations.ts)', () => {
  it('the current version is 4 and the table reaches it without gaps', () => {
    expect(SESSION_VERSION).toBe(4);
    expect(SESSION_MIGRATIONS.map((m) => m.from)).toEqual([1, 2, 3]);
    expect(emptySession('25k').version).toBe(SESSION_VERSION);
    const froms = SESSION_MIGRATIONS.map((m) => m.from);
    froms.forEach((f, i) => {
      expect(f).toBe(froms[0] + i);
      expect(SESSION_MIGRATIONS[i].name).toMatch(new RegExp(`^v${f}-to-v${f + 1}: `));
    });
    if (froms.length) expect(froms[froms.length - 1] + 1).toBe(SESSION_VERSION);
  });

  it('refuses a newer version, saying it was made by a newer hairsketch', () => {
    for (const version of [5, 17])
      expect(parseSession({ version, curves: [] })).toEqual({
        ok: false,
        error: `session.version: must be an integer from 1 to 4; version ${version} was made by a newer hairsketch (update hairsketch to open it)`,
      });
  });

  it('refuses a missing, older or non-integer version', () => {
    expect(parseSession({ curves: [] })).toEqual({
      ok: false,
      error: 'session.version: missing (must be an integer from 1 to 4)',
    });
    expect(parseSession({ version: 0, curves: [] })).toMatchObject({
      error:
        'session.version: must be an integer from 1 to 4; version 0 is older than any hairsketch',
    });
    for (const version of [1.5, '2', null, true, Number.NaN])
      expect(parseSession({ version, curves: [] })).toMatchObject({
        error: 'session.version: must be an integer from 1 to 4',
      });
  });

  // A made-up history (v1 → v2 → v3) to test the runner apart from the real table.
  const v1ToV2: SessionMigration = {
    name: 'v1-to-v2: hairColor becomes hair.colour',
    from: 1,
    migrate: (s) => {
      const { hairColor, ...rest } = s;
      return { ...rest, version: 2, hair: { colour: hairColor ?? '#5a3825' } };
    },
  };
  const v2ToV3: SessionMigration = {
    name: 'v2-to-v3: curves gain a visible flag',
    from: 2,
    migrate: (s) => ({
      ...s,
      version: 3,
      curves: (s.curves as PlainRecord[]).map((c) => ({ ...c, visible: true })),
    }),
  };
  const table = { migrations: [v1ToV2, v2ToV3], current: 3 };

  it('runs each step in order, as pure functions, and says which ran', () => {
    const v1 = Object.freeze(plain({ version: 1, hairColor: '#112233', curves: [{ id: 'a' }] }));
    const before = JSON.stringify(v1);
    const r = migrateSession(v1, table);
    expect(r).toEqual({
      ok: true,
      value: { version: 3, hair: { colour: '#112233' }, curves: [{ id: 'a', visible: true }] },
      applied: [v1ToV2.name, v2ToV3.name],
    });
    expect(JSON.stringify(v1)).toBe(before); // the input is untouched
    const v2 = plain({ version: 2, hair: { colour: '#000000' }, curves: [] });
    expect(migrateSession(v2, table)).toMatchObject({ ok: true, applied: [v2ToV3.name] });
    const v3 = plain({ version: 3, curves: [] });
    const same = migrateSession(v3, table);
    expect(same).toMatchObject({ ok: true, applied: [] });
    expect(same.ok && same.value).toBe(v3);
  });

  it('each made-up step alone is pure and gives the next version', () => {
    for (const step of table.migrations) {
      const input = Object.freeze(plain({ version: step.from, hairColor: '#010203', curves: [] }));
      const out = step.migrate(input);
      expect(out.version).toBe(step.from + 1);
      expect(step.migrate(input)).toEqual(out); // deterministic
    }
  });

  it('names the range and the newer/older cases for a multi-version table', () => {
    expect(migrateSession(plain({ version: 4 }), table)).toEqual({
      ok: false,
      error:
        'session.version: must be an integer from 1 to 3; version 4 was made by a newer hairsketch (update hairsketch to open it)',
    });
    expect(migrateSession(plain({ version: 0 }), table)).toMatchObject({
      error:
        'session.version: must be an integer from 1 to 3; version 0 is older than any hairsketch',
    });
  });

  it('reports a gap, a step that throws, and a step that forgets the version', () => {
    expect(migrateSession(plain({ version: 1 }), { migrations: [v2ToV3], current: 3 })).toEqual({
      ok: false,
      error:
        'session.version: must be an integer from 2 to 3; version 1 is older than any hairsketch',
    });
    expect(
      migrateSession(plain({ version: 1 }), {
        migrations: [v1ToV2, { ...v2ToV3, from: 4 }],
        current: 3,
      }),
    ).toMatchObject({ error: 'session.version: no migration from version 2 (internal)' });
    const throws: SessionMigration = {
      name: 'v1-to-v2: broken',
      from: 1,
      migrate: () => {
        throw new Error('boom');
      },
    };
    expect(migrateSession(plain({ version: 1 }), { migrations: [throws], current: 2 })).toEqual({
      ok: false,
      error: 'session: migration v1-to-v2: broken failed (boom)',
    });
    const forgets: SessionMigration = {
      name: 'v1-to-v2: forgets',
      from: 1,
      migrate: (s) => ({ ...s }),
    };
    expect(migrateSession(plain({ version: 1 }), { migrations: [forgets], current: 2 })).toEqual({
      ok: false,
      error: 'session: migration v1-to-v2: forgets did not give version 2 (internal)',
    });
  });
});
