// Fuzz targets: everything that reads what comes in from outside (a session file, a share link,
// a CLI problem, an exported file) and every export writer, each with its arbitraries and its
// property ("nothing a user makes is lost, whatever comes in"):
//   - no throw escapes a reader or a writer;
//   - accepted inputs round-trip (a session read back after JSON, a link re-encoded, the
//     session carried by an export);
//   - rejected inputs say what is wrong on one short line (the session reader names a field).
// tests/unit/fuzz.test.ts runs each with a fixed seed and a bounded count (npm test);
// tests/fuzz/run.ts (npm run fuzz) runs 100,000 cases each with random seeds and counts.
import { createHash } from 'node:crypto';
import { deflateRawSync } from 'node:zlib';
import fc from 'fast-check';
import { presetSession } from '../../web/cli/presetSession';
import { decodeProblem, MAX_GRID_POINTS } from '../../web/cli/problem';
import { CHUNK_BYTES } from '../../web/export/chunkSink';
import type { ExportFormat } from '../../web/export/formats';
import { hairFileSize } from '../../web/export/hairWriter';
import { readExportedSession } from '../../web/export/readExport';
import { type ExportHead, MAX_POINTS_PER_STRAND } from '../../web/export/types';
import { writeExport } from '../../web/export/writeExport';
import { Head } from '../../web/head/head';
import { PRESET_NAMES } from '../../web/model/presets';
import { quantizeSession } from '../../web/model/quantize';
import type { SessionState } from '../../web/model/session';
import { parseSession, readSessionFile, writeSessionFile } from '../../web/model/sessionFile';
import { decodeSessionLink, encodeSessionLink, MAX_LINK_BYTES } from '../../web/model/sessionLink';
import type { StrandArrays } from '../../web/solver/protocol';
import { pngFile } from '../support/pictureFiles';
import { rng } from '../support/seededRandom';
import {
  applyMutations,
  type Mutation,
  type MutationOptions,
  mutation,
  type Places,
  placesOf,
  show,
} from './mutate';

// ---- outcomes ----------------------------------------------------------------------------------

export type Outcome = 'accepted' | 'rejected';

/** The code under test threw (none may escape). */
export class EscapedThrow extends Error {}
/** The code under test answered, wrongly (a round trip changed the data, an error names
 *  nothing, an output invariant broke). */
export class Violation extends Error {}

function escaped(what: string, e: unknown): EscapedThrow {
  const msg = e instanceof Error ? `${e.name}: ${e.message}` : show(e);
  return new EscapedThrow(`${what} threw ${msg}`);
}

function guard<T>(what: string, f: () => T): T {
  try {
    return f();
  } catch (e) {
    throw escaped(what, e);
  }
}

async function guardAsync<T>(what: string, f: () => Promise<T>): Promise<T> {
  try {
    return await f();
  } catch (e) {
    throw escaped(what, e);
  }
}

function check(ok: boolean, what: () => string): asserts ok {
  if (!ok) throw new Violation(what());
}

/** The first place where a and b differ (numbers by Object.is, so -0 ≠ 0; holes ≠ values;
 *  own enumerable keys), or null when deep-equal. */
export function firstDifference(a: unknown, b: unknown, at = ''): string | null {
  if (typeof a === 'number' && typeof b === 'number')
    return Object.is(a, b) ? null : `${at || '(root)'}: ${show(a)} vs ${show(b)}`;
  if (typeof a !== 'object' || typeof b !== 'object' || a === null || b === null)
    return a === b ? null : `${at || '(root)'}: ${show(a)} vs ${show(b)}`;
  if (Array.isArray(a) !== Array.isArray(b)) return `${at}: array vs not`;
  if (Array.isArray(a) && Array.isArray(b)) {
    if (a.length !== b.length) return `${at}.length: ${a.length} vs ${b.length}`;
    for (let i = 0; i < a.length; i++) {
      if (i in a !== i in b) return `${at}[${i}]: a hole on one side`;
      const d = firstDifference(a[i], b[i], `${at}[${i}]`);
      if (d) return d;
    }
    return null;
  }
  const ka = Object.keys(a);
  const kb = Object.keys(b);
  const ra = a as Record<string, unknown>;
  const rb = b as Record<string, unknown>;
  for (const k of ka) if (!Object.hasOwn(rb, k)) return `${at}.${k}: missing on one side`;
  for (const k of kb) if (!Object.hasOwn(ra, k)) return `${at}.${k}: missing on one side`;
  for (const k of ka) {
    const d = firstDifference(ra[k], rb[k], `${at}.${k}`);
    if (d) return d;
  }
  return null;
}

/** A rejection message: present, on one line, short (a CLI prints it as its one line). */
function checkMessage(error: unknown, where: string): asserts error is string {
  check(
    typeof error === 'string' && error.length > 0,
    () => `${where}: the error is not a message (${show(error)})`,
  );
  check(!/[\r\n]/.test(error), () => `${where}: the error is not one line: ${show(error)}`);
  check(
    error.length <= 500,
    () => `${where}: the error is ${error.length} characters: ${show(error)}`,
  );
}

/** The session reader's messages start with the path of the field: `session.curves[2].points[4]
 *  [1]: must be a finite number`; a key that is not an identifier would be quoted as JSON
 *  (`session["a b"]: …`), so that the path stays unambiguous. */
export const SESSION_FIELD = /^session(\.[A-Za-z_$][\w$]*|\[\d+\]|\["(?:[^"\\]|\\.)*"\])*: \S/;

/** A session the reader accepted reads back, after JSON, as the same session. */
function checkReadsBack(value: SessionState, where: string): void {
  let json: unknown;
  try {
    json = JSON.parse(JSON.stringify(value));
  } catch (e) {
    throw new Violation(`${where}: the accepted session is not JSON (${show(e)})`);
  }
  const again = guard('parseSession (reading back)', () => parseSession(json));
  check(again.ok, () => `${where}: the accepted session reads back rejected: ${show(again)}`);
  const d = firstDifference(value, again.ok ? again.value : null, 'session');
  check(d === null, () => `${where}: the accepted session reads back changed at ${d}`);
}

