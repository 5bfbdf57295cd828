// Figures of the hair's colour in a picture (issue: colour as named, the same in both qualities):
// the hair's pixels are those that differ from a picture of the same view without hair; of them
// the mean hue (a circular mean of HSV hue weighted by saturation × value, degrees), the mean
// luma (Rec. 709 of the linear values) and the mean HSV saturation. Pure arithmetic on RGBA.

export interface Rgba {
  width: number;
  height: number;
  rgba: Uint8Array;
}

export interface HairColourFigures {
  /** Pixels counted as hair. */
  pixels: number;
  /** Degrees, 0..360 (red 0, yellow 60). */
  hue: number;
  /** Mean relative luminance of the hair's pixels, 0..1. */
  luma: number;
  /** Mean HSV saturation, 0..1. */
  saturation: number;
}

const linear = (b: number) => {
  const c = b / 255;
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
};

/** HSV hue (degrees), saturation and value of an sRGB byte triple. */
export function hsv(r: number, g: number, b: number): [number, number, number] {
  const max = Math.max(r, g, b);
  const min = Math.min(r, g, b);
  const d = max - min;
  let h = 0;
  if (d > 0) {
    if (max === r) h = ((g - b) / d) % 6;
    else if (max === g) h = (b - r) / d + 2;
    else h = (r - g) / d + 4;
  }
  return [(h * 60 + 360) % 360, max > 0 ? d / max : 0, max / 255];
}

/** Whether the pixel at byte offset i is hair: its RGB differs from the bald picture's by more
 *  than `threshold` (sum of absolute byte differences). */
function isHair(a: Uint8Array, z: Uint8Array, i: number, threshold: number): boolean {
  return (
    Math.abs(a[i] - z[i]) + Math.abs(a[i + 1] - z[i + 1]) + Math.abs(a[i + 2] - z[i + 2]) >
    threshold
  );
}

/** The hair's pixels: those whose RGB differs from the bald picture's by more than `threshold`
 *  (sum of absolute byte differences). */
export function hairColour(withHair: Rgba, bald: Rgba, threshold = 24): HairColourFigures {
  if (withHair.width !== bald.width || withHair.height !== bald.height)
    throw new Error('the two pictures differ in size');
  let n = 0;
  let sx = 0;
  let sy = 0;
  let luma = 0;
  let sat = 0;
  const a = withHair.rgba;
  const z = bald.rgba;
  for (let i = 0; i < a.length; i += 4) {
    if (!isHair(a, z, i, threshold)) continue;
    n++;
    const [h, s, v] = hsv(a[i], a[i + 1], a[i + 2]);
    const w = s * v;
    sx += w * Math.cos((h * Math.PI) / 180);
    sy += w * Math.sin((h * Math.PI) / 180);
    luma += 0.2126 * linear(a[i]) + 0.7152 * linear(a[i + 1]) + 0.0722 * linear(a[i + 2]);
    sat += s;
  }
  const hue = ((Math.atan2(sy, sx) * 180) / Math.PI + 360) % 360;
  return { pixels: n, hue, luma: n ? luma / n : 0, saturation: n ? sat / n : 0 };
}

/** The colour a colourist names the hair by, its body colour: of the hair's pixels (as hairColour
 *  finds them) in the top `topShare` of their rows (below that the hair's shadow on the neck and
 *  shoulders differs from the bald picture too), the middle half by luma (no highlights, no gaps);
 *  their mean in linear RGB, as sRGB bytes, with its HSV and luma. */
