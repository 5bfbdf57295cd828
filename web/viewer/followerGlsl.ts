// The strands placed on a motion's guides in the vertex shader (model/guideFollowers.ts is the
// same on the CPU, and says why): the guides' points and unit tangents now are two float
// textures, each strand point's guide, place along it, offset and rest tangent are vertex
// attributes, the head's pose two uniforms. Both strand shaders (strandShaders.ts) and every
// pass drawn with them (order-independent, deep opacity) run it while `followGuides` is 1; at 0
// the hair is drawn as it was groomed.
import * as THREE from 'three';
import { FOLLOW_TURN_FAR, FOLLOW_TURN_NEAR } from '../model/guideFollowers';

/** Guides a texture row holds: guide g's point j is texel (g % GUIDES_PER_ROW * G + j,
 *  floor(g / GUIDES_PER_ROW)). */
export const GUIDES_PER_ROW = 64;

export const FOLLOWER_GLSL = /* glsl */ `
uniform float followGuides; // 1 while a motion plays: the strands ride their guides
uniform highp sampler2D guidePositions; // xyz: a guide's point now (world)
uniform highp sampler2D guideTangents; // xyz: its unit tangent now
uniform int guidePoints; // G, points per guide
uniform mat3 followRotation; // the head's pose: world = R * groom + t
uniform vec3 followTranslation;
attribute vec2 follow; // the point's guide (-1: none) and place along it (guide points)
attribute vec3 followOffset; // the point less its guide's rest point there (groom frame)
attribute vec3 followTangent; // the guide's rest unit tangent there (normalised bytes)

ivec2 guideTexel(int g, int j) {
  return ivec2((g % ${GUIDES_PER_ROW}) * guidePoints + j, g / ${GUIDES_PER_ROW});
}

// v turned by the least rotation taking unit a to unit b
vec3 rotateBetween(vec3 a, vec3 b, vec3 v) {
  float c = dot(a, b);
  vec3 k = cross(a, b);
  return v * c + cross(k, v) + k * (dot(k, v) / max(1.0 + c, 1e-6));
}

// The groomed point P and tangent T (groom frame) where the motion has them now (world).
void followGuide(inout vec3 P, inout vec3 T) {
  if (follow.x < -0.5) {
    P = followRotation * P + followTranslation;
    T = followRotation * T;
    return;
  }
  int g = int(follow.x + 0.5);
  int j = clamp(int(floor(follow.y)), 0, guidePoints - 2);
  float w = follow.y - float(j);
  vec3 b0 = texelFetch(guidePositions, guideTexel(g, j), 0).xyz;
  vec3 b1 = texelFetch(guidePositions, guideTexel(g, j + 1), 0).xyz;
  vec3 t0 = texelFetch(guideTangents, guideTexel(g, j), 0).xyz;
  vec3 t1 = texelFetch(guideTangents, guideTexel(g, j + 1), 0).xyz;
  vec3 now = normalize(mix(t0, t1, w));
  vec3 rest = normalize(followRotation * followTangent);
  vec3 offset = followRotation * followOffset;
  // turned with the guide near it, carried without turning far from it (guideFollowers.ts)
  float f = smoothstep(${FOLLOW_TURN_NEAR.toFixed(3)}, ${FOLLOW_TURN_FAR.toFixed(3)}, length(followOffset));
  P = mix(b0, b1, w) + mix(rotateBetween(rest, now, offset), offset, f);
  T = mix(rotateBetween(rest, now, followRotation * T), followRotation * T, f);
}
`;

/** The follower uniforms of a strand material (all `{ value }` objects). */
export interface FollowerUniforms {
  [name: string]: THREE.IUniform;
  followGuides: THREE.IUniform<number>;
  guidePositions: THREE.IUniform<THREE.Texture | null>;
  guideTangents: THREE.IUniform<THREE.Texture | null>;
  guidePoints: THREE.IUniform<number>;
  followRotation: THREE.IUniform<THREE.Matrix3>;
  followTranslation: THREE.IUniform<THREE.Vector3>;
}

export function followerUniforms(): FollowerUniforms {
  return {
    followGuides: { value: 0 },
    guidePositions: { value: null },
    guideTangents: { value: null },
    guidePoints: { value: 2 },
    followRotation: { value: new THREE.Matrix3() },
    followTranslation: { value: new THREE.Vector3() },
  };
}
