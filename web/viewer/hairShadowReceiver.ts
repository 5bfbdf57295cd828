// The hair's shadow on the head and the bust. Fast: the head scales its key light by a per-vertex
// transmittance from the worker's lighting grid (headMaterial.ts `hairShadow`), the bust by none
// of its own (it is lit as before). High: both read the deep opacity maps the strands use
// (deepOpacity.ts) per fragment, so a strand's shadow falls where it is: the opacity of the hair
// between the key light and the point, exp(−κ·opacity), scales the key light (the scene's first
// directional light). The head is in the maps itself (an opaque fragment adds HEAD_FRAGMENT_
// OPACITY to every layer that ends past it): its own fragment is taken out again at its depth,
// so a head point counts only what lies in front of it. The bust is not in the maps; the head's
// opacity in front of it is its shadow from the head.
import * as THREE from 'three';

/** How much of the key light the hair's shadow takes away (1 = all of it). */
export const HAIR_SHADOW_STRENGTH = 0.85;

/** The receivers' uniforms, shared by every head and bust material (one viewer per page):
 *  `hairShadowMaps` 1 reads the maps (High with deep opacity maps), 0 does not. */
export const HAIR_SHADOW_UNIFORMS = {
  hairShadowMaps: { value: 0 },
  hsDepth: { value: null as THREE.Texture | null },
  hsOpacity: { value: null as THREE.Texture | null },
  hsMatrix: { value: new THREE.Matrix4() },
  hsLayers: { value: new THREE.Vector3(1, 2, 3) },
  hsRange: { value: 1 },
  hsKappa: { value: 1 },
  hsBias: { value: 0.01 },
  hsHeadOpacity: { value: 0 },
  hsTexel: { value: 1 / 512 }, // one texel of the maps, in texture coordinates
};

const receiverGlsl = (inMap: boolean) => /* glsl */ `
uniform float hairShadowMaps;
uniform sampler2D hsDepth;
uniform sampler2D hsOpacity;
uniform mat4 hsMatrix;
uniform vec3 hsLayers;
uniform float hsRange;
uniform float hsKappa;
uniform float hsBias;
uniform float hsHeadOpacity;
uniform float hsTexel;
varying vec3 vHsWorld;
float hairShadowAt(vec3 q) {
  if (q.x <= 0.0 || q.y <= 0.0 || q.x >= 1.0 || q.y >= 1.0) return 1.0;
  float z0 = texture2D(hsDepth, q.xy).r;
  float d = (q.z - z0) * hsRange;
  vec3 o = texture2D(hsOpacity, q.xy).rgb;
  ${
    inMap
      ? "// this point's own head fragment, in every layer ending past it\n  o = max(o - hsHeadOpacity * step(vec3(d), hsLayers), vec3(0.0));"
      : ''
  }
  d -= hsBias;
  if (d <= 0.0) return 1.0;
  float opacity;
  if (d < hsLayers.x) opacity = o.r * d / hsLayers.x;
  else if (d < hsLayers.y) opacity = mix(o.r, o.g, (d - hsLayers.x) / (hsLayers.y - hsLayers.x));
  else if (d < hsLayers.z) opacity = mix(o.g, o.b, (d - hsLayers.y) / (hsLayers.z - hsLayers.y));
  else opacity = o.b;
  return exp(-hsKappa * opacity);
}
// four taps two texels apart, averaged: the first-hair depth is per texel, so a thin strand's
// shadow read from one tap is a hard line a texel wide, dotted where the surface crosses texels
float hairShadowFromMaps(vec3 world) {
  vec4 p = hsMatrix * vec4(world, 1.0);
  vec3 q = p.xyz / p.w * 0.5 + 0.5;
  float t = hsTexel;
  return 0.25 * (hairShadowAt(q + vec3(-t, -t, 0.0)) + hairShadowAt(q + vec3(t, -t, 0.0))
    + hairShadowAt(q + vec3(-t, t, 0.0)) + hairShadowAt(q + vec3(t, t, 0.0)));
}
`;

/** Patches a lit (standard) material's shader in onBeforeCompile: the key light is scaled by the
 *  hair's transmittance; `perVertex` names a varying float the vertex stage fills (the head's
 *  `vHairShadow`) that Fast uses; `inMap`: the mesh is drawn into the deep opacity maps. */
export function patchHairShadowReceiver(
  shader: THREE.WebGLProgramParametersWithUniforms,
  options: { perVertex: string | null; inMap: boolean },
): void {
  Object.assign(shader.uniforms, HAIR_SHADOW_UNIFORMS);
  shader.vertexShader = shader.vertexShader
    .replace('#include <common>', '#include <common>\nvarying vec3 vHsWorld;')
    .replace(
      '#include <begin_vertex>',
      '#include <begin_vertex>\nvHsWorld = (modelMatrix * vec4(transformed, 1.0)).xyz;',
    );
  const fast = options.perVertex ?? '1.0';
  const lights = THREE.ShaderChunk.lights_fragment_begin.replace(
    'getDirectionalLightInfo( directionalLight, directLight );',
    `getDirectionalLightInfo( directionalLight, directLight );
		#if UNROLLED_LOOP_INDEX == 0
		float hairT = hairShadowMaps > 0.5 ? hairShadowFromMaps( vHsWorld ) : ${fast};
		directLight.color *= mix( 1.0, hairT, ${HAIR_SHADOW_STRENGTH.toFixed(2)} );
		#endif`,
  );
  shader.fragmentShader = shader.fragmentShader
    .replace('#include <common>', `#include <common>\n${receiverGlsl(options.inMap)}`)
    .replace('#include <lights_fragment_begin>', lights);
}
