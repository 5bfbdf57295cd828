// The hair cards' texture atlas, drawn in TypeScript from the clusters' strands (no GPU: the same
// pixels in the browser and under Node). ATLAS_TILES tiles of TILE_W × TILE_H pixels; tile j is
// drawn from the strands of cards j, j + ATLAS_TILES, j + 2 · ATLAS_TILES, … until it holds
// TILE_STRANDS strands, each strand mapped into its own card's coordinates (across: 0 at the
// card's lo edge .. 1 at its hi edge; along: its fraction of its length, root at the tile's top),
// so one tile suits any card; card c uses tile c mod ATLAS_TILES. Three images, same layout:
//   colour    RGBA, the strands' colour (sRGB, each point's with a colour model's lighter tips;
//             × 0.8 .. 1.2 in linear light from the deepest to the highest in the clump) and
//             their coverage as alpha;
//   root–tip  grey, 0 at the root .. 255 at the tip, of the strand nearest the viewer outside;
//   depth     grey, 128 + 127 · d / DEPTH_RANGE (clamped): d the height of that strand above the
//             card along its normal (above = out from the head).
// Strands are drawn as antialiased lines LINE_WIDTH_ROOT → LINE_WIDTH_TIP pixels wide, and a tile
// holds more strands than one cluster has: a card stands for the whole depth of its clump, and
// an alpha-tested texture must stay mostly opaque in its smaller mipmaps (a sparse tile averages
// below the cutoff and the card vanishes at a distance).
import type { Cards } from './cardMesh';
import { type ExportStrands, srgbToLinear, strandArc } from './strandsForExport';

export const ATLAS_SIZE = 1024;
export const TILE_COLUMNS = 8;
export const TILE_ROWS = 2;
export const ATLAS_TILES = TILE_COLUMNS * TILE_ROWS;
export const TILE_W = ATLAS_SIZE / TILE_COLUMNS; // 128
export const TILE_H = ATLAS_SIZE / TILE_ROWS; // 512
/** Transparent border inside each tile, pixels (mipmaps do not bleed between tiles at once). */
export const TILE_PAD = 2;
/** Strands drawn into each tile (at least; whole clusters are drawn). */
export const TILE_STRANDS = 160;
export const LINE_WIDTH_ROOT = 2.4;
export const LINE_WIDTH_TIP = 1.2;
/** The clump's shading of a strand's colour (linear light) from the deepest to the highest. */
export const LIT_DEEP = 0.8;
export const LIT_HIGH = 1.2;
/** Depth map: ±this height above the card (world units, 1 cm) spans 1..255. */
export const DEPTH_RANGE = 0.1;

export interface CardAtlas {
  size: number;
  colour: Uint8Array; // RGBA, rows top to bottom
  rootTip: Uint8Array; // grey
  depth: Uint8Array; // grey
}

/** Atlas rectangle [u0, v0, u1, v1] (0..1, v down) of the drawable part of card c's tile. */
export function tileRect(card: number): number[] {
  const j = card % ATLAS_TILES;
  const x0 = (j % TILE_COLUMNS) * TILE_W + TILE_PAD;
  const y0 = Math.floor(j / TILE_COLUMNS) * TILE_H + TILE_PAD;
  return [
    x0 / ATLAS_SIZE,
    y0 / ATLAS_SIZE,
    (x0 + TILE_W - 2 * TILE_PAD) / ATLAS_SIZE,
    (y0 + TILE_H - 2 * TILE_PAD) / ATLAS_SIZE,
  ];
}

/** Linear 0..1 → sRGB byte: the byte whose decoded value is nearest (a table of the sRGB
 *  decoding, so no inverse power function is evaluated). */
const SRGB_EDGES = (() => {
  const e = new Float64Array(255);
  for (let b = 0; b < 255; b++) e[b] = srgbToLinear((b + 0.5) / 255);
  return e;
})();

