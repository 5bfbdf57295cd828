// The strand shaders (method S6.1), GLSL for both geometries: GL lines shaded per vertex (the
// Fast quality) and camera-facing strips expanded in the vertex shader and shaded per fragment
// (High, with deep opacity maps: deepOpacity.ts). Shading: the hair BSDF of hairBsdf.ts for a key
// light fixed in world space, its shadow the precomputed transmittance of the hair (the
// `lighting` attribute) or, in High, the deep opacity maps; a fill light from behind and a sky
// ambient on the base colour, both scaled by the occlusion; root darkening on top. Colour:
// absorption σa (model/hairLook.ts) spread per strand by four seeded random bytes. The tips taper
// and fade; strands are blended order-independently (hairOit.ts). While a motion plays the
// vertex shaders place each point on its guide first (followerGlsl.ts). The material that uses
// them: strandMaterial.ts.
import { GREY_SCATTER } from '../model/colourPlacement';
import { BALAYAGE_FULL, BALAYAGE_LENGTH, BALAYAGE_STRENGTH } from '../model/hairLook';
import { DOM_LAYERED_OPACITY_GLSL } from './deepOpacityGlsl';
import { FOLLOWER_GLSL } from './followerGlsl';
import { HAIR_BSDF_GLSL } from './hairBsdf';
import { OIT_FRAGMENT_GLSL } from './hairOit';
import { MAX_TURN, TIP_DISTANCE_RANGE } from './strandAttributes';
import { WIDTH_HASH, WIDTH_HASH_SCALE } from './strandWidth';

const commonVertex = /* glsl */ `
${FOLLOWER_GLSL}
attribute vec3 tangent;
attribute vec4 along; // x: 0 root … 1 tip (by point); y: distance from the tip, encoded; z: the
// strand's grey rank; w: its balayage section (strandAttributes.ts, colourPlacement.ts)
attribute vec4 strandRandom;
attribute vec2 lighting;
varying vec3 vTangent;
varying vec3 vWorldPosition;
varying vec4 vAlong; // x: along.x; y: the distance from the tip, world units; z, w: along.zw
varying vec4 vRandom;
varying vec2 vLight;
varying float vCoverage;
varying float vTipKeep; // what the strand's end keeps of its width and opacity (tipKeepOf)
varying float vTurn; // the strand's turn at its points (turnOf), for the strips' fragments
// the angle the strand turns between its two segments at a point (radians), from its tangent
// attribute's length (strandAttributes.ts encodeTurn: 1 straight … ½ at MAX_TURN)
float turnOf(vec3 t) {
  return clamp(2.0 * (1.0 - length(t)), 0.0, 1.0) * ${MAX_TURN.toFixed(3)};
}
// the distance from the tip, world units, of along.y (strandAttributes.ts decodeTipDistance: the
// byte's steps are finest near the tip)
float tipDistanceOf(float encoded) {
  return ${TIP_DISTANCE_RANGE.toFixed(1)} * encoded * encoded;
}
`;

/** The longest an end tapers over, world units (1.5 cm): shorter hair tapers over tipFade of its
 *  length. Over 3 cm, long hair's ends read as "see-through, fading into the bust" to three
 *  judges. */
export const TIP_TAPER_MAX = 0.15;