// ---- the fixtures the arbitraries start from -------------------------------------------------

export interface FuzzContext {
  /** Preset sessions as the app builds them (plus one on the 100k grid with avoid scalp on, a
   *  session-wide detail and a curve's own detail), as plain JSON. */
  sessions: { name: string; json: unknown; places: Places }[];
  /** Their share links. */
  links: string[];
  /** Small valid problems for `hairsketch solve`, as JSON. */
  problems: { json: unknown; places: Places }[];
  /** A .usda and a .glb export of a small hair with each preset session. */
  exports: Uint8Array[];
  /** Saved session files (JSON) that embed reference picture files. */
  sessionFiles: { name: string; json: unknown; places: Places }[];
}

function concat(chunks: Uint8Array[]): Uint8Array {
  let n = 0;
  for (const c of chunks) n += c.length;
  const out = new Uint8Array(n);
  let at = 0;
  for (const c of chunks) {
    out.set(c, at);
    at += c.length;
  }
  return out;
}

export async function makeContext(): Promise<FuzzContext> {
  const head = Head.builtin();
  const built: { name: string; session: SessionState }[] = PRESET_NAMES.map((name) => ({
    name,
    session: presetSession(name, head),
  }));
  const withAvoid = presetSession('fig7', head, '100k', 5000);
  built.push({
    name: 'fig7+avoidScalp+detail@100k',
    session: {
      ...withAvoid,
      hairColor: '#C0FFEE',
      avoidScalp: true,
      detail: {
        curl: { radius: 0.05, frequency: 3, start: 0.15, randomOffset: 1 },
        clump: { factor: 0.5, shape: -0.3, tipSpread: 0.02, guideDistance: 0.12 },
        frizz: { distance: 0.006, shape: 0.5 },
        lengthJitter: 0.15,
      },
      curves: withAvoid.curves.map((c, i) =>
        i === 1 ? { ...c, detail: { frizz: { distance: 0.01, shape: -1 } } } : c,
      ),
    },
  });
  // a loaded head (its reference), scalp brush strokes and a tilted mirror plane (version 3)
  const def = presetSession('default', head);
  built.push({
    name: 'default+loaded head+scalp strokes+mirror plane',
    session: quantizeSession({
      ...def,
      head: {
        kind: 'mesh',
        name: 'my head.glb',
        hash: '9f86d081884c7d659a2feaa0c55ad015a3bf4f1b2b0b822cd15d6c15b0f00a08',
        format: 'glb',
        up: 'z',
        turns: [
          { axis: 'y', quarterTurns: 1 },
          { axis: 'x', quarterTurns: 3 },
        ],
      },
      scalpPaint: [
        { erase: false, radius: 0.15, points: def.curves[0].points.slice(0, 12) },
        { erase: true, radius: 0.04, points: [def.curves[1].points[0]] },
      ],
      symmetry: { normal: [0.9986295347545738, 0.05233595624294383, 0], offset: 0.012 },
    }),
  });
  // reference pictures (one hidden, one moved) on the empty preset, so that most of the places a
  // mutation picks are theirs
  const pictures = [pngFile(4, 6, () => [255, 0, 255]), pngFile(3, 3, (x) => [x * 80, 200, 0])];
  const sha = (b: Uint8Array) => createHash('sha256').update(b).digest('hex');
  const withPictures = quantizeSession({
    ...presetSession('empty', head),
    references: [
      {
        name: 'front photo.jpg',
        hash: sha(pictures[0]),
        format: 'png',
        width: 4,
        height: 6,
        view: 'front',
        opacity: 0.6,
        scale: 3.2,
        offset: [0, 0.15],
      },
      {
        name: 'side.webp',
        hash: sha(pictures[1]),
        format: 'png',
        width: 3,
        height: 3,
        view: 'side',
        opacity: 1,
        scale: 2.5,
        offset: [-0.4, 0],
        hidden: true,
      },
    ],
  });
  built.push({ name: 'empty+reference pictures', session: withPictures });
  const fileText = await writeSessionFile(withPictures, {
    pictureBytes: new Map(
      pictures.map((b) => [sha(b), new Uint8Array(b).slice().buffer as ArrayBuffer]),
    ),
  });
  const fileJson = JSON.parse(fileText);
  const sessionFiles = [
    { name: 'session file with pictures', json: fileJson, places: placesOf(fileJson) },
  ];
  const sessions = built.map(({ name, session }) => {
    const json = JSON.parse(JSON.stringify(session));
    return { name, json, places: placesOf(json) };
  });
  const links = await Promise.all(built.map(({ session }) => encodeSessionLink(session)));
  const problems = [
    { grid: [4, 3, 2], omega: 100, steps: [{ set: [[1, 2, 1, 0, 1, 0]], unset: [] }] },
    {
      grid: [5, 5, 5],
      steps: [
        {
          set: [
            [0, 0, 0, 1, 0, 0],
            [4, 4, 4, 0, 0.5, -0.5],
          ],
        },
        { unset: [[0, 0, 0]], set: [[2, 3, 4, 1e-3, 2, 3]] },
        {},
      ],
    },
  ].map((json) => ({ json, places: placesOf(json) }));
  const strands = packStrands(
    [2, 5, 0, 1, 300].map((n, s) => Array.from({ length: 3 * n }, (_, i) => (s + 1) * 0.01 * i)),
  );
  const exports: Uint8Array[] = [];
  for (const { session } of built)
    for (const format of ['usda', 'glb'] as const)
      exports.push(concat([...writeExport(format, { strands, session, head: null })]));
  return { sessions, links, problems, exports, sessionFiles };
}

export function packStrands(strands: number[][]): StrandArrays {
  const strandStart = new Uint32Array(strands.length + 1);
  let p = 0;
  strands.forEach((s, i) => {
    p += s.length / 3;
    strandStart[i + 1] = p;
  });
  return { points: new Float32Array(strands.flat()), strandStart };
}

/** Any code points, lone surrogates included (made once: building it takes a second). */
let binaryTextArb: fc.Arbitrary<string> | null = null;
const binaryText: fc.Arbitrary<string> = fc.constant(null).chain(() => {
  binaryTextArb ??= fc.string({ unit: 'binary', maxLength: 40 });
  return binaryTextArb;
});

