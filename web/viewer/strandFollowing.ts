// A motion drawn on the hair shown without moving a vertex on the CPU: the followers' attributes
// (model/guideFollowers.ts followerAttributes) go on the strand geometry once, each frame the
// guides' points and tangents go into two float textures and the head's pose into uniforms, and
// the strand shader places every point (followerGlsl.ts). The geometry's positions stay the
// groom's, so the groom is back bit for bit the moment following stops.
import * as THREE from 'three';
import { type FollowerAttributes, guideTangents } from '../model/guideFollowers';
import { type FollowerUniforms, GUIDES_PER_ROW } from './followerGlsl';
import { bothSides } from './strandGeometry';

/** The hair objects the strand builders make: lines (one vertex a point) or strips (two). */
type StrandObject = THREE.LineSegments | THREE.Mesh;

/** Puts the followers' attributes on a strand object's geometry (false: its vertices are not
 *  these points, once or twice each; nothing done). The object is no longer culled by its
 *  groomed bounds (the hair moves past them). */
export function attachFollowers(object: StrandObject, attrs: FollowerAttributes): boolean {
  const g = object.geometry as THREE.BufferGeometry;
  const points = attrs.follow.length / 2;
  const vertices = g.getAttribute('position')?.count ?? -1;
  const per = vertices === points ? 1 : vertices === 2 * points ? 2 : 0;
  if (per === 0) return false;
  const set = (
    name: string,
    array: Float32Array | Int8Array,
    size: number,
    normalized: boolean,
  ) => {
    const data = per === 1 ? array : bothSides(array, size);
    const old = g.getAttribute(name);
    // the same buffer again when the geometry had one (a geometry's GL buffers are freed with it)
    if (old instanceof THREE.BufferAttribute && old.array.length === data.length) {
      old.array = data;
      old.needsUpdate = true;
    } else g.setAttribute(name, new THREE.BufferAttribute(data, size, normalized));
  };
  set('follow', attrs.follow, 2, false);
  set('followOffset', attrs.offset, 3, false);
  set('followTangent', attrs.tangent, 3, true);
  object.frustumCulled = false;
  return true;
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
