// How lines and points drawn over the head and hair (style curves, the stroke being drawn, ponytail
// guides, constraint and field glyphs, the box) meet the depth buffer. Every overlay is drawn in
// two passes of the same geometry, both after the head and hair (the settled hair's depth is
// its fragments' weighted mean where it covers half a pixel or more: hairOit.ts; a stroke's
// previews and the sample drawn while the view moves write none, so there a curve under the
// hair is drawn in full):
//   - hidden: depthFunc GreaterDepth at low opacity, so the parts behind the head or hair stay
//     visible but faint (a curve behind the head no longer looks as if it ran over the face);
//   - visible: depth-tested as usual, in full colour.
// Both passes move each vertex a little towards the eye (OVERLAY_DEPTH_BIAS world units along the
// view ray, which leaves its place on screen unchanged), so curves lying on the scalp neither
// z-fight with it nor vanish into it. Polygon offset would not do: it applies to triangles only.
// Materials are shared and never disposed: a disposed material releases its shader program, and
// compiling it again stalls on the GPU (seconds behind a software rasteriser).

import * as THREE from 'three';
import { kindDef } from '../model/kinds';
import { shared } from './displayMaterials';

/** What kind of overlay line a colour is for. */
export type OverlayKind =
  | 'stream'
  | 'dividing'
  | 'ponytail' // a ponytail's spine
  | 'ponytailGuide' // its strokes and circles
  | 'draft' // the stroke being drawn
  | 'selected'; // the selected curve, whatever its type

/** sRGB colour (0xRRGGBB) of each kind: distinct hues that read against skin, hair and the grey
 *  background. */
export const OVERLAY_RGB: Readonly<Record<OverlayKind, number>> = {
  stream: 0x00b7d4, // cyan
  dividing: 0xff2f86, // pink
  ponytail: 0x7a3cff, // violet
  ponytailGuide: 0xc58aff, // light purple (the purple circles of docs/user-guide.md)
  draft: 0x1f6bff, // blue
  selected: 0xffc400, // amber
};

/** The scalp brush's ring (overlayLayer.ts setBrushRing): the draft's blue while it paints, red
 *  while it erases. */
export const BRUSH_RING_RGB = { paint: OVERLAY_RGB.draft, erase: 0xff3b30 } as const;

/** Colour of a session curve of `type` (selected or not). Unknown types draw as stream curves. */
export function curveRgb(type: string | undefined, selected: boolean): number {
  if (selected) return OVERLAY_RGB.selected;
  // every tie (ponytail, braid, bun) in the ponytail's colour
  const role = kindDef(type)?.role;
  return role === 'parting'
    ? OVERLAY_RGB.dividing
    : role === 'tie'
      ? OVERLAY_RGB.ponytail
      : OVERLAY_RGB.stream;
}

/** Opacity of the hidden (behind head or hair) pass. */
export const HIDDEN_OPACITY = 0.3;
/** Opacity of the selected curve's hidden pass: it stays easy to follow under the hair. */
export const SELECTED_HIDDEN_OPACITY = 0.65;

/** World units each overlay vertex moves towards the eye for depth testing (~a sixth of the 25K
 *  grid step: enough to clear the polygonised scalp under a curve drawn on it, far less than the
 *  head's thickness). Shared by every overlay material; settable at run time. */
export const OVERLAY_DEPTH_BIAS: THREE.IUniform<number> = { value: 0.02 };

export type OverlayPass = 'visible' | 'hidden';

/** renderOrder of each pass (transparent objects draw by renderOrder after the opaque ones); the
 *  selected curve and the draft are drawn after the other curves. */
export const OVERLAY_ORDER = { hidden: 10, visible: 11, selected: 12, draft: 13 } as const;

/** Depth settings of a pass: the hidden pass shows only what something opaque is in front of. */
export function passDepth(
  pass: OverlayPass,
  hiddenOpacity = HIDDEN_OPACITY,
): {
  depthFunc: THREE.DepthModes;
  opacity: number;
} {
  return pass === 'hidden'
    ? { depthFunc: THREE.GreaterDepth, opacity: hiddenOpacity }
    : { depthFunc: THREE.LessEqualDepth, opacity: 1 };
}

/** A view-space point moved `bias` towards the eye (at the origin) along its view ray, as
 *  DEPTH_BIAS_GLSL does; never past the eye. */
export function biasTowardsEye(v: readonly [number, number, number], bias: number): number[] {
  const len = Math.hypot(v[0], v[1], v[2]);
  const k = Math.max(0, 1 - bias / Math.max(len, 1e-6));
  return [v[0] * k, v[1] * k, v[2] * k];
}