// ---- targets -----------------------------------------------------------------------------------

export interface FuzzTarget<T> {
  name: string;
  arbitrary: fc.Arbitrary<T>;
  /** Checks one case: 'accepted' / 'rejected' by the code under test; throws EscapedThrow or
   *  Violation. */
  run(input: T): Outcome | Promise<Outcome>;
  /** What the case is, for a report (the input it makes, the mutations applied). */
  explain(input: T): string;
}

// ---- 1. the session reader ------------------------------------------------------------------

const SESSION_MUTATIONS: MutationOptions = { exotic: true, longLengths: [3, 201, 5001, 200_001] };
const PLAIN_MUTATIONS: MutationOptions = { exotic: false, longLengths: [3, 201, 5001] };

export type SessionCase =
  | { kind: 'mutated'; base: number; mutations: Mutation[] }
  | { kind: 'json'; value: unknown }
  | { kind: 'anything'; value: unknown };

function sessionCase(ctx: FuzzContext, opts: MutationOptions): fc.Arbitrary<SessionCase> {
  const mutated = fc.record({
    kind: fc.constant('mutated' as const),
    base: fc.nat(ctx.sessions.length - 1),
    mutations: fc.array(mutation(opts), { maxLength: 4 }),
  });
  const arbs: fc.WeightedArbitrary<SessionCase>[] = [
    { weight: 12, arbitrary: mutated },
    {
      weight: 1,
      arbitrary: fc.record({ kind: fc.constant('json' as const), value: fc.jsonValue() }),
    },
  ];
  if (opts.exotic)
    arbs.push({
      weight: 1,
      arbitrary: fc.record({
        kind: fc.constant('anything' as const),
        value: fc.anything({
          withBigInt: true,
          withBoxedValues: true,
          withDate: true,
          withMap: true,
          withNullPrototype: true,
          withSparseArray: true,
          withTypedArray: true,
        }),
      }),
    });
  return fc.oneof(...arbs);
}

function makeSession(
  ctx: FuzzContext,
  c: SessionCase,
  opts: MutationOptions,
): { input: unknown; log: string[] } {
  if (c.kind !== 'mutated') return { input: c.value, log: [`${c.kind}: ${show(c.value)}`] };
  const base = ctx.sessions[c.base];
  const r = applyMutations(base.json, base.places, c.mutations, opts, 'session');
  return { input: r.input, log: [`preset ${base.name}`, ...r.log] };
}

/** A session the reader accepts, from a case: the mutated preset when the reader accepts it
 *  (-0, 1e308, missing optional fields, …), else the preset itself; as the reader returns it. */
export function acceptedSession(ctx: FuzzContext, c: SessionCase): SessionState {
  const r = parseSession(makeSession(ctx, c, PLAIN_MUTATIONS).input);
  if (r.ok) return r.value;
  const base = parseSession(ctx.sessions[c.kind === 'mutated' ? c.base : 0].json);
  if (!base.ok) throw new Error(`a preset session is refused: ${base.error}`);
  return base.value;
}

export function sessionTarget(ctx: FuzzContext): FuzzTarget<SessionCase> {
  return {
    name: 'session reader',
    arbitrary: sessionCase(ctx, SESSION_MUTATIONS),
    explain: (c) => makeSession(ctx, c, SESSION_MUTATIONS).log.join('; '),
    run(c) {
      const { input } = makeSession(ctx, c, SESSION_MUTATIONS);
      const r = guard('parseSession', () => parseSession(input));
      if (!r.ok) {
        checkMessage(r.error, 'parseSession');
        check(SESSION_FIELD.test(r.error), () => `the error names no field: ${show(r.error)}`);
        return 'rejected';
      }
      checkReadsBack(r.value, 'parseSession');
      return 'accepted';
    },
  };
}

// ---- 1b. session files (embedded picture files) ----------------------------------------------

export type SessionFileCase = { base: number; mutations: Mutation[] };

export function sessionFileTarget(ctx: FuzzContext): FuzzTarget<SessionFileCase> {
  const make = (c: SessionFileCase) => {
    const base = ctx.sessionFiles[c.base];
    return applyMutations(base.json, base.places, c.mutations, SESSION_MUTATIONS, 'session');
  };
  return {
    name: 'session file reader',
    arbitrary: fc.record({
      base: fc.nat(ctx.sessionFiles.length - 1),
      mutations: fc.array(mutation(SESSION_MUTATIONS), { maxLength: 4 }),
    }),
    explain: (c) => make(c).log.join('; '),
    async run(c) {
      const { input } = make(c);
      const r = await guardAsync('readSessionFile', () => readSessionFile(input));
      if (!r.ok) {
        checkMessage(r.error, 'readSessionFile');
        check(SESSION_FIELD.test(r.error), () => `the error names no field: ${show(r.error)}`);
        return 'rejected';
      }
      checkReadsBack(r.value.session, 'readSessionFile');
      // every embedded file is one the session names, with the bytes its hash says
      const named = new Set((r.value.session.references ?? []).map((p) => p.hash));
      for (const f of r.value.pictureFiles ?? []) {
        check(named.has(f.hash), () => `picture file ${f.hash} is no picture of the session`);
        const h = createHash('sha256').update(new Uint8Array(f.bytes)).digest('hex');
        check(h === f.hash, () => `picture file ${f.name}: its bytes hash to ${h}, not ${f.hash}`);
      }
      return 'accepted';
    },
  };
}

// ---- 2. the link codec -----------------------------------------------------------------------

export type LinkCase =
  | { kind: 'text'; prefix: string; text: string }
  | { kind: 'bytes'; prefix: string; bytes: Uint8Array; deflate: boolean }
  | { kind: 'json'; prefix: string; value: unknown }
  | { kind: 'session'; prefix: string; session: SessionCase }
  | {
      kind: 'damaged';
      link: number;
      how: 'truncate' | 'flipBit' | 'flipChar' | 'insert' | 'append';
      at: number;
      bit: number;
      text: string;
    }
  | { kind: 'bomb'; prefix: string; bytes: number }
  | { kind: 'encode'; session: SessionCase };

