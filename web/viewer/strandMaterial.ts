// Hair strands (method S6.1): geometry and shading.
// Shading: the hair BSDF of hairBsdf.ts (Marschner's R, TT and TRT lobes as Unreal evaluates
// them, dual scattering after Zinke 2008 from the hairs between a point and the key light: the
// shadow's optical depth) for a key light fixed in world space (lighting/keyLight.ts), whose
// shadow is the precomputed transmittance of the hair (the `lighting` attribute: transmittance,
// ambient occlusion, from the solver worker: lighting/hairLighting.ts) or, in High, the deep
// opacity maps; a fill light from behind and a sky ambient on the base colour, both scaled by
// the occlusion; root darkening on top. Colour: absorption σa (model/hairLook.ts: melanin,
// redness, dye, grey strands, lighter tips fading in over a length from each strand's tip (the
// `along` attribute's second byte: the distance from the tip), or a direct colour's absorption),
// spread per strand (four seeded random bytes: melanin, hue, where the tip starts to fade,
// roughness).
// Thin strands: each drawn strand stands for several of a head's hairs (representedWidth), and
// is drawn at least a pixel wide with the rest of its width as coverage in alpha, tapering to
// the tip, the tips fading out, blended order-independently without depth writes (hairOit.ts;
// unsorted where the renderer has no half-float targets). Two geometries: GL lines (1 pixel,
// shaded per vertex; the Fast quality), and camera-facing strips (two vertices per point,
// expanded in the vertex shader; alpha-to-coverage with MSAA; the High quality, which also reads deep opacity
// maps: deepOpacity.ts).
import * as THREE from 'three';
import { FILL_LIGHT_DIRECTION, KEY_LIGHT_DIRECTION } from '../lighting/keyLight';
import { strandCount } from '../model/hairArrays';
import { type HairLook, lookUniforms } from '../model/hairLook';
import { DEFAULT_HAIR_COLOR } from '../model/session';
import { HAIR_BSDF_GLSL } from './hairBsdf';
import { OIT_FRAGMENT_GLSL } from './hairOit';
import {
  type LineAttributes,
  lineAttributes,
  lodIndex,
  type PointAttributes,
  pointAttributes,
  TIP_DISTANCE_RANGE,
} from './strandAttributes';

export { LOD_GROUPS } from './strandAttributes';

const commonVertex = /* glsl */ `
attribute vec3 tangent;
attribute vec2 along; // x: 0 root … 1 tip (by point); y: distance from the tip, encoded
attribute vec4 strandRandom;
attribute vec2 lighting;
varying vec3 vTangent;
varying vec3 vWorldPosition;
varying vec2 vAlong; // x: along.x; y: the distance from the tip, world units
varying vec4 vRandom;
varying vec2 vLight;
varying float vCoverage;
// the distance from the tip, world units, of along.y (strandAttributes.ts decodeTipDistance: the
// byte's steps are finest near the tip)
float tipDistanceOf(float encoded) {
  return ${TIP_DISTANCE_RANGE.toFixed(1)} * encoded * encoded;
}
`;

/** Each strand's width is strandWidth times 1 ± WIDTH_VARIATION, from a hash of its four random
 *  bytes (uniform, so the mean width is strandWidth): some strands read finer, some coarser. */
export const WIDTH_VARIATION = 0.4;
const WIDTH_HASH = [0.4142136, 0.7320508, 0.236068, 0.6457513] as const;
const WIDTH_HASH_SCALE = 113.17;

/** The width factor the shaders give a strand of random values `rnd` (each 0..1, as the
 *  normalised `strandRandom` attribute reads): what `widthOf` computes, for tests. */
export function strandWidthFactor(rnd: readonly [number, number, number, number]): number {
  const d = rnd.reduce((a, v, i) => a + v * WIDTH_HASH[i], 0) * WIDTH_HASH_SCALE;
  return 1 + WIDTH_VARIATION * (2 * (d - Math.floor(d)) - 1);
}