/** Where a strand's end is and how it tapers, and its width (both shaders of either geometry). */
const tips = /* glsl */ `
uniform float lengthVariation; // mean share of a strand's length its end is cut back by
uniform float tipFade; // share of the strand over which its end tapers, at most TIP_TAPER_MAX
uniform float widthVariation; // ± share of the width, per strand (WIDTH_VARIATION)
// the longest taper of an end, world units: 3 cm (a fixed share of the length smeared long hair's
// ends over 6 cm or more, a judge's 'a blurred smear, like motion blur')
const float TIP_TAPER_MAX = ${TIP_TAPER_MAX.toFixed(3)};
// What a strand keeps of its width and opacity at a point x along it (0 root … 1 tip, by point),
// tipDistance from its grown tip (world units): 0 past its end, rising to 1 over its taper. Its
// end is cut back by 0 to twice lengthVariation of its length (mean lengthVariation), mostly by
// its lock (rnd.w, the lock's value: |2w - 1|, so the locks that tilt furthest either way end
// highest) and a little by strand (rnd.z): ends in pieces, not one even fade. The strand's length
// is the distance from the tip over the share of points left (its points are evenly spaced).
float tipKeepOf(vec4 rnd, float x, float tipDistance) {
  if (x > 0.999) return 0.0;
  float len = tipDistance / (1.0 - x);
  float cut = lengthVariation * len * (1.4 * abs(2.0 * rnd.w - 1.0) + 0.6 * rnd.z);
  float taper = max(min(tipFade * len, TIP_TAPER_MAX), 1e-4);
  return smoothstep(cut, cut + taper, tipDistance);
}
// the strand's width factor, 1 ± widthVariation (strandWidthFactor): a hash of its random values
// other than the colour's (uniform over the strands: the mean width is unchanged)
float widthOf(vec4 rnd) {
  float h = fract(dot(rnd, vec4(${WIDTH_HASH.map((v) => v.toFixed(7)).join(', ')})) * ${WIDTH_HASH_SCALE.toFixed(2)});
  return 1.0 + widthVariation * (2.0 * h - 1.0);
}
`;

/** Roots emerge from the skin: a strand's coverage rises from 0 over its first ROOT_FADE (world
 *  units; ROOT_FADE_SHARE of a shorter strand's length, so short hair keeps its body) from the
 *  root, so where roots are seen (a hairline, a parting) the hair thins into the skin instead of
 *  starting at a hard, pencil-drawn edge. along: x 0 root … 1 tip, y the distance from the tip
 *  (world units), so the strand's length is y / (1 − x) and the distance from the root x of it. */