const b64url = (b: Uint8Array) => Buffer.from(b).toString('base64url');

function linkPrefixes(ctx: FuzzContext): string[] {
  const real = new Set(ctx.links.map((l) => /^[^=]*=(\d+\.)?/.exec(l)?.[0] ?? 's='));
  const out = ['#s=', 's=', '', '#', '#s', 's=2.', 's=1.', '#s=9.', 'x=', '#S='];
  for (const p of real) out.push(p, `#${p}`);
  return [...new Set(out)];
}

const bombs = new Map<number, Uint8Array>();
function bomb(size: number): Uint8Array {
  let b = bombs.get(size);
  if (!b) {
    b = deflateRawSync(new Uint8Array(size).fill(0x20));
    bombs.set(size, b);
  }
  return b;
}

function makeLink(ctx: FuzzContext, c: LinkCase): string {
  switch (c.kind) {
    case 'text':
      return c.prefix + c.text;
    case 'bytes':
      return c.prefix + b64url(c.deflate ? deflateRawSync(c.bytes) : c.bytes);
    case 'json':
      return c.prefix + b64url(deflateRawSync(Buffer.from(JSON.stringify(c.value) ?? 'null')));
    case 'session': {
      const { input } = makeSession(ctx, c.session, PLAIN_MUTATIONS);
      return c.prefix + b64url(deflateRawSync(Buffer.from(JSON.stringify(input) ?? 'null')));
    }
    case 'bomb':
      return c.prefix + b64url(bomb(c.bytes));
    case 'damaged': {
      const link = ctx.links[c.link % ctx.links.length];
      const at = link.length === 0 ? 0 : c.at % link.length;
      switch (c.how) {
        case 'truncate':
          return link.slice(0, at);
        case 'flipChar': {
          const alphabet = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_';
          return link.slice(0, at) + alphabet[c.bit % 64] + link.slice(at + 1);
        }
        case 'flipBit': {
          // a bit of the payload (after the prefix), re-encoded
          const m = /^([^=]*=(?:\d+\.)?)(.*)$/.exec(link);
          if (!m) return link;
          const bytes = Buffer.from(m[2], 'base64url');
          if (bytes.length === 0) return link;
          const i = c.at % bytes.length;
          bytes[i] ^= 1 << (c.bit % 8);
          return m[1] + b64url(bytes);
        }
        case 'insert':
          return link.slice(0, at) + c.text + link.slice(at);
        case 'append':
          return link + c.text;
      }
      return link;
    }
    case 'encode':
      return '';
  }
}

export function linkTarget(ctx: FuzzContext): FuzzTarget<LinkCase> {
  const prefix = fc.constantFrom(...linkPrefixes(ctx));
  const arbitrary: fc.Arbitrary<LinkCase> = fc.oneof(
    {
      weight: 20,
      arbitrary: fc.record({
        kind: fc.constant('text' as const),
        prefix,
        text: fc.oneof(
          fc.string({ maxLength: 60 }),
          binaryText,
          fc.stringMatching(/^[A-Za-z0-9_-]{0,80}$/),
        ),
      }),
    },
    {
      weight: 20,
      arbitrary: fc.record({
        kind: fc.constant('bytes' as const),
        prefix,
        bytes: fc.uint8Array({ maxLength: 200 }),
        deflate: fc.boolean(),
      }),
    },
    {
      weight: 10,
      arbitrary: fc.record({ kind: fc.constant('json' as const), prefix, value: fc.jsonValue() }),
    },
    {
      weight: 20,
      arbitrary: fc.record({
        kind: fc.constant('session' as const),
        prefix,
        session: sessionCase(ctx, PLAIN_MUTATIONS),
      }),
    },
    {
      weight: 40,
      arbitrary: fc.record({
        kind: fc.constant('damaged' as const),
        link: fc.nat(),
        how: fc.constantFrom('truncate', 'flipBit', 'flipChar', 'insert', 'append'),
        at: fc.nat(),
        bit: fc.nat(),
        text: fc.oneof(fc.constantFrom('=', '%2B', ' ', '\n', '#s=', '.', '..'), fc.string()),
      }),
    },
    {
      weight: 1,
      arbitrary: fc.record({
        kind: fc.constant('bomb' as const),
        prefix,
        bytes: fc.constantFrom(MAX_LINK_BYTES - 1024, MAX_LINK_BYTES + 1),
      }),
    },
    {
      weight: 30,
      arbitrary: fc.record({
        kind: fc.constant('encode' as const),
        session: sessionCase(ctx, PLAIN_MUTATIONS),
      }),
    },
  );
  return {
    name: 'link codec',
    arbitrary,
    explain(c) {
      if (c.kind === 'encode' || c.kind === 'session')
        return `${c.kind}: ${makeSession(ctx, c.session, PLAIN_MUTATIONS).log.join('; ')}`;
      return `${c.kind}: ${show(makeLink(ctx, c), 400)}`;
    },
    async run(c) {
      if (c.kind === 'encode') {
        const session = acceptedSession(ctx, c.session);
        const l1 = await guardAsync('encodeSessionLink', () => encodeSessionLink(session));
        check(typeof l1 === 'string', () => `encodeSessionLink gave ${show(l1)}`);
        check(/^[A-Za-z0-9_.=-]*$/.test(l1), () => `the link is not URL-safe: ${show(l1)}`);
        const d1 = await guardAsync('decodeSessionLink', () => decodeSessionLink(l1));
        check(d1.ok, () => `the link of an accepted session is refused: ${show(d1)}`);
        checkReadsBack(d1.value, 'decodeSessionLink');
        const l2 = await guardAsync('encodeSessionLink', () => encodeSessionLink(d1.value));
        check(l2 === l1, () => `re-encoding changes the link: ${show(l1)} → ${show(l2)}`);
        return 'accepted';
      }
      const link = makeLink(ctx, c);
      const r = await guardAsync('decodeSessionLink', () => decodeSessionLink(link));
      if (!r.ok) {
        checkMessage(r.error, 'decodeSessionLink');
        return 'rejected';
      }
      checkReadsBack(r.value, 'decodeSessionLink');
      return 'accepted';
    },
  };
}

