// Reads the binary body of a share link (linkFormat.ts has the layout) into plain session data,
// checking the layout byte by byte; the strict reader (sessionRead.ts) checks the session.
import { CURVE_PARAMS, curveParamSpecs, quantumScale } from './curveParams';
import { DIRECTION_SCALE as DIR, POSITION_SCALE as POS } from './gridNumbers';
import { DEFAULT_GROWTH, GROWTH_KEYS } from './growthParams';
import { kindDef } from './kinds';
import { crc32, LinkError, Reader, readPolyline, readVec } from './linkBytes';
import {
  AXES,
  GRIDS,
  kindOfFlags,
  MODES,
  PART_HEAD,
  PART_SCALP_PAINT,
  PART_SYMMETRY,
  PARTS,
  TYPES,
  V2_KINDS,
  v2ParamCount,
} from './linkFormat';
import { HEAD_FORMATS } from './session';
import { SESSION_VERSION } from './sessionMigrations';
import type { Vec3 } from './vec3';

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

/** The session data a version 2 or 3 body spells (plain JSON-able data, not yet checked). */
export function unpackSession(body: Uint8Array, version: 2 | 3 = 3): Record<string, unknown> {
  if (body.length < 4) throw new LinkError('it ends too early');
  const crc = new DataView(body.buffer, body.byteOffset + body.length - 4, 4).getUint32(0, true);
  if (crc32(body.subarray(0, body.length - 4)) !== crc)
    throw new LinkError('its checksum does not match');
  const r = new Reader(body.subarray(0, body.length - 4));
  const { counts, kinds } =
    version === 2 ? { counts: TYPES.map((k) => v2ParamCount(k)), kinds: V2_KINDS } : paramCounts(r);
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
    const kind = kindOfFlags(flags);
    const type = kind < kinds ? TYPES[kind] : undefined;
    const mode = (flags >> 3) & 3;
    if (!type || mode >= MODES.length) throw new LinkError(`curve ${ci} is unknown`);
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
    // parameters the link's writer did not have are left out: the reader gives them defaults
    for (const spec of curveParamSpecs(type).slice(0, counts[kind]))
      c[spec.name] = r.zigzag() / quantumScale(spec) + 0;
    c.points = readPolyline(r, POS);
    const def = kindDef(type);
    if (def?.extends) c.extend = (flags & 4) !== 0;
    def?.readLink(r, c, mode);
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

/** Version 3's parameter count per curve kind; refused when it has more kinds or parameters
 *  than this build's tables (a newer hairsketch wrote it: its values would be misread). */
function paramCounts(r: Reader): { counts: number[]; kinds: number } {
  const kinds = r.varint();
  if (kinds > TYPES.length)
    throw new LinkError('it has curve kinds this app does not know (made by a newer hairsketch?)');
  const counts = TYPES.map((k, i) => {
    const n = i < kinds ? r.varint() : 0;
    if (n > CURVE_PARAMS[k].length)
      throw new LinkError(
        `its ${k} curves have parameters this app does not know (made by a newer hairsketch?)`,
      );
    return n;
  });
  return { counts, kinds };
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