/** Where a strand's tip starts to taper and fade, and its width (both shaders of either
 *  geometry). */
const tips = /* glsl */ `
uniform float lengthVariation; // ± shift of where the tip fade starts, per strand
uniform float tipFade; // fraction of the strand over which the tip tapers and fades out
uniform float widthVariation; // ± share of the width, per strand (WIDTH_VARIATION)
// where a strand's tip starts (rnd: its random values; length appearance, ragged ends)
float fadeStartOf(vec4 rnd) {
  return clamp(1.0 - tipFade + lengthVariation * (2.0 * rnd.z - 1.0), 0.3, 0.98);
}
// the strand's width factor, 1 ± widthVariation (strandWidthFactor): a hash of its random values
// other than the colour's (uniform over the strands: the mean width is unchanged)
float widthOf(vec4 rnd) {
  float h = fract(dot(rnd, vec4(${WIDTH_HASH.map((v) => v.toFixed(7)).join(', ')})) * ${WIDTH_HASH_SCALE.toFixed(2)});
  return 1.0 + widthVariation * (2.0 * h - 1.0);
}
`;

/** Uniforms, helpers and shadeStrand(): the shading, shared by the lines' vertex shader and
 *  the strips' fragment shader. */
const shading = /* glsl */ `
uniform vec3 rootSigma; // absorption at the root (melanin.ts; from the colour for a direct colour)
uniform vec3 tipSigma; // absorption at the tips (the lighter tips' colour)
uniform vec3 greySigma; // absorption of a grey (unpigmented) strand
// grey share, an older session's tip start along the strand (>= 1: none; else tipLength), melanin
// and roughness variation
uniform vec4 lookShares;
uniform float tipLength; // the lighter tips' length from the tip, world units (0: none)
uniform float roughness; // longitudinal roughness β of the hair BSDF
uniform float bsdfGain; // the key light's radiance per unit of the BSDF
uniform vec3 keyDirection; // world space, towards the light (fixed: not the camera's)
uniform vec3 keyColor;
uniform vec3 fillDirection;
uniform vec3 fillColor;
uniform vec3 ambientColor;
uniform vec3 headCenter; // strand normals point away from it
uniform float rootDarkening; // roots are darker by this fraction
uniform float hueVariation; // ± red/blue balance per strand
// the largest tilt of a strand's shading tangent towards its normal (about 8 degrees)
const float HIGHLIGHT_TILT = 0.14;
uniform float precomputed; // 1: use the precomputed lighting attribute; 0: ignore it (all lit)
#ifdef DEEP_OPACITY
uniform sampler2D domDepth;
uniform sampler2D domOpacity;
uniform mat4 domMatrix; // world -> the light's clip space
uniform vec3 domLayers; // far ends of the 3 layers past the first hair, world units
uniform float domRange; // world depth of the light camera's [0, 1]
uniform float domKappa; // optical depth per unit of accumulated opacity
uniform float domBias; // world units
#endif
${HAIR_BSDF_GLSL}
${tips}

#ifdef DEEP_OPACITY
// Yuksel & Keyser 2008: the opacity accumulated between the first hair seen from the light and
// this point, interpolated between the 3 layers' cumulative values.
float deepOpacityTransmittance(vec3 world) {
  vec4 p = domMatrix * vec4(world, 1.0);
  vec3 q = p.xyz / p.w * 0.5 + 0.5;
  if (q.x <= 0.0 || q.y <= 0.0 || q.x >= 1.0 || q.y >= 1.0) return 1.0;
  float z0 = texture2D(domDepth, q.xy).r;
  float d = (q.z - z0) * domRange - domBias;
  if (d <= 0.0) return 1.0;
  vec3 o = texture2D(domOpacity, q.xy).rgb;
  float opacity;
  if (d < domLayers.x) opacity = o.r * d / domLayers.x;
  else if (d < domLayers.y) opacity = mix(o.r, o.g, (d - domLayers.x) / (domLayers.y - domLayers.x));
  else if (d < domLayers.z) opacity = mix(o.g, o.b, (d - domLayers.y) / (domLayers.z - domLayers.y));
  else opacity = o.b;
  return exp(-domKappa * opacity);
}
#endif


// The tip colour's share (hairLook.ts tipShare): fading in over tipLength from the strand's tip
// (tipDistance, world units), or an older session's fraction of the strand (along: 0 root … 1
// tip).
float tipShare(float along, float tipDistance) {
  if (lookShares.y < 0.999) return smoothstep(lookShares.y, 1.0, along);
  return tipLength > 0.0 ? 1.0 - smoothstep(0.0, tipLength, tipDistance) : 0.0;
}

// The strand's absorption at \`along\` (x: 0 root … 1 tip; y: distance from the tip, world
// units; rnd: its seeded random values): root → lighter tips, grey strands, a seeded spread of
// melanin and a little of the red/blue balance.
vec3 strandSigma(vec4 rnd, vec2 along) {
  vec3 s = mix(rootSigma, tipSigma, tipShare(along.x, along.y));
  float pick = fract(dot(rnd, vec4(0.7548777, 0.5698403, 0.3308946, 0.1234567)) * 97.31);
  if (pick < lookShares.x) s = greySigma;
  float hue = hueVariation * (2.0 * rnd.y - 1.0);
  return s * (1.0 + lookShares.z * (2.0 * rnd.x - 1.0)) * vec3(1.0 - hue, 1.0, 1.0 + hue);
}

// The strand's colour at world point P with unit tangent T (root -> tip); along as strandSigma's.
vec3 shadeStrand(vec3 T, vec3 P, vec2 along, vec4 rnd, vec2 light) {
  vec3 V = normalize(cameraPosition - P);
  vec3 radial = P - headCenter;
  vec3 N = radial - T * dot(radial, T);
  N = dot(N, N) > 1e-10 ? normalize(N) : V;
  vec3 sigma = strandSigma(rnd, along);
  // the shading tangent tilted towards N per strand and along it (shifted tangents, Scheuermann
  // 2004): a head's hairs are not parallel (cuticle tilt, waves, strands crossing), so the key
  // light's highlight breaks into strands instead of lying on the hair as one smooth band that
  // rings a whorl (read as a cowlick) or outlines a fringe
  float tilt = HIGHLIGHT_TILT * ((2.0 * fract(rnd.w * 13.71 + rnd.x * 3.17) - 1.0)
    + 0.5 * sin(along.y * 25.0 + 6.2832 * rnd.z));
  vec3 Ts = normalize(T + tilt * N);
  float beta = roughness * (1.0 + lookShares.w * (2.0 * fract(rnd.w * 7.31) - 1.0));

  float shadow = mix(1.0, light.x, precomputed);
  float ao = mix(1.0, light.y, precomputed);
#ifdef DEEP_OPACITY
  // the deep opacity maps, per pixel, in place of the precomputed grid's (which blurs a strand
  // over a cell: the two together count the hairs in front twice)
  shadow = deepOpacityTransmittance(P);
#endif
  // root darkening: occlusion towards the scalp, on top of the hair's own occlusion
  float rootAo = mix(1.0 - rootDarkening, 1.0, smoothstep(0.0, 0.3, along.x));
  vec3 key = keyColor * bsdfGain * hairBsdf(Ts, keyDirection, V, sigma, beta, shadow);
  // fill and sky: the base colour (what a head of this hair scatters back), occluded
  vec3 base = hairBaseColor(sigma);
  float TF = dot(T, fillDirection);
  float fill = mix(0.3, 1.0, sqrt(max(0.0, 1.0 - TF * TF)));
  float sky = 0.65 + 0.35 * N.y;
  return rootAo * (key + ao * (fillColor * fill + ambientColor * sky) * base);
}
`;

