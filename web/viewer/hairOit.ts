// Weighted blended order-independent transparency (McGuire & Bavoil 2013) for thin strands
// (Fast's lines; High's strips where the canvas is not multisampled): every hair fragment adds
// its colour times its weight w = α·f(depth) to one sum and its weight to another, and multiplies the "revealage"
// (what is seen through the hair) by 1 − α; a composite pass then lays the weighted mean colour
// over the scene with opacity 1 − revealage. Sums and products do not depend on the order the
// strands are drawn in, so dense hair shows no sorting artefacts.
//
// Targets: two half-float colour attachments with a depth buffer, at the size of what is drawn
// into. Attachment 0 (RGBA): rgb Σ c·w (additive), a Π(1 − α) (multiplicative); attachment 1
// (RG): Σ w and Σ w·depth. 16 bytes a pixel with the depth buffer. After the composite, the
// hair's weighted mean depth goes into the depth buffer where it covers half a pixel or more, so
// overlays drawn after it are faint under the hair as behind the head (overlayStyle.ts).
// One blend function serves both (colour: one, one; alpha: zero, one minus source alpha), so it
// needs neither per-attachment blending nor 32-bit float blending. The head and the body write
// their depth first (colour off), so hair behind them is not counted.
//
// f(depth): exp(−(d − d0)/OIT_DEPTH_SCALE), d the fragment's distance from the camera and d0 that
// of the hair nearest the camera in the same pixel: a strand 5 mm (0.05 units) behind another
// counts 1/e as much, which keeps the outer hair's strands, locks and highlights on top of the
// inner hair's shade. Clamped to a range a half float carries (about 6 cm of depth past d0 is
// told apart). d0 comes from a first pass over the same strands (HAIR_FRONT: no shading, each
// fragment's distance blended by MIN into a one-channel half-float target). With one d0 for the
// whole hair (its bounding sphere's nearest point) every fragment of hair more than 6 cm behind
// that point weighed the same, so a head of hair seen from behind or from the side was the plain
// mean of all its layers: a smooth shell without strands, curls or locks.
import * as THREE from 'three';

/** e-folding depth of a fragment's weight, world units (1 unit = 10 cm). */
export const OIT_DEPTH_SCALE = 0.05;

/** The front pass counts a fragment when its strand covers at least this much of the pixel. */
export const FRONT_MIN_ALPHA = 0.05;

/** The front target holds distances past oitNear over this range (world units), so its clear
 *  colour, 1 (white, the same in every colour space), is 'no hair here'. */
const FRONT_RANGE = 100;

/** GLSL for a strand fragment shader under HAIR_OIT (glslVersion GLSL3): the two outputs and
 *  oitWrite(colour, alpha), which writes them. */
export const OIT_FRAGMENT_GLSL = /* glsl */ `
uniform float oitNear; // distance from the camera to the hair's nearest bounding point
#ifdef HAIR_FRONT
layout(location = 0) out highp vec4 oitFront;
void oitWrite(vec3 color, float alpha, float dist) {
  // the front pass: fragments a strand covers well (not its fading tip) give their distance past
  // oitNear; the target's MIN blending keeps the nearest
  if (alpha < ${FRONT_MIN_ALPHA.toFixed(2)}) discard;
  oitFront = vec4((dist - oitNear) / ${FRONT_RANGE.toFixed(1)}, 0.0, 0.0, 1.0);
}
#else
layout(location = 0) out highp vec4 oitAccum;
layout(location = 1) out highp vec4 oitWeight;
uniform sampler2D oitFrontDepth; // the front pass: the nearest hair's distance past oitNear
void oitWrite(vec3 color, float alpha, float dist) {
  float front = oitNear + ${FRONT_RANGE.toFixed(1)} * texelFetch(oitFrontDepth, ivec2(gl_FragCoord.xy), 0).r;
  // ln f in [-7, 4.6]: f from ~1e-3 to 100, so c·w stays a normal half float for α >= 0.004
  float lnF = clamp((front - dist) / ${OIT_DEPTH_SCALE.toFixed(3)} + 4.6, -7.0, 4.6);
  float w = alpha * exp(lnF);
  oitAccum = vec4(color * w, alpha);
  // and the weighted depth past oitNear (small numbers: a half float keeps them to ~0.1 mm)
  oitWeight = vec4(w, w * (dist - oitNear), 0.0, alpha);
}
#endif
`;

const compositeVertex = /* glsl */ `
varying vec2 vUv;
void main() {
  vUv = uv;
  gl_Position = vec4(position.xy, 0.0, 1.0);
}
`;

