// The hair strands' material (method S6.1): uniforms and settings over the shaders of
// strandShaders.ts, for either geometry of strandGeometry.ts (lines: Fast; strips: High, with
// alpha-to-coverage under MSAA and deep opacity maps). Thin strands: each drawn strand stands for
// several of a head's hairs (strandWidth.ts representedWidth), drawn at least a pixel wide with the
// rest of its width as coverage in alpha, tapering to the tip, the tips fading out, blended
// order-independently without depth writes (hairOit.ts; unsorted where the renderer has no
// half-float targets).
import * as THREE from 'three';
import { FILL_LIGHT_DIRECTION, KEY_LIGHT_DIRECTION } from '../lighting/keyLight';
import { type HairLook, lookUniforms } from '../model/hairLook';
import { DEFAULT_HAIR_COLOR } from '../model/session';
import { type FollowerUniforms, followerUniforms } from './followerGlsl';
import {
  linesFragmentShader,
  linesVertexShader,
  stripsFragmentShader,
  stripsVertexShader,
} from './strandShaders';
import { drawnStrands, representedWidth, WIDTH_VARIATION } from './strandWidth';

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
export interface StrandUniforms extends FollowerUniforms {
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
    lengthVariation: { value: 0.08 }, // mean share of the length an end is cut back by (tipKeepOf)
    widthVariation: { value: WIDTH_VARIATION },
    tipFade: { value: 0.12 },
    precomputed: { value: 1 },
    strandWidth: { value: representedWidth(30_000) }, // set per draw
    tipWidth: { value: 0.25 },
    viewportHeight: { value: 750 },
    ...followerUniforms(),
  };
  const defines: Record<string, string> = {};
  if (options.deepOpacity) defines.DEEP_OPACITY = '';
  if (strips && options.alphaToCoverage) defines.ALPHA_TO_COVERAGE = '';
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
