// Test probe for the hair's blending: the view drawn whole with the hair's primitives (triangles
// of strips, segments of lines) in their order and in reverse, once order-independently
// (hairOit.ts) and once blended unsorted, and how much of the picture each reversal changed.
// Order-independent blending should change nothing but rounding; unsorted blending shows what
// the order would change. And what the hair's depth (written after the composite) changes: the
// overlays drawn faint where the hair covers them.
import * as THREE from 'three';
import type { WeightedBlendedHair } from './hairOit';
import { ALL_LAYERS, drawLayers, type SceneLayers } from './layeredDrawing';

/** Share of the drawing buffer's pixels that the hair's depth (hairOit.ts writesDepth) changes:
 *  the overlays drawn after the hair are faint where it covers them. Null when the hair shown is
 *  not drawn order-independently. */
export function hairDepthProbe(s: SceneLayers): number | null {
  const hair = s.hair();
  const oit = hair?.userData.oit as WeightedBlendedHair | undefined;
  if (!hair || !oit) return null;
  const draw = (depth: boolean): Uint8Array => {
    oit.writesDepth = depth;
    return drawAndRead(s);
  };
  const range = { ...hair.geometry.drawRange };
  hair.geometry.setDrawRange(0, Number.POSITIVE_INFINITY);
  try {
    return changedShare(draw(true), draw(false));
  } finally {
    oit.writesDepth = true;
    hair.geometry.setDrawRange(range.start, range.count);
  }
}

/** The view drawn whole (every layer), as RGBA pixels of the drawing buffer. */
function drawAndRead(s: SceneLayers): Uint8Array {
  const gl = s.renderer.getContext();
  const size = s.renderer.getDrawingBufferSize(new THREE.Vector2());
  drawLayers(s, ALL_LAYERS);
  const px = new Uint8Array(4 * size.x * size.y);
  gl.readPixels(0, 0, size.x, size.y, gl.RGBA, gl.UNSIGNED_BYTE, px);
  return px;
}

/** Share of the pixels of two RGBA images whose colour differs by more than 6 levels in a
 *  channel. */
function changedShare(a: Uint8Array, b: Uint8Array): number {
  let n = 0;
  for (let i = 0; i < a.length; i += 4)
    for (let c = 0; c < 3; c++)
      if (Math.abs(a[i + c] - b[i + c]) > 6) {
        n++;
        break;
      }
  return n / (a.length / 4);
}

/** Share of the drawing buffer's pixels whose colour a reversal of the drawing order changed by
 *  more than 6 levels in a channel: `oit` with the order-independent drawing, `unsorted` with
 *  plain blending; null when the hair shown is not drawn order-independently. */
export function blendOrderProbe(s: SceneLayers): { oit: number; unsorted: number } | null {
  const hair = s.hair();
  const index = hair?.geometry.index;
  if (!hair || !index || !hair.userData.oit) return null;
  const oit = hair.userData.oit;
  const original = (index.array as Uint32Array).slice();
  // primitives (triangles of strips, segments of lines) in reverse order, each kept whole
  const k = hair instanceof THREE.Mesh ? 3 : 2;
  const primitives = original.length / k;
  const reversed = new Uint32Array(original.length);
  for (let t = 0; t < primitives; t++)
    reversed.set(original.subarray(k * (primitives - 1 - t), k * (primitives - t)), k * t);
  const drawWith = (order: Uint32Array): Uint8Array => {
    (index.array as Uint32Array).set(order);
    index.needsUpdate = true;
    return drawAndRead(s);
  };
  const range = { ...hair.geometry.drawRange };
  hair.geometry.setDrawRange(0, Number.POSITIVE_INFINITY);
  try {
    const withOit = changedShare(drawWith(original), drawWith(reversed));
    delete hair.userData.oit;
    const unsorted = changedShare(drawWith(original), drawWith(reversed));
    return { oit: withOit, unsorted };
  } finally {
    hair.userData.oit = oit;
    (index.array as Uint32Array).set(original);
    index.needsUpdate = true;
    hair.geometry.setDrawRange(range.start, range.count);
  }
}