// ---- 3. the CLI problem reader ----------------------------------------------------------------

export type ProblemCase =
  | { kind: 'text'; text: string }
  | { kind: 'json'; value: unknown }
  | { kind: 'made'; value: unknown; numbers: { at: number; token: string }[]; cut: number | null }
  | { kind: 'mutated'; base: number; mutations: Mutation[]; cut: number | null };

/** Number spellings JSON.parse reads as values a JSON writer never writes. */
const NUMBER_TOKENS = ['1e999', '-1e999', '-0', '1.5', '1e-400', '4294967297', '9007199254740993'];

/** A grid size: mostly valid (2..6), now and then not. */
const gridSize = fc.oneof(
  { weight: 9, arbitrary: fc.integer({ min: 2, max: 6 }) },
  { weight: 1, arbitrary: fc.constantFrom(0, 1, 7) },
);
/** A grid index: mostly inside every valid grid (0, 1), now and then anywhere. */
const gridIndex = fc.oneof(
  { weight: 9, arbitrary: fc.integer({ min: 0, max: 1 }) },
  { weight: 1, arbitrary: fc.integer({ min: -1, max: 7 }) },
);

function made(): fc.Arbitrary<unknown> {
  return fc
    .record({
      grid: fc.tuple(gridSize, gridSize, gridSize),
      omega: fc.option(fc.oneof(fc.double(), fc.constantFrom(100, 1, 0, -1))),
      steps: fc.array(
        fc.record(
          {
            set: fc.array(
              fc.tuple(
                gridIndex,
                gridIndex,
                gridIndex,
                fc.oneof(fc.double({ min: -2, max: 2 }), fc.double()),
                fc.double({ min: -2, max: 2, noNaN: true }),
                fc.double({ min: -2, max: 2, noNaN: true }),
              ),
              { maxLength: 6 },
            ),
            unset: fc.array(
              fc.tuple(gridIndex, gridIndex, gridIndex).map((t) => [...t]),
              { maxLength: 3 },
            ),
          },
          { requiredKeys: [] },
        ),
        { maxLength: 4 },
      ),
    })
    .map((p) => ({ ...p, omega: p.omega ?? undefined }));
}

const cut = fc.option(fc.nat(), { freq: 6 });

function problemText(ctx: FuzzContext, c: ProblemCase): { text: string; log: string } {
  switch (c.kind) {
    case 'text':
      return { text: c.text, log: 'text' };
    case 'json':
      return { text: JSON.stringify(c.value) ?? '', log: 'json' };
    case 'made': {
      let text = JSON.stringify(c.value) ?? '';
      const log = [`made ${show(c.value, 300)}`];
      for (const { at, token } of c.numbers) {
        const all = [...text.matchAll(/-?\d+(\.\d+)?([eE][-+]?\d+)?/g)];
        if (all.length === 0) break;
        const m = all[at % all.length];
        const i = m.index ?? 0;
        text = text.slice(0, i) + token + text.slice(i + m[0].length);
        log.push(`number #${at % all.length} → ${token}`);
      }
      if (c.cut !== null) {
        text = text.slice(0, c.cut % (text.length + 1));
        log.push(`cut at ${c.cut % (text.length + 1)}`);
      }
      return { text, log: log.join('; ') };
    }
    case 'mutated': {
      const base = ctx.problems[c.base % ctx.problems.length];
      const r = applyMutations(base.json, base.places, c.mutations, PLAIN_MUTATIONS, 'problem');
      let text = JSON.stringify(r.input) ?? '';
      if (c.cut !== null) text = text.slice(0, c.cut % (text.length + 1));
      return { text, log: [...r.log, c.cut === null ? '' : `cut at ${c.cut}`].join('; ') };
    }
  }
}

export function problemTarget(ctx: FuzzContext): FuzzTarget<ProblemCase> {
  const arbitrary: fc.Arbitrary<ProblemCase> = fc.oneof(
    {
      weight: 1,
      arbitrary: fc.record({
        kind: fc.constant('text' as const),
        text: fc.oneof(fc.string(), binaryText, fc.json()),
      }),
    },
    {
      weight: 1,
      arbitrary: fc.record({ kind: fc.constant('json' as const), value: fc.jsonValue() }),
    },
    {
      weight: 4,
      arbitrary: fc.record({
        kind: fc.constant('made' as const),
        value: made(),
        numbers: fc.array(fc.record({ at: fc.nat(), token: fc.constantFrom(...NUMBER_TOKENS) }), {
          maxLength: 2,
        }),
        cut,
      }),
    },
    {
      weight: 4,
      arbitrary: fc.record({
        kind: fc.constant('mutated' as const),
        base: fc.nat(),
        mutations: fc.array(mutation(PLAIN_MUTATIONS), { maxLength: 3 }),
        cut,
      }),
    },
  );
  return {
    name: 'CLI problem reader',
    arbitrary,
    explain: (c) => {
      const { text, log } = problemText(ctx, c);
      return `${log}; text ${show(text, 400)}`;
    },
    run(c) {
      const { text } = problemText(ctx, c);
      const r = guard('decodeProblem', () => decodeProblem(text));
      if (!r.ok) {
        checkMessage(r.error, 'decodeProblem');
        check(
          /\b(JSON|problem|grid|omega|steps?|set|unset|key)\b/.test(r.error),
          () => `the error says nothing of what is wrong: ${show(r.error)}`,
        );
        return 'rejected';
      }
      const { grid, omega, steps } = r.value;
      check(
        Array.isArray(grid) &&
          grid.length === 3 &&
          grid.every((n) => Number.isInteger(n) && n >= 2),
        () => `accepted grid ${show(grid)}`,
      );
      const points = grid[0] * grid[1] * grid[2];
      check(points <= MAX_GRID_POINTS, () => `accepted a grid of ${points} points`);
      check(Number.isFinite(omega) && omega > 0, () => `accepted omega ${show(omega)}`);
      const inGrid = (e: readonly unknown[]) =>
        [0, 1, 2].every((a) => Number.isInteger(e[a]) && (e[a] as number) >= 0) &&
        (e[0] as number) < grid[0] &&
        (e[1] as number) < grid[1] &&
        (e[2] as number) < grid[2];
      steps.forEach((st, s) => {
        st.set.forEach((e, i) => {
          check(
            Array.isArray(e) && e.length === 6 && inGrid(e),
            () => `accepted step ${s} set[${i}] = ${show(e)}`,
          );
          check(
            e.slice(3).every((x) => typeof x === 'number' && Number.isFinite(x)),
            () => `accepted a target that is not finite: step ${s} set[${i}] = ${show(e)}`,
          );
        });
        st.unset.forEach((e, i) => {
          check(
            Array.isArray(e) && e.length === 3 && inGrid(e),
            () => `accepted step ${s} unset[${i}] = ${show(e)}`,
          );
        });
      });
      return 'accepted';
    },
  };
}