const ROOT_FADE = 0.15;
const ROOT_FADE_SHARE = 0.08;
const rootFade = /* glsl */ `
float rootFadeOf(vec2 along) {
  float len = along.y / max(1.0 - along.x, 1e-3);
  return smoothstep(0.0, min(${ROOT_FADE.toFixed(3)}, ${ROOT_FADE_SHARE.toFixed(3)} * len), along.x * len);
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
// the lock's share of the tilt (in HIGHLIGHT_TILTs)
const float LOCK_TILT = 2.5;
// the lock's brightness, ± this share
const float LOCK_VALUE = 0.15;
// the share of a strand (from the root) over which its lock's tilt and brightness grow in
const float LOCK_FROM = 0.3;
// the fill's sheen, over the fill's brightness (the key's BSDF gain's share of it)
const float FILL_SHEEN = 5.0;
const float FILL_SHEEN_SPREAD = 3.0;
// where the highlights' soft shoulder starts (linear)
const float HIGHLIGHT_KNEE = 0.7;
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
${DOM_LAYERED_OPACITY_GLSL}
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
  return exp(-domKappa * domLayeredOpacity(o, d, domLayers));
}
#endif


// The tip colour's share (hairLook.ts tipShare): a balayage's piece of the strand's own length
// and strength (piece: its seeded value), full over the last BALAYAGE_FULL of that length from
// the tip and fading in over the rest (tipDistance, world units); or an older session's fraction
// of the strand (along: 0 root … 1 tip).
float tipShare(float along, float tipDistance, float piece) {
  if (lookShares.y < 0.999) return smoothstep(lookShares.y, 1.0, along);
  if (tipLength <= 0.0) return 0.0;
  float len = tipLength * (${BALAYAGE_LENGTH[0].toFixed(3)} + ${BALAYAGE_LENGTH[1].toFixed(3)} * piece);
  return (${BALAYAGE_STRENGTH[0].toFixed(3)} + ${BALAYAGE_STRENGTH[1].toFixed(3)} * piece) * (1.0 - smoothstep(${BALAYAGE_FULL.toFixed(3)} * len, len, tipDistance));
}

// The strand's absorption at \`along\` (x: 0 root … 1 tip; y: distance from the tip, world
// units; z, w: its grey rank and balayage section; rnd: its seeded random values): root → lighter tips, grey strands, a seeded spread of
// melanin and a little of the red/blue balance.
vec3 strandSigma(vec4 rnd, vec4 along) {
  // Lighter tips: an older session's fraction, mixed linearly (whatever its length, as
  // hairLook.ts mixAbsorption); else a balayage's piece (tipShare; the strand's section),
  // mixed in log space (a linear mix shows lighter tips only at the last
  // few centimetres). Branches on uniforms: hair without tips does none of it (every preview
  // frame draws this per vertex).
  vec3 s = rootSigma;
  if (lookShares.y < 0.999) {
    s = mix(rootSigma, tipSigma, tipShare(along.x, along.y, 0.0));
  } else if (tipLength > 0.0) {
    // painted in sections (along.w: the strand's section, colourPlacement.ts, a byte's middle)
    float piece = (255.0 * along.w + 0.5) / 256.0;
    s = exp(mix(log(max(rootSigma, 1e-4)), log(max(tipSigma, 1e-4)), tipShare(along.x, along.y, piece)));
  }
  // grey strands by their rank (along.z, a byte's middle: colourPlacement.ts, temples first,
  // in fine streaks), so a share g greys the strands ranked below it; as most of the hair turns
  // grey, more of the strands by their own even value (colourPlacement.ts greyPick). Branches on
  // uniforms: hair without grey does none of it
  if (lookShares.x > 0.0) {
    float pick = (255.0 * along.z + 0.5) / 256.0;
    if (lookShares.x > ${GREY_SCATTER[0].toFixed(2)} && fract(dot(rnd, vec4(0.4142136, 0.7320508, 0.2360680, 0.6457513)) * 53.71) < smoothstep(${GREY_SCATTER[0].toFixed(2)}, ${GREY_SCATTER[1].toFixed(2)}, lookShares.x))
      pick = fract(dot(rnd, vec4(0.7548777, 0.5698403, 0.3308946, 0.1234567)) * 97.31);
    if (pick < lookShares.x) s = greySigma;
  }
  float hue = hueVariation * (2.0 * rnd.y - 1.0);
  return s * (1.0 + lookShares.z * (2.0 * rnd.x - 1.0)) * vec3(1.0 - hue, 1.0, 1.0 + hue);
}

// The strand's colour at world point P with unit tangent T (root -> tip); along as strandSigma's.
vec3 shadeStrand(vec3 T, vec3 P, vec4 along, vec4 rnd, vec2 light, float turn) {
  vec3 V = normalize(cameraPosition - P);
  vec3 radial = P - headCenter;
  vec3 N = radial - T * dot(radial, T);
  N = dot(N, N) > 1e-10 ? normalize(N) : V;
  vec3 sigma = strandSigma(rnd, along);
  // the shading tangent tilted towards N per strand and along it (shifted tangents, Scheuermann
  // 2004): a head's hairs are not parallel (cuticle tilt, waves, strands crossing), so the key
  // light's highlight breaks into strands instead of lying on the hair as one smooth band that
  // rings a whorl (read as a cowlick) or outlines a fringe
  // mostly by lock (rnd.w: strandAttributes.ts lockNoise of the root), so whole locks catch the
  // light together and the highlight shows locks; a little by strand, and along it. Locks form
  // away from the root (hair combed flat at the hairline lies as one): the lock's share grows
  // over the first LOCK_FROM of the strand (at the root a pulled-back hairline drew lock streaks
  // into the skin's edge)
  float lockShare = smoothstep(0.0, LOCK_FROM, along.x) * (2.0 * rnd.w - 1.0);
  float tilt = HIGHLIGHT_TILT * (LOCK_TILT * lockShare
    + 0.5 * (2.0 * fract(rnd.x * 13.71 + rnd.y * 3.17) - 1.0)
    + 0.5 * sin(along.y * 25.0 + 6.2832 * rnd.z));
  vec3 Ts = normalize(T + tilt * N);
  float beta = roughness * (1.0 + lookShares.w * (2.0 * fract(rnd.w * 7.31) - 1.0));
  // widened by the angle the strand turns between its points (the lobe at least as wide as the
  // steps it is sampled at, as a pixel's footprint widens a lobe by the normals it spans): a tight
  // curl's narrow highlight, shaded at its points, lit a few of them as sparks (a judge: 'white
  // glitter specks all over' coily hair; bright specks in a close-up of the library's coily from
  // the front, Fast: 1,044 pixels before, 525 after)
  beta = sqrt(beta * beta + turn * turn);

  float shadow = mix(1.0, light.x, precomputed);
  float ao = mix(1.0, light.y, precomputed);
#ifdef DEEP_OPACITY
  // the deep opacity maps, per pixel, in place of the precomputed grid's (which blurs a strand
  // over a cell: the two together count the hairs in front twice)
  shadow = deepOpacityTransmittance(P);
#endif
  // the head's terminator, soft, in both qualities: light reaching round the head falls off over
  // the hair lying on it (wrapped as light scattered through a head of hair is), so High's
  // hard-edged head shadow in the maps meets hair already in half light instead of drawing a
  // line across the back, and Fast's back is as dark as High's (the same look in both); wrapped
  // from N.L -1.1 to 0.7: from -0.2 to 0.5 the light ended over the crown's tight curve, a lit
  // cap with a hard rim on the back of long hair. It scales the key's light (hairBsdf's headT),
  // not the hair's transmittance: as hairs crossed, the light scattered forward round the head
  // kept only its red on dark hair (a red band down a brown bob's side); wrapped from -0.7 there
  // as before, the back lost that glow's light and Silver read grey (value 0.51)
  // Only hair lying on the head: the terminator fades out over the lengths hanging free of it
  // (from 16 to 34 cm from its centre), whose shadow the grid and the maps give. Taken from
  // their direction from the centre, long hair's lengths behind the shoulders were lit by the
  // cool fill alone: the lighter ends read as "a drab olive ombre", no lighter than the roots
  float headSide = mix(smoothstep(-1.1, 0.7, dot(N, keyDirection)), 1.0,
    smoothstep(1.6, 3.4, length(radial)));
  // root darkening: occlusion towards the scalp, on top of the hair's own occlusion
  float rootAo = mix(1.0 - rootDarkening, 1.0, smoothstep(0.0, 0.3, along.x));
  vec3 key = keyColor * bsdfGain * hairBsdf(Ts, keyDirection, V, sigma, beta, shadow, headSide);
  // fill and sky: the base colour (what a head of this hair scatters back), occluded
  vec3 base = hairBaseColor(sigma);
  float TF = dot(T, fillDirection);
  float fill = mix(0.3, 1.0, sqrt(max(0.0, 1.0 - TF * TF)));
  float sky = 0.65 + 0.35 * N.y;
  // the fill's sheen: its primary reflection, white, where the hair turns towards it (from
  // behind, dark hair lit by the fill alone was a black shell with no strand showing)
  // its lobe FILL_SHEEN_SPREAD times as wide as the key's: as sharp as the key's it drew a thin
  // grey-blue line across the side of long hair where the strands turn through the mirror angle
  float sheen = FILL_SHEEN * dot(fillColor, vec3(0.2126, 0.7152, 0.0722))
    * hairR(Ts, fillDirection, V, FILL_SHEEN_SPREAD * beta);
  // locks lighter and darker (rnd.w, the lock's value as for the tilt): a head of hair's locks
  // lie at different depths and angles, so they differ in brightness as a whole
  float lockValue = 1.0 + LOCK_VALUE * lockShare;
  vec3 c = lockValue * rootAo * (key + ao * ((fillColor * fill + ambientColor * sky) * base + sheen));
  // a soft shoulder over the top of the range (linear, per channel): light hair's brightest
  // highlights roll off instead of clipping to flat white
  vec3 over = max(c - HIGHLIGHT_KNEE, 0.0);
  return min(c, HIGHLIGHT_KNEE) + (1.0 - HIGHLIGHT_KNEE) * (1.0 - exp(-over / (1.0 - HIGHLIGHT_KNEE)));
}
`;

