// Structure-aware mutations of JSON documents for the fuzz targets (tests/fuzz/targets/).
// A case is a description (a base document and a list of mutations, each naming its place by
// an index into the base's paths), so fast-check prints and shrinks the description, and the
// input itself is made afresh for every run of the property (exotic inputs keep state: a getter
// that answers differently on its second read, a proxy, a cycle).
import fc from 'fast-check';

export type Key = string | number;
export type Path = readonly Key[];

/** The places of a document: every value, the containers (objects and arrays) and the object
 *  fields (a value under a string key). The root is the empty path. */
export interface Places {
  any: Path[];
  containers: Path[];
  fields: Path[];
}

export function placesOf(root: unknown): Places {
  const out: Places = { any: [], containers: [], fields: [] };
  const walk = (v: unknown, path: Key[]) => {
    out.any.push(path);
    if (typeof path[path.length - 1] === 'string') out.fields.push(path);
    if (Array.isArray(v)) {
      out.containers.push(path);
      v.forEach((x, i) => {
        walk(x, [...path, i]);
      });
    } else if (v !== null && typeof v === 'object') {
      out.containers.push(path);
      for (const k of Object.keys(v)) walk((v as Record<string, unknown>)[k], [...path, k]);
    }
  };
  walk(root, []);
  return out;
}

/** `root.curves[3].points[2][1]` style. */
export function pathText(root: string, path: Path): string {
  return root + path.map((k) => (typeof k === 'number' ? `[${k}]` : `.${k}`)).join('');
}

// ---- values ------------------------------------------------------------------------------------

/** Numbers that break readers: not finite, past float ranges, -0, fractions where integers
 *  belong, past 2^31 / 2^32 / 2^53, denormals, and in-range values near the limits. */
export const SPECIAL_NUMBERS: readonly number[] = [
  Number.NaN,
  Number.POSITIVE_INFINITY,
  Number.NEGATIVE_INFINITY,
  1e308,
  -1e308,
  Number.MAX_VALUE,
  -0,
  0,
  0.5,
  1.5,
  -1,
  1e-7,
  5e-324,
  2 ** 31 - 1,
  2 ** 31,
  2 ** 32 - 1,
  2 ** 32,
  2 ** 53,
  2 ** 53 + 2,
  1e21,
  123456.789012345,
  Math.PI,
  -Math.PI,
  3.5e38,
];

const SPECIAL_STRINGS: readonly string[] = [
  '',
  '1',
  '0',
  'NaN',
  'Infinity',
  '#5a3825',
  '#5A3825',
  '#zzzzzz',
  '#fff',
  'stream',
  'dividing',
  'ponytail',
  'ruled',
  'strip',
  '25k',
  '250k',
  '1e9',
  'c1',
  'c2',
  '__proto__',
  'constructor',
  'toString',
  'a'.repeat(33),
  'x\ny',
  '\u0000',
  '\ud800',
  'é',
];

/** JSON-able odd values (numbers outside JSON, NaN and ±Infinity, included: JSON.stringify
 *  writes them as null). */
export const weirdValue: fc.Arbitrary<unknown> = fc.oneof(
  { weight: 5, arbitrary: fc.constantFrom(...SPECIAL_NUMBERS) },
  { weight: 2, arbitrary: fc.double() },
  { weight: 1, arbitrary: fc.integer() },
  { weight: 2, arbitrary: fc.constantFrom(...SPECIAL_STRINGS) },
  { weight: 1, arbitrary: fc.string({ maxLength: 10 }) },
  { weight: 2, arbitrary: fc.constantFrom(null, true, false) },
  {
    weight: 1,
    arbitrary: fc.constantFrom<unknown>(
      {},
      [],
      [0, 0, 0],
      [0, 0],
      [0, 0, 0, 0],
      [
        [0, 0, 0],
        [0, 0, 1],
      ],
      { position: [0, 0, 1], target: [0, 0, 0] },
      { index: [], target: [] },
    ),
  },
  { weight: 1, arbitrary: fc.jsonValue({ maxDepth: 2 }) },
);