// ---- 4. the export writers, and the reader of exports ------------------------------------------

export interface HairCase {
  /** points per strand */
  lengths: number[];
  /** how coordinates are made: small (a head's size), zero-length segments, float32 extremes */
  style: 'small' | 'still' | 'extreme' | 'mixed';
  seed: number;
  specials: number[];
}

const FLOAT32_MAX = 3.4028234663852886e38;

export function makeHair(h: HairCase): StrandArrays {
  const rand = rng(h.seed);
  let total = 0;
  for (const n of h.lengths) total += n;
  const strandStart = new Uint32Array(h.lengths.length + 1);
  const points = new Float32Array(3 * total);
  let p = 0;
  h.lengths.forEach((n, s) => {
    let x = rand() * 2 - 1;
    let y = rand() * 2;
    let z = rand() * 2 - 1;
    for (let i = 0; i < n; i++, p++) {
      const kind = h.style === 'mixed' ? ['small', 'still', 'extreme'][(rand() * 3) | 0] : h.style;
      if (kind === 'small') {
        x += (rand() - 0.5) * 0.05;
        y -= rand() * 0.05;
        z += (rand() - 0.5) * 0.05;
      } else if (kind === 'extreme') {
        const big = () => (rand() - 0.5) * 2 * FLOAT32_MAX * rand() ** 8;
        x = big();
        y = big();
        z = big();
      }
      const sp = h.specials.length > 0 && rand() < 0.1 ? h.specials : null;
      points[3 * p] = sp ? sp[(rand() * sp.length) | 0] : x;
      points[3 * p + 1] = y;
      points[3 * p + 2] = z;
    }
    strandStart[s + 1] = p;
  });
  return { points, strandStart };
}

const hairCase: fc.Arbitrary<HairCase> = fc.record({
  lengths: fc.array(
    fc.oneof(
      { weight: 3, arbitrary: fc.constantFrom(0, 1, 2, 3) },
      { weight: 4, arbitrary: fc.integer({ min: 0, max: 40 }) },
      { weight: 1, arbitrary: fc.constantFrom(254, 255, 256, 257) },
      { weight: 1, arbitrary: fc.integer({ min: 256, max: 700 }) },
    ),
    { maxLength: 12 },
  ),
  style: fc.constantFrom('small', 'small', 'still', 'extreme', 'mixed'),
  seed: fc.nat(),
  specials: fc.array(fc.float({ noNaN: true, noDefaultInfinity: true }), { maxLength: 4 }),
});

export interface HeadCase {
  vertices: number;
  triangles: [number, number, number][];
  normals: boolean;
  seed: number;
}

const headCase: fc.Arbitrary<HeadCase | null> = fc.option(
  fc.integer({ min: 0, max: 12 }).chain((vertices) =>
    fc.record({
      vertices: fc.constant(vertices),
      triangles:
        vertices === 0
          ? fc.constant([])
          : fc.array(fc.tuple(fc.nat(vertices - 1), fc.nat(vertices - 1), fc.nat(vertices - 1)), {
              maxLength: 16,
            }),
      normals: fc.boolean(),
      seed: fc.nat(),
    }),
  ),
  { freq: 2 },
);

function makeHead(h: HeadCase | null): ExportHead | null {
  if (!h) return null;
  const rand = rng(h.seed);
  const positions = Float32Array.from({ length: 3 * h.vertices }, () => rand() * 2 - 1);
  return {
    positions,
    indices: Uint32Array.from(h.triangles.flat()),
    ...(h.normals ? { normals: Float32Array.from(positions, (v) => v / 2) } : {}),
  };
}

export interface ExportCase {
  format: ExportFormat;
  hair: HairCase;
  head: HeadCase | null;
  session: SessionCase;
}

/** Every number in `text` read as a float32 is finite. */
function finiteNumbers(text: string): boolean {
  for (const m of text.matchAll(/-?\d+(\.\d+)?([eE][-+]?\d+)?|\b(inf|nan)\b/gi))
    if (!Number.isFinite(Math.fround(Number(m[0])))) return false;
  return true;
}

function listOf(text: string, decl: string): string | null {
  const i = text.indexOf(decl);
  if (i < 0) return null;
  const open = text.indexOf('= [', i) + 2;
  const close = text.indexOf(']', open);
  return text.slice(open + 1, close);
}

