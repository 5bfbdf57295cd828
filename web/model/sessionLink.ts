// Share links: a session in the address bar's fragment, URL-safe characters only, no line breaks.
//
//   #s=2.<base64url(varint n + deflate-raw(body), n bytes)>   version 2 (written): below
//   #s=<base64url(deflate-raw(JSON))>     version 1 (still read): the session JSON, numbers to 1e-5
//
// Version 2 states the deflated length n up front, so a link cut short or with characters added
// (a chat client's doing) is named as such before anything is inflated.
//
// Version 2 stores every number as an integer on the grid of quantize.ts, so a session the
// editor made (already on that grid) reopens deep-equal, and grows the same hair. The body:
//
//   u8        grid preset: 0 25k, 1 50k, 2 100k, 3 250k
//   u8 × 3    hair colour r, g, b
//   varint    growth mask: bit i set when GROWTH_KEYS[i] differs from DEFAULT_GROWTH;
//             then for each set bit, in order, the value as f64 little-endian (exact)
//   varint    curve count; per curve:
//     u8        bits 0-1 type (0 stream, 1 dividing, 2 ponytail); bit 2 extend;
//               bits 3-4 surfaceMode (0 absent, 1 ruled, 2 strip); bit 5 viewpoint as the
//               previous curve's; bit 6 the id is "c<n>" (then n as varint, else a
//               varint length and the id's bytes)
//     id
//     viewpoint unless bit 5: position, target as 6 zigzag varints (position grid)
//     params    the kind's CURVE_PARAMS in order, zigzag varints (their grids)
//     points    a polyline (below)
//     dividing: normals: a polyline on the direction grid
//     ponytail: crossSection, profiles[0], profiles[1]: polylines; circle count (varint);
//               per circle, each a zigzag varint of the difference from the previous circle
//               (the first from zero): spineIndex, centre x y z, axis x y z, radius
//   varint    avoid (session version 1): 0 for none, else entries + 1; then per entry the
//             zigzag difference of the grid index from the previous one; then per entry the
//             zigzag differences of the target's x y z from the previous entry's (direction
//             grid). Written as 0 since version 2; a link with entries is a version 1 session.
//   varint    length of a JSON tail, then the tail (UTF-8): fields the layout has no place for
//             (avoidScalp, detail, a curve's detail), {"session": {…}, "growth": {…},
//             "curves": [[i, {…}], …]}
//   [parts]   optional (session version 3; absent when the session has none of them, so such a
//             link is byte for byte what it was before): varint mask of the parts present,
//             1 head, 2 scalpPaint, 4 symmetry, then each present part in that order:
//     head        (a loaded head: its reference, never the mesh) the SHA-256 as 32 bytes; the
//                 name as a varint length and UTF-8; u8 format (session.ts HEAD_FORMATS); u8 up
//                 (0 y, 1 z); varint turn count, then per turn a u8 4·axis (0 x, 1 y, 2 z) +
//                 quarter turns
//     scalpPaint  varint stroke count; per stroke a u8 (1 erase, 0 paint), the radius as a
//                 varint (position grid) and its points as a polyline (position grid)
//     symmetry    the plane's unit normal as 3 f64 little-endian (exact), its offset as a
//                 zigzag varint (position grid)
//   u32       CRC-32 of everything before it, little-endian
//
// A polyline is a varint point count, the first point as 3 zigzag varints, the second as its
// difference from the first, then each point as its difference from the straight-line guess
// 2·p[i-1] − p[i-2] (curves are resampled at an even step, so these stay small).
//
// Reading never throws and never trusts the link: its length is capped before decoding, the
// inflated size is capped while inflating (a deflate bomb is refused after MAX_LINK_BYTES), the
// layout is checked byte by byte, and the session it spells goes through the strict reader
// (sessionFile.ts parseSession).

import { CURVE_PARAMS, type CurveParamSpec, type GrowthParams } from '../solver/protocol';
import { deflateRaw, fromBase64Url, inflateCapped, toBase64Url } from './bytes';
import { GRID_PRESETS, type GridPreset } from './grid';
import { DIRECTION_SCALE as DIR, POSITION_SCALE as POS, paramScale, toGridInt } from './quantize';
import {
  DEFAULT_GROWTH,
  HEAD_FORMATS,
  type HeadRef,
  type ScalpStroke,
  type SessionState,
  type StyleCurve,
} from './session';
import { type Parsed, parseSession } from './sessionFile';
import { SESSION_VERSION } from './sessionMigrations';
import type { Vec3 } from './vec3';