/** Values no JSON document holds: bigints, symbols, functions, dates, maps, typed arrays, boxed
 *  primitives, null-prototype objects, sparse arrays. */
export const exoticValue: fc.Arbitrary<unknown> = fc.oneof(
  fc.anything({
    maxDepth: 2,
    withBigInt: true,
    withBoxedValues: true,
    withDate: true,
    withMap: true,
    withSet: true,
    withNullPrototype: true,
    withObjectString: true,
    withSparseArray: true,
    withTypedArray: true,
  }),
  fc.constantFrom<unknown>(Symbol('fuzz'), () => 1, 10n, new Float64Array([0, 0, 0])),
);

// ---- mutations ---------------------------------------------------------------------------------

export interface Where {
  /** which list of places `at` indexes (modulo its length) */
  kind: keyof Places;
  at: number;
}

const ARRAY_HOW = ['empty', 'truncate', 'duplicate', 'drop', 'long', 'reverse'] as const;
const EXOTIC_HOW = [
  'throwingProxy',
  'throwingGetter',
  'flakyGetter',
  'cycle',
  'nullProto',
  'inherited',
  'revokedProxy',
  'sparse',
  'lyingLength',
  'arrayLike',
  'ownProto',
  'prototypeFields',
  'boxed',
  'frozen',
  'symbolKey',
] as const;

export type Mutation =
  | { op: 'replace'; where: Where; value: unknown }
  | { op: 'delete'; where: Where }
  | { op: 'addKey'; where: Where; key: string; value: unknown }
  | { op: 'array'; where: Where; how: (typeof ARRAY_HOW)[number]; n: number }
  | { op: 'exotic'; where: Where; how: (typeof EXOTIC_HOW)[number]; value: unknown };

export interface MutationOptions {
  /** allow proxies, getters, cycles, non-JSON values (false: the input stays JSON-able) */
  exotic: boolean;
  /** lengths the 'long' array mutation makes (the readers' caps and past them) */
  longLengths: readonly number[];
}

const where: fc.Arbitrary<Where> = fc.record({
  kind: fc.constantFrom<keyof Places>('any', 'any', 'fields', 'fields', 'fields', 'containers'),
  at: fc.nat(),
});

const EXTRA_KEYS = ['__proto__', 'constructor', 'prototype', 'toString', 'valueOf', 'extra', ''];

export function mutation(opts: MutationOptions): fc.Arbitrary<Mutation> {
  const value = opts.exotic
    ? fc.oneof({ weight: 4, arbitrary: weirdValue }, { weight: 1, arbitrary: exoticValue })
    : weirdValue;
  const ops: fc.WeightedArbitrary<Mutation>[] = [
    { weight: 8, arbitrary: fc.record({ op: fc.constant('replace'), where, value }) },
    { weight: 2, arbitrary: fc.record({ op: fc.constant('delete'), where }) },
    {
      weight: 2,
      arbitrary: fc.record({
        op: fc.constant('addKey'),
        where,
        key: fc.oneof(fc.constantFrom(...EXTRA_KEYS), fc.string({ maxLength: 6 })),
        value,
      }),
    },
    {
      weight: 3,
      arbitrary: fc.record({
        op: fc.constant('array'),
        where,
        how: fc.constantFrom(...ARRAY_HOW),
        n: fc.nat(),
      }),
    },
  ];
  if (opts.exotic)
    ops.push({
      weight: 3,
      arbitrary: fc.record({
        op: fc.constant('exotic'),
        where,
        how: fc.constantFrom(...EXOTIC_HOW),
        value,
      }),
    });
  return fc.oneof(...ops);
}

// ---- applying them -----------------------------------------------------------------------------

function isObject(v: unknown): v is Record<Key, unknown> {
  return typeof v === 'object' && v !== null;
}

/** A copy of plain arrays and objects (holes, null prototypes and non-plain objects kept). */
export function clonePlain(v: unknown): unknown {
  if (Array.isArray(v)) {
    const out = new Array(v.length);
    for (let i = 0; i < v.length; i++) if (i in v) out[i] = clonePlain(v[i]);
    return out;
  }
  if (isObject(v)) {
    const proto = Object.getPrototypeOf(v);
    if (proto !== Object.prototype && proto !== null) return v;
    const out: Record<string, unknown> = Object.create(proto);
    for (const k of Object.keys(v)) out[k] = clonePlain(v[k]);
    return out;
  }
  return v;
}