/** The hair's depth for the overlays drawn after it (curves under the hair are faint, as behind
 *  the head): where the hair covers at least half a pixel, the weighted mean distance of its
 *  fragments, along the pixel's ray, as the depth buffer's value. Perspective cameras only. */
const depthFragment = /* glsl */ `
uniform sampler2D accumTexture;
uniform sampler2D weightTexture;
uniform float oitNear;
uniform mat4 cameraProjection;
uniform mat4 cameraProjectionInverse;
varying vec2 vUv;
void main() {
  if (texture2D(accumTexture, vUv).a > 0.5) discard; // less than half covered
  vec2 w = texture2D(weightTexture, vUv).rg;
  float dist = oitNear + w.y / max(w.x, 1e-6);
  vec4 r = cameraProjectionInverse * vec4(2.0 * vUv - 1.0, -1.0, 1.0);
  vec3 ray = normalize(r.xyz / r.w);
  vec4 clip = cameraProjection * vec4(ray * dist, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
  gl_FragColor = vec4(0.0);
}
`;

const compositeFragment = /* glsl */ `
uniform sampler2D accumTexture;
uniform sampler2D weightTexture;
varying vec2 vUv;
void main() {
  vec4 accum = texture2D(accumTexture, vUv);
  float reveal = accum.a;
  if (reveal > 0.999) discard; // no hair here
  float w = texture2D(weightTexture, vUv).r;
  gl_FragColor = vec4(accum.rgb / max(w, 1e-6), 1.0 - reveal);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
}
`;

/** The order-independent drawing of one strand material's hair (strips or lines): its twin
 *  material (same shaders and uniforms, HAIR_OIT defined), the targets and the composite pass. */
export class WeightedBlendedHair {
  readonly material: THREE.ShaderMaterial;
  private target: THREE.WebGLRenderTarget | null = null;
  /** The front pass's material and target (one half float a pixel: the nearest hair's distance
   *  past oitNear). */
  private readonly frontMaterial: THREE.ShaderMaterial;
  private frontTarget: THREE.WebGLRenderTarget | null = null;
  private readonly depthOnly = new THREE.MeshBasicMaterial({ colorWrite: false });
  private readonly composite: THREE.ShaderMaterial;
  private readonly depth: THREE.ShaderMaterial;
  private readonly quad: THREE.Mesh;
  private readonly quadCamera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly sphere = new THREE.Sphere();
  /** The hair's depth is written for the overlays drawn after it (false: not; a test switch). */
  writesDepth = true;