/** Vertex shader lines moving a vertex `bias` towards the eye along its view ray: view-space
 *  positions scale about the eye, so the projected x/y stay put and only the depth changes. */
export const DEPTH_BIAS_GLSL = `
  gl_Position = projectionMatrix * vec4(
    mvPosition.xyz * max(0.0, 1.0 - overlayDepthBias / max(length(mvPosition.xyz), 1e-6)),
    mvPosition.w);`;

/** Makes `m` an overlay material of `pass`: transparent (drawn after opaque objects), not writing
 *  depth, depth-tested by the pass's rule, and biased towards the eye. */
function asOverlay<M extends THREE.Material>(
  m: M,
  pass: OverlayPass,
  hiddenOpacity = HIDDEN_OPACITY,
): M {
  const { depthFunc, opacity } = passDepth(pass, hiddenOpacity);
  m.transparent = true;
  m.depthWrite = false;
  m.depthTest = true;
  m.depthFunc = depthFunc;
  m.opacity = opacity;
  m.onBeforeCompile = (shader) => {
    shader.uniforms.overlayDepthBias = OVERLAY_DEPTH_BIAS;
    shader.vertexShader = `uniform float overlayDepthBias;\n${shader.vertexShader.replace(
      '#include <project_vertex>',
      `#include <project_vertex>${DEPTH_BIAS_GLSL}`,
    )}`;
  };
  m.customProgramCacheKey = () => 'overlay-depth-bias';
  return m;
}

/** A line material of one colour (sRGB hex) for `pass` (`hiddenOpacity`: the hidden pass's). */
export const overlayLineMaterial = (
  rgb: number,
  pass: OverlayPass,
  hiddenOpacity = HIDDEN_OPACITY,
): THREE.LineBasicMaterial =>
  shared(`line:${rgb}:${pass}:${pass === 'hidden' ? hiddenOpacity : 1}`, () =>
    asOverlay(new THREE.LineBasicMaterial({ color: rgb }), pass, hiddenOpacity),
  );

/** A line material coloured per vertex for `pass`. */
export const overlayVertexColourLines = (pass: OverlayPass): THREE.LineBasicMaterial =>
  shared(`vlines:${pass}`, () =>
    asOverlay(new THREE.LineBasicMaterial({ vertexColors: true }), pass),
  );

/** Round-ish screen-space points coloured per vertex for `pass`. */
export const overlayVertexColourPoints = (pass: OverlayPass): THREE.PointsMaterial =>
  shared(`vpoints:${pass}`, () =>
    asOverlay(
      new THREE.PointsMaterial({ vertexColors: true, size: 5, sizeAttenuation: false }),
      pass,
    ),
  );

type Drawable = THREE.Line | THREE.LineSegments | THREE.Points;

/** Gives `object` (drawn with its visible-pass material) a hidden-pass twin: a child sharing its
 *  geometry, drawn first. `hidden` is the twin's material. Returns `object`. */
export function withHiddenTwin<T extends Drawable>(
  object: T,
  hidden: THREE.Material,
  order: number = OVERLAY_ORDER.visible,
): T {
  const twin =
    object instanceof THREE.Points
      ? new THREE.Points(object.geometry, hidden)
      : object instanceof THREE.LineSegments
        ? new THREE.LineSegments(object.geometry, hidden)
        : new THREE.Line(object.geometry, hidden);
  twin.userData.hiddenTwin = true;
  twin.renderOrder = OVERLAY_ORDER.hidden;
  twin.raycast = () => {}; // picking sees the curve once
  object.renderOrder = order;
  object.add(twin);
  return object;
}

/** Gives `object` (and its hidden twin, if any) new geometry, freeing the old one's GPU buffers
 *  (materials stay). */
export function setOverlayGeometry(object: Drawable, geometry: THREE.BufferGeometry): void {
  const old = object.geometry;
  object.geometry = geometry;
  for (const c of object.children) if (c.userData.hiddenTwin) (c as Drawable).geometry = geometry;
  if (old !== geometry) old.dispose();
}

/** A polyline of `points` in colour `rgb`, drawn by the depth rule above (both passes). */
export function overlayPolyline(
  points: readonly (readonly number[])[],
  rgb: number,
  order: number = OVERLAY_ORDER.visible,
  hiddenOpacity = HIDDEN_OPACITY,
): THREE.Line {
  const arr = new Float32Array(points.length * 3);
  points.forEach((p, i) => {
    arr[3 * i] = p[0];
    arr[3 * i + 1] = p[1];
    arr[3 * i + 2] = p[2];
  });
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(arr, 3));
  return withHiddenTwin(
    new THREE.Line(g, overlayLineMaterial(rgb, 'visible')),
    overlayLineMaterial(rgb, 'hidden', hiddenOpacity),
    order,
  );
}