/** Lines shade per vertex (the strand is a 1-pixel line: the only interpolation is along
 *  segments a few pixels long), so a fragment costs no more than a flat colour. */
const linesVertexShader = /* glsl */ `
${commonVertex}
${shading}
uniform float strandWidth; // world units at the root (representedWidth)
uniform float tipWidth; // fraction of strandWidth at the tip (the width tapers over the tip fade)
uniform float viewportHeight; // pixels of the target being drawn
varying vec3 vColor;
varying float vFadeStart; // vCoverage: commonVertex's
varying float vDistance; // from the camera (the order-independent pass's weight)
void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
  vec3 T = normalize(mat3(modelMatrix) * tangent);
  vAlong = vec2(along.x, tipDistanceOf(along.y));
#ifdef HAIR_FRONT
  vColor = vec3(0.0); // the front pass needs the distance only (hairOit.ts)
#else
  vColor = shadeStrand(T, world.xyz, vAlong, strandRandom, lighting);
#endif
  // a line is one pixel wide: its opacity is the strand's true coverage of that pixel (as the
  // strips' width / drawn width), tapering to the tip
  float dist = length(cameraPosition - world.xyz);
  vDistance = dist;
  float pixel = 2.0 * dist / (projectionMatrix[1][1] * max(viewportHeight, 1.0));
  if (projectionMatrix[3][3] > 0.5) pixel = 2.0 / (projectionMatrix[1][1] * max(viewportHeight, 1.0));
  float width = strandWidth * widthOf(strandRandom) * mix(1.0, tipWidth, smoothstep(fadeStartOf(strandRandom), 1.0, along.x));
  vCoverage = min(1.0, width / pixel);
  vFadeStart = fadeStartOf(strandRandom);
  gl_Position = projectionMatrix * viewMatrix * world;
}
`;