export function bodyColour(
  withHair: Rgba,
  bald: Rgba,
  topShare = 0.6,
  threshold = 24,
): { rgb: [number, number, number]; hue: number; saturation: number; value: number; luma: number } {
  const { width } = withHair;
  const a = withHair.rgba;
  const b = bald.rgba;
  const hair: number[] = [];
  for (let i = 0; i < a.length; i += 4) {
    if (isHair(a, b, i, threshold)) hair.push(i);
  }
  if (hair.length === 0) throw new Error('no hair in the picture');
  const row = (i: number) => Math.floor(i / 4 / width);
  const top = row(hair[0]);
  const cut = top + topShare * (row(hair[hair.length - 1]) - top);
  const luma = (i: number) =>
    0.2126 * linear(a[i]) + 0.7152 * linear(a[i + 1]) + 0.0722 * linear(a[i + 2]);
  const upper = hair.filter((i) => row(i) <= cut).sort((x, y) => luma(x) - luma(y));
  const middle = upper.slice(Math.floor(upper.length / 4), Math.ceil((3 * upper.length) / 4));
  const sum = [0, 0, 0];
  for (const i of middle) for (let c = 0; c < 3; c++) sum[c] += linear(a[i + c]);
  const toByte = (v: number) =>
    Math.round(255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * v ** (1 / 2.4) - 0.055));
  const rgb = sum.map((v) => toByte(v / middle.length)) as [number, number, number];
  const [hue, saturation, value] = hsv(...rgb);
  const l = sum.map((v) => v / middle.length);
  return { rgb, hue, saturation, value, luma: 0.2126 * l[0] + 0.7152 * l[1] + 0.0722 * l[2] };
}

/** How much of the hair is drawn black (the back of dark hair as a shell lit by nothing): of the
 *  hair's pixels (as hairColour finds them), the share whose brightest sRGB channel is under
 *  `below` (bytes). Dark brown hair's own colour is brighter than that where any light reaches
 *  it. */
export function blackShare(withHair: Rgba, bald: Rgba, below = 12, threshold = 24): number {
  let hair = 0;
  let black = 0;
  const a = withHair.rgba;
  const b = bald.rgba;
  for (let i = 0; i < a.length; i += 4) {
    if (!isHair(a, b, i, threshold)) continue;
    hair++;
    if (Math.max(a[i], a[i + 1], a[i + 2]) < below) black++;
  }
  return hair > 0 ? black / hair : 0;
}

/** How much bare skin shows through the hair (stripes of scalp between clumps, a crown's whorl):
 *  in the top `topShare` of the hair's bounding box (as hairColour finds the hair's pixels: there
 *  the head is covered by hair), the share of all pixels that read as skin (sRGB with r > g > b,
 *  HSV saturation 0.15 to 0.6 and value above 90 of 255). */
export function skinThroughHair(
  withHair: Rgba,
  bald: Rgba,
  topShare = 0.6,
  threshold = 24,
): number {
  const { width, height } = withHair;
  const a = withHair.rgba;
  const b = bald.rgba;
  let x0 = width;
  let x1 = -1;
  let y0 = height;
  let y1 = -1;
  for (let y = 0; y < height; y++)
    for (let x = 0; x < width; x++) {
      const i = 4 * (y * width + x);
      if (!isHair(a, b, i, threshold)) continue;
      x0 = Math.min(x0, x);
      x1 = Math.max(x1, x);
      y0 = Math.min(y0, y);
      y1 = Math.max(y1, y);
    }
  if (x1 < 0) return 0;
  const yEnd = y0 + topShare * (y1 - y0);
  let all = 0;
  let skin = 0;
  for (let y = y0; y <= yEnd; y++)
    for (let x = x0; x <= x1; x++) {
      const i = 4 * (y * width + x);
      all++;
      const [r, g, bl] = [a[i], a[i + 1], a[i + 2]];
      const [, sat, val] = hsv(r, g, bl);
      if (r > g && g > bl && sat >= 0.15 && sat <= 0.6 && val > 90 / 255) skin++;
    }
  return all > 0 ? skin / all : 0;
}

/** The smaller angle between two hues, degrees. */
export function hueDistance(a: number, b: number): number {
  const d = Math.abs(a - b) % 360;
  return d > 180 ? 360 - d : d;
}

/** Of the hair's coloured pixels (as hairColour finds them, with HSV saturation over 0.3 and
 *  value over 0.1), the share whose hue is under `hue` degrees (taking 180-360 as negative): a
 *  red glow on hair of a warmer hue. */
