// Deep opacity maps (Yuksel & Keyser 2008) for the High quality: seen from the key light (an
// orthographic camera along KEY_LIGHT_DIRECTION, fitted to the hair), a depth pass keeps the
// first hair (or head) per texel, then an opacity pass adds every hair fragment's opacity, with
// additive blending into one RGBA16F target, to the 3 layers (R, G, B: cumulative up to
// DOM_LAYERS past that first depth) it lies in front of. The strand shader interpolates the
// opacity at its own depth and takes exp(−κ·opacity). The light is fixed in world space, so the
// maps are rendered once per hair revision, not per frame.
import * as THREE from 'three';
import { KEY_LIGHT_DIRECTION } from '../lighting/keyLight';
import { HAIR_SHADOW_UNIFORMS } from './hairShadowReceiver';
import type { StrandMaterial } from './strandMaterial';

/** Far ends of the 3 layers past the first hair, world units (1 unit = 10 cm). */
export const DOM_LAYERS: readonly [number, number, number] = [0.05, 0.15, 0.4];
/** Opacity a hair fragment adds, and a head fragment (opaque). */
const HAIR_FRAGMENT_OPACITY = 0.12;
const HEAD_FRAGMENT_OPACITY = 40;

const depthFragment = /* glsl */ `
void main() {
  gl_FragColor = vec4(gl_FragCoord.z, 0.0, 0.0, 1.0);
}
`;

const opacityFragment = /* glsl */ `
uniform sampler2D domDepth;
uniform vec2 domSize;
uniform float domRange;
uniform vec3 domLayers;
uniform float fragmentOpacity;
void main() {
  float z0 = texture2D(domDepth, gl_FragCoord.xy / domSize).r;
  float d = (gl_FragCoord.z - z0) * domRange;
  gl_FragColor = vec4(step(d, domLayers.x), step(d, domLayers.y), step(d, domLayers.z), 0.0)
    * fragmentOpacity;
}
`;

