// The strict reader never throws and never runs the caller's code: Proxies whose traps throw,
// getters (with or without side effects), cycles, BigInt, symbols, functions, class instances,
// sparse and huge arrays, __proto__ keys all give {ok: false, error} naming where; a valid
// session behind a harmless Proxy reads like the plain one. Plus the reader's time on a 55 MB,
// 10^6-point input, printed as a figure (not asserted).
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import type { SessionState } from '../../web/model/session';
import { SESSION_LIMITS as L, parseSession } from '../../web/model/sessionFile';

const base: SessionState = presetSession('fig1', Head.builtin(), '25k', 0);
const S = 5; // a stream curve of fig1
// biome-ignore lint/suspicious/noExplicitAny: builds arbitrary inputs
type Json = any;
const fresh = (): Json => JSON.parse(JSON.stringify(base));

function errorOf(v: unknown): string {
  let r: ReturnType<typeof parseSession>;
  expect(() => {
    r = parseSession(v);
  }).not.toThrow();
  // biome-ignore lint/style/noNonNullAssertion: assigned just above
  const out = r!;
  return out.ok ? 'accepted' : out.error;
}

/** A Proxy whose every trap throws. */
const hostile = () =>
  new Proxy(
    {},
    {
      get() {
        throw new Error('get');
      },
      getOwnPropertyDescriptor() {
        throw new Error('gOPD');
      },
      ownKeys() {
        throw new Error('ownKeys');
      },
      getPrototypeOf() {
        throw new Error('getPrototypeOf');
      },
      has() {
        throw new Error('has');
      },
    },
  );

describe('Proxies', () => {
  it('a Proxy whose traps throw, as the session or deep inside it', () => {
    expect(errorOf(hostile())).toBe('session: could not be read (reading it threw)');
    const j = fresh();
    j.curves[S].points[3] = hostile();
    expect(errorOf(j)).toBe(`session.curves[${S}].points[3]: could not be read (reading it threw)`);
    const k = fresh();
    k.growth = hostile();
    expect(errorOf(k)).toBe('session.growth: could not be read (reading it threw)');
  });

  it('a Proxy that throws a Proxy (whose own traps throw)', () => {
    const thrower = new Proxy(
      {},
      {
        ownKeys() {
          throw hostile();
        },
      },
    );
    expect(errorOf(thrower)).toBe('session: could not be read (reading it threw)');
  });

  it('a revoked Proxy', () => {
    const { proxy, revoke } = Proxy.revocable({}, {});
    revoke();
    expect(errorOf(proxy)).toBe('session: could not be read (reading it threw)');
    const j = fresh();
    j.curves = proxy;
    expect(errorOf(j)).toBe('session.curves: could not be read (reading it threw)');
  });

  it('a transparent Proxy over a valid session reads as the session itself', () => {
    const wrap = (v: Json): Json =>
      typeof v === 'object' && v !== null
        ? new Proxy(
            Array.isArray(v)
              ? v.map(wrap)
              : Object.fromEntries(Object.entries(v).map(([k, x]) => [k, wrap(x)])),
            {},
          )
        : v;
    const r = parseSession(wrap(fresh()));
    expect(r.ok && r.value).toEqual(
      parseSession(fresh()).ok && (parseSession(fresh()) as { value: unknown }).value,
    );
  });
});