  constructor(strands: THREE.ShaderMaterial) {
    const material = new THREE.ShaderMaterial({
      uniforms: strands.uniforms, // shared: the look and the deep opacity maps stay in step
      defines: { ...strands.defines, HAIR_OIT: '' },
      vertexShader: strands.vertexShader,
      fragmentShader: strands.fragmentShader,
      glslVersion: THREE.GLSL3,
      side: THREE.DoubleSide,
      transparent: true,
      depthWrite: false,
      blending: THREE.CustomBlending,
      blendEquation: THREE.AddEquation,
      blendSrc: THREE.OneFactor,
      blendDst: THREE.OneFactor,
      blendSrcAlpha: THREE.ZeroFactor,
      blendDstAlpha: THREE.OneMinusSrcAlphaFactor,
    });
    material.name = 'HairStripsOit';
    material.uniforms.oitNear = { value: 0 };
    material.uniforms.oitFrontDepth = { value: null };
    material.onBeforeRender = strands.onBeforeRender;
    this.material = material;
    this.frontMaterial = new THREE.ShaderMaterial({
      uniforms: strands.uniforms,
      defines: { ...strands.defines, HAIR_OIT: '', HAIR_FRONT: '' },
      vertexShader: strands.vertexShader,
      fragmentShader: strands.fragmentShader,
      glslVersion: THREE.GLSL3,
      side: THREE.DoubleSide,
      transparent: true,
      depthTest: false,
      depthWrite: false,
      blending: THREE.CustomBlending,
      blendEquation: THREE.MinEquation,
      blendSrc: THREE.OneFactor,
      blendDst: THREE.OneFactor,
    });
    this.frontMaterial.name = 'HairFrontOit';
    this.frontMaterial.onBeforeRender = strands.onBeforeRender;
    this.composite = new THREE.ShaderMaterial({
      uniforms: { accumTexture: { value: null }, weightTexture: { value: null } },
      vertexShader: compositeVertex,
      fragmentShader: compositeFragment,
      depthTest: false,
      depthWrite: false,
      transparent: true,
      blending: THREE.CustomBlending,
      blendEquation: THREE.AddEquation,
      blendSrc: THREE.SrcAlphaFactor,
      blendDst: THREE.OneMinusSrcAlphaFactor,
      blendSrcAlpha: THREE.OneFactor,
      blendDstAlpha: THREE.OneMinusSrcAlphaFactor,
    });
    this.quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2), this.composite);
    this.quad.frustumCulled = false;
    this.depth = new THREE.ShaderMaterial({
      uniforms: {
        accumTexture: { value: null },
        weightTexture: { value: null },
        oitNear: { value: 0 },
        cameraProjection: { value: new THREE.Matrix4() },
        cameraProjectionInverse: { value: new THREE.Matrix4() },
      },
      vertexShader: compositeVertex,
      fragmentShader: depthFragment,
      colorWrite: false,
      depthTest: true,
      depthWrite: true,
      depthFunc: THREE.LessEqualDepth,
    });
  }

  /** Whether this renderer can draw it (half-float colour attachments). */
  static supported(renderer: THREE.WebGLRenderer): boolean {
    return renderer.extensions.has('EXT_color_buffer_float');
  }

  private targetFor(renderer: THREE.WebGLRenderer): THREE.WebGLRenderTarget {
    const into = renderer.getRenderTarget();
    const size = into
      ? new THREE.Vector2(into.width, into.height)
      : renderer.getDrawingBufferSize(new THREE.Vector2());
    if (!this.target) {
      this.target = new THREE.WebGLRenderTarget(size.x, size.y, {
        count: 2,
        type: THREE.HalfFloatType,
        minFilter: THREE.NearestFilter,
        magFilter: THREE.NearestFilter,
        depthBuffer: true,
      });
      this.target.textures[1].format = THREE.RGFormat; // Σ w, Σ w·depth: 4 bytes a pixel, not 8
    } else if (this.target.width !== size.x || this.target.height !== size.y) {
      this.target.setSize(size.x, size.y);
    }
    if (!this.frontTarget) {
      this.frontTarget = new THREE.WebGLRenderTarget(size.x, size.y, {
        type: THREE.HalfFloatType,
        format: THREE.RedFormat,
        minFilter: THREE.NearestFilter,
        magFilter: THREE.NearestFilter,
        depthBuffer: false,
      });
    } else if (this.frontTarget.width !== size.x || this.frontTarget.height !== size.y) {
      this.frontTarget.setSize(size.x, size.y);
    }
    return this.target;
  }

  /** Bumped by every pass that clears the targets (begin, and so draw): a drawing spread over
   *  several frames (ProgressiveHair) starts again when another drawing came between. */
  generation = 0;

  /** Draws `hair` (strips or lines of this material's twin) over what the current target holds:
   *  `occluders` (children of the scene drawn opaque, shown or not: the head, the body) hide the
   *  hair behind them. The hair's draw range is drawn (all of it, for the whole hair).
   *  The renderer's target, clear colour and autoClear are left as they were. */
  draw(
    renderer: THREE.WebGLRenderer,
    scene: THREE.Scene,
    camera: THREE.Camera,
    hair: THREE.Mesh | THREE.LineSegments,
    occluders: readonly THREE.Object3D[],
  ): void {
    this.begin(renderer, camera, hair);
    this.front(renderer, camera, hair);
    this.beginSums(renderer, scene, camera, occluders);
    this.sums(renderer, camera, hair);
    this.compose(renderer, camera);
  }

  /** The passes one at a time (draw runs them in this order; each may run on a part of the hair,
   *  its draw range, several times over, in other frames): begin sets the hair's nearest
   *  distance and clears the front target. */
  begin(renderer: THREE.WebGLRenderer, camera: THREE.Camera, hair: THREE.Object3D): void {
    this.generation++;
    const sphere = this.sphere.copy(
      (hair as THREE.Mesh).geometry.boundingSphere ?? new THREE.Sphere(),
    );
    sphere.applyMatrix4(hair.matrixWorld);
    const eye = new THREE.Vector3().setFromMatrixPosition(camera.matrixWorld);
    this.material.uniforms.oitNear.value = Math.max(
      0,
      eye.distanceTo(sphere.center) - sphere.radius,
    );
    this.targetFor(renderer);
    this.keepingState(renderer, () => {
      renderer.setRenderTarget(this.frontTarget);
      renderer.setClearColor(0xffffff, 1); // no hair: FRONT_RANGE past oitNear
      renderer.clear(true, false, false);
    });
  }

  /** The front pass over the hair's draw range: each pixel's nearest hair distance. */
  front(
    renderer: THREE.WebGLRenderer,
    camera: THREE.Camera,
    hair: THREE.Mesh | THREE.LineSegments,
  ): void {
    this.pass(renderer, camera, hair, this.frontTarget, this.frontMaterial);
  }

  /** Clears the sums and writes the occluders' depth (only they, opaque surfaces only, colour
   *  off; shown for this pass if the caller's layer pass hid them). After every front pass. */
  beginSums(
    renderer: THREE.WebGLRenderer,
    scene: THREE.Scene,
    camera: THREE.Camera,
    occluders: readonly THREE.Object3D[],
  ): void {
    this.material.uniforms.oitFrontDepth.value = this.frontTarget?.texture ?? null;
    const restore: THREE.Object3D[] = [];
    const hide = (o: THREE.Object3D) => {
      if (!o.visible) return;
      o.visible = false;
      restore.push(o);
    };
    const shown = occluders.filter((c) => !c.visible);
    this.keepingState(renderer, () => {
      try {
        renderer.setRenderTarget(this.target);
        renderer.setClearColor(0x000000, 1); // Σ = 0, revealage 1
        renderer.clear(true, true, false);
        renderer.autoClear = false;
        for (const c of shown) c.visible = true;
        for (const c of scene.children)
          if (!(c instanceof THREE.Light) && !occluders.includes(c)) hide(c);
        for (const c of occluders)
          c.traverse((o) => {
            const m = (o as THREE.Mesh).material as THREE.Material | undefined;
            const drawn =
              o instanceof THREE.Line || o instanceof THREE.Points || o instanceof THREE.Sprite;
            if (drawn || (m && (m.transparent || !m.depthWrite))) hide(o);
          });
        if (occluders.length > 0) {
          scene.overrideMaterial = this.depthOnly;
          renderer.render(scene, camera);
        }
      } finally {
        scene.overrideMaterial = null;
        for (const c of shown) c.visible = false;
        for (const o of restore) o.visible = true;
      }
    });
  }

  /** The sums over the hair's draw range (after beginSums). */
  sums(
    renderer: THREE.WebGLRenderer,
    camera: THREE.Camera,
    hair: THREE.Mesh | THREE.LineSegments,
  ): void {
    this.pass(renderer, camera, hair, this.target, this.material);
  }

  /** Lays the sums over the renderer's current target (the composite), then the hair's depth. */
  compose(renderer: THREE.WebGLRenderer, camera: THREE.Camera): void {
    const target = this.target;
    if (!target) return;
    this.keepingState(renderer, () => {
      this.composite.uniforms.accumTexture.value = target.textures[0];
      this.composite.uniforms.weightTexture.value = target.textures[1];
      renderer.autoClear = false;
      renderer.render(this.quad, this.quadCamera);
      if (this.writesDepth && camera instanceof THREE.PerspectiveCamera) {
        const u = this.depth.uniforms;
        u.accumTexture.value = target.textures[0];
        u.weightTexture.value = target.textures[1];
        u.oitNear.value = this.material.uniforms.oitNear.value;
        u.cameraProjection.value.copy(camera.projectionMatrix);
        u.cameraProjectionInverse.value.copy(camera.projectionMatrixInverse);
        this.quad.material = this.depth;
        try {
          renderer.render(this.quad, this.quadCamera);
        } finally {
          this.quad.material = this.composite;
        }
      }
    });
  }

  /** Draws the hair alone into `target` (not cleared) with `material` in place of its own. */
  private pass(
    renderer: THREE.WebGLRenderer,
    camera: THREE.Camera,
    hair: THREE.Mesh | THREE.LineSegments,
    target: THREE.WebGLRenderTarget | null,
    material: THREE.Material,
  ): void {
    const own = hair.material;
    this.keepingState(renderer, () => {
      renderer.setRenderTarget(target);
      renderer.autoClear = false;
      hair.material = material;
      try {
        renderer.render(hair, camera);
      } finally {
        hair.material = own;
      }
    });
  }

  /** Runs `f`, then puts back the renderer's target, clear colour and autoClear. */
  private keepingState(renderer: THREE.WebGLRenderer, f: () => void): void {
    const into = renderer.getRenderTarget();
    const clear = new THREE.Color();
    renderer.getClearColor(clear);
    const clearAlpha = renderer.getClearAlpha();
    const autoClear = renderer.autoClear;
    try {
      f();
    } finally {
      renderer.setRenderTarget(into);
      renderer.setClearColor(clear, clearAlpha);
      renderer.autoClear = autoClear;
    }
  }

  dispose(): void {
    this.target?.dispose();
    this.frontTarget?.dispose();
    this.frontMaterial.dispose();
    this.material.dispose();
    this.composite.dispose();
    this.depth.dispose();
    this.depthOnly.dispose();
    this.quad.geometry.dispose();
  }
}