export function linearToSrgbByte(x: number): number {
  let lo = 0;
  let hi = 255;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (SRGB_EDGES[mid] < x) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/** Draws the atlas of `cards` (built over `clusters`' strands) from `strands`. */
export function drawCardAtlas(
  strands: ExportStrands,
  cards: Cards,
  members: { start: Int32Array; members: Int32Array },
): CardAtlas {
  const S = ATLAS_SIZE;
  const colour = new Uint8Array(4 * S * S);
  const rootTip = new Uint8Array(S * S);
  const depth = new Uint8Array(S * S).fill(128);
  const cover = new Float32Array(S * S);
  const top = new Float32Array(S * S).fill(Number.NEGATIVE_INFINITY);
  const { points, strandStart, colors, pointColors } = strands;
  const n = strandStart.length - 1;

  // transparent pixels carry the mean hair colour, so filtering at the strands' edges does not
  // darken them
  const mean = [0, 0, 0];
  for (let s = 0; s < n; s++) for (let q = 0; q < 3; q++) mean[q] += colors[3 * s + q] / n;
  const bg = mean.map(linearToSrgbByte);
  for (let i = 0; i < S * S; i++) {
    colour[4 * i] = bg[0];
    colour[4 * i + 1] = bg[1];
    colour[4 * i + 2] = bg[2];
  }

  let longest = 2;
  for (let s = 0; s < n; s++) longest = Math.max(longest, strandStart[s + 1] - strandStart[s]);
  const cum = new Float64Array(longest);
  const w = TILE_W - 2 * TILE_PAD;
  const h = TILE_H - 2 * TILE_PAD;
  const xs = new Float64Array(longest);
  const ys = new Float64Array(longest);
  const ds = new Float64Array(longest);

  const drawn = new Int32Array(ATLAS_TILES);
  for (let c = 0; c < cards.count; c++) {
    const j = c % ATLAS_TILES;
    if (drawn[j] >= TILE_STRANDS) continue;
    drawn[j] += members.start[c + 1] - members.start[c];
    const tx = (j % TILE_COLUMNS) * TILE_W + TILE_PAD;
    const ty = Math.floor(j / TILE_COLUMNS) * TILE_H + TILE_PAD;
    const r0 = cards.rowStart[c];
    const nr = cards.rowStart[c + 1] - r0;
    for (let k = members.start[c]; k < members.start[c + 1]; k++) {
      const s = members.members[k];
      const np = strandArc(points, strandStart, s, cum);
      const a = strandStart[s];
      const total = cum[np - 1];
      for (let i = 0; i < np; i++) {
        const t = total > 0 ? cum[i] / total : i / (np - 1);
        // the card's frame at t, interpolated between its rows
        const rf = t * (nr - 1);
        const r = Math.min(nr - 2, Math.floor(rf));
        const f = rf - r;
        const ra = r0 + r;
        const rb = ra + 1;
        let across = 0;
        let height = 0;
        for (let q = 0; q < 3; q++) {
          const centre = cards.centre[3 * ra + q] * (1 - f) + cards.centre[3 * rb + q] * f;
          const d = points[3 * (a + i) + q] - centre;
          across += d * (cards.across[3 * ra + q] * (1 - f) + cards.across[3 * rb + q] * f);
          height += d * (cards.normal[3 * ra + q] * (1 - f) + cards.normal[3 * rb + q] * f);
        }
        const lo = cards.lo[ra] * (1 - f) + cards.lo[rb] * f;
        const hi = cards.hi[ra] * (1 - f) + cards.hi[rb] * f;
        const u = Math.min(1, Math.max(0, (across - lo) / (hi - lo)));
        xs[i] = tx + u * w;
        ys[i] = ty + t * h;
        ds[i] = height;
      }
      const rgb = [0, 1, 2].map((q) => colors[3 * s + q]);
      for (let i = 0; i + 1 < np; i++) {
        // a colour model's lighter tips: each segment in its first point's colour
        if (pointColors) for (let q = 0; q < 3; q++) rgb[q] = pointColors[3 * (a + i) + q];
        const t0 = i / (np - 1);
        const width =
          LINE_WIDTH_ROOT + (LINE_WIDTH_TIP - LINE_WIDTH_ROOT) * ((t0 * 2 + 1 / (np - 1)) / 2);
        // every pixel whose centre is within half the width + 0.5 of the segment, its coverage
        // falling off linearly over the last pixel (pixel centres at +0.5)
        const x0 = xs[i];
        const y0 = ys[i];
        const dx = xs[i + 1] - x0;
        const dy = ys[i + 1] - y0;
        const len2 = dx * dx + dy * dy;
        const reach = width / 2 + 0.5;
        const xa = Math.max(0, Math.floor(Math.min(x0, x0 + dx) - reach));
        const xb = Math.min(S - 1, Math.floor(Math.max(x0, x0 + dx) + reach));
        const ya = Math.max(0, Math.floor(Math.min(y0, y0 + dy) - reach));
        const yb = Math.min(S - 1, Math.floor(Math.max(y0, y0 + dy) + reach));
        for (let y = ya; y <= yb; y++)
          for (let x = xa; x <= xb; x++) {
            const qx = x + 0.5 - x0;
            const qy = y + 0.5 - y0;
            const along = len2 > 0 ? Math.min(1, Math.max(0, (qx * dx + qy * dy) / len2)) : 0;
            const ex = qx - along * dx;
            const ey = qy - along * dy;
            const cov = Math.min(1, reach - Math.sqrt(ex * ex + ey * ey));
            if (!(cov > 0)) continue;
            const px = x + S * y;
            const d = ds[i] + (ds[i + 1] - ds[i]) * along;
            cover[px] = 1 - (1 - cover[px]) * (1 - cov);
            if (cov >= 0.25 && d > top[px]) {
              top[px] = d;
              // strands deeper in the clump are darker (the light they lose to the ones above),
              // so a card shows strands, not a flat colour
              // (in linear light, LIT_DEEP .. LIT_HIGH around 1: the atlas's mean stays the
              // strands' colour; scaling the sRGB bytes darkened the cards by about a third)
              const h = Math.min(1, Math.max(0, (d / DEPTH_RANGE + 1) / 2));
              const lit = LIT_DEEP + (LIT_HIGH - LIT_DEEP) * h;
              colour[4 * px] = linearToSrgbByte(Math.min(1, rgb[0] * lit));
              colour[4 * px + 1] = linearToSrgbByte(Math.min(1, rgb[1] * lit));
              colour[4 * px + 2] = linearToSrgbByte(Math.min(1, rgb[2] * lit));
              const tt = (cum[i] + (cum[i + 1] - cum[i]) * along) / (total > 0 ? total : 1);
              rootTip[px] = Math.round(255 * Math.min(1, Math.max(0, tt)));
              depth[px] = Math.round(128 + 127 * Math.min(1, Math.max(-1, d / DEPTH_RANGE)));
            }
          }
      }
    }
  }
  for (let i = 0; i < S * S; i++) colour[4 * i + 3] = Math.round(255 * cover[i]);
  return { size: S, colour, rootTip, depth };
}
