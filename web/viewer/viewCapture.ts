// The current view drawn once with every strand, outside the frame loop: as a PNG image (Export
// → PNG) and as a timed frame (a benchmark probe).
import * as THREE from 'three';
import type { DrawnHair } from './hairLevelOfDetail';
import { ALL_LAYERS, drawLayers, type SceneLayers } from './layeredDrawing';
import { basePixelRatio } from './rendererProbe';

/** What a capture draws: the viewer's scene layers (renderer, scene, camera), its canvas (for
 *  the size), and the hair with its full index count (its draw range is set to all of it). */
export interface CaptureSource {
  layers: SceneLayers;
  canvas: HTMLCanvasElement;
  software: boolean;
  hair: DrawnHair;
  allHair: number;
}

function linearToSrgb(v: number): number {
  const c = Math.min(1, Math.max(0, v));
  return c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055;
}

/** The view as a PNG at `scale` × the canvas's resolution, with every strand drawn (not the
 *  level-of-detail sample), on a transparent background when asked. Rendered into a half-float
 *  target and encoded to sRGB here (a render target is drawn in linear light). The caller
 *  requests a frame afterwards. */
export async function captureImage(
  src: CaptureSource,
  opts: { scale?: number; transparent?: boolean } = {},
): Promise<Blob> {
  const scale = opts.scale ?? 2;
  const ratio = basePixelRatio() * scale;
  const w = Math.max(1, Math.round(src.canvas.clientWidth * ratio));
  const h = Math.max(1, Math.round(src.canvas.clientHeight * ratio));
  const r = src.layers.renderer;
  const half = r.extensions.has('EXT_color_buffer_float');
  const rt = new THREE.WebGLRenderTarget(w, h, {
    type: half ? THREE.HalfFloatType : THREE.UnsignedByteType,
    samples: src.software ? 0 : 4,
  });
  const clear = new THREE.Color();
  r.getClearColor(clear);
  const clearAlpha = r.getClearAlpha();
  const pixels = half ? new Uint16Array(4 * w * h) : new Uint8Array(4 * w * h);
  try {
    if (src.hair && src.allHair > 0) src.hair.geometry.setDrawRange(0, src.allHair);
    if (opts.transparent) r.setClearColor(clear, 0);
    r.setRenderTarget(rt);
    drawLayers(src.layers, ALL_LAYERS);
    r.readRenderTargetPixels(rt, 0, 0, w, h, pixels);
  } finally {
    r.setRenderTarget(null);
    r.setClearColor(clear, clearAlpha);
    rt.dispose();
  }
  const out = new Uint8ClampedArray(4 * w * h);
  const channel = half
    ? (k: number) => THREE.DataUtils.fromHalfFloat((pixels as Uint16Array)[k])
    : (k: number) => (pixels as Uint8Array)[k] / 255;
  for (let y = 0; y < h; y++) {
    const srcRow = (h - 1 - y) * w * 4; // rows come bottom-up
    const dst = y * w * 4;
    for (let x = 0; x < 4 * w; x += 4) {
      for (let c = 0; c < 3; c++) out[dst + x + c] = 255 * linearToSrgb(channel(srcRow + x + c));
      out[dst + x + 3] = 255 * Math.min(1, Math.max(0, channel(srcRow + x + 3)));
    }
  }
  const canvas = document.createElement('canvas');
  canvas.width = w;
  canvas.height = h;
  const ctx = canvas.getContext('2d');
  if (!ctx) throw new Error('this browser cannot draw images (no 2D canvas)');
  ctx.putImageData(new ImageData(out, w, h), 0, 0);
  return new Promise((resolve, reject) =>
    canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('PNG encoding failed'))), 'image/png'),
  );
}

/** Draws the view once with every strand and returns its time in ms, GPU work included (a
 *  one-pixel read before and after waits for the GPU). The caller requests a frame afterwards. */
export function measureFullFrame(src: CaptureSource): number {
  const gl = src.layers.renderer.getContext();
  const px = new Uint8Array(4);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
  const t0 = performance.now();
  if (src.hair && src.allHair > 0) src.hair.geometry.setDrawRange(0, src.allHair);
  drawLayers(src.layers, ALL_LAYERS);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
  return performance.now() - t0;
}