/** The container holding `path` (through data properties only) and the last key. */
function locate(holder: { root: unknown }, path: Path): { parent: Record<Key, unknown>; key: Key } {
  let parent: Record<Key, unknown> = holder as unknown as Record<Key, unknown>;
  let key: Key = 'root';
  for (const k of path) {
    const d = Object.getOwnPropertyDescriptor(parent, key);
    if (!d || !('value' in d) || !isObject(d.value)) throw new Error('gone');
    parent = d.value;
    key = k;
  }
  if (!Object.hasOwn(parent, key)) throw new Error('gone');
  return { parent, key };
}

function fuzzError(): never {
  throw new Error('fuzz: a hostile getter threw');
}

function applyArray(a: unknown[], how: (typeof ARRAY_HOW)[number], n: number, long: number) {
  const len = a.length;
  switch (how) {
    case 'empty':
      a.length = 0;
      return;
    case 'truncate':
      a.length = len === 0 ? 0 : n % len;
      return;
    case 'duplicate':
      if (len > 0) a.splice(n % len, 0, clonePlain(a[n % len]));
      return;
    case 'drop':
      if (len > 0) a.splice(n % len, 1);
      return;
    case 'long': {
      if (len === 0) return;
      const from = a.slice();
      for (let i = len; i < long; i++) a.push(from[i % len]);
      return;
    }
    case 'reverse':
      a.reverse();
      return;
  }
}

function applyExotic(
  parent: Record<Key, unknown>,
  key: Key,
  how: (typeof EXOTIC_HOW)[number],
  value: unknown,
  root: unknown,
): void {
  const v = parent[key];
  const set = (x: unknown) => {
    parent[key] = x;
  };
  switch (how) {
    case 'throwingProxy':
      set(
        new Proxy(isObject(v) ? v : {}, {
          get: fuzzError,
          has: fuzzError,
          ownKeys: fuzzError,
          getOwnPropertyDescriptor: fuzzError,
        }),
      );
      return;
    case 'throwingGetter':
      Object.defineProperty(parent, key, { get: fuzzError, enumerable: true, configurable: true });
      return;
    case 'flakyGetter': {
      // the document's value on the first read, another on every later read
      let reads = 0;
      Object.defineProperty(parent, key, {
        get: () => (reads++ === 0 ? v : value),
        enumerable: true,
        configurable: true,
      });
      return;
    }
    case 'cycle':
      set(isObject(value) ? parent : root);
      return;
    case 'nullProto':
      if (isObject(v) && !Array.isArray(v)) set(Object.assign(Object.create(null), v));
      return;
    case 'inherited':
      if (isObject(v)) set(Object.create(v));
      return;
    case 'revokedProxy': {
      const r = Proxy.revocable(isObject(v) ? v : {}, {});
      r.revoke();
      set(r.proxy);
      return;
    }
    case 'sparse':
      if (Array.isArray(v) && v.length > 0) {
        const i = Math.abs(Number(value) | 0) % (v.length + 2);
        if (i < v.length) delete v[i];
        else v.length += i - v.length + 1;
      }
      return;
    case 'lyingLength':
      if (Array.isArray(v))
        set(
          new Proxy(v, {
            get: (t, p, r) => (p === 'length' ? Number(value) || 2 : Reflect.get(t, p, r)),
          }),
        );
      return;
    case 'arrayLike':
      if (Array.isArray(v)) set(Object.assign({ length: v.length }, v));
      return;
    case 'ownProto':
      // as JSON.parse makes it: an own, enumerable "__proto__" property
      if (isObject(v))
        Object.defineProperty(v, '__proto__', {
          value,
          enumerable: true,
          writable: true,
          configurable: true,
        });
      return;
    case 'prototypeFields':
      // the object's own fields moved to a prototype, plus an inherited odd one
      if (isObject(v) && !Array.isArray(v))
        set(Object.create(Object.assign(Object.create(null), v, { version: 1, id: value })));
      return;
    case 'boxed':
      if (typeof v === 'number') set(new Number(v));
      else if (typeof v === 'string') set(new String(v));
      else if (typeof v === 'boolean') set(new Boolean(v));
      return;
    case 'frozen':
      if (isObject(v)) Object.freeze(v);
      return;
    case 'symbolKey':
      if (isObject(v)) (v as Record<symbol, unknown>)[Symbol('fuzz')] = value;
      return;
  }
}

