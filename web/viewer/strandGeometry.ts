// Strand geometry (method S6.1): GL line segments (Fast) and camera-facing strips (High) built
// from a groom's points and the per-point attributes of strandAttributes.ts, with levels of
// detail as index prefixes and bounds from the attribute loop.
import * as THREE from 'three';
import { strandCount } from '../model/hairArrays';
import {
  type LineAttributes,
  lineAttributes,
  lodIndex,
  type PointAttributes,
  pointAttributes,
} from './strandAttributes';

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
 *  along the strand, the distance from its tip, its grey rank and balayage section), `strandRandom` (a hash of the strand index
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
  geometry.setAttribute('along', new THREE.BufferAttribute(attrs.along, 4, true));
  geometry.setAttribute('strandRandom', new THREE.BufferAttribute(attrs.random, 4, true));
  geometry.setAttribute('lighting', new THREE.BufferAttribute(attrs.light, 2, true));
}

/** A strip segment's two triangles over the vertices of its two points (2i, 2i + 1, 2j, 2j + 1). */
export const STRIP_SEGMENT = [0, 1, 2, 1, 3, 2] as const;

/** Each point's `size` values twice, for a strip's two sides (vertices 2i and 2i + 1 are point
 *  i's), over its first `count` points. */
export function bothSides<T extends Int8Array | Uint8Array | Float32Array>(
  src: T,
  size: number,
  count = src.length / size,
): T {
  const out = new (src.constructor as { new (n: number): T })(2 * src.length);
  for (let i = 0; i < count; i++)
    for (let c = 0; c < size; c++) {
      const v = src[size * i + c];
      out[2 * size * i + c] = v;
      out[2 * size * i + size + c] = v;
    }
  return out;
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
  const twice = <T extends Int8Array | Uint8Array | Float32Array>(src: T, size: number): T =>
    bothSides(src, size, pointCount);
  // vertices 2i, 2i + 1 are point i's two sides: two triangles per segment
  const { index, lodCounts } = lodIndex(strandStart, STRIP_SEGMENT, 2);
  const geometry = new THREE.BufferGeometry();
  geometry.userData.lodCounts = lodCounts;
  geometry.userData.strands = strandCount({ points, strandStart });
  geometry.setAttribute(
    'position',
    new THREE.BufferAttribute(twice(points.subarray(0, 3 * pointCount), 3), 3),
  );
  setPointAttributes(geometry, {
    tangent: twice(attrs.tangent, 3),
    along: twice(attrs.along, 4),
    random: twice(attrs.random, 4),
    light: twice(attrs.light, 2),
  });
  geometry.setIndex(new THREE.BufferAttribute(index, 1));
  setBounds(geometry, attrs.box);
  return geometry;
}