describe('getters and side effects', () => {
  it('refuses a getter without calling it', () => {
    let calls = 0;
    const j = fresh();
    Object.defineProperty(j, 'hairColor', {
      enumerable: true,
      get() {
        calls++;
        return '#000000';
      },
    });
    expect(errorOf(j)).toBe('session.hairColor: must be plain data (it is a getter or setter)');
    const k = fresh();
    Object.defineProperty(k.curves[S].points, 2, {
      enumerable: true,
      get() {
        calls++;
        throw new Error('boom');
      },
    });
    expect(errorOf(k)).toBe(
      `session.curves[${S}].points[2]: must be plain data (it is a getter or setter)`,
    );
    expect(calls).toBe(0);
  });

  it('reads each field once: a Proxy that changes its answer on every read cannot pass a check and then differ', () => {
    let reads = 0;
    const j = fresh();
    const target = j.curves[S].points[1];
    j.curves[S].points[1] = new Proxy(target, {
      getOwnPropertyDescriptor(t, k) {
        const d = Reflect.getOwnPropertyDescriptor(t, k);
        if (k !== '0') return d;
        reads++;
        // valid the first time, 1e6 afterwards
        return d && reads > 1 ? { ...d, value: 1e6 } : d;
      },
    });
    const r = parseSession(j);
    expect(r.ok).toBe(true);
    if (r.ok) expect((r.value.curves[S].points[1] as number[])[0]).toBe(target[0]);
    expect(reads).toBe(1);
  });

  it('ignores non-enumerable and symbol-keyed properties, as JSON does', () => {
    const j = fresh();
    Object.defineProperty(j, 'secret', { value: 1, enumerable: false });
    j[Symbol('x')] = 2;
    expect(errorOf(j)).toBe('accepted');
  });
});

describe('cycles, odd values and odd objects', () => {
  it('refuses a cycle, naming where it closes', () => {
    const j = fresh();
    j.curves[S].viewpoint.position = j.curves[S];
    expect(errorOf(j)).toBe(`session.curves[${S}].viewpoint.position: refers to itself (a cycle)`);
    const k = fresh();
    k.curves.push(k);
    // the session itself pushed after fig1's curves: the cycle closes at the first new index
    const n = base.curves.length;
    expect(errorOf(k)).toBe(`session.curves[${n}]: refers to itself (a cycle)`);
  });

  it('accepts shared (acyclic) references, as the editor shares viewpoints', () => {
    const j = fresh();
    const vp = j.curves[0].viewpoint;
    for (const c of j.curves) c.viewpoint = vp;
    expect(errorOf(j)).toBe('accepted');
  });

  it('refuses BigInt, symbols, functions, boxed numbers, class instances and typed arrays', () => {
    const cases: [string, (j: Json) => void, string][] = [
      [
        'bigint',
        (j) => (j.growth.seed = 5n),
        'session.growth.seed: must be JSON data, not a bigint',
      ],
      ['symbol', (j) => (j.grid = Symbol('25k')), 'session.grid: must be JSON data, not a symbol'],
      [
        'function',
        (j) => (j.growth = () => ({})),
        'session.growth: must be JSON data, not a function',
      ],
      [
        'boxed',
        (j) => (j.growth.seed = new Number(3)),
        'session.growth.seed: must be a plain object',
      ],
      ['date', (j) => (j.growth = new Date()), 'session.growth: must be a plain object'],
      ['map', (j) => (j.detail = new Map()), 'session.detail: must be a plain object'],
      [
        'typed',
        (j) => (j.curves[S].points[0] = new Float64Array(3)),
        `session.curves[${S}].points[0]: must be a plain object`,
      ],
      [
        'class',
        (j) => (j.curves[S].viewpoint = new (class V {})()),
        `session.curves[${S}].viewpoint: must be a plain object`,
      ],
    ];
    for (const [, edit, error] of cases) {
      const j = fresh();
      edit(j);
      expect(errorOf(j)).toBe(error);
    }
  });

  it('refuses a sparse array, naming the hole', () => {
    const j = fresh();
    delete j.curves[S].points[4];
    expect(errorOf(j)).toBe(`session.curves[${S}].points[4]: is missing (a hole in the array)`);
    const k = fresh();
    const n = base.curves.length;
    k.curves.length = n + 4;
    expect(errorOf(k)).toBe(`session.curves[${n}]: is missing (a hole in the array)`);
  });

  it('refuses a huge array by its length, before reading it', () => {
    const j = fresh();
    j.curves[S].points = new Array(2 ** 32 - 1);
    expect(errorOf(j)).toBe(
      `session.curves[${S}].points: has ${2 ** 32 - 1} points, more than ${L.maxPoints} (the cap)`,
    );
    const k = fresh();
    k.curves[S].viewpoint.position = new Array(1e7);
    expect(errorOf(k)).toBe(
      `session.curves[${S}].viewpoint.position: has 10000000 items, more than 16 (the cap)`,
    );
  });

  it('refuses deep nesting and huge strings', () => {
    const j = fresh();
    let deep: Json = {};
    for (let i = 0; i < 1e5; i++) deep = { a: deep };
    j.camera = deep;
    expect(errorOf(j)).toMatch(/^session\.camera(\.a)+: is nested deeper than 10 levels$/);
    const k = fresh();
    k.hairColor = 'x'.repeat(1e7);
    expect(errorOf(k)).toBe(`session.hairColor: is longer than ${L.maxString} characters`);
  });

  it('treats __proto__ keys as unknown fields, and prototype tricks as not plain', () => {
    const fromJson = JSON.parse(`{"__proto__": {"version": 1}, ${JSON.stringify(base).slice(1)}`);
    expect(errorOf(fromJson)).toBe('session.__proto__: is not a field hairsketch knows');
    const inherits = Object.create(fresh());
    expect(errorOf(inherits)).toBe('session: must be a plain object');
    const polluted = fresh();
    polluted.curves[S] = JSON.parse(
      `{"__proto__": {"type": "stream"}, ${JSON.stringify(base.curves[S]).slice(1)}`,
    );
    expect(errorOf(polluted)).toBe(
      `session.curves[${S}].__proto__: is not a field hairsketch knows`,
    );
    expect(({} as Json).type).toBeUndefined(); // nothing leaked into Object.prototype
    // a null-prototype object is plain data
    expect(errorOf(Object.assign(Object.create(null), fresh()))).toBe('accepted');
  });

  it('caps the values of the whole input', () => {
    // a DAG: 30 levels of two references to the same object expands to 2^30 values
    let dag: Json = [1];
    for (let i = 0; i < 9; i++) dag = [dag, dag];
    const j = fresh();
    j.camera = { a: { b: { c: dag } } };
    expect(errorOf(j)).toMatch(/nested deeper than 10 levels|more than \d+ values/);
  });
});