const linesFragmentShader = /* glsl */ `
varying vec3 vColor;
varying vec2 vAlong;
varying float vCoverage;
varying float vFadeStart;
varying float vDistance;
#ifdef HAIR_OIT
${OIT_FRAGMENT_GLSL}
#endif
void main() {
  // coverage times the tip's fade, blended order-independently (HAIR_OIT: hairOit.ts) or
  // unsorted, without depth writes
  float alpha = vCoverage * (1.0 - smoothstep(vFadeStart, 1.0, vAlong.x));
  if (alpha < 0.004) discard;
#ifdef HAIR_OIT
  oitWrite(vColor, alpha, vDistance);
#else
  gl_FragColor = vec4(vColor, alpha);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
#endif
}
`;

/** Strip expansion: vertex 2i and 2i + 1 are the two sides of point i (gl_VertexID parity). In
 *  the deep-opacity passes (DOM_PASS) the strip faces the light instead of the camera. */
const stripsVertexShader = /* glsl */ `
${commonVertex}
${tips}
uniform float strandWidth; // world units at the root
uniform float tipWidth; // fraction of strandWidth at the tip (the width tapers over the tip fade)
uniform float viewportHeight; // pixels of the target being drawn
#ifdef DOM_PASS
uniform vec3 domViewDirection; // towards the light
uniform float domPixelSize; // world units per map texel
#endif

void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
  vec3 T = normalize(mat3(modelMatrix) * tangent);
#ifdef DOM_PASS
  vec3 V = domViewDirection;
  float pixel = domPixelSize;
#else
  vec3 toEye = cameraPosition - world.xyz;
  float dist = length(toEye);
  vec3 V = toEye / max(dist, 1e-6);
  // world size of a pixel at this distance (perspective: 2 d tan(fov / 2) / height)
  float pixel = 2.0 * dist / (projectionMatrix[1][1] * max(viewportHeight, 1.0));
  if (projectionMatrix[3][3] > 0.5) pixel = 2.0 / (projectionMatrix[1][1] * max(viewportHeight, 1.0));
#endif
  vec3 side = cross(T, V);
  float sl = length(side);
  side = sl > 1e-4 ? side / sl : normalize(cross(T, abs(T.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
  float width = strandWidth * widthOf(strandRandom) * mix(1.0, tipWidth, smoothstep(fadeStartOf(strandRandom), 1.0, along.x));
  float drawn = max(width, pixel);
  float s = (gl_VertexID % 2 == 0) ? -0.5 : 0.5;
  world.xyz += side * (s * drawn);
  vWorldPosition = world.xyz;
  vTangent = T;
  vAlong = vec2(along.x, tipDistanceOf(along.y)); // linear along a segment, as the distance is
  vRandom = strandRandom;
  vLight = lighting;
  vCoverage = width / drawn;
  gl_Position = projectionMatrix * viewMatrix * world;
}
`;