export function hueBelowShare(withHair: Rgba, bald: Rgba, hue: number, threshold = 24): number {
  const a = withHair.rgba;
  const z = bald.rgba;
  let n = 0;
  let red = 0;
  for (let i = 0; i < a.length; i += 4) {
    if (!isHair(a, z, i, threshold)) continue;
    const [h, s, v] = hsv(a[i], a[i + 1], a[i + 2]);
    if (!(s > 0.3 && v > 0.1)) continue;
    n++;
    if ((h > 180 ? h - 360 : h) < hue) red++;
  }
  return n ? red / n : 0;
}

/** How the key light's highlight stands out over the top of the hair (ring- and
 *  S-shaped highlights read as cowlicks): of the hair's pixels in the top `topShare` of its
 *  height (the crown and the sides above the ears, where hair covers the head: no skin), the
 *  luma averaged over (2r + 1)² pixels (the scale of a band, not of a strand); the 99th
 *  percentile of that over its median. One smooth bright band lying on dark hair gives a high
 *  ratio; a highlight broken into strands averages out. */
export function highlightPeak(withHair: Rgba, bald: Rgba, r = 3, topShare = 0.35): number {
  const { width: W, height: H } = withHair;
  if (W !== bald.width || H !== bald.height) throw new Error('the two pictures differ in size');
  const a = withHair.rgba;
  const z = bald.rgba;
  const hair = new Uint8Array(W * H);
  const L = new Float64Array(W * H);
  let top = H;
  let bottom = -1;
  for (let i = 0; i < W * H; i++) {
    const k = 4 * i;
    const diff =
      Math.abs(a[k] - z[k]) + Math.abs(a[k + 1] - z[k + 1]) + Math.abs(a[k + 2] - z[k + 2]);
    if (diff <= 24) continue;
    hair[i] = 1;
    const y = Math.floor(i / W);
    top = Math.min(top, y);
    bottom = Math.max(bottom, y);
    L[i] = 0.2126 * linear(a[k]) + 0.7152 * linear(a[k + 1]) + 0.0722 * linear(a[k + 2]);
  }
  const limit = top + topShare * (bottom - top);
  const means: number[] = [];
  for (let y = r; y < Math.min(H - r, limit); y++)
    for (let x = r; x < W - r; x++) {
      let sum = 0;
      let inside = true;
      for (let dy = -r; dy <= r && inside; dy++)
        for (let dx = -r; dx <= r; dx++) {
          const j = (y + dy) * W + x + dx;
          if (!hair[j]) {
            inside = false;
            break;
          }
          sum += L[j];
        }
      if (inside) means.push(sum / (2 * r + 1) ** 2);
    }
  if (means.length < 100) return Number.NaN;
  means.sort((p, q) => p - q);
  const at = (f: number) => means[Math.floor(f * (means.length - 1))];
  return at(0.99) / at(0.5);
}

/** How much the hair's strands and locks show: of the hair's pixels, the mean of |v − the mean v
 *  of its (2r + 1)² neighbourhood| over the mean v, v the pixel's sRGB grey (as an eye weighs
 *  dark hair: in linear light every dark strand is near 0). A smooth shell gives nearly 0. */
export function strandContrast(withHair: Rgba, bald: Rgba, r = 1): number {
  const { width: W, height: H } = withHair;
  if (W !== bald.width || H !== bald.height) throw new Error('the two pictures differ in size');
  const a = withHair.rgba;
  const z = bald.rgba;
  const hair = new Uint8Array(W * H);
  const v = new Float64Array(W * H);
  for (let i = 0; i < W * H; i++) {
    const k = 4 * i;
    v[i] = 0.299 * a[k] + 0.587 * a[k + 1] + 0.114 * a[k + 2];
    const diff =
      Math.abs(a[k] - z[k]) + Math.abs(a[k + 1] - z[k + 1]) + Math.abs(a[k + 2] - z[k + 2]);
    hair[i] = diff > 24 ? 1 : 0;
  }
  let dev = 0;
  let sum = 0;
  for (let y = r; y < H - r; y++)
    for (let x = r; x < W - r; x++) {
      const i = y * W + x;
      if (!hair[i]) continue;
      let m = 0;
      for (let dy = -r; dy <= r; dy++) for (let dx = -r; dx <= r; dx++) m += v[i + dy * W + dx];
      m /= (2 * r + 1) ** 2;
      dev += Math.abs(v[i] - m);
      sum += v[i];
    }
  return sum > 0 ? dev / sum : 0;
}

