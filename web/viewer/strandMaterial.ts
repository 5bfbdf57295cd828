// Hair strands as THREE.LineSegments with Kajiya–Kay shading (SPEC S6.1). Per vertex: the strand
// tangent, `along` (0 at the root, 1 at the tip) and `strandRandom` (one value in [0, 1] per
// strand, for colour variation). Uniforms: hair colour, light direction and colour, ambient,
// two specular lobes (primary white-ish, secondary tinted by the hair colour).
import * as THREE from 'three';

const vertexShader = /* glsl */ `
attribute vec3 tangent;
attribute float along;
attribute float strandRandom;
varying vec3 vTangent;
varying vec3 vWorldPosition;
varying float vAlong;
varying float vRandom;

void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
  vWorldPosition = world.xyz;
  vTangent = mat3(modelMatrix) * tangent;
  vAlong = along;
  vRandom = strandRandom;
  gl_Position = projectionMatrix * viewMatrix * world;
}
`;

const fragmentShader = /* glsl */ `
uniform vec3 hairColor;
uniform vec3 lightDirection; // world space, toward the light
uniform vec3 lightColor;
uniform vec3 ambientColor;
uniform vec3 headCenter; // world space: hair on the far side of it from the light is shadowed
uniform float selfShadow; // 0 = off, 1 = full
uniform float diffuseStrength;
uniform float specularStrength;
uniform float specularPower;
uniform float secondaryStrength;
uniform float secondaryPower;
uniform float rootDarkening; // 0 = none; roots are darker by this fraction
uniform float colorVariation; // ± fraction of brightness varying per strand
varying vec3 vTangent;
varying vec3 vWorldPosition;
varying float vAlong;
varying float vRandom;

void main() {
  vec3 T = normalize(vTangent);
  vec3 L = normalize(lightDirection);
  vec3 V = normalize(cameraPosition - vWorldPosition);
  float TL = dot(T, L);
  float TV = dot(T, V);
  float sinTL = sqrt(max(0.0, 1.0 - TL * TL));
  float sinTV = sqrt(max(0.0, 1.0 - TV * TV));
  // Kajiya-Kay: diffuse ~ sin(T, L); specular peaks where V lies on the cone of reflection
  // around T: cos(angle(T, V) - (pi - angle(T, L))) = sinTL sinTV - TL TV.
  float diffuse = sinTL;
  float cosCone = max(0.0, sinTL * sinTV - TL * TV);
  float primary = pow(cosCone, specularPower);
  float secondary = pow(cosCone, secondaryPower);

  float shade = 1.0 + colorVariation * (2.0 * vRandom - 1.0);
  float root = mix(1.0 - rootDarkening, 1.0, smoothstep(0.0, 0.45, vAlong));
  vec3 base = hairColor * shade * root;

  vec3 toPoint = vWorldPosition - headCenter;
  float facing = dot(normalize(toPoint + 1e-6), L);
  float lit = mix(1.0, smoothstep(-0.45, 0.35, facing), selfShadow);

  vec3 color = base * ambientColor
    + lit * lightColor * (diffuseStrength * diffuse * base
    + specularStrength * primary * vec3(1.0)
    + secondaryStrength * secondary * hairColor * root);
  gl_FragColor = vec4(color, 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
}
`;

export interface StrandMaterialOptions {
  color?: THREE.ColorRepresentation; // hair colour (CSS string, hex number or THREE.Color)
  lightDirection?: [number, number, number]; // world space, toward the light
  lightColor?: THREE.ColorRepresentation;
  ambient?: THREE.ColorRepresentation;
  headCenter?: [number, number, number];
}

/** Uniform names of the strand material (all `{ value }` objects, settable at any time). */
export interface StrandUniforms {
  [name: string]: THREE.IUniform;
  hairColor: THREE.IUniform<THREE.Color>;
  lightDirection: THREE.IUniform<THREE.Vector3>;
  lightColor: THREE.IUniform<THREE.Color>;
  ambientColor: THREE.IUniform<THREE.Color>;
  headCenter: THREE.IUniform<THREE.Vector3>;
  selfShadow: THREE.IUniform<number>;
  diffuseStrength: THREE.IUniform<number>;
  specularStrength: THREE.IUniform<number>;
  specularPower: THREE.IUniform<number>;
  secondaryStrength: THREE.IUniform<number>;
  secondaryPower: THREE.IUniform<number>;
  rootDarkening: THREE.IUniform<number>;
  colorVariation: THREE.IUniform<number>;
}