/** Lines shade per vertex (the strand is a 1-pixel line: the only interpolation is along
 *  segments a few pixels long), so a fragment costs no more than a flat colour. */
export const linesVertexShader = /* glsl */ `
${commonVertex}
${shading}
uniform float strandWidth; // world units at the root (representedWidth)
uniform float tipWidth; // fraction of strandWidth at the tip (the width tapers over the tip fade)
uniform float viewportHeight; // pixels of the target being drawn
varying vec3 vColor;
varying float vDistance; // from the camera (the order-independent pass's weight)
void main() {
  vec3 P = position;
  vec3 T0 = tangent;
  if (followGuides > 0.5) followGuide(P, T0); // a motion playing (followerGlsl.ts)
  vec4 world = modelMatrix * vec4(P, 1.0);
  vec3 T = normalize(mat3(modelMatrix) * T0);
  vAlong = vec4(along.x, tipDistanceOf(along.y), along.zw);
#ifdef HAIR_FRONT
  vColor = vec3(0.0); // the front pass needs the distance only (hairOit.ts)
#else
  vColor = shadeStrand(T, world.xyz, vAlong, strandRandom, lighting, turnOf(tangent));
#endif
  // a line is one pixel wide: its opacity is the strand's true coverage of that pixel (as the
  // strips' width / drawn width), tapering to the tip
  float dist = length(cameraPosition - world.xyz);
  vDistance = dist;
  float pixel = 2.0 * dist / (projectionMatrix[1][1] * max(viewportHeight, 1.0));
  if (projectionMatrix[3][3] > 0.5) pixel = 2.0 / (projectionMatrix[1][1] * max(viewportHeight, 1.0));
  vTipKeep = tipKeepOf(strandRandom, along.x, vAlong.y);
  float width = strandWidth * widthOf(strandRandom) * mix(tipWidth, 1.0, vTipKeep);
  vCoverage = min(1.0, width / pixel);
  gl_Position = projectionMatrix * viewMatrix * world;
}
`;

