// A motion drawn on the hair shown without moving a vertex on the CPU: the followers' attributes
// (model/guideFollowers.ts followerAttributes) go on the strand geometry once, each frame the
// guides' points and tangents go into two float textures and the head's pose into uniforms, and
// the strand shader places every point (followerGlsl.ts). The groom's geometry keeps its
// positions, so the groom is back bit for bit the moment following stops. Where a frame cannot
// draw every point (a software rasteriser), a geometry of every few points of every strand
// stands in for it while the motion plays (thinForMotion).
import * as THREE from 'three';
import { type FollowerAttributes, guideTangents } from '../model/guideFollowers';
import { everyNthPoint } from '../model/strandSubsample';
import { type FollowerUniforms, GUIDES_PER_ROW } from './followerGlsl';
import { lodIndex } from './strandAttributes';
import { STRIP_SEGMENT } from './strandGeometry';

/** The hair objects the strand builders make: lines (one vertex a point) or strips (two). */
type StrandObject = THREE.LineSegments | THREE.Mesh;

/** Vertices a point of `object` has for these attributes' points: lines 1, strips 2; 0 when its
 *  vertices are not these points. */
function verticesPerPoint(object: StrandObject, attrs: FollowerAttributes): number {
  const points = attrs.follow.length / 2;
  const vertices = object.geometry.getAttribute('position')?.count ?? -1;
  return vertices === points ? 1 : vertices === 2 * points ? 2 : 0;
}

/** `size` values an item of `src` for the points `points` (all when null), each `per` times. */
function pick<T extends Float32Array | Int8Array | Uint8Array | Uint32Array>(
  src: T,
  size: number,
  per: number,
  points: Uint32Array | null,
): T {
  if (!points && per === 1) return src;
  const n = points ? points.length : src.length / size;
  const out = new (src.constructor as { new (n: number): T })(per * size * n);
  for (let i = 0; i < n; i++) {
    const from = (points ? points[i] : i) * size;
    for (let side = 0; side < per; side++)
      for (let c = 0; c < size; c++) out[(per * i + side) * size + c] = src[from + c];
  }
  return out;
}

/** The followers' vertex attributes, `per` vertices a point, over `points` (null: all). */
function followerVertexAttributes(
  attrs: FollowerAttributes,
  per: number,
  points: Uint32Array | null,
): [string, THREE.BufferAttribute][] {
  return [
    ['follow', new THREE.BufferAttribute(pick(attrs.follow, 2, per, points), 2)],
    ['followOffset', new THREE.BufferAttribute(pick(attrs.offset, 3, per, points), 3)],
    ['followTangent', new THREE.BufferAttribute(pick(attrs.tangent, 3, per, points), 3, true)],
  ];
}

/** Puts the followers' attributes on a strand object's geometry (false: its vertices are not
 *  these points, once or twice each; nothing done). The object is no longer culled by its
 *  groomed bounds (the hair moves past them). */
export function attachFollowers(object: StrandObject, attrs: FollowerAttributes): boolean {
  const per = verticesPerPoint(object, attrs);
  if (per === 0) return false;
  const g = object.geometry as THREE.BufferGeometry;
  for (const [name, a] of followerVertexAttributes(attrs, per, null)) {
    const old = g.getAttribute(name);
    // the same buffer again when the geometry had one (a geometry's GL buffers are freed with it)
    if (old instanceof THREE.BufferAttribute && old.array.length === a.array.length) {
      old.array = a.array;
      old.needsUpdate = true;
    } else g.setAttribute(name, a);
  }
  object.frustumCulled = false;
  return true;
}

/** Draws a strand object with every `stride`-th point of each strand and its tip, blended
 *  unsorted (a motion on a slow renderer: every strand, fewer segments, one pass), following
 *  its guides (`attrs`: of those points, in order): a geometry of those points only stands in
 *  for the object's own until the returned function puts it back. Null (nothing done) when the
 *  object's vertices are not the strands' points, or `attrs` not those of the points kept. */