export type StrandMaterial = THREE.ShaderMaterial & { uniforms: StrandUniforms };

export function createStrandMaterial(options: StrandMaterialOptions = {}): StrandMaterial {
  const light = options.lightDirection ?? [0.45, 0.8, 0.55];
  const center = options.headCenter ?? [0, 0, 0];
  const uniforms: StrandUniforms = {
    hairColor: { value: new THREE.Color(options.color ?? '#5a3825') },
    lightDirection: { value: new THREE.Vector3(...light).normalize() },
    lightColor: { value: new THREE.Color(options.lightColor ?? '#ffffff') },
    ambientColor: { value: new THREE.Color(options.ambient ?? '#6e6e6e') },
    headCenter: { value: new THREE.Vector3(...center) },
    selfShadow: { value: 0.7 },
    diffuseStrength: { value: 0.9 },
    specularStrength: { value: 0.22 },
    specularPower: { value: 80 },
    secondaryStrength: { value: 0.35 },
    secondaryPower: { value: 12 },
    rootDarkening: { value: 0.35 },
    colorVariation: { value: 0.12 },
  };
  const material = new THREE.ShaderMaterial({ uniforms, vertexShader, fragmentShader });
  material.name = 'KajiyaKayStrands';
  return material as StrandMaterial;
}

/** Set the hair colour (CSS string, hex number or THREE.Color). */
export function setHairColor(material: StrandMaterial, color: THREE.ColorRepresentation): void {
  material.uniforms.hairColor.value.set(color);
}

/** Set the light direction (world space, toward the light; need not be unit). */
export function setLightDirection(material: StrandMaterial, x: number, y: number, z: number): void {
  material.uniforms.lightDirection.value.set(x, y, z).normalize();
}

/** Strands are drawn in this many interleaved groups (see buildStrandGeometry). */
export const LOD_GROUPS = 64;
const LOD_ORDER = Array.from({ length: LOD_GROUPS }, (_, g) => {
  let r = 0;
  for (let b = 1, x = g; b < LOD_GROUPS; b <<= 1, x >>= 1) r = (r << 1) | (x & 1);
  return r;
});

/** Build indexed LineSegments geometry for strands. Strand s owns points
 *  strandStart[s] .. strandStart[s + 1] − 1 of `points` (points[3 * point + axis]); each pair of
 *  consecutive points is a segment. The `position` attribute views `points` (not copied: do not
 *  change it afterwards). Added per point: `tangent` (unit, central differences; one-sided at the
 *  ends; Int8 normalised), `along` (0 at the root … 1 at the tip; Uint8 normalised) and
 *  `strandRandom` (per strand, in [0, 1]: a hash of the strand index and `colorSeed`; Uint8
 *  normalised).
 *  Level of detail: the index lists strands interleaved (stride LOD_GROUPS, groups in
 *  bit-reversed order), so any prefix of the groups is an even sample of the whole head of hair;
 *  `userData.lodCounts[g]` is the index count of the first g groups (a draw range). */