export const linesFragmentShader = /* glsl */ `
varying vec3 vColor;
varying vec4 vAlong;
varying float vCoverage;
varying float vTipKeep;
varying float vDistance;
#ifdef HAIR_OIT
${OIT_FRAGMENT_GLSL}
#endif
${rootFade}
void main() {
  // coverage times the tip's and the root's fades, blended order-independently (HAIR_OIT:
  // hairOit.ts) or unsorted, without depth writes
  float alpha = vCoverage * vTipKeep * rootFadeOf(vAlong.xy);
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
export const stripsVertexShader = /* glsl */ `
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
  vec3 P = position;
  vec3 T0 = tangent;
  if (followGuides > 0.5) followGuide(P, T0); // a motion playing (followerGlsl.ts)
  vec4 world = modelMatrix * vec4(P, 1.0);
  vec3 T = normalize(mat3(modelMatrix) * T0);
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
  vTipKeep = tipKeepOf(strandRandom, along.x, tipDistanceOf(along.y));
  vTurn = turnOf(tangent);
  float width = strandWidth * widthOf(strandRandom) * mix(tipWidth, 1.0, vTipKeep);
  float drawn = max(width, pixel);
  float s = (gl_VertexID % 2 == 0) ? -0.5 : 0.5;
  world.xyz += side * (s * drawn);
  vWorldPosition = world.xyz;
  vTangent = T;
  vAlong = vec4(along.x, tipDistanceOf(along.y), along.zw); // linear along a segment, as the distance is
  vRandom = strandRandom;
  vLight = lighting;
  vCoverage = width / drawn;
  gl_Position = projectionMatrix * viewMatrix * world;
}
`;

/** Strips shade per fragment (wide strands on a GPU). HAIR_OIT: the order-independent pass's
 *  two outputs instead of a colour (hairOit.ts). */
export const stripsFragmentShader = /* glsl */ `
${shading}
varying vec3 vTangent;
varying vec3 vWorldPosition;
varying vec4 vAlong;
varying vec4 vRandom;
varying vec2 vLight;
varying float vCoverage;
varying float vTipKeep;
varying float vTurn;
#ifdef HAIR_OIT
${OIT_FRAGMENT_GLSL}
#endif
${rootFade}

void main() {
  float alpha = vCoverage * vTipKeep * rootFadeOf(vAlong.xy);
#ifdef ALPHA_TO_COVERAGE
  if (alpha < 0.02) discard;
#else
  if (alpha < 0.004) discard;
#endif
#ifdef HAIR_FRONT
  vec3 color = vec3(0.0); // the front pass needs the distance only (hairOit.ts)
#else
  vec3 color = shadeStrand(normalize(vTangent), vWorldPosition, vAlong, vRandom, vLight, vTurn);
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
