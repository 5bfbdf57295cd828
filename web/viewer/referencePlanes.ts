// Reference pictures in the view: one textured plane per picture, through the head's middle
// (referenceImage.ts REFERENCE_CENTRE) and facing the camera of its view, drawn before the head
// without depth so the head, the hair and every overlay draw over it. Each plane fades as the
// camera leaves its view (viewFade). The planes never take part in picking: tools cast rays at
// the head's own geometry, and each plane's raycast is empty besides.
import * as THREE from 'three';
import { REFERENCE_CENTRE, type ReferenceImage, viewFade } from '../model/referenceImage';
import type { Vec3 } from '../model/vec3';

/** Drawn first: before the head (renderOrder 0) in the opaque pass. */
const BACKDROP_ORDER = -1000;

const YAW: Record<ReferenceImage['view'], number> = { front: 0, side: Math.PI / 2, back: Math.PI };

interface Plane {
  mesh: THREE.Mesh<THREE.PlaneGeometry, THREE.MeshBasicMaterial>;
  texture: THREE.Texture;
}

export class ReferencePlanes {
  /** Add to the scene once; its children follow `show`. */
  readonly group = new THREE.Group();
  private readonly planes = new Map<string, Plane>();
  private readonly geometry = new THREE.PlaneGeometry(1, 1);

  constructor() {
    this.group.name = 'reference pictures';
  }

  /** Shows `refs` (hidden ones not), each with its decoded picture from `images` (by hash; a
   *  picture without one is not drawn yet). */
  show(refs: readonly ReferenceImage[], images: ReadonlyMap<string, ImageBitmap>): void {
    const wanted = new Set<string>();
    for (const r of refs) {
      const image = images.get(r.hash);
      if (!image || r.hidden) continue;
      wanted.add(r.hash);
      const plane = this.planeFor(r.hash, image);
      place(plane.mesh, r);
    }
    for (const [hash, p] of this.planes)
      if (!wanted.has(hash)) {
        this.group.remove(p.mesh);
        p.mesh.material.dispose();
        p.texture.dispose();
        this.planes.delete(hash);
      }
  }

  /** How many planes are drawn (shown and decoded). */
  get count(): number {
    return this.planes.size;
  }

  private planeFor(hash: string, image: ImageBitmap): Plane {
    const had = this.planes.get(hash);
    if (had && had.texture.image === image) return had;
    if (had) {
      this.group.remove(had.mesh);
      had.mesh.material.dispose();
      had.texture.dispose();
    }
    const texture = new THREE.Texture(image);
    texture.colorSpace = THREE.SRGBColorSpace;
    texture.flipY = false; // an ImageBitmap is uploaded as decoded: flipped at decode time
    texture.needsUpdate = true;
    const material = new THREE.MeshBasicMaterial({
      map: texture,
      // blended without joining the transparent pass (which draws after the head): custom
      // blending applies with `transparent` off
      transparent: false,
      blending: THREE.CustomBlending,
      blendSrc: THREE.SrcAlphaFactor,
      blendDst: THREE.OneMinusSrcAlphaFactor,
      depthTest: false,
      depthWrite: false,
      toneMapped: false,
    });
    const mesh = new THREE.Mesh(this.geometry, material);
    mesh.renderOrder = BACKDROP_ORDER;
    mesh.raycast = () => {};
    const p: Plane = { mesh, texture };
    this.planes.set(hash, p);
    this.group.add(mesh);
    return p;
  }
}

/** Puts `mesh` where picture `r` goes and fades it with the camera as it is drawn. */
function place(mesh: THREE.Mesh<THREE.PlaneGeometry, THREE.MeshBasicMaterial>, r: ReferenceImage) {
  const yaw = YAW[r.view];
  mesh.rotation.set(0, yaw, 0);
  const right = new THREE.Vector3(1, 0, 0).applyAxisAngle(new THREE.Vector3(0, 1, 0), yaw);
  mesh.position
    .set(...REFERENCE_CENTRE)
    .addScaledVector(right, r.offset[0])
    .add(new THREE.Vector3(0, r.offset[1], 0));
  mesh.scale.set((r.scale * r.width) / r.height, r.scale, 1);
  const view = r.view;
  const opacity = r.opacity;
  const centre = new THREE.Vector3(...REFERENCE_CENTRE);
  mesh.onBeforeRender = (_renderer, _scene, camera) => {
    const d = camera.position.clone().sub(centre).normalize();
    mesh.material.opacity = opacity * viewFade(view, [d.x, d.y, d.z] as Vec3);
  };
}