export function buildStrandGeometry(
  points: Float32Array,
  strandStart: Uint32Array,
  colorSeed = 0,
): THREE.BufferGeometry {
  const strands = Math.max(0, strandStart.length - 1);
  const pointCount = strands > 0 ? strandStart[strands] : 0;
  if (3 * pointCount > points.length) throw new Error('strandStart exceeds the points array');
  // compact, normalised attributes: tangent as signed bytes (÷127), along and strandRandom as
  // unsigned bytes (÷255); the shader reads floats either way
  const tangent = new Int8Array(3 * pointCount);
  const along = new Uint8Array(pointCount);
  const random = new Uint8Array(pointCount);
  let segments = 0;
  for (let s = 0; s < strands; s++) {
    const n = strandStart[s + 1] - strandStart[s];
    if (n > 1) segments += n - 1;
  }
  const index = new Uint32Array(2 * segments);
  let w = 0;
  const seedMix = Math.imul(colorSeed >>> 0, 0x9e3779b1);
  let minX = Infinity;
  let minY = Infinity;
  let minZ = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  let maxZ = -Infinity;
  for (let s = 0; s < strands; s++) {
    const a = strandStart[s];
    const b = strandStart[s + 1];
    const n = b - a;
    if (n <= 0) continue;
    const r = hash32(s ^ seedMix) >>> 24; // 0..255
    const inv = n > 1 ? 255 / (n - 1) : 0;
    let tx = 0;
    let ty = 127;
    let tz = 0;
    for (let i = a; i < b; i++) {
      const px = points[3 * i];
      const py = points[3 * i + 1];
      const pz = points[3 * i + 2];
      if (px < minX) minX = px;
      if (px > maxX) maxX = px;
      if (py < minY) minY = py;
      if (py > maxY) maxY = py;
      if (pz < minZ) minZ = pz;
      if (pz > maxZ) maxZ = pz;
      const i0 = i > a ? i - 1 : i;
      const i1 = i < b - 1 ? i + 1 : i;
      const dx = points[3 * i1] - points[3 * i0];
      const dy = points[3 * i1 + 1] - points[3 * i0 + 1];
      const dz = points[3 * i1 + 2] - points[3 * i0 + 2];
      const l = Math.sqrt(dx * dx + dy * dy + dz * dz);
      if (l > 1e-12) {
        const k = 127 / l;
        tx = Math.round(dx * k);
        ty = Math.round(dy * k);
        tz = Math.round(dz * k);
      }
      tangent[3 * i] = tx;
      tangent[3 * i + 1] = ty;
      tangent[3 * i + 2] = tz;
      along[i] = Math.round((i - a) * inv);
      random[i] = r;
    }
  }
  const lodCounts = new Uint32Array(LOD_GROUPS + 1);
  for (let g = 0; g < LOD_GROUPS; g++) {
    for (let s = LOD_ORDER[g]; s < strands; s += LOD_GROUPS) {
      for (let i = strandStart[s]; i + 1 < strandStart[s + 1]; i++) {
        index[w++] = i;
        index[w++] = i + 1;
      }
    }
    lodCounts[g + 1] = w;
  }
  const geometry = new THREE.BufferGeometry();
  geometry.userData.lodCounts = lodCounts;
  const used = pointCount === points.length / 3 ? points : points.subarray(0, 3 * pointCount);
  geometry.setAttribute('position', new THREE.BufferAttribute(used, 3));
  geometry.setAttribute('tangent', new THREE.BufferAttribute(tangent, 3, true));
  geometry.setAttribute('along', new THREE.BufferAttribute(along, 1, true));
  geometry.setAttribute('strandRandom', new THREE.BufferAttribute(random, 1, true));
  geometry.setIndex(new THREE.BufferAttribute(index, 1));
  // bounds from the loop above (three's computeBoundingSphere takes ~40× longer on 4M points);
  // the sphere around the box is conservative, which is all culling and picking need
  if (pointCount > 0) {
    geometry.boundingBox = new THREE.Box3(
      new THREE.Vector3(minX, minY, minZ),
      new THREE.Vector3(maxX, maxY, maxZ),
    );
    const center = geometry.boundingBox.getCenter(new THREE.Vector3());
    const radius = 0.5 * Math.hypot(maxX - minX, maxY - minY, maxZ - minZ);
    geometry.boundingSphere = new THREE.Sphere(center, radius);
  } else {
    geometry.boundingBox = new THREE.Box3();
    geometry.boundingSphere = new THREE.Sphere(new THREE.Vector3(), 0);
  }
  return geometry;
}

/** 32-bit integer hash (lowbias32, Chris Wellons). */
function hash32(x: number): number {
  let h = x >>> 0;
  h ^= h >>> 16;
  h = Math.imul(h, 0x7feb352d);
  h ^= h >>> 15;
  h = Math.imul(h, 0x846ca68b);
  h ^= h >>> 16;
  return h >>> 0;
}