/** Strips shade per fragment (wide strands on a GPU). HAIR_OIT: the order-independent pass's
 *  two outputs instead of a colour (hairOit.ts). */
const stripsFragmentShader = /* glsl */ `
${shading}
varying vec3 vTangent;
varying vec3 vWorldPosition;
varying vec2 vAlong;
varying vec4 vRandom;
varying vec2 vLight;
varying float vCoverage;
#ifdef HAIR_OIT
${OIT_FRAGMENT_GLSL}
#endif

void main() {
  float alpha = vCoverage * (1.0 - smoothstep(fadeStartOf(vRandom), 1.0, vAlong.x));
#ifdef ALPHA_TO_COVERAGE
  if (alpha < 0.02) discard;
#else
  if (alpha < 0.004) discard;
#endif
#ifdef HAIR_FRONT
  vec3 color = vec3(0.0); // the front pass needs the distance only (hairOit.ts)
#else
  vec3 color = shadeStrand(normalize(vTangent), vWorldPosition, vAlong, vRandom, vLight);
#endif
#ifdef HAIR_OIT
  oitWrite(color, alpha, length(cameraPosition - vWorldPosition));
#else
  // without multisampling and without the order-independent pass: blended unsorted, no depth
  // writes
  gl_FragColor = vec4(color, alpha);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
#endif
}
`;

export interface StrandMaterialOptions {
  color?: THREE.ColorRepresentation; // direct hair colour (CSS string, hex number or THREE.Color)
  look?: HairLook | null; // the colour model (hairLook.ts); null or absent: the direct colour
  lightDirection?: readonly [number, number, number]; // world space, toward the key light
  lightColor?: THREE.ColorRepresentation;
  ambient?: THREE.ColorRepresentation;
  headCenter?: readonly [number, number, number];
  /** 'lines' (GL lines, Fast) or 'strips' (camera-facing tapered strips, High). */
  kind?: 'lines' | 'strips';
  /** Strips: alpha-to-coverage (only with a multisampled target; else a dither). */
  alphaToCoverage?: boolean;
  /** Strips: read deep opacity maps (deepOpacity.ts) for the key light's shadow. */
  deepOpacity?: boolean;
}

/** Uniform names of the strand material (all `{ value }` objects, settable at any time). */
export interface StrandUniforms {
  [name: string]: THREE.IUniform;
  rootSigma: THREE.IUniform<THREE.Vector3>;
  tipSigma: THREE.IUniform<THREE.Vector3>;
  greySigma: THREE.IUniform<THREE.Vector3>;
  lookShares: THREE.IUniform<THREE.Vector4>;
  tipLength: THREE.IUniform<number>;
  roughness: THREE.IUniform<number>;
  bsdfGain: THREE.IUniform<number>;
  keyDirection: THREE.IUniform<THREE.Vector3>;
  keyColor: THREE.IUniform<THREE.Color>;
  fillDirection: THREE.IUniform<THREE.Vector3>;
  fillColor: THREE.IUniform<THREE.Color>;
  ambientColor: THREE.IUniform<THREE.Color>;
  headCenter: THREE.IUniform<THREE.Vector3>;
  rootDarkening: THREE.IUniform<number>;
  hueVariation: THREE.IUniform<number>;
  lengthVariation: THREE.IUniform<number>;
  widthVariation: THREE.IUniform<number>;
  tipFade: THREE.IUniform<number>;
  precomputed: THREE.IUniform<number>;
  strandWidth: THREE.IUniform<number>;
  tipWidth: THREE.IUniform<number>;
  viewportHeight: THREE.IUniform<number>;
}