export function thinForMotion(
  object: StrandObject,
  strandStart: Uint32Array,
  attrs: FollowerAttributes,
  stride: number,
): (() => void) | null {
  const g = object.geometry as THREE.BufferGeometry;
  const { points, start } = everyNthPoint(strandStart, stride);
  const pointCount = strandStart.length > 0 ? strandStart[strandStart.length - 1] : 0;
  const vertices = g.getAttribute('position')?.count ?? -1;
  const per = vertices === pointCount ? 1 : vertices === 2 * pointCount ? 2 : 0;
  if (per === 0 || attrs.follow.length !== 2 * points.length) return null;
  const thin = new THREE.BufferGeometry();
  for (const [name, a] of Object.entries(g.attributes)) {
    if (!(a instanceof THREE.BufferAttribute) || name.startsWith('follow')) continue;
    const array = pick(a.array as Float32Array, a.itemSize, per, points);
    thin.setAttribute(name, new THREE.BufferAttribute(array, a.itemSize, a.normalized));
  }
  for (const [name, a] of followerVertexAttributes(attrs, per, null)) thin.setAttribute(name, a);
  const made = lodIndex(start, per === 2 ? STRIP_SEGMENT : [0, 1], per);
  thin.setIndex(new THREE.BufferAttribute(made.index, 1));
  thin.userData.lodCounts = made.lodCounts;
  thin.userData.strands = g.userData.strands;
  thin.userData.motionPoints = points; // the point each pair (strips) or vertex (lines) is
  const oit = object.userData.oit as unknown;
  object.geometry = thin;
  object.frustumCulled = false;
  delete object.userData.oit;
  return () => {
    object.geometry = g;
    if (oit) object.userData.oit = oit;
    thin.dispose();
  };
}

/** The guides as the strand shader reads them: positions and unit tangents, RGBA float
 *  textures of GUIDES_PER_ROW guides a row. */
export class GuideTextures {
  readonly positions: THREE.DataTexture;
  readonly tangents: THREE.DataTexture;
  private readonly tangent: Float32Array<ArrayBuffer>;

  constructor(
    readonly guideCount: number,
    readonly guidePoints: number,
  ) {
    const width = GUIDES_PER_ROW * guidePoints;
    const height = Math.max(1, Math.ceil(guideCount / GUIDES_PER_ROW));
    const make = () => {
      const t = new THREE.DataTexture(
        new Float32Array(4 * width * height),
        width,
        height,
        THREE.RGBAFormat,
        THREE.FloatType,
      );
      t.minFilter = THREE.NearestFilter;
      t.magFilter = THREE.NearestFilter;
      t.generateMipmaps = false;
      return t;
    };
    this.positions = make();
    this.tangents = make();
    this.tangent = new Float32Array(3 * guideCount * guidePoints);
  }

  /** The guides now (3 * (guide * G + point) + axis). */
  update(guides: Float32Array): void {
    const G = this.guidePoints;
    guideTangents(guides, G, this.tangent);
    const pos = this.positions.image.data as Float32Array;
    const tan = this.tangents.image.data as Float32Array;
    const width = GUIDES_PER_ROW * G;
    for (let g = 0; g < this.guideCount; g++) {
      const row = Math.floor(g / GUIDES_PER_ROW);
      const first = row * width + (g % GUIDES_PER_ROW) * G;
      for (let j = 0; j < G; j++) {
        const i = 3 * (g * G + j);
        const o = 4 * (first + j);
        pos[o] = guides[i];
        pos[o + 1] = guides[i + 1];
        pos[o + 2] = guides[i + 2];
        tan[o] = this.tangent[i];
        tan[o + 1] = this.tangent[i + 1];
        tan[o + 2] = this.tangent[i + 2];
      }
    }
    this.positions.needsUpdate = true;
    this.tangents.needsUpdate = true;
  }

  /** Points `u` at these textures with the head's pose (pose[0..8] rotation row-major,
   *  pose[9..11] translation), following on. */
  bind(u: FollowerUniforms, pose: ArrayLike<number>): void {
    u.followGuides.value = 1;
    u.guidePositions.value = this.positions;
    u.guideTangents.value = this.tangents;
    u.guidePoints.value = this.guidePoints;
    u.followRotation.value.set(
      pose[0],
      pose[1],
      pose[2],
      pose[3],
      pose[4],
      pose[5],
      pose[6],
      pose[7],
      pose[8],
    );
    u.followTranslation.value.set(pose[9], pose[10], pose[11]);
  }

  dispose(): void {
    this.positions.dispose();
    this.tangents.dispose();
  }
}

/** Following off: the hair is drawn as groomed. */
export function unbindFollowers(u: FollowerUniforms): void {
  u.followGuides.value = 0;
  u.guidePositions.value = null;
  u.guideTangents.value = null;
}
