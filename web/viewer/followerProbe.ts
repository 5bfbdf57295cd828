// Test probe: where the strand shader's follower code (followerGlsl.ts) puts each vertex of the
// hair shown, read back from the GPU. Every vertex is drawn as one point into its own texel of a
// float target, coloured with its placed position, through the same GLSL and uniforms the strand
// material draws with; the browser tests compare it with the CPU reference
// (model/guideFollowers.ts placeFollowers).
import * as THREE from 'three';
import { FOLLOWER_GLSL, type FollowerUniforms } from './followerGlsl';

const WIDTH = 1024;

const vertexShader = /* glsl */ `
${FOLLOWER_GLSL}
attribute vec3 tangent;
uniform float probeHeight;
varying vec3 vPlaced;
void main() {
  vec3 P = position;
  vec3 T = tangent;
  followGuide(P, T);
  vPlaced = P;
  int i = gl_VertexID;
  vec2 texel = vec2(float(i % ${WIDTH}), float(i / ${WIDTH})) + 0.5;
  gl_Position = vec4(2.0 * texel.x / ${WIDTH.toFixed(1)} - 1.0, 2.0 * texel.y / probeHeight - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
`;

const fragmentShader = /* glsl */ `
varying vec3 vPlaced;
void main() {
  gl_FragColor = vec4(vPlaced, 1.0);
}
`;

/** The placed position of each vertex of `geometry` (3 floats a vertex) under `uniforms` (a
 *  strand material's, following a motion), or null where the renderer cannot draw to a float
 *  target. */
export function readFollowedVertices(
  renderer: THREE.WebGLRenderer,
  geometry: THREE.BufferGeometry,
  uniforms: FollowerUniforms,
): Float32Array | null {
  if (!renderer.extensions.has('EXT_color_buffer_float')) return null;
  const count = geometry.getAttribute('position').count;
  const height = Math.max(1, Math.ceil(count / WIDTH));
  // the same attributes, no index: each vertex once, in order
  const points = new THREE.BufferGeometry();
  for (const name of ['position', 'tangent', 'follow', 'followOffset', 'followTangent']) {
    const a = geometry.getAttribute(name);
    if (!a) return null;
    points.setAttribute(name, a);
  }
  const material = new THREE.ShaderMaterial({
    uniforms: { ...uniforms, probeHeight: { value: height } },
    vertexShader,
    fragmentShader,
    depthTest: false,
    depthWrite: false,
    blending: THREE.NoBlending,
  });
  const target = new THREE.WebGLRenderTarget(WIDTH, height, {
    type: THREE.FloatType,
    minFilter: THREE.NearestFilter,
    magFilter: THREE.NearestFilter,
    depthBuffer: false,
  });
  const scene = new THREE.Scene();
  const object = new THREE.Points(points, material);
  object.frustumCulled = false;
  scene.add(object);
  const before = renderer.getRenderTarget();
  const clear = renderer.getClearColor(new THREE.Color());
  const alpha = renderer.getClearAlpha();
  try {
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x000000, 0);
    renderer.clear();
    renderer.render(scene, new THREE.Camera());
    const px = new Float32Array(4 * WIDTH * height);
    renderer.readRenderTargetPixels(target, 0, 0, WIDTH, height, px);
    const out = new Float32Array(3 * count);
    for (let i = 0; i < count; i++) {
      out[3 * i] = px[4 * i];
      out[3 * i + 1] = px[4 * i + 1];
      out[3 * i + 2] = px[4 * i + 2];
    }
    return out;
  } finally {
    renderer.setRenderTarget(before);
    renderer.setClearColor(clear, alpha);
    target.dispose();
    material.dispose();
    points.dispose();
  }
}