describe('performance figure (printed, not asserted)', () => {
  /** A session JSON of about 55 MB holding 10^6 points, in two shapes. */
  function bigInputs(): { name: string; json: string }[] {
    const pt = (i: number) => [0.123456789012345 + i * 1e-9, 1.23456789012345, -0.12345678901234];
    const curve = (id: string, n: number, offset: number) => ({
      ...base.curves[S],
      id,
      points: Array.from({ length: n }, (_, i) => pt(offset + i)),
    });
    const one = { ...base, curves: [curve('big', 1e6, 0)] };
    const spread = {
      ...base,
      curves: Array.from({ length: 200 }, (_, c) => curve(`s${c}`, 5000, c * 5000)),
    };
    return [
      { name: 'one curve of 10^6 points', json: JSON.stringify(one) },
      { name: '200 curves of 5000 points', json: JSON.stringify(spread) },
    ];
  }

  it('rejects a 55 MB / 10^6-point input by the caps, and says how long that took', () => {
    for (const { name, json } of bigInputs()) {
      const data = JSON.parse(json);
      const t0 = performance.now();
      const r = parseSession(data);
      const ms = performance.now() - t0;
      expect(r.ok).toBe(false);
      console.log(
        `session reader, ${name} (${(json.length / 1e6).toFixed(1)} MB JSON): rejected in ${ms.toFixed(1)} ms — ${r.ok ? '' : r.error}`,
      );
    }
    // and the largest session the caps allow (100,000 points) is accepted, for comparison
    const curves = Array.from({ length: 20 }, (_, c) => ({
      ...base.curves[S],
      id: `m${c}`,
      points: Array.from({ length: 5000 }, (_, i) => [0.5, -2 + i * 2e-4, (c - 10) * 0.1]),
    }));
    const max = JSON.parse(JSON.stringify({ ...base, curves }));
    const t0 = performance.now();
    const r = parseSession(max);
    const ms = performance.now() - t0;
    expect(r.ok).toBe(true);
    console.log(
      `session reader, the largest accepted session (20 × 5000 points, ${(JSON.stringify(max).length / 1e6).toFixed(1)} MB JSON): read in ${ms.toFixed(1)} ms`,
    );
  });
});