/** Inflated size cap (bytes), enforced while inflating. */
export const MAX_LINK_BYTES = 8 << 20;
/** Characters in the fragment, checked before decoding. */
export const MAX_LINK_CHARS = 2_000_000;

const GRIDS = Object.keys(GRID_PRESETS) as GridPreset[];
const TYPES = ['stream', 'dividing', 'ponytail'] as const;
const MODES = [undefined, 'ruled', 'strip'] as const;
const GROWTH_KEYS = Object.keys(DEFAULT_GROWTH) as (keyof GrowthParams)[];
const KNOWN_TOP = [
  'version',
  'head',
  'grid',
  'curves',
  'growth',
  'hairColor',
  'avoid',
  'scalpPaint',
  'symmetry',
];
const AXES = ['x', 'y', 'z'] as const;
/** The optional parts after the JSON tail (the mask's bits). */
const PART_HEAD = 1;
const PART_SCALP_PAINT = 2;
const PART_SYMMETRY = 4;
const PARTS = PART_HEAD | PART_SCALP_PAINT | PART_SYMMETRY;
const KNOWN_CURVE: Record<StyleCurve['type'], string[]> = {
  stream: ['id', 'type', 'points', 'extend', 'viewpoint', 'surfaceMode'],
  dividing: ['id', 'type', 'points', 'normals', 'viewpoint'],
  ponytail: ['id', 'type', 'points', 'extend', 'viewpoint', 'crossSection', 'profiles', 'circles'],
};

// base64url and deflate: bytes.ts (re-exported here, where they were first defined)
export { fromBase64Url, inflateCapped, toBase64Url };

// ---- CRC-32 ----------------------------------------------------------------------------------

const CRC_TABLE = (() => {
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    t[n] = c >>> 0;
  }
  return t;
})();