export type StrandMaterial = THREE.ShaderMaterial & { uniforms: StrandUniforms };

/** A hair's width, world units (1 unit = 10 cm): 75 µm, a medium human hair. */
export const HAIR_WIDTH = 0.00075;
/** Hairs on a head: about 100,000 (90,000 to 150,000 by colour). */
export const HAIRS_ON_A_HEAD = 100_000;
/** The widest a drawn strand gets (world units, 1.2 mm): a sparse sample stays strands, not
 *  ribbons. */
const MAX_STRAND_WIDTH = 0.012;

/** The width each of `drawn` strands is drawn at (world units, at the root): together they
 *  cover what a head's hairs cover, so the hair's density does not depend on how many strands
 *  are grown or, while the view moves, on how sparse a sample of them is drawn (Unreal widens
 *  a decimated groom's strands the same way). At least one hair's width, at most
 *  MAX_STRAND_WIDTH. */
export function representedWidth(drawn: number): number {
  const hairs = HAIRS_ON_A_HEAD / Math.max(drawn, 1);
  return Math.min(MAX_STRAND_WIDTH, HAIR_WIDTH * Math.max(1, hairs));
}

/** Strands a draw of `geometry` (a strand geometry: userData.strands, lodCounts) covers: its
 *  draw range's share of the index (prefixes are even samples of the strands). */
export function drawnStrands(geometry: THREE.BufferGeometry): number {
  const strands = (geometry.userData.strands as number | undefined) ?? 0;
  const all = geometry.index?.count ?? 0;
  if (all === 0) return strands;
  return (strands * Math.min(geometry.drawRange.count, all)) / all;
}

/** Key light radiance per unit of the hair BSDF (hairBsdf.ts), chosen by eye against the head's
 *  lighting: a mid-brown outer layer about as bright as the Kajiya–Kay shading it replaced. */
export const BSDF_GAIN = 3;

const viewport = new THREE.Vector4();

export function createStrandMaterial(options: StrandMaterialOptions = {}): StrandMaterial {
  const light = options.lightDirection ?? KEY_LIGHT_DIRECTION;
  const center = options.headCenter ?? [0, 0, 0];
  const strips = options.kind === 'strips';
  const uniforms: StrandUniforms = {
    rootSigma: { value: new THREE.Vector3() },
    tipSigma: { value: new THREE.Vector3() },
    greySigma: { value: new THREE.Vector3() },
    lookShares: { value: new THREE.Vector4() },
    tipLength: { value: 0 },
    roughness: { value: 0.3 },
    bsdfGain: { value: BSDF_GAIN },
    keyDirection: { value: new THREE.Vector3(...light).normalize() },
    keyColor: { value: new THREE.Color(options.lightColor ?? '#fff6ea').multiplyScalar(1.05) },
    fillDirection: { value: new THREE.Vector3(...FILL_LIGHT_DIRECTION).normalize() },
    fillColor: { value: new THREE.Color('#9db4d6').multiplyScalar(0.45) },
    ambientColor: { value: new THREE.Color(options.ambient ?? '#b4aca4').multiplyScalar(0.55) },
    headCenter: { value: new THREE.Vector3(...center) },
    rootDarkening: { value: 0.3 },
    hueVariation: { value: 0.05 },
    lengthVariation: { value: 0.06 },
    widthVariation: { value: WIDTH_VARIATION },
    tipFade: { value: 0.12 },
    precomputed: { value: 1 },
    strandWidth: { value: representedWidth(30_000) }, // set per draw
    tipWidth: { value: 0.25 },
    viewportHeight: { value: 750 },
  };
  const defines: Record<string, string> = {};
  if (options.deepOpacity) defines.DEEP_OPACITY = '';
  if (strips && options.alphaToCoverage) defines.ALPHA_TO_COVERAGE = '';
  if (!strips) defines.HAIR_CHEAP = ''; // per vertex: the cheaper dual scattering
  const material = new THREE.ShaderMaterial({
    uniforms,
    defines,
    vertexShader: strips ? stripsVertexShader : linesVertexShader,
    fragmentShader: strips ? stripsFragmentShader : linesFragmentShader,
  });
  material.name = strips ? 'HairStrips' : 'HairLines';
  setHairLook(material as StrandMaterial, options.look ?? null, colorCss(options.color));
  if (strips) {
    material.side = THREE.DoubleSide;
    material.alphaToCoverage = !!options.alphaToCoverage;
  }
  if (!strips || !options.alphaToCoverage) {
    material.transparent = true;
    material.depthWrite = false;
  }
  // the strands' width stands for the hairs of a head (representedWidth: the fewer drawn, the
  // wider each), and a strip's width and a line's coverage depend on the target's pixel size
  material.onBeforeRender = (renderer, _scene, _camera, geometry) => {
    renderer.getCurrentViewport(viewport);
    uniforms.viewportHeight.value = viewport.w;
    uniforms.strandWidth.value = representedWidth(drawnStrands(geometry));
  };
  return material as StrandMaterial;
}