function checkUsda(bytes: Uint8Array, n: number, p: number, lengths: number[]): void {
  const text = new TextDecoder().decode(bytes);
  check(text.startsWith('#usda 1.0\n'), () => 'the .usda does not start with #usda 1.0');
  const hair = text.slice(text.indexOf('def BasisCurves "hair"'));
  const counts = (listOf(hair, 'int[] curveVertexCounts') ?? '')
    .split(',')
    .map((s) => s.trim())
    .filter((s) => s !== '')
    .map(Number);
  check(counts.length === n, () => `the .usda has ${counts.length} curves, not ${n}`);
  check(
    counts.every((c, i) => c === lengths[i]),
    () => `the .usda's curve counts ${show(counts)} are not ${show(lengths)}`,
  );
  const sum = counts.reduce((a, b) => a + b, 0);
  const pts = listOf(hair, 'point3f[] points') ?? '';
  const tuples = pts.match(/\(([^)]*)\)/g) ?? [];
  check(
    tuples.length === sum && sum === p,
    () => `the .usda's counts sum to ${sum}, it lists ${tuples.length} points, expected ${p}`,
  );
  check(
    tuples.every((t) => t.split(',').length === 3),
    () => 'a .usda point is not (x, y, z)',
  );
  check(finiteNumbers(pts), () => 'a .usda point is not a finite float');
  const widths = (listOf(hair, 'float[] widths') ?? '').split(',').filter((s) => s.trim() !== '');
  check(widths.length === p, () => `the .usda has ${widths.length} widths for ${p} points`);
  const colours = listOf(hair, 'color3f[] primvars:displayColor')?.match(/\(/g)?.length ?? 0;
  check(colours === n, () => `the .usda has ${colours} colours for ${n} curves`);
  check(
    finiteNumbers(listOf(hair, 'float3[] extent') ?? ''),
    () => 'the .usda extent is not finite',
  );
}

function u32(b: Uint8Array, at: number): number {
  return new DataView(b.buffer, b.byteOffset, b.byteLength).getUint32(at, true);
}

function checkGlb(bytes: Uint8Array, n: number, p: number): void {
  check(bytes.length >= 20, () => 'the .glb is shorter than its header');
  check(u32(bytes, 0) === 0x46546c67 && u32(bytes, 4) === 2, () => 'not a glTF 2 binary');
  check(
    u32(bytes, 8) === bytes.length,
    () => `the .glb header says ${u32(bytes, 8)} bytes, the file has ${bytes.length}`,
  );
  check(bytes.length % 4 === 0, () => 'the .glb length is not a multiple of 4');
  const jsonLength = u32(bytes, 12);
  check(u32(bytes, 16) === 0x4e4f534a, () => 'the .glb does not start with its JSON chunk');
  const gltf = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLength)));
  const binAt = 20 + jsonLength;
  const binLength = binAt < bytes.length ? u32(bytes, binAt) : 0;
  check(
    binAt === bytes.length || (binAt + 8 + binLength === bytes.length && binLength % 4 === 0),
    () => 'the .glb chunks do not add up to the file',
  );
  const declared = gltf.buffers?.[0]?.byteLength ?? 0;
  check(
    declared <= binLength && binLength - declared < 4,
    () => `buffer 0 is ${declared} bytes in a BIN chunk of ${binLength}`,
  );
  const hair = (gltf.meshes ?? []).find((m: { name: string }) => m.name === 'hair');
  check(!!hair === n > 0, () => `${n} strands, hair mesh ${hair ? 'present' : 'absent'}`);
  if (hair) {
    const prim = hair.primitives[0];
    const count = (a: number) => gltf.accessors[a].count;
    check(count(prim.attributes.POSITION) === p, () => `POSITION count is not ${p}`);
    check(count(prim.indices) === 2 * (p - n), () => `LINES index count is not ${2 * (p - n)}`);
    const pos = gltf.accessors[prim.attributes.POSITION];
    check(
      [...pos.min, ...pos.max].every((v: unknown) => typeof v === 'number' && Number.isFinite(v)),
      () => `POSITION bounds ${show([pos.min, pos.max])}`,
    );
  }
}

function checkHair(bytes: Uint8Array, n: number, p: number, lengths: number[]): void {
  check(
    bytes.length === hairFileSize(n, p),
    () => `the .hair is ${bytes.length} bytes, the format says ${hairFileSize(n, p)}`,
  );
  check(
    String.fromCharCode(...bytes.subarray(0, 4)) === 'HAIR' &&
      u32(bytes, 4) === n &&
      u32(bytes, 8) === p,
    () => 'the .hair header is wrong',
  );
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  for (let s = 0; s < n; s++)
    check(
      view.getUint16(128 + 2 * s, true) === lengths[s] - 1,
      () => `.hair strand ${s} has ${view.getUint16(128 + 2 * s, true)} segments`,
    );
  for (let i = 0; i < 3 * p; i++)
    check(Number.isFinite(view.getFloat32(128 + 2 * n + 4 * i, true)), () => '.hair point');
}

function checkObj(bytes: Uint8Array, n: number, p: number, head: ExportHead | null): void {
  const lines = new TextDecoder().decode(bytes).split('\n');
  const verts = lines.filter((l) => l.startsWith('v '));
  const strands = lines.filter((l) => l.startsWith('l '));
  const faces = lines.filter((l) => l.startsWith('f '));
  const hv = head ? head.positions.length / 3 : 0;
  const ht = head ? head.indices.length / 3 : 0;
  check(verts.length === p + hv, () => `the .obj has ${verts.length} v lines, not ${p + hv}`);
  check(strands.length === n, () => `the .obj has ${strands.length} l lines, not ${n}`);
  check(faces.length === ht, () => `the .obj has ${faces.length} f lines, not ${ht}`);
  let next = 1;
  for (const l of strands) {
    const idx = l.slice(2).split(' ').map(Number);
    check(
      idx.length >= 2 && idx.length <= MAX_POINTS_PER_STRAND && idx.every((v, i) => v === next + i),
      () => `the .obj line "${l.slice(0, 60)}" does not continue at ${next}`,
    );
    next += idx.length;
  }
  for (const f of faces)
    check(
      f
        .slice(2)
        .split(' ')
        .map(Number)
        .every((v) => v > p && v <= p + hv),
      () => `the .obj face "${f}" is not on the head`,
    );
  check(finiteNumbers(verts.join(' ')), () => 'an .obj vertex is not a finite float');
}

/** The session an export carries, read back: the input session, deep-equal. */
function checkCarries(bytes: Uint8Array, session: SessionState, format: string): void {
  const r = guard('readExportedSession', () => readExportedSession(bytes));
  check(r?.ok === true, () => `the .${format} carries no session: ${show(r)}`);
  const parsed = guard('parseSession', () => parseSession(r.ok ? r.session : null));
  check(parsed.ok, () => `the .${format} session is refused: ${show(parsed)}`);
  const d = firstDifference(session, parsed.ok ? parsed.value : null, 'session');
  check(d === null, () => `the .${format} session differs at ${d}`);
}

