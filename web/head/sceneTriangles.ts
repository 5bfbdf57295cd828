// The triangles of every mesh in a loaded three.js scene, in world space (instances and mirrored
// transforms included), as one indexed triangle list, with the texture coordinates of every
// vertex when every mesh has them (three's loaders give them as the 'uv' attribute: glTF
// TEXCOORD_0, OBJ vt, PLY s/t or u/v; STL has none).
import * as THREE from 'three';
import { capCheck, HeadFileError } from './headFileError';
import type { IndexedTriangles } from './weldMesh';

/** Every mesh's triangles in world space, one vertex per source vertex (welding comes after),
 *  and `uvs[2 * vertex + k]` when every mesh has UVs. `flipV`: store 1 − v (a glTF's texture
 *  coordinates start at the image's top left; the app keeps OBJ's and USD's, bottom left). */
export function collectTriangles(
  root: THREE.Object3D,
  maxTriangles: number,
  flipV = false,
): IndexedTriangles & { uvs?: Float32Array } {
  root.updateMatrixWorld(true);
  const meshes: { geometry: THREE.BufferGeometry; matrices: THREE.Matrix4[] }[] = [];
  let triangles = 0;
  let vertices = 0;
  root.traverse((o) => {
    const mesh = o as THREE.Mesh;
    if (!mesh.isMesh || !mesh.geometry?.getAttribute('position')) return;
    const geometry = mesh.geometry;
    const position = geometry.getAttribute('position');
    const count = geometry.index ? geometry.index.count : position.count;
    const matrices: THREE.Matrix4[] = [];
    const instanced = o as THREE.InstancedMesh;
    if (instanced.isInstancedMesh) {
      for (let i = 0; i < instanced.count; i++) {
        const m = new THREE.Matrix4();
        instanced.getMatrixAt(i, m);
        matrices.push(m.premultiply(o.matrixWorld));
      }
    } else matrices.push(o.matrixWorld.clone());
    meshes.push({ geometry, matrices });
    triangles += Math.floor(count / 3) * matrices.length;
    vertices += position.count * matrices.length;
  });
  capCheck(triangles, maxTriangles);
  const withUv = meshes.every((m) => m.geometry.getAttribute('uv')?.itemSize === 2);
  if (triangles === 0)
    throw new HeadFileError('it contains no triangles (not a mesh, or an empty one)');
  const positions = new Float32Array(3 * vertices);
  const indices = new Uint32Array(3 * triangles);
  const uvs = withUv ? new Float32Array(2 * vertices) : undefined;
  let v0 = 0;
  let t = 0;
  const p = new THREE.Vector3();
  for (const { geometry, matrices } of meshes) {
    const position = geometry.getAttribute('position');
    const index = geometry.index;
    const uv = geometry.getAttribute('uv');
    const count = Math.floor((index ? index.count : position.count) / 3) * 3;
    for (const matrix of matrices) {
      for (let v = 0; v < position.count; v++) {
        p.fromBufferAttribute(position, v).applyMatrix4(matrix);
        if (!Number.isFinite(p.x) || !Number.isFinite(p.y) || !Number.isFinite(p.z))
          throw new HeadFileError(`vertex ${v + 1} has a non-finite coordinate (NaN or infinity)`);
        positions[3 * (v0 + v)] = p.x;
        positions[3 * (v0 + v) + 1] = p.y;
        positions[3 * (v0 + v) + 2] = p.z;
        if (uvs) {
          const u = uv.getX(v);
          const w = uv.getY(v);
          uvs[2 * (v0 + v)] = u;
          uvs[2 * (v0 + v) + 1] = flipV ? 1 - w : w;
        }
      }
      const mirrored = matrix.determinant() < 0;
      for (let k = 0; k < count; k += 3) {
        const a = index ? index.getX(k) : k;
        let b = index ? index.getX(k + 1) : k + 1;
        let c = index ? index.getX(k + 2) : k + 2;
        if (mirrored) [b, c] = [c, b];
        if (a >= position.count || b >= position.count || c >= position.count)
          throw new HeadFileError('a triangle refers to a vertex that does not exist');
        indices[t++] = v0 + a;
        indices[t++] = v0 + b;
        indices[t++] = v0 + c;
      }
      v0 += position.count;
    }
  }
  // a non-finite UV makes the file's UVs unusable, not the head
  const finite = uvs?.every(Number.isFinite) ?? false;
  return { positions, indices: indices.subarray(0, t), ...(uvs && finite ? { uvs } : {}) };
}