function colorCss(c: THREE.ColorRepresentation | undefined): string {
  if (c === undefined) return DEFAULT_HAIR_COLOR;
  return `#${new THREE.Color(c).getHexString()}`;
}

/** Sets the hair's colour model (hairLook.ts; null: the direct colour `hairColor`, #rrggbb). */
export function setHairLook(
  material: StrandMaterial,
  look: HairLook | null,
  hairColor: string,
): void {
  const v = lookUniforms(look, hairColor);
  const u = material.uniforms;
  u.rootSigma.value.set(...v.rootSigma);
  u.tipSigma.value.set(...v.tipSigma);
  u.greySigma.value.set(...v.greySigma);
  u.lookShares.value.set(...v.shares);
  u.tipLength.value = v.tipLength;
  u.roughness.value = v.roughness;
}

/** Set a direct hair colour (CSS string, hex number or THREE.Color): no colour model. */
export function setHairColor(material: StrandMaterial, color: THREE.ColorRepresentation): void {
  setHairLook(material, null, colorCss(color));
}

/** Set the key light direction (world space, toward the light; need not be unit). */
export function setLightDirection(material: StrandMaterial, x: number, y: number, z: number): void {
  material.uniforms.keyDirection.value.set(x, y, z).normalize();
}

function setBounds(geometry: THREE.BufferGeometry, b: Float32Array): void {
  // bounds from the attribute loop (three's computeBoundingSphere takes ~40× longer on 4M
  // points); the sphere around the box is conservative, which is all culling and picking need
  if (b.length < 6) {
    geometry.boundingBox = new THREE.Box3();
    geometry.boundingSphere = new THREE.Sphere(new THREE.Vector3(), 0);
    return;
  }
  const box = new THREE.Box3(
    new THREE.Vector3(b[0], b[1], b[2]),
    new THREE.Vector3(b[3], b[4], b[5]),
  );
  geometry.boundingBox = box;
  const center = box.getCenter(new THREE.Vector3());
  const size = box.getSize(new THREE.Vector3());
  geometry.boundingSphere = new THREE.Sphere(center, 0.5 * size.length());
}

/** Build indexed LineSegments geometry for strands. Strand s owns points
 *  strandStart[s] .. strandStart[s + 1] − 1 of `points` (points[3 * point + axis]); each pair of
 *  consecutive points is a segment. The `position` attribute views `points` (not copied: do not
 *  change it afterwards). Added per point (strandAttributes.ts): `tangent`, `along` (the place
 *  along the strand and the distance from its tip), `strandRandom` (a hash of the strand index
 *  and `colorSeed`) and `lighting` (from `lighting`, 2 per point as protocol.ts
 *  HairLightingArrays.strand; 1, 1 without it), all normalised.
 *  `prebuilt`: those attributes and the index as lineAttributes made them for these strands
 *  (by the worker), used as they are. Level of detail: any prefix of the index's groups is an
 *  even sample of the whole head of hair; `userData.lodCounts[g]` is the index count of the first
 *  g groups (a draw range), `userData.strands` the number of strands. */