export function exportTarget(ctx: FuzzContext): FuzzTarget<ExportCase> {
  return {
    name: 'export writers',
    arbitrary: fc.record({
      format: fc.constantFrom<ExportFormat>('usda', 'hair', 'obj', 'glb'),
      hair: hairCase,
      head: headCase,
      session: sessionCase(ctx, PLAIN_MUTATIONS),
    }),
    explain: (c) =>
      `${c.format}: hair ${show(c.hair, 300)}; head ${show(c.head, 200)}; session ${makeSession(ctx, c.session, PLAIN_MUTATIONS).log.join('; ')}`,
    run(c) {
      const session = acceptedSession(ctx, c.session);
      const strands = makeHair(c.hair);
      const head = makeHead(c.head);
      const kept = c.hair.lengths.filter((k) => k >= 2).map((k) => Math.min(k, 255));
      const n = kept.length;
      const p = kept.reduce((a, b) => a + b, 0);
      {
        const format = c.format;
        const progress: number[] = [];
        const chunks = guard(`writeExport(${format})`, () => [
          ...writeExport(format, { strands, session, head }, (f) => progress.push(f)),
        ]);
        check(
          chunks.every((k) => k instanceof Uint8Array && k.length <= CHUNK_BYTES),
          () => `a .${format} chunk is over ${CHUNK_BYTES} bytes`,
        );
        check(
          progress.every((f, i) => f >= 0 && f <= 1 && (i === 0 || f >= progress[i - 1])) &&
            progress[progress.length - 1] === 1,
          () => `.${format} progress ${show(progress)}`,
        );
        const bytes = concat(chunks);
        if (format === 'usda') {
          checkUsda(bytes, n, p, kept);
          checkCarries(bytes, session, format);
        } else if (format === 'glb') {
          checkGlb(bytes, n, p);
          checkCarries(bytes, session, format);
        } else if (format === 'hair') checkHair(bytes, n, p, kept);
        else checkObj(bytes, n, p, head);
      }
      return 'accepted';
    },
  };
}

export type ExportBytesCase =
  | { kind: 'random'; bytes: Uint8Array; magic: 'usda' | 'glb' | 'none' }
  | {
      kind: 'damaged';
      file: number;
      how: 'truncate' | 'flip' | 'insert';
      at: number;
      bit: number;
      text: string;
    }
  | { kind: 'usdaText'; value: string; key: number; quote: number; close: boolean };

const MAGIC = {
  usda: new TextEncoder().encode('#usda 1.0\n'),
  glb: new Uint8Array([0x67, 0x6c, 0x54, 0x46, 2, 0, 0, 0]),
  none: new Uint8Array(0),
};

function makeExportBytes(ctx: FuzzContext, c: ExportBytesCase): Uint8Array {
  switch (c.kind) {
    case 'random':
      return concat([MAGIC[c.magic], c.bytes]);
    case 'damaged': {
      const file = ctx.exports[c.file % ctx.exports.length];
      const at = c.at % (file.length + 1);
      if (c.how === 'truncate') return file.slice(0, at);
      if (c.how === 'insert')
        return concat([file.subarray(0, at), new TextEncoder().encode(c.text), file.subarray(at)]);
      const out = file.slice();
      if (out.length > 0) out[at % out.length] ^= 1 << (c.bit % 8);
      return out;
    }
    case 'usdaText': {
      const keys = ['"hairsketch:session"', "'hairsketch:session'", '"hairsketch:sessio"', 'def'];
      const quotes = ['"', "'", '"""', "'''"];
      const q = quotes[c.quote % quotes.length];
      const text = `#usda 1.0\n(\n  customLayerData = {\n    string ${keys[c.key % keys.length]} = ${q}${c.value}${c.close ? q : ''}\n  }\n)\n`;
      return new TextEncoder().encode(text);
    }
  }
}

export function exportReadTarget(ctx: FuzzContext): FuzzTarget<ExportBytesCase> {
  const arbitrary: fc.Arbitrary<ExportBytesCase> = fc.oneof(
    fc.record({
      kind: fc.constant('random' as const),
      bytes: fc.uint8Array({ maxLength: 300 }),
      magic: fc.constantFrom('usda', 'glb', 'none'),
    }),
    fc.record({
      kind: fc.constant('damaged' as const),
      file: fc.nat(),
      how: fc.constantFrom('truncate', 'flip', 'insert'),
      at: fc.nat(),
      bit: fc.nat(),
      text: fc.oneof(fc.constantFrom('"', "'", '\\', '\\x', '\\7', '\n', 'def '), fc.string()),
    }),
    fc.record({
      kind: fc.constant('usdaText' as const),
      value: fc.oneof(
        fc.string(),
        binaryText,
        fc.constantFrom('{}', '\\', '\\x', '\\x4', '\\777', '\\"', '{"version":1,"curves":[]}'),
      ),
      key: fc.nat(),
      quote: fc.nat(),
      close: fc.boolean(),
    }),
  );
  return {
    name: 'export reader',
    arbitrary,
    explain: (c) =>
      `${c.kind}: ${show(Buffer.from(makeExportBytes(ctx, c)).toString('latin1'), 400)}`,
    run(c) {
      const bytes = makeExportBytes(ctx, c);
      const r = guard('readExportedSession', () => readExportedSession(bytes));
      if (r === null) return 'rejected';
      check(typeof r === 'object' && typeof r.ok === 'boolean', () => `answered ${show(r)}`);
      if (!r.ok) {
        checkMessage(r.error, 'readExportedSession');
        return 'rejected';
      }
      // whatever it found goes through the strict reader, which must not throw either
      guard('parseSession', () => parseSession(r.session));
      return 'accepted';
    },
  };
}

/** All targets, in report order. */
export async function loadTargets(): Promise<FuzzTarget<never>[]> {
  const ctx = await makeContext();
  return [
    sessionTarget(ctx),
    sessionFileTarget(ctx),
    linkTarget(ctx),
    problemTarget(ctx),
    exportTarget(ctx),
    exportReadTarget(ctx),
  ] as unknown as FuzzTarget<never>[];
}
