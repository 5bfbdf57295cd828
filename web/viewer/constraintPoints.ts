// The constraints of the current solve (method S6.2): a point at each constrained grid point and a
// short segment along its target direction, coloured by kind as in the paper's Figs. 2, 4, 5.
// The segment's length is proportional to the target's magnitude (the red 0.3 constraints of a
// dividing curve are short), and it fades towards white at its tip to show the direction.
import * as THREE from 'three';
import type { ConstraintArrays, GridSpec } from '../model/hairArrays';
import { flatGeometry } from './displayMaterials';
import {
  overlayVertexColourLines,
  overlayVertexColourPoints,
  setOverlayGeometry,
  withHiddenTwin,
} from './overlayStyle';

/** RGB (0xRRGGBB) of each ConstraintColour code: blue, red, purple, green, grey (extra). */
export const CONSTRAINT_RGB: readonly number[] = [0x1f5fe0, 0xe0262f, 0x9a3fc4, 0x1f9e4a, 0x7d848f];
const UNKNOWN_RGB = CONSTRAINT_RGB[4];

/** RGB of a ConstraintColour code (grey for codes it does not know). */
export function constraintRgb(code: number): number {
  return CONSTRAINT_RGB[code] ?? UNKNOWN_RGB;
}

/** World position of grid point p (index p = i + nx * (j + ny * k)). */
export function gridPointPosition(grid: GridSpec, p: number): [number, number, number] {
  const [nx, ny] = grid.dims;
  const i = p % nx;
  const j = Math.floor(p / nx) % ny;
  const k = Math.floor(p / (nx * ny));
  return [
    grid.origin[0] + grid.step * i,
    grid.origin[1] + grid.step * j,
    grid.origin[2] + grid.step * k,
  ];
}

export interface ConstraintGlyphs {
  points: Float32Array; // points[3 * c + axis]: grid position of constraint c
  /** pointColours[3 * c + channel], 0..1 in three's linear working space (the CONSTRAINT_RGB
   *  sRGB colour on screen). */
  pointColours: Float32Array;
  segments: Float32Array; // segments[6 * c + 3 * end + axis]: end 0 at the point, 1 at the tip
  segmentColours: Float32Array; // same layout, 0..1
}

/** Glyph arrays of the constraints. A segment runs from the point to point + length · d · target
 *  (d = grid step, `length` in grid steps per unit of target). */
export function constraintGlyphs(
  c: ConstraintArrays,
  grid: GridSpec,
  length = 0.8,
): ConstraintGlyphs {
  const n = c.index.length;
  const points = new Float32Array(3 * n);
  const pointColours = new Float32Array(3 * n);
  const segments = new Float32Array(6 * n);
  const segmentColours = new Float32Array(6 * n);
  const k = length * grid.step;
  // vertex colours are in three's linear working space: sRGB hex -> linear, once per colour
  const palette = CONSTRAINT_RGB.map((hex) => new THREE.Color(hex).toArray() as number[]);
  for (let e = 0; e < n; e++) {
    const p = gridPointPosition(grid, c.index[e]);
    const col = palette[c.colour[e]] ?? palette[4];
    for (let a = 0; a < 3; a++) {
      points[3 * e + a] = p[a];
      segments[6 * e + a] = p[a];
      segments[6 * e + 3 + a] = p[a] + k * c.target[3 * e + a];
      pointColours[3 * e + a] = col[a];
      segmentColours[6 * e + a] = col[a];
      segmentColours[6 * e + 3 + a] = col[a] + 0.55 * (1 - col[a]);
    }
  }
  return { points, pointColours, segments, segmentColours };
}

/** The constraint display: one THREE.Group of points and segments, rebuilt by update(). */
export class ConstraintPointsView {
  readonly object = new THREE.Group();
  // depth-tested against head and hair, faint where hidden (overlayStyle.ts)
  private readonly points = withHiddenTwin(
    new THREE.Points(new THREE.BufferGeometry(), overlayVertexColourPoints('visible')),
    overlayVertexColourPoints('hidden'),
  );
  private readonly segments = withHiddenTwin(
    new THREE.LineSegments(new THREE.BufferGeometry(), overlayVertexColourLines('visible')),
    overlayVertexColourLines('hidden'),
  );
  /** Number of constraints drawn. */
  count = 0;

  constructor() {
    this.object.name = 'constraints';
    this.object.add(this.segments, this.points);
  }

  update(c: ConstraintArrays | null, grid: GridSpec): void {
    const g = c ? constraintGlyphs(c, grid) : null;
    this.count = c ? c.index.length : 0;
    this.object.visible = this.count > 0;
    setOverlayGeometry(
      this.points,
      g ? flatGeometry(g.points, g.pointColours) : new THREE.BufferGeometry(),
    );
    setOverlayGeometry(
      this.segments,
      g ? flatGeometry(g.segments, g.segmentColours) : new THREE.BufferGeometry(),
    );
  }
}