/** How soft a hairline seen from the front is, in pixels: down each column of the middle third
 *  of the hair's box, from the hair's top to where the picture is the bald one's again (three
 *  pixels in a row within `threshold`: the forehead's skin), the grey g (sRGB, 0.299 r + 0.587 g +
 *  0.114 b) goes from the hair's (the median over 14 to 20 pixels above the skin) to the skin's
 *  (the pixel below it); the width is from the last pixel above the skin still within a fifth of
 *  that change to the first after it past four fifths. A line drawn with a pencil is a pixel or
 *  two; hair thinning into the skin, more. The median over the columns whose change is at least
 *  20 grey levels. */
export function hairlineWidth(withHair: Rgba, bald: Rgba, threshold = 24): number {
  const { width: W, height: H } = withHair;
  if (W !== bald.width || H !== bald.height) throw new Error('the two pictures differ in size');
  const a = withHair.rgba;
  const z = bald.rgba;
  const differs = (x: number, y: number) => {
    const k = 4 * (y * W + x);
    return (
      Math.abs(a[k] - z[k]) + Math.abs(a[k + 1] - z[k + 1]) + Math.abs(a[k + 2] - z[k + 2]) >
      threshold
    );
  };
  const grey = (x: number, y: number) => {
    const k = 4 * (y * W + x);
    return 0.299 * a[k] + 0.587 * a[k + 1] + 0.114 * a[k + 2];
  };
  let x0 = W;
  let x1 = -1;
  for (let y = 0; y < H; y++)
    for (let x = 0; x < W; x++)
      if (differs(x, y)) {
        x0 = Math.min(x0, x);
        x1 = Math.max(x1, x);
      }
  const widths: number[] = [];
  const third = (x1 - x0) / 3;
  for (let x = Math.ceil(x0 + third); x <= x1 - third; x++) {
    let top = 0;
    while (top < H && !differs(x, top)) top++;
    let skin = -1;
    for (let y = top + 20; y < H - 3; y++)
      if (!differs(x, y) && !differs(x, y + 1) && !differs(x, y + 2)) {
        skin = y;
        break;
      }
    if (skin < 0) continue;
    const above: number[] = [];
    for (let y = skin - 20; y <= skin - 14; y++) above.push(grey(x, y));
    above.sort((p, q) => p - q);
    const hair = above[3];
    const change = grey(x, skin + 1) - hair;
    if (Math.abs(change) < 20) continue;
    const share = (y: number) => (grey(x, y) - hair) / change;
    let low = skin - 20;
    for (let y = skin - 20; y <= skin; y++) if (share(y) < 0.2) low = y;
    let high = skin + 1;
    for (let y = low + 1; y <= skin + 1; y++)
      if (share(y) > 0.8) {
        high = y;
        break;
      }
    widths.push(high - low);
  }
  widths.sort((p, q) => p - q);
  return widths.length ? widths[Math.floor(widths.length / 2)] : Number.NaN;
}

/** Summed-area tables of the grey (sRGB, 0.299 r + 0.587 g + 0.114 b) and of the hair's mask (as
 *  hairColour's), and box(T, x, y, r): T's sum over the (2r + 1)² square round (x, y). */
