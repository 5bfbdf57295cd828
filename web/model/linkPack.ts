// Writes a session as the binary body of a share link (linkFormat.ts has the layout).
import { curveParamNames, curveParamSpecs, quantumScale } from './curveParams';
import { POSITION_SCALE as POS, toGridInt } from './gridNumbers';
import { DEFAULT_GROWTH, GROWTH_KEYS } from './growthParams';
import { COMMON_CURVE_FIELDS, defOf, extendsPastEnd } from './kinds';
import { crc32, Writer, writePolyline, writeVec } from './linkBytes';
import {
  AXES,
  GRIDS,
  KNOWN_TOP,
  LINK_VERSION,
  PART_HEAD,
  PART_SCALP_PAINT,
  PART_SYMMETRY,
  TYPES,
  typeBits,
  V2_KINDS,
  v2ParamCount,
} from './linkFormat';
import {
  HEAD_FORMATS,
  type HeadRef,
  type ScalpStroke,
  type SessionState,
  type StyleCurve,
} from './session';

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

/** The body (before deflate) of a session in link version `version` (3, written; 2 for tests
 *  that need the layout of version 2, which holds v2ParamCount parameters per curve kind);
 *  its numbers go on the grid of quantize.ts as they are written. */
export function packSession(s: SessionState, version: 2 | 3 = LINK_VERSION): Uint8Array {
  const w = new Writer();
  const counts = TYPES.map((k) => (version === 2 ? v2ParamCount(k) : curveParamSpecs(k).length));
  if (version === 3) {
    // the kinds up to the last one used (at least the first three, as before braids and buns)
    let kinds = V2_KINDS;
    for (const c of s.curves) kinds = Math.max(kinds, TYPES.indexOf(c.type) + 1);
    w.varint(kinds);
    for (const n of counts.slice(0, kinds)) w.varint(n);
  }
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
    const def = defOf(c);
    const mode = def.linkMode(c);
    const idNum = /^c([1-9]\d{0,14})$/.exec(c.id);
    const sameVp =
      prevVp !== null &&
      [0, 1, 2].every(
        (a) =>
          prevVp !== null &&
          toGridInt(prevVp.position[a], POS) === toGridInt(c.viewpoint.position[a], POS) &&
          toGridInt(prevVp.target[a], POS) === toGridInt(c.viewpoint.target[a], POS),
      );
    const extend = extendsPastEnd(c);
    w.u8(
      typeBits(TYPES.indexOf(c.type)) |
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
    for (const spec of curveParamSpecs(c.type).slice(0, counts[TYPES.indexOf(c.type)]))
      w.zigzag(toGridInt(rec[spec.name] ?? spec.default, quantumScale(spec)));
    writePolyline(w, c.points, POS);
    const known = [
      ...COMMON_CURVE_FIELDS.slice(0, 4), // id, type, points, viewpoint: detail and mirror go in the tail
      ...def.fields,
      ...curveParamNames(c.type).slice(0, counts[TYPES.indexOf(c.type)]),
    ];
    const extra = rest(c, known) ?? {};
    def.writeLink(w, c, extra);
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