export function buildStrandGeometry(
  points: Float32Array,
  strandStart: Uint32Array,
  colorSeed = 0,
  lighting: Float32Array | null = null,
  prebuilt: LineAttributes | null = null,
): THREE.BufferGeometry {
  const attrs = prebuilt ?? lineAttributes(points, strandStart, colorSeed, lighting);
  const { pointCount, index, lodCounts } = attrs;
  const geometry = new THREE.BufferGeometry();
  geometry.userData.lodCounts = lodCounts;
  geometry.userData.strands = strandCount({ points, strandStart });
  const used = pointCount === points.length / 3 ? points : points.subarray(0, 3 * pointCount);
  geometry.setAttribute('position', new THREE.BufferAttribute(used, 3));
  setPointAttributes(geometry, attrs);
  geometry.setIndex(new THREE.BufferAttribute(index, 1));
  setBounds(geometry, attrs.box);
  return geometry;
}

function setPointAttributes(
  geometry: THREE.BufferGeometry,
  attrs: Pick<PointAttributes, 'tangent' | 'along' | 'random' | 'light'>,
): void {
  geometry.setAttribute('tangent', new THREE.BufferAttribute(attrs.tangent, 3, true));
  geometry.setAttribute('along', new THREE.BufferAttribute(attrs.along, 2, true));
  geometry.setAttribute('strandRandom', new THREE.BufferAttribute(attrs.random, 4, true));
  geometry.setAttribute('lighting', new THREE.BufferAttribute(attrs.light, 2, true));
}

/** Strip geometry for the same strands: point i becomes vertices 2i and 2i + 1 (the two sides,
 *  by gl_VertexID parity; same attributes as buildStrandGeometry, each twice) and each segment
 *  two triangles. The index lists strands in the same level-of-detail order, with
 *  `userData.lodCounts` (6 index entries per segment). */
export function buildStrandStripGeometry(
  points: Float32Array,
  strandStart: Uint32Array,
  colorSeed = 0,
  lighting: Float32Array | null = null,
  prebuilt: PointAttributes | null = null,
): THREE.BufferGeometry {
  const attrs = prebuilt ?? pointAttributes(points, strandStart, colorSeed, lighting);
  const { pointCount } = attrs;
  const twice = <T extends Int8Array | Uint8Array | Float32Array>(src: T, size: number): T => {
    const out = new (src.constructor as { new (n: number): T })(2 * src.length);
    for (let i = 0; i < pointCount; i++)
      for (let c = 0; c < size; c++) {
        const v = src[size * i + c];
        out[2 * size * i + c] = v;
        out[2 * size * i + size + c] = v;
      }
    return out;
  };
  // vertices 2i, 2i + 1 are point i's two sides: two triangles per segment
  const { index, lodCounts } = lodIndex(strandStart, [0, 1, 2, 1, 3, 2], 2);
  const geometry = new THREE.BufferGeometry();
  geometry.userData.lodCounts = lodCounts;
  geometry.userData.strands = strandCount({ points, strandStart });
  geometry.setAttribute(
    'position',
    new THREE.BufferAttribute(twice(points.subarray(0, 3 * pointCount), 3), 3),
  );
  setPointAttributes(geometry, {
    tangent: twice(attrs.tangent, 3),
    along: twice(attrs.along, 2),
    random: twice(attrs.random, 4),
    light: twice(attrs.light, 2),
  });
  geometry.setIndex(new THREE.BufferAttribute(index, 1));
  setBounds(geometry, attrs.box);
  return geometry;
}
