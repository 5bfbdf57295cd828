// Share links: a session in the address bar's fragment, URL-safe characters only, no line breaks.
//
//   #s=3.<base64url(varint n + deflate-raw(body), n bytes)>   version 3 (written): below
//   #s=2.<base64url(varint n + deflate-raw(body), n bytes)>   version 2 (still read): below
//   #s=<base64url(deflate-raw(JSON))>     version 1 (still read): the session JSON, numbers to 1e-5
//
// Versions 2 and 3 state the deflated length n up front, so a link cut short or with characters
// added (a chat client's doing) is named as such before anything is inflated.
//
// Versions 2 and 3 store every number as an integer on the grid of quantize.ts, so a session the
// editor made (already on that grid) reopens deep-equal, and grows the same hair. Version 3 is
// version 2 with, first, what a reader needs to decode it after the tables grow: how many
// scalar parameters each curve kind had when it was written. A version 2 link holds the
// parameters of v2ParamCount (the table when version 2 was replaced); parameters added since
// are absent from older links, so their curves get the defaults, as a saved file without them
// does. The body:
//
//   (version 3 only)
//   varint    number of curve kinds k; then k varints: the scalar parameter count of each kind
//             (CURVE_KINDS order: stream, dividing, ponytail, braid, bun); a count above this
//             build's table is refused (a newer hairsketch made it). k is 3 unless the session
//             has a braid (4) or a bun (5), so a link without them is byte for byte what the
//             build before braids and buns wrote (and opens there); a curve whose kind is not
//             among the first k is refused
//   u8        grid preset: 0 25k, 1 50k, 2 100k, 3 250k
//   u8 × 3    hair colour r, g, b
//   varint    growth mask: bit i set when GROWTH_KEYS[i] (growthParams.ts, rows added at the
//             end only) differs from DEFAULT_GROWTH;
//             then for each set bit, in order, the value as f64 little-endian (exact)
//   varint    curve count; per curve:
//     u8        bits 0-1 and 7 type (bits 0-1 + 4 × bit 7: 0 stream, 1 dividing, 2 ponytail,
//               3 braid, 4 bun; version 2 has only the first three); bit 2 extend;
//               bits 3-4 surfaceMode (0 absent, 1 ruled, 2 strip); bit 5 viewpoint as the
//               previous curve's; bit 6 the id is "c<n>" (then n as varint, else a
//               varint length and the id's bytes)
//     id
//     viewpoint unless bit 5: position, target as 6 zigzag varints (position grid)
//     params    the first count (version 3: as stated; version 2: v2ParamCount) of the
//               kind's CURVE_PARAMS in order, zigzag varints (their rows' quantum)
//     points    a polyline (below)
//     dividing: normals: a polyline on the direction grid
//     braid, bun: nothing more (their parameters are scalars)
//     ponytail: crossSection, profiles[0], profiles[1]: polylines; circle count (varint);
//               per circle, each a zigzag varint of the difference from the previous circle
//               (the first from zero): spineIndex, centre x y z, axis x y z, radius
//   varint    avoid (session version 1): 0 for none, else entries + 1; then per entry the
//             zigzag difference of the grid index from the previous one; then per entry the
//             zigzag differences of the target's x y z from the previous entry's (direction
//             grid). Written as 0 since version 2; a link with entries is a version 1 session.
//   varint    length of a JSON tail, then the tail (UTF-8): fields the layout has no place for
//             (sessionSchema.ts link: 'tail': the settings such as avoidScalp and fall, detail;
//             a curve's detail), {"session": {…}, "growth": {…},
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
// (sessionRead.ts parseSession).

import { CURVE_KINDS, type CurveKindName } from './curveParams';
import { GRID_PRESETS, type GridPreset } from './grid';
import { SESSION_FIELD_NAMES, SESSION_FIELDS } from './sessionSchema';

/** The link version written (`#s=3.`), and the versions read. */
export const LINK_VERSION = 3;
export const LINK_VERSIONS_READ = [1, 2, 3] as const;

/** Inflated size cap (bytes), enforced while inflating. */
export const MAX_LINK_BYTES = 8 << 20;
/** Characters in the fragment, checked before decoding. */
export const MAX_LINK_CHARS = 2_000_000;

/** Scalar parameters per curve kind in a version 2 link: CURVE_PARAMS when version 3 replaced
 *  it. Never changes: version 2 links hold exactly these (no kind after these three). */
const V2_PARAM_COUNT: Readonly<Partial<Record<CurveKindName, number>>> = {
  stream: 0,
  dividing: 4,
  ponytail: 1,
};

/** The scalar parameters of kind `k` in a version 2 link (0 for a kind it cannot hold). */
export const v2ParamCount = (k: CurveKindName): number => V2_PARAM_COUNT[k] ?? 0;

/** Curve kinds a version 2 link can hold, and the fewest a version 3 link states. */
export const V2_KINDS = 3;

/** The type bits of a curve's flags byte: bits 0-1 the kind's low bits, bit 7 its bit 2. */
export function typeBits(kind: number): number {
  return (kind & 3) | ((kind >> 2) << 7);
}

/** The kind in a curve's flags byte (typeBits undone). */
export function kindOfFlags(flags: number): number {
  return (flags & 3) | ((flags >> 7) << 2);
}

export const GRIDS = Object.keys(GRID_PRESETS) as GridPreset[];
export const TYPES = CURVE_KINDS;
export const MODES = [undefined, 'ruled', 'strip'] as const;
/** Session fields with a place in the layout (the rest go in the JSON tail), and version 1's
 *  avoid slot. */
export const KNOWN_TOP = [
  ...SESSION_FIELD_NAMES.filter((k) => SESSION_FIELDS[k].link === 'layout'),
  'avoid',
];
export const AXES = ['x', 'y', 'z'] as const;
/** The optional parts after the JSON tail (the mask's bits). */
export const PART_HEAD = 1;
export const PART_SCALP_PAINT = 2;
export const PART_SYMMETRY = 4;
export const PARTS = PART_HEAD | PART_SCALP_PAINT | PART_SYMMETRY;
