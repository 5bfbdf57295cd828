// The solved vector field as glyphs (method S6.2, the paper's Fig. 2): a short line segment at
// grid points of a subsampled grid (every `stride`-th point along each axis), only where the
// field is not negligible (|v| > minMagnitude, the growth stop threshold), and never more than
// `maxGlyphs` of them (an even sample when there are more), so the display stays light on a
// software rasteriser. Each segment runs from the point along v, darker at its root.
import * as THREE from 'three';
import type { GridSpec } from '../model/hairArrays';
import { flatGeometry } from './displayMaterials';
import { overlayVertexColourLines, setOverlayGeometry, withHiddenTwin } from './overlayStyle';

export interface FieldGlyphOptions {
  stride: number; // take every stride-th grid point along each axis
  minMagnitude: number; // skip points with |v| <= this
  maxGlyphs: number; // at most this many segments
  length: number; // a unit vector's segment is length · stride · d long (d = grid step)
}

export const DEFAULT_FIELD_GLYPHS: FieldGlyphOptions = {
  stride: 2,
  minMagnitude: 0.05,
  maxGlyphs: 12_000,
  length: 0.8,
};

/** Grid indices p of the glyphs: the subsampled points with |v| > minMagnitude, evenly thinned
 *  to at most maxGlyphs (in increasing order of p). vectors[3 * p + axis]. */
export function fieldGlyphPoints(
  vectors: Float32Array,
  grid: GridSpec,
  opts: Partial<FieldGlyphOptions> = {},
): Int32Array {
  const o = { ...DEFAULT_FIELD_GLYPHS, ...opts };
  const [nx, ny, nz] = grid.dims;
  const stride = Math.max(1, Math.floor(o.stride));
  const min2 = o.minMagnitude * o.minMagnitude;
  const picked: number[] = [];
  for (let k = 0; k < nz; k += stride)
    for (let j = 0; j < ny; j += stride)
      for (let i = 0; i < nx; i += stride) {
        const p = i + nx * (j + ny * k);
        const x = vectors[3 * p];
        const y = vectors[3 * p + 1];
        const z = vectors[3 * p + 2];
        if (x * x + y * y + z * z > min2) picked.push(p);
      }
  const cap = Math.max(0, Math.floor(o.maxGlyphs));
  if (picked.length <= cap) return Int32Array.from(picked);
  // an even sample: glyph g takes candidate floor(g * n / cap)
  const out = new Int32Array(cap);
  for (let g = 0; g < cap; g++) out[g] = picked[Math.floor((g * picked.length) / cap)];
  return out;
}

// vertex colours are linear (three's working space): sRGB hex -> linear
const ROOT_RGB = new THREE.Color(0x2a3342).toArray();
const TIP_RGB = new THREE.Color(0xe08a1e).toArray();

/** Segment arrays of the glyphs: positions[6 * g + 3 * end + axis], colours the same layout. */
export function fieldGlyphSegments(
  vectors: Float32Array,
  grid: GridSpec,
  opts: Partial<FieldGlyphOptions> = {},
): { positions: Float32Array; colours: Float32Array; count: number } {
  const o = { ...DEFAULT_FIELD_GLYPHS, ...opts };
  const pts = fieldGlyphPoints(vectors, grid, o);
  const [nx, ny] = grid.dims;
  const k = o.length * Math.max(1, Math.floor(o.stride)) * grid.step;
  const positions = new Float32Array(6 * pts.length);
  const colours = new Float32Array(6 * pts.length);
  for (let g = 0; g < pts.length; g++) {
    const p = pts[g];
    const ijk = [p % nx, Math.floor(p / nx) % ny, Math.floor(p / (nx * ny))];
    for (let a = 0; a < 3; a++) {
      const x = grid.origin[a] + grid.step * ijk[a];
      positions[6 * g + a] = x;
      positions[6 * g + 3 + a] = x + k * vectors[3 * p + a];
      colours[6 * g + a] = ROOT_RGB[a];
      colours[6 * g + 3 + a] = TIP_RGB[a];
    }
  }
  return { positions, colours, count: pts.length };
}

/** The field display: one THREE.LineSegments, rebuilt by update(). */
export class FieldGlyphsView {
  // depth-tested against head and hair, faint where hidden (overlayStyle.ts)
  readonly object = withHiddenTwin(
    new THREE.LineSegments(new THREE.BufferGeometry(), overlayVertexColourLines('visible')),
    overlayVertexColourLines('hidden'),
  );
  /** Number of glyphs drawn. */
  count = 0;

  constructor(private readonly opts: Partial<FieldGlyphOptions> = {}) {
    this.object.name = 'field';
    this.object.visible = false;
  }

  update(vectors: Float32Array | null, grid: GridSpec): void {
    if (!vectors) {
      this.count = 0;
      setOverlayGeometry(this.object, new THREE.BufferGeometry());
    } else {
      const s = fieldGlyphSegments(vectors, grid, this.opts);
      this.count = s.count;
      setOverlayGeometry(this.object, flatGeometry(s.positions, s.colours));
    }
    this.object.visible = this.count > 0;
  }
}