function greyAndHairTables(withHair: Rgba, bald: Rgba, threshold: number) {
  const { width: W, height: H } = withHair;
  if (W !== bald.width || H !== bald.height) throw new Error('the two pictures differ in size');
  const a = withHair.rgba;
  const z = bald.rgba;
  const S = new Float64Array((W + 1) * (H + 1));
  const M = new Float64Array((W + 1) * (H + 1));
  for (let y = 0; y < H; y++)
    for (let x = 0; x < W; x++) {
      const k = 4 * (y * W + x);
      const hair =
        Math.abs(a[k] - z[k]) + Math.abs(a[k + 1] - z[k + 1]) + Math.abs(a[k + 2] - z[k + 2]) >
        threshold;
      const g = 0.299 * a[k] + 0.587 * a[k + 1] + 0.114 * a[k + 2];
      const i = (y + 1) * (W + 1) + x + 1;
      S[i] = g + S[i - 1] + S[i - W - 1] - S[i - W - 2];
      M[i] = (hair ? 1 : 0) + M[i - 1] + M[i - W - 1] - M[i - W - 2];
    }
  const box = (T: Float64Array, x: number, y: number, r: number) =>
    T[(y + r + 1) * (W + 1) + x + r + 1] -
    T[(y - r) * (W + 1) + x + r + 1] -
    T[(y + r + 1) * (W + 1) + x - r] +
    T[(y - r) * (W + 1) + x - r];
  return { S, M, box };
}

/** How sharply the light changes over the top of the hair: over the hair's pixels in the top
 *  `topShare` of its rows whose whole (4r + 1)² square is hair, the gradient of the grey's
 *  (2r + 1)² box means r pixels to either side (|up − down|, |left − right|, their length), over
 *  the mean grey; its 90th percentile. Strands are averaged out by the boxes; what is left is
 *  shading, and a lit cap ending in a rim across the crown is a band of steep gradient. */
export function lightRim(withHair: Rgba, bald: Rgba, r = 4, topShare = 0.4, threshold = 24) {
  const { width: W, height: H } = withHair;
  const { box, S, M } = greyAndHairTables(withHair, bald, threshold);
  let top = H;
  let bottom = -1;
  for (let y = 0; y < H; y++)
    if (M[(y + 1) * (W + 1) + W] - M[y * (W + 1) + W] > 0) {
      top = Math.min(top, y);
      bottom = y;
    }
  const n = (2 * r + 1) ** 2;
  const gradients: number[] = [];
  let grey = 0;
  for (
    let y = Math.max(top, 2 * r + 1);
    y < Math.min(top + topShare * (bottom - top), H - 2 * r - 1);
    y++
  )
    for (let x = 2 * r + 1; x < W - 2 * r - 1; x++) {
      if (box(M, x, y, 2 * r) < (4 * r + 1) ** 2) continue;
      const up = box(S, x, y - r, r) / n;
      const down = box(S, x, y + r, r) / n;
      gradients.push(Math.hypot(up - down, (box(S, x - r, y, r) - box(S, x + r, y, r)) / n));
      grey += (up + down) / 2;
    }
  if (gradients.length === 0) throw new Error('no hair in the picture');
  gradients.sort((p, q) => p - q);
  return gradients[Math.floor(0.9 * (gradients.length - 1))] / (grey / gradients.length);
}

/** How blotched the hair's shading is: over the hair's pixels (as hairColour's) whose whole
 *  (2·wide + 1)² square is hair, the mean of |the grey's mean over a (2·fine + 1)² square − its
 *  mean over the (2·wide + 1)² square|, over the hair's mean grey (sRGB, 0.299 r + 0.587 g +
 *  0.114 b). Strands and their grain are averaged out by the fine square; what is left is shading
 *  that changes over a few strands' width: blotches, and shadow lines drawn across the hair. */
export function shadingBlotches(
  withHair: Rgba,
  bald: Rgba,
  fine = 3,
  wide = 10,
  threshold = 24,
): number {
  const { width: W, height: H } = withHair;
  const { box, S, M } = greyAndHairTables(withHair, bald, threshold);
  let sum = 0;
  let grey = 0;
  for (let y = wide; y < H - wide; y++)
    for (let x = wide; x < W - wide; x++) {
      if (box(M, x, y, wide) < (2 * wide + 1) ** 2) continue;
      const f = box(S, x, y, fine) / (2 * fine + 1) ** 2;
      const w = box(S, x, y, wide) / (2 * wide + 1) ** 2;
      sum += Math.abs(f - w);
      grey += w;
    }
  return grey > 0 ? sum / grey : 0;
}