export function crc32(bytes: Uint8Array): number {
  let c = 0xffffffff;
  for (let i = 0; i < bytes.length; i++) c = CRC_TABLE[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

// ---- writing ---------------------------------------------------------------------------------

class Writer {
  private buf = new Uint8Array(1024);
  length = 0;

  private room(n: number) {
    if (this.length + n <= this.buf.length) return;
    const next = new Uint8Array(Math.max(this.buf.length * 2, this.length + n));
    next.set(this.buf.subarray(0, this.length));
    this.buf = next;
  }

  u8(b: number) {
    this.room(1);
    this.buf[this.length++] = b;
  }

  bytes(b: Uint8Array) {
    this.room(b.length);
    this.buf.set(b, this.length);
    this.length += b.length;
  }

  /** Unsigned integers up to 2^53 (arithmetic, not 32-bit shifts). */
  varint(n: number) {
    let v = n;
    while (v >= 0x80) {
      this.u8((v % 0x80) | 0x80);
      v = Math.floor(v / 0x80);
    }
    this.u8(v);
  }

  zigzag(n: number) {
    this.varint(n >= 0 ? 2 * n : -2 * n - 1);
  }

  f64(x: number) {
    const b = new Uint8Array(8);
    new DataView(b.buffer).setFloat64(0, x, true);
    this.bytes(b);
  }

  u32(x: number) {
    const b = new Uint8Array(4);
    new DataView(b.buffer).setUint32(0, x, true);
    this.bytes(b);
  }

  done(): Uint8Array {
    return this.buf.slice(0, this.length);
  }
}

function writePolyline(w: Writer, pts: readonly Vec3[], scale: number) {
  w.varint(pts.length);
  const prev = [0, 0, 0];
  const prev2 = [0, 0, 0];
  pts.forEach((p, i) => {
    for (let a = 0; a < 3; a++) {
      const k = toGridInt(p[a], scale);
      const guess = i === 0 ? 0 : i === 1 ? prev[a] : 2 * prev[a] - prev2[a];
      w.zigzag(k - guess);
      prev2[a] = prev[a];
      prev[a] = k;
    }
  });
}

function writeVec(w: Writer, v: Vec3, scale: number) {
  for (let a = 0; a < 3; a++) w.zigzag(toGridInt(v[a], scale));
}

function rest(o: object, known: readonly string[]): Record<string, unknown> | null {
  const out: Record<string, unknown> = {};
  let any = false;
  for (const [k, v] of Object.entries(o))
    if (!known.includes(k) && v !== undefined) {
      out[k] = v;
      any = true;
    }
  return any ? out : null;
}

function colourBytes(c: string): [number, number, number] | null {
  const m = /^#([0-9a-fA-F]{2})([0-9a-fA-F]{2})([0-9a-fA-F]{2})$/.exec(c);
  return m ? [parseInt(m[1], 16), parseInt(m[2], 16), parseInt(m[3], 16)] : null;
}

/** The version 2 body (before deflate) of a session; its numbers go on the grid of
 *  quantize.ts as they are written. */
export function packSession(s: SessionState): Uint8Array {
  const w = new Writer();
  const tail: {
    session?: Record<string, unknown>;
    growth?: Record<string, unknown>;
    curves?: [number, Record<string, unknown>][];
  } = {};
  const top = rest(s, KNOWN_TOP) ?? {};
  const head = packableHead(s.head);
  if (s.head !== 'builtin' && !head) top.head = s.head; // not a head reference: the reader says so
  const grid = GRIDS.indexOf(s.grid);
  if (grid < 0) top.grid = s.grid;
  w.u8(Math.max(0, grid));
  const rgb = colourBytes(s.hairColor);
  if (!rgb) top.hairColor = s.hairColor;
  for (const b of rgb ?? [0, 0, 0]) w.u8(b);
  if (Object.keys(top).length) tail.session = top;

  let mask = 0;
  GROWTH_KEYS.forEach((k, i) => {
    if (!Object.is(s.growth[k], DEFAULT_GROWTH[k])) mask += 2 ** i;
  });
  w.varint(mask);
  GROWTH_KEYS.forEach((k, i) => {
    if (Math.floor(mask / 2 ** i) % 2) w.f64(s.growth[k]);
  });
  const growthRest = rest(s.growth, GROWTH_KEYS);
  if (growthRest) tail.growth = growthRest;

  w.varint(s.curves.length);
  let prevVp: StyleCurve['viewpoint'] | null = null;
  s.curves.forEach((c, ci) => {
    const mode = c.type === 'stream' ? MODES.indexOf(c.surfaceMode) : 0;
    const idNum = /^c([1-9]\d{0,14})$/.exec(c.id);
    const sameVp =
      prevVp !== null &&
      [0, 1, 2].every(
        (a) =>
          prevVp !== null &&
          toGridInt(prevVp.position[a], POS) === toGridInt(c.viewpoint.position[a], POS) &&
          toGridInt(prevVp.target[a], POS) === toGridInt(c.viewpoint.target[a], POS),
      );
    const extend = c.type !== 'dividing' && c.extend;
    w.u8(
      TYPES.indexOf(c.type) |
        (extend ? 4 : 0) |
        (Math.max(0, mode) << 3) |
        (sameVp ? 32 : 0) |
        (idNum ? 64 : 0),
    );
    if (idNum) w.varint(Number(idNum[1]));
    else {
      const id = new TextEncoder().encode(c.id);
      w.varint(id.length);
      w.bytes(id);
    }
    if (!sameVp) {
      writeVec(w, c.viewpoint.position, POS);
      writeVec(w, c.viewpoint.target, POS);
    }
    prevVp = c.viewpoint;
    const rec = c as unknown as Record<string, number>;
    for (const spec of CURVE_PARAMS[c.type] as readonly CurveParamSpec[])
      w.zigzag(toGridInt(rec[spec.name] ?? spec.default, paramScale(spec.name)));
    writePolyline(w, c.points, POS);
    const known = [
      ...KNOWN_CURVE[c.type],
      ...(CURVE_PARAMS[c.type] as readonly CurveParamSpec[]).map((p) => p.name),
    ];
    const extra = rest(c, known) ?? {};
    if (c.type === 'stream' && mode < 0) extra.surfaceMode = c.surfaceMode;
    if (c.type === 'dividing') writePolyline(w, c.normals, DIR);
    if (c.type === 'ponytail') {
      writePolyline(w, c.crossSection, POS);
      writePolyline(w, c.profiles[0], POS);
      writePolyline(w, c.profiles[1], POS);
      w.varint(c.circles.length);
      const prev = [0, 0, 0, 0, 0, 0, 0, 0];
      for (const q of c.circles) {
        const now = [
          toGridInt(q.spineIndex, 1),
          ...q.centre.map((x) => toGridInt(x, POS)),
          ...q.axis.map((x) => toGridInt(x, DIR)),
          toGridInt(q.radius, POS),
        ];
        now.forEach((k, i) => {
          w.zigzag(k - prev[i]);
          prev[i] = k;
        });
      }
    }
    if (Object.keys(extra).length) {
      tail.curves ??= [];
      tail.curves.push([ci, extra]);
    }
  });

  // The slot of version 1's scalp-avoidance constraints: empty since version 2 (avoidScalp is
  // a setting, carried in the JSON tail).
  w.varint(0);

  if (Object.keys(tail).length) {
    const json = new TextEncoder().encode(JSON.stringify(tail));
    w.varint(json.length);
    w.bytes(json);
  } else w.varint(0);

  const strokes = s.scalpPaint ?? [];
  const parts =
    (head ? PART_HEAD : 0) |
    (strokes.length > 0 ? PART_SCALP_PAINT : 0) |
    (s.symmetry ? PART_SYMMETRY : 0);
  if (parts) {
    w.varint(parts);
    if (head) writeHead(w, head);
    if (strokes.length > 0) {
      w.varint(strokes.length);
      for (const st of strokes) writeStroke(w, st);
    }
    if (s.symmetry) {
      for (const x of s.symmetry.normal) w.f64(x);
      w.zigzag(toGridInt(s.symmetry.offset, POS));
    }
  }
  w.u32(crc32(w.done()));
  return w.done();
}

/** The head when it is a reference the layout can hold, else null. */
function packableHead(h: SessionState['head']): HeadRef | null {
  if (typeof h !== 'object' || h === null || h.kind !== 'mesh') return null;
  if (typeof h.hash !== 'string' || !/^[0-9a-f]{64}$/.test(h.hash)) return null;
  if (typeof h.name !== 'string' || !HEAD_FORMATS.includes(h.format)) return null;
  if ((h.up !== 'y' && h.up !== 'z') || !Array.isArray(h.turns)) return null;
  const turnOk = (t: HeadRef['turns'][number]) =>
    AXES.includes(t?.axis) && Number.isInteger(t.quarterTurns) && t.quarterTurns >= 0;
  return h.turns.every((t) => turnOk(t) && t.quarterTurns <= 3) ? h : null;
}

function writeHead(w: Writer, h: HeadRef) {
  for (let i = 0; i < 64; i += 2) w.u8(parseInt(h.hash.slice(i, i + 2), 16));
  const name = new TextEncoder().encode(h.name);
  w.varint(name.length);
  w.bytes(name);
  w.u8(HEAD_FORMATS.indexOf(h.format));
  w.u8(h.up === 'y' ? 0 : 1);
  w.varint(h.turns.length);
  for (const t of h.turns) w.u8(4 * AXES.indexOf(t.axis) + t.quarterTurns);
}

function writeStroke(w: Writer, st: ScalpStroke) {
  w.u8(st.erase ? 1 : 0);
  w.varint(Math.max(0, toGridInt(st.radius, POS)));
  writePolyline(w, st.points, POS);
}

/** The link fragment for a session (without '#'): `s=2.` + base64url(deflate-raw(body)). */
export async function encodeSessionLink(s: SessionState): Promise<string> {
  const deflated = await deflateRaw(packSession(s));
  const w = new Writer();
  w.varint(deflated.length);
  w.bytes(deflated);
  return `s=2.${toBase64Url(w.done())}`;
}

/** The version 1 fragment (`s=` + base64url(deflate-raw(JSON)), numbers to 1e-5), as links were
 *  written before version 2; kept so tests can make the links people already hold. */
export async function encodeSessionLinkV1(s: SessionState): Promise<string> {
  const json = JSON.stringify(s, (_k, v) =>
    typeof v === 'number' ? Math.round(v * 1e5) / 1e5 : v,
  );
  return `s=${toBase64Url(await deflateRaw(new TextEncoder().encode(json)))}`;
}

// ---- reading ---------------------------------------------------------------------------------

class LinkError extends Error {}

class Reader {
  at = 0;
  constructor(private readonly b: Uint8Array) {}

  get left(): number {
    return this.b.length - this.at;
  }

  u8(): number {
    if (this.at >= this.b.length) throw new LinkError('it ends too early');
    return this.b[this.at++];
  }

  bytes(n: number): Uint8Array {
    if (n > this.left) throw new LinkError('it ends too early');
    this.at += n;
    return this.b.subarray(this.at - n, this.at);
  }

  varint(): number {
    let v = 0;
    let mul = 1;
    for (let i = 0; i < 8; i++) {
      const b = this.u8();
      v += (b & 0x7f) * mul;
      if (b < 0x80) return v;
      mul *= 0x80;
    }
    throw new LinkError('a number is too long');
  }

  /** A count of items that need at least `min` bytes each (so a count cannot ask for more than
   *  the data holds). */
  count(min: number): number {
    const n = this.varint();
    if (n * min > this.left) throw new LinkError('a count is larger than the data');
    return n;
  }

  zigzag(): number {
    const z = this.varint();
    return z % 2 === 0 ? z / 2 : -(z + 1) / 2;
  }

  f64(): number {
    const b = this.bytes(8);
    return new DataView(b.buffer, b.byteOffset, 8).getFloat64(0, true);
  }
}

function readPolyline(r: Reader, scale: number): Vec3[] {
  const n = r.count(3);
  const out: Vec3[] = [];
  const prev = [0, 0, 0];
  const prev2 = [0, 0, 0];
  for (let i = 0; i < n; i++) {
    const p = [0, 0, 0];
    for (let a = 0; a < 3; a++) {
      const guess = i === 0 ? 0 : i === 1 ? prev[a] : 2 * prev[a] - prev2[a];
      const k = guess + r.zigzag();
      prev2[a] = prev[a];
      prev[a] = k;
      p[a] = k / scale + 0;
    }
    out.push(p as Vec3);
  }
  return out;
}

function readVec(r: Reader, scale: number): Vec3 {
  return [r.zigzag() / scale + 0, r.zigzag() / scale + 0, r.zigzag() / scale + 0];
}

function merge(into: Record<string, unknown>, from: unknown) {
  if (typeof from !== 'object' || from === null || Array.isArray(from)) return;
  for (const [k, v] of Object.entries(from))
    if (k !== '__proto__')
      Object.defineProperty(into, k, {
        value: v,
        enumerable: true,
        writable: true,
        configurable: true,
      });
}

/** The session data a version 2 body spells (plain JSON-able data, not yet checked). */
export function unpackSession(body: Uint8Array): Record<string, unknown> {
  if (body.length < 4) throw new LinkError('it ends too early');
  const crc = new DataView(body.buffer, body.byteOffset + body.length - 4, 4).getUint32(0, true);
  if (crc32(body.subarray(0, body.length - 4)) !== crc)
    throw new LinkError('its checksum does not match');
  const r = new Reader(body.subarray(0, body.length - 4));
  const gridIndex = r.u8();
  if (gridIndex >= GRIDS.length) throw new LinkError('unknown grid');
  const hex = [r.u8(), r.u8(), r.u8()].map((b) => b.toString(16).padStart(2, '0')).join('');
  const mask = r.varint();
  if (mask >= 2 ** GROWTH_KEYS.length) throw new LinkError('unknown growth settings');
  const growth: Record<string, number> = { ...DEFAULT_GROWTH };
  GROWTH_KEYS.forEach((k, i) => {
    if (Math.floor(mask / 2 ** i) % 2) growth[k] = r.f64();
  });
  const nCurves = r.count(3);
  const curves: Record<string, unknown>[] = [];
  let prevVp: { position: Vec3; target: Vec3 } | null = null;
  for (let ci = 0; ci < nCurves; ci++) {
    const flags = r.u8();
    const type = TYPES[flags & 3];
    const mode = (flags >> 3) & 3;
    if (!type || mode >= MODES.length || flags & 128) throw new LinkError(`curve ${ci} is unknown`);
    let id: string;
    if (flags & 64) id = `c${r.varint()}`;
    else {
      const n = r.count(1);
      id = new TextDecoder().decode(r.bytes(n));
    }
    let viewpoint: { position: Vec3; target: Vec3 };
    if (flags & 32) {
      if (!prevVp) throw new LinkError(`curve ${ci} has no viewpoint`);
      viewpoint = { position: [...prevVp.position], target: [...prevVp.target] };
    } else viewpoint = { position: readVec(r, POS), target: readVec(r, POS) };
    prevVp = viewpoint;
    const c: Record<string, unknown> = { id, type, viewpoint };
    for (const spec of CURVE_PARAMS[type] as readonly CurveParamSpec[])
      c[spec.name] = r.zigzag() / paramScale(spec.name) + 0;
    c.points = readPolyline(r, POS);
    if (type !== 'dividing') c.extend = (flags & 4) !== 0;
    if (type === 'stream' && mode) c.surfaceMode = MODES[mode];
    if (type === 'dividing') c.normals = readPolyline(r, DIR);
    if (type === 'ponytail') {
      c.crossSection = readPolyline(r, POS);
      c.profiles = [readPolyline(r, POS), readPolyline(r, POS)];
      const m = r.count(8);
      const prev = [0, 0, 0, 0, 0, 0, 0, 0];
      const circles = [];
      for (let i = 0; i < m; i++) {
        for (let j = 0; j < 8; j++) prev[j] += r.zigzag();
        circles.push({
          centre: [prev[1] / POS + 0, prev[2] / POS + 0, prev[3] / POS + 0],
          axis: [prev[4] / DIR + 0, prev[5] / DIR + 0, prev[6] / DIR + 0],
          radius: prev[7] / POS + 0,
          spineIndex: prev[0],
        });
      }
      c.circles = circles;
    }
    curves.push(c);
  }
  let avoid: { index: number[]; target: number[] } | null = null;
  const nAvoid = r.varint();
  if (nAvoid > 0) {
    const n = nAvoid - 1;
    if (n * 4 > r.left) throw new LinkError('a count is larger than the data');
    const index: number[] = [];
    let k = 0;
    for (let e = 0; e < n; e++) {
      k += r.zigzag();
      index.push(k);
    }
    const target: number[] = [];
    const p = [0, 0, 0];
    for (let e = 0; e < n; e++)
      for (let a = 0; a < 3; a++) {
        p[a] += r.zigzag();
        target.push(p[a] / DIR + 0);
      }
    avoid = { index, target };
  }
  // Constraints in the avoid slot: a version 1 session (its migration turns them into the
  // avoidScalp setting); none: the current version (whose extra fields are in the tail).
  const session: Record<string, unknown> = {
    version: avoid ? 1 : SESSION_VERSION,
    head: 'builtin',
    grid: GRIDS[gridIndex],
    curves,
    growth,
    hairColor: `#${hex}`,
  };
  if (avoid) session.avoid = avoid;
  const tailLength = r.count(1);
  if (tailLength > 0) {
    let tail: { session?: unknown; growth?: unknown; curves?: unknown };
    try {
      tail = JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(r.bytes(tailLength)));
    } catch {
      throw new LinkError('its JSON part is not JSON');
    }
    merge(session, tail?.session);
    merge(growth, tail?.growth);
    if (Array.isArray(tail?.curves))
      for (const entry of tail.curves)
        if (Array.isArray(entry) && Number.isInteger(entry[0]) && curves[entry[0]])
          merge(curves[entry[0]], entry[1]);
  }
  if (r.left > 0) readParts(r, session);
  if (r.left > 0) throw new LinkError('it has data past its end');
  return session;
}

/** The optional parts after the JSON tail (head, scalpPaint, symmetry) into `session`. */
function readParts(r: Reader, session: Record<string, unknown>) {
  const mask = r.varint();
  if (mask === 0 || mask > PARTS)
    throw new LinkError('it has parts this app does not know (made by a newer hairsketch?)');
  if (mask & PART_HEAD) {
    const hash = Array.from(r.bytes(32), (b) => b.toString(16).padStart(2, '0')).join('');
    let name: string;
    try {
      name = new TextDecoder('utf-8', { fatal: true }).decode(r.bytes(r.count(1)));
    } catch (e) {
      if (e instanceof LinkError) throw e;
      throw new LinkError("its head's name is not UTF-8");
    }
    const format = HEAD_FORMATS[r.u8()];
    if (!format) throw new LinkError("its head's file format is unknown");
    const upByte = r.u8();
    if (upByte > 1) throw new LinkError("its head's up axis is unknown");
    const turns = [];
    for (let i = r.count(1); i > 0; i--) {
      const t = r.u8();
      if (t >> 2 >= AXES.length) throw new LinkError("its head's turns are unknown");
      turns.push({ axis: AXES[t >> 2], quarterTurns: t & 3 });
    }
    session.head = { kind: 'mesh', name, hash, format, up: upByte ? 'z' : 'y', turns };
  }
  if (mask & PART_SCALP_PAINT) {
    const strokes = [];
    for (let i = r.count(3); i > 0; i--) {
      const erase = r.u8();
      if (erase > 1) throw new LinkError('a scalp stroke is unknown');
      const radius = r.varint() / POS + 0;
      strokes.push({ erase: erase === 1, radius, points: readPolyline(r, POS) });
    }
    session.scalpPaint = strokes;
  }
  if (mask & PART_SYMMETRY) {
    const normal = [r.f64() + 0, r.f64() + 0, r.f64() + 0];
    session.symmetry = { normal, offset: r.zigzag() / POS + 0 };
  }
}

const damaged = (why: string): Parsed<SessionState> => ({
  ok: false,
  error: `the session link is damaged (${why})`,
});

/** Reads a link fragment made by encodeSessionLink or a version 1 link (with or without the
 *  leading '#'). Never throws: a bad link gives a sentence saying what is wrong. */
export async function decodeSessionLink(fragment: string): Promise<Parsed<SessionState>> {
  if (fragment.length > MAX_LINK_CHARS)
    return {
      ok: false,
      error: `the session link is too long (${fragment.length.toLocaleString('en-US')} characters; at most ${MAX_LINK_CHARS.toLocaleString('en-US')})`,
    };
  const m = /^#?s=(?:(\d+)\.)?(.*)$/s.exec(fragment);
  if (!m) return { ok: false, error: 'the link holds no session (#s=…)' };
  const version = m[1] === undefined ? 1 : Number(m[1]);
  if (version !== 1 && version !== 2)
    return {
      ok: false,
      error: `the session link is version ${m[1].slice(0, 12)}; this app opens versions 1 and 2`,
    };
  if (/^[A-Za-z0-9_-]*$/.test(m[2]) && m[2].length % 4 === 1)
    return damaged('a character too many or too few: cut short?');
  let packed = fromBase64Url(m[2]);
  if (!packed || packed.length === 0) return damaged('not base64url');
  if (version === 2) {
    const r = new Reader(packed);
    let n: number;
    try {
      n = r.varint();
    } catch {
      return damaged('it is cut short');
    }
    if (r.left < n) return damaged(`it is cut short (${r.left} of ${n} bytes)`);
    if (r.left > n) return damaged(`it has ${r.left - n} bytes too many at the end`);
    packed = packed.subarray(r.at);
  }
  const inflated = await inflateCapped(packed, MAX_LINK_BYTES);
  if (inflated === 'too large') return { ok: false, error: 'the session link is too large' };
  if (inflated === 'damaged') return damaged('it does not inflate');
  let data: unknown;
  if (version === 1) {
    try {
      data = JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(inflated));
    } catch {
      return damaged('not JSON');
    }
  } else {
    try {
      data = unpackSession(inflated);
    } catch (e) {
      if (e instanceof LinkError) return damaged(e.message);
      return damaged('it cannot be read');
    }
  }
  const parsed = parseSession(data);
  return parsed.ok ? parsed : { ok: false, error: `the session link is invalid: ${parsed.error}` };
}
