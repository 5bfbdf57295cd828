// Pictures side by side: the views of one render (front, side, back) as one PNG, 2 pixels apart
// on white, for the look and style pictures.
import { readPng } from '../tests/unit/pngPixels';
import { encodePng } from '../web/export/png';

/** The PNGs side by side, top-aligned, 2 pixels apart on white. */
export function sideBySide(pngs: readonly Uint8Array[]): Uint8Array {
  const views = pngs.map((p) => readPng(p));
  const gap = 2;
  const height = Math.max(...views.map((v) => v.height));
  const width = views.reduce((w, v) => w + v.width, 0) + gap * (views.length - 1);
  const rgba = new Uint8Array(4 * width * height).fill(255);
  let x0 = 0;
  for (const v of views) {
    for (let y = 0; y < v.height; y++)
      rgba.set(v.rgba.subarray(4 * y * v.width, 4 * (y + 1) * v.width), 4 * (y * width + x0));
    x0 += v.width + gap;
  }
  return encodePng(width, height, 4, rgba);
}