/** How much of strongly coloured hair is crossed by a pale, greyed line: of the pixels whose
 *  7 × 7 neighbourhood's median HSV saturation is above `vivid` (inside auburn or copper hair;
 *  skin, the background and grey hair are far below it), the share whose own saturation is more
 *  than `dip` below that median. A white sheen from the fill light drawn as a thin line over red
 *  hair is such a dip; strands' own spread of colour is not. */
export function greyLineShare(picture: Rgba, vivid = 0.7, dip = 0.3): number {
  const { width: W, height: H, rgba: a } = picture;
  const sat = new Float32Array(W * H);
  for (let i = 0; i < W * H; i++) {
    const [, s] = hsv(a[4 * i], a[4 * i + 1], a[4 * i + 2]);
    sat[i] = s;
  }
  const window: number[] = [];
  let inside = 0;
  let lines = 0;
  for (let y = 3; y < H - 3; y++)
    for (let x = 3; x < W - 3; x++) {
      window.length = 0;
      for (let dy = -3; dy <= 3; dy++)
        for (let dx = -3; dx <= 3; dx++) window.push(sat[(y + dy) * W + x + dx]);
      window.sort((p, q) => p - q);
      const median = window[24];
      if (median <= vivid) continue;
      inside++;
      if (sat[y * W + x] < median - dip) lines++;
    }
  return inside ? lines / inside : 0;
}

/** How grainy the skin is in `picture` where `smooth` (the same view in another quality) has
 *  smooth skin: of the skin pixels (sRGB red over 120, 25 over blue, red > green > blue) of
 *  `smooth` whose grey is within 1.5 of its 5 × 5 mean, the share whose grey in `picture` is 4
 *  or more off its own 5 × 5 mean. A hair's shadow that is a speckle of single strands' shadows
 *  makes such pixels; a soft one, none. `top`: the share of the rows counted, from the top (the
 *  face, not the bust below it). */
export function skinGrain(picture: Rgba, smooth: Rgba, top = 1): number {
  const { width: W, height: H } = picture;
  if (W !== smooth.width || H !== smooth.height) throw new Error('the two pictures differ in size');
  const grey = (p: Uint8Array) => {
    const g = new Float64Array(W * H);
    for (let i = 0; i < W * H; i++)
      g[i] = 0.299 * p[4 * i] + 0.587 * p[4 * i + 1] + 0.114 * p[4 * i + 2];
    return g;
  };
  const offMean = (g: Float64Array, i: number) => {
    let m = 0;
    for (let dy = -2; dy <= 2; dy++) for (let dx = -2; dx <= 2; dx++) m += g[i + dy * W + dx];
    return Math.abs(g[i] - m / 25);
  };
  const [gp, gs] = [grey(picture.rgba), grey(smooth.rgba)];
  const s = smooth.rgba;
  let skin = 0;
  let grainy = 0;
  for (let y = 2; y < Math.min(H - 2, Math.round(top * H)); y++)
    for (let x = 2; x < W - 2; x++) {
      const i = y * W + x;
      const [r, g, b] = [s[4 * i], s[4 * i + 1], s[4 * i + 2]];
      if (!(r > 120 && r - b > 25 && r > g && g > b) || offMean(gs, i) >= 1.5) continue;
      skin++;
      if (offMean(gp, i) >= 4) grainy++;
    }
  return skin > 0 ? grainy / skin : 0;
}

/** Of the hair's pixels (those that differ from the bald picture by more than `threshold`, summed
 *  over the channels), the share with a channel at `level` or more: highlights clipped to white. */
export function clippedShare(withHair: Rgba, bald: Rgba, level = 250, threshold = 24): number {
  const { width: W, height: H } = withHair;
  if (W !== bald.width || H !== bald.height) throw new Error('the two pictures differ in size');
  let hair = 0;
  let clipped = 0;
  for (let i = 0; i < W * H; i++) {
    if (!isHair(withHair.rgba, bald.rgba, 4 * i, threshold)) continue;
    hair++;
    const [r, g, b] = [withHair.rgba[4 * i], withHair.rgba[4 * i + 1], withHair.rgba[4 * i + 2]];
    if (Math.max(r, g, b) >= level) clipped++;
  }
  return hair > 0 ? clipped / hair : 0;
}