function placeOf(places: Places, w: Where): Path | null {
  const list = places[w.kind];
  return list.length === 0 ? null : list[w.at % list.length];
}

/** A fresh input: a copy of `base` with the mutations applied in order (exotic ones last, so
 *  that later mutations find their place); a mutation whose place is gone is skipped. `log`
 *  says what was done, for reports. */
export function applyMutations(
  base: unknown,
  places: Places,
  mutations: readonly Mutation[],
  opts: MutationOptions,
  rootName = 'root',
): { input: unknown; log: string[] } {
  const holder = { root: clonePlain(base) };
  const log: string[] = [];
  const ordered = [
    ...mutations.filter((m) => m.op !== 'exotic'),
    ...mutations.filter((m) => m.op === 'exotic'),
  ];
  for (const m of ordered) {
    const path = placeOf(places, m.where);
    if (!path) continue;
    let spot: { parent: Record<Key, unknown>; key: Key };
    try {
      spot = locate(holder, path);
    } catch {
      continue;
    }
    const { parent, key } = spot;
    const at = pathText(rootName, path);
    switch (m.op) {
      case 'replace':
        parent[key] = clonePlain(m.value);
        log.push(`${at} = ${show(m.value)}`);
        break;
      case 'delete':
        // a typed array's elements cannot be deleted (a replace may have put one there): skipped
        if (ArrayBuffer.isView(parent)) continue;
        if (Array.isArray(parent) && typeof key === 'number') parent.splice(key, 1);
        else delete parent[key];
        log.push(`delete ${at}`);
        break;
      case 'addKey': {
        const v = parent[key];
        if (!isObject(v) || Array.isArray(v) || ArrayBuffer.isView(v)) continue;
        try {
          Object.defineProperty(v, m.key, {
            value: clonePlain(m.value),
            enumerable: true,
            writable: true,
            configurable: true,
          });
        } catch {
          continue; // a value that takes no new keys (frozen, exotic): not a case for the reader
        }
        log.push(`${at}[${JSON.stringify(m.key)}] = ${show(m.value)}`);
        break;
      }
      case 'array': {
        const v = parent[key];
        if (!Array.isArray(v)) continue;
        const long = opts.longLengths[m.n % opts.longLengths.length];
        applyArray(v, m.how, m.n, long);
        log.push(`${at}: ${m.how}${m.how === 'long' ? ` to ${long}` : ''} (n=${m.n})`);
        break;
      }
      case 'exotic':
        // a getter on the holder of the root is no input at all
        if (path.length === 0 && (m.how === 'throwingGetter' || m.how === 'flakyGetter')) continue;
        try {
          applyExotic(parent, key, m.how, clonePlain(m.value), holder.root);
        } catch {
          continue; // its place is behind an earlier hostile getter or proxy
        }
        log.push(`${at}: ${m.how} (${show(m.value)})`);
        break;
    }
  }
  return { input: holder.root, log };
}

/** A short, never-throwing description of any value. */
export function show(v: unknown, max = 120): string {
  let s: string;
  try {
    if (typeof v === 'number') s = Object.is(v, -0) ? '-0' : String(v);
    else if (typeof v === 'bigint') s = `${v}n`;
    else if (typeof v === 'symbol' || typeof v === 'function') s = String(v);
    else if (v === undefined) s = 'undefined';
    else s = JSON.stringify(v) ?? String(v);
  } catch {
    s = Object.prototype.toString.call(v);
  }
  return s.length > max ? `${s.slice(0, max)}…(${s.length} chars)` : s;
}
