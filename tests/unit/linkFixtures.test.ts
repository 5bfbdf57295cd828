// Share links of every format ever written (tests/fixtures/links.json, made by the encoder of the
// build that wrote each format: scripts/record-link-fixtures.ts) decode, and the versions of one
// session decode to the same session; tests/e2e/oldLinks.spec.ts checks the hair they grow.
// A curve parameter added to the table (curveParams.ts) leaves every older link's decoding as it
// was: version 2 links hold the parameters version 2 had, version 3 links say how many they hold.
import { readFileSync } from 'node:fs';
import { afterEach, describe, expect, it } from 'vitest';
import { CURVE_PARAMS, CurveKind, type CurveParamSpec } from '../../web/model/curveParams';
import type { SessionState } from '../../web/model/session';
import { decodeSessionLink, encodeSessionLink } from '../../web/model/sessionLink';

interface LinkFixture {
  name: string;
  format: 1 | 2 | 3;
  covers: string;
  link: string;
  strands: number;
  hairHash: string;
}
const fixtures = JSON.parse(readFileSync('tests/fixtures/links.json', 'utf8')) as LinkFixture[];

async function open(link: string): Promise<SessionState> {
  const r = await decodeSessionLink(link);
  if (!r.ok) throw new Error(r.error);
  return r.value;
}

describe('link fixtures', () => {
  it('hold every format, every curve kind, with the hair each opens to', async () => {
    expect(new Set(fixtures.map((f) => f.format))).toEqual(new Set([1, 2, 3]));
    for (const f of fixtures) {
      expect(f.link.startsWith(f.format === 1 ? '#s=' : `#s=${f.format}.`)).toBe(true);
      expect(f.hairHash).toMatch(/^[0-9a-f]+-[0-9a-f]+$/);
    }
    const kinds = new Set<string>();
    for (const f of fixtures) for (const c of (await open(f.link)).curves) kinds.add(c.type);
    expect(kinds).toEqual(new Set(Object.keys(CurveKind))); // every kind the app has
  });

  it('the versions of one session open to the same session and are meant to grow the same hair', async () => {
    const byName = new Map<string, { session: SessionState; hairHash: string }>();
    for (const f of fixtures) {
      const s = await open(f.link);
      const first = byName.get(f.name);
      if (!first) byName.set(f.name, { session: s, hairHash: f.hairHash });
      else {
        expect(s, `${f.name} v${f.format}`).toEqual(first.session);
        expect(f.hairHash, `${f.name} v${f.format}`).toBe(first.hairHash);
      }
    }
  });
});

describe('a curve parameter added to the table', () => {
  const added: { kind: 'stream' | 'dividing' | 'ponytail'; spec: CurveParamSpec }[] = [
    {
      kind: 'stream',
      spec: {
        name: 'twist',
        label: 'Twist',
        unit: 'rad',
        default: 0.25,
        min: -1,
        max: 1,
        quantum: 1e-5,
        view: { min: -45, max: 45, step: 1 },
      },
    },
    {
      kind: 'dividing',
      spec: {
        name: 'lift',
        label: 'Lift',
        unit: 'grid steps',
        default: 0.5,
        min: 0,
        max: 4,
        quantum: 1e-4,
        view: { min: 0, max: 2, step: 0.05 },
      },
    },
  ];
  const tables = CURVE_PARAMS as unknown as Record<string, CurveParamSpec[]>;
  const add = () => {
    for (const a of added) tables[a.kind].push(a.spec);
  };
  afterEach(() => {
    for (const a of added) {
      const t = tables[a.kind];
      if (t.at(-1) === a.spec) t.pop();
    }
  });

  it('leaves how every older link decodes as it was (the new parameter gets its default)', async () => {
    const before = await Promise.all(fixtures.map((f) => open(f.link)));
    add();
    for (let i = 0; i < fixtures.length; i++) {
      const f = fixtures[i];
      const now = await open(f.link);
      const expected = {
        ...before[i],
        curves: before[i].curves.map((c) => {
          const a = added.find((x) => x.kind === c.type);
          return a ? { ...c, [a.spec.name]: a.spec.default } : c;
        }),
      };
      expect(now, `${f.name} v${f.format}`).toEqual(expected);
    }
  });

  it('travels in new links, and a build without it refuses them instead of misreading', async () => {
    const v3 = fixtures.find((f) => f.format === 3 && f.name === 'paper-everything');
    if (!v3) throw new Error('no version 3 fixture of paper-everything');
    const s = await open(v3.link);
    add();
    const withAdded = {
      ...s,
      curves: s.curves.map((c) =>
        c.type === 'stream'
          ? { ...c, twist: -0.5 }
          : c.type === 'dividing'
            ? { ...c, lift: 1.25 }
            : c,
      ),
    } as SessionState;
    const link = `#${await encodeSessionLink(withAdded)}`;
    expect(await open(link)).toEqual(withAdded);
    for (const a of added) tables[a.kind].pop();
    const r = await decodeSessionLink(link);
    expect(r.ok).toBe(false);
    expect(!r.ok && r.error).toMatch(
      /parameters this app does not know \(made by a newer hairsketch\?\)/,
    );
  });
});