const headVertex = /* glsl */ `
void main() {
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;

export class DeepOpacityMaps {
  readonly size: number;
  private readonly depthTarget: THREE.WebGLRenderTarget;
  private readonly opacityTarget: THREE.WebGLRenderTarget;
  readonly camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 10);
  private readonly scene = new THREE.Scene();
  private readonly matrix = new THREE.Matrix4();
  private range = 1;
  private texel = 0.01;

  constructor(size = 1024) {
    this.size = size;
    this.depthTarget = new THREE.WebGLRenderTarget(size, size, {
      type: THREE.FloatType,
      format: THREE.RedFormat,
      minFilter: THREE.NearestFilter,
      magFilter: THREE.NearestFilter,
      depthBuffer: true,
    });
    this.opacityTarget = new THREE.WebGLRenderTarget(size, size, {
      type: THREE.HalfFloatType,
      minFilter: THREE.LinearFilter,
      magFilter: THREE.LinearFilter,
      depthBuffer: false,
    });
  }

  /** Renders both maps for `hair` (strip geometry, drawn in full) and `head` (its geometry),
   *  from the key light; `template` supplies the strip vertex shader and its uniforms. */
  render(
    renderer: THREE.WebGLRenderer,
    hair: THREE.BufferGeometry,
    template: StrandMaterial,
    head: THREE.Mesh | null,
  ): void {
    const sphere = hair.boundingSphere ?? new THREE.Sphere(new THREE.Vector3(), 1);
    const fit = new THREE.Sphere().copy(sphere);
    if (head) {
      head.geometry.computeBoundingSphere();
      const hs = head.geometry.boundingSphere;
      if (hs) fit.union(hs);
    }
    const r = Math.max(fit.radius, 1e-3);
    const L = new THREE.Vector3(...KEY_LIGHT_DIRECTION);
    const cam = this.camera;
    cam.position.copy(fit.center).addScaledVector(L, 2 * r);
    cam.up.set(0, 1, 0);
    if (Math.abs(L.y) > 0.99) cam.up.set(0, 0, 1);
    cam.lookAt(fit.center);
    cam.left = -r;
    cam.right = r;
    cam.top = r;
    cam.bottom = -r;
    cam.near = r * 0.5;
    cam.far = r * 3.5;
    cam.updateProjectionMatrix();
    cam.updateMatrixWorld(true);
    this.range = cam.far - cam.near;
    this.texel = (2 * r) / this.size;
    this.matrix.multiplyMatrices(cam.projectionMatrix, cam.matrixWorldInverse);

    const stripUniforms = {
      ...template.uniforms,
      domViewDirection: { value: L.clone() },
      domPixelSize: { value: this.texel },
    };
    const stripMaterial = (fragmentShader: string, extra: Record<string, THREE.IUniform>) =>
      new THREE.ShaderMaterial({
        uniforms: { ...stripUniforms, ...extra },
        defines: { DOM_PASS: '' },
        vertexShader: template.vertexShader,
        fragmentShader,
        side: THREE.DoubleSide,
      });
    const opacityUniforms = (opacity: number) => ({
      domDepth: { value: this.depthTarget.texture },
      domSize: { value: new THREE.Vector2(this.size, this.size) },
      domRange: { value: this.range },
      domLayers: { value: new THREE.Vector3(...DOM_LAYERS) },
      fragmentOpacity: { value: opacity },
    });
    const additive = (m: THREE.ShaderMaterial) => {
      m.blending = THREE.CustomBlending;
      m.blendEquation = THREE.AddEquation;
      m.blendSrc = THREE.OneFactor;
      m.blendDst = THREE.OneFactor;
      m.depthTest = false;
      m.depthWrite = false;
      return m;
    };
    const hairDepth = stripMaterial(depthFragment, {});
    const hairOpacity = additive(
      stripMaterial(opacityFragment, opacityUniforms(HAIR_FRAGMENT_OPACITY)),
    );
    const headDepth = new THREE.ShaderMaterial({
      vertexShader: headVertex,
      fragmentShader: depthFragment,
      side: THREE.DoubleSide,
    });
    const headOpacity = additive(
      new THREE.ShaderMaterial({
        uniforms: opacityUniforms(HEAD_FRAGMENT_OPACITY),
        vertexShader: headVertex,
        fragmentShader: opacityFragment,
        side: THREE.DoubleSide,
      }),
    );
    const hairMesh = new THREE.Mesh(hair, hairDepth);
    hairMesh.frustumCulled = false;
    const headMesh = head ? new THREE.Mesh(head.geometry, headDepth) : null;
    if (head && headMesh) headMesh.matrixAutoUpdate = false;
    if (head && headMesh) headMesh.matrix.copy(head.matrixWorld);
    this.scene.clear();
    this.scene.add(hairMesh);
    if (headMesh) this.scene.add(headMesh);

    const drawRange = { ...hair.drawRange };
    hair.setDrawRange(0, Number.POSITIVE_INFINITY);
    const previousTarget = renderer.getRenderTarget();
    const clear = new THREE.Color();
    renderer.getClearColor(clear);
    const clearAlpha = renderer.getClearAlpha();
    const autoClear = renderer.autoClear;
    try {
      renderer.autoClear = true;
      renderer.setClearColor(0xffffff, 1); // far
      renderer.setRenderTarget(this.depthTarget);
      renderer.render(this.scene, cam);
      hairMesh.material = hairOpacity;
      if (headMesh) headMesh.material = headOpacity;
      renderer.setClearColor(0x000000, 0);
      renderer.setRenderTarget(this.opacityTarget);
      renderer.render(this.scene, cam);
    } finally {
      renderer.setRenderTarget(previousTarget);
      renderer.setClearColor(clear, clearAlpha);
      renderer.autoClear = autoClear;
      hair.setDrawRange(drawRange.start, drawRange.count);
      this.scene.clear();
      for (const m of [hairDepth, hairOpacity, headDepth, headOpacity]) m.dispose();
    }
  }

  /** Points `material` (made with deepOpacity: true) at these maps. */
  bind(material: StrandMaterial): void {
    const u = material.uniforms;
    u.domDepth = { value: this.depthTarget.texture };
    u.domOpacity = { value: this.opacityTarget.texture };
    u.domMatrix = { value: this.matrix };
    u.domLayers = { value: new THREE.Vector3(...DOM_LAYERS) };
    u.domRange = { value: this.range };
    u.domKappa = { value: 1.0 };
    u.domBias = { value: 2 * this.texel };
  }

  /** Updates the range and bias uniforms after a render (the matrix is shared by reference). */
  refresh(material: StrandMaterial): void {
    const u = material.uniforms;
    if (u.domRange) u.domRange.value = this.range;
    if (u.domBias) u.domBias.value = 2 * this.texel;
  }

  /** Points the head's and the bust's materials (hairShadowReceiver.ts) at these maps, after a
   *  render; `on` false: they go back to Fast's shadow. */
  bindReceivers(on: boolean): void {
    const u = HAIR_SHADOW_UNIFORMS;
    u.hairShadowMaps.value = on ? 1 : 0;
    u.hsDepth.value = this.depthTarget.texture;
    u.hsOpacity.value = this.opacityTarget.texture;
    u.hsMatrix.value = this.matrix;
    u.hsLayers.value.set(...DOM_LAYERS);
    u.hsRange.value = this.range;
    u.hsKappa.value = 1.0;
    u.hsBias.value = 2 * this.texel;
    u.hsHeadOpacity.value = HEAD_FRAGMENT_OPACITY;
    u.hsTexel.value = 1 / this.size;
    u.hsTexelWorld.value = this.texel;
  }

  dispose(): void {
    this.depthTarget.dispose();
    this.opacityTarget.dispose();
  }
}
