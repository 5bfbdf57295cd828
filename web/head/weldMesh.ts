// Triangle-soup helpers for loaded heads: weld vertices that share a position (STL and the OBJ
// loader give one vertex per corner; glTF splits vertices at UV seams) into one indexed mesh,
// drop triangles that collapse, and turn every connected part outward (positive signed volume).
// Texture coordinates go per triangle corner (cornerUvs), so welding across a UV seam keeps each
// side's UVs, and they follow the triangles that are dropped or turned.

/** An indexed triangle mesh: positions[3 * vertex + axis], indices[3 * triangle + corner]. */
export interface IndexedTriangles {
  positions: Float32Array;
  indices: Uint32Array;
  /** cornerUvs[6 * triangle + 2 * corner + k]: the file's UV at each corner, when it has UVs. */
  cornerUvs?: Float32Array;
}

/** Merge vertices with bit-identical positions (after Float32 rounding; -0 equals 0) and drop
 *  triangles that use one vertex twice. `indices` refers to `positions`' vertices; `uvs`
 *  (uvs[2 * vertex + k], optional) become the kept triangles' cornerUvs. */
export function weldByPosition(
  positions: Float32Array,
  indices: Uint32Array,
  uvs?: Float32Array,
): IndexedTriangles {
  const sourceVertices = positions.length / 3;
  const bits = new Uint32Array(3);
  const f = new Float32Array(bits.buffer);
  let size = 16;
  while (size < 2 * sourceVertices) size *= 2;
  const mask = size - 1;
  const table = new Int32Array(size).fill(-1); // welded vertex id
  const out = new Float32Array(positions.length);
  const remap = new Uint32Array(sourceVertices);
  let count = 0;
  for (let v = 0; v < sourceVertices; v++) {
    f[0] = positions[3 * v] + 0; // -0 + 0 = +0
    f[1] = positions[3 * v + 1] + 0;
    f[2] = positions[3 * v + 2] + 0;
    let h =
      Math.imul(bits[0], 0x9e3779b1) ^
      Math.imul(bits[1], 0x85ebca77) ^
      Math.imul(bits[2], 0xc2b2ae3d);
    h ^= h >>> 15;
    let slot = h & mask;
    for (;;) {
      const id = table[slot];
      if (id < 0) {
        table[slot] = count;
        out[3 * count] = f[0];
        out[3 * count + 1] = f[1];
        out[3 * count + 2] = f[2];
        remap[v] = count++;
        break;
      }
      if (out[3 * id] === f[0] && out[3 * id + 1] === f[1] && out[3 * id + 2] === f[2]) {
        remap[v] = id;
        break;
      }
      slot = (slot + 1) & mask;
    }
  }
  const kept = new Uint32Array(indices.length);
  const corners = uvs ? new Float32Array(2 * indices.length) : null;
  let k = 0;
  for (let t = 0; t < indices.length; t += 3) {
    const a = remap[indices[t]];
    const b = remap[indices[t + 1]];
    const c = remap[indices[t + 2]];
    if (a === b || b === c || a === c) continue;
    if (corners && uvs)
      for (let j = 0; j < 3; j++) {
        corners[2 * (k + j)] = uvs[2 * indices[t + j]];
        corners[2 * (k + j) + 1] = uvs[2 * indices[t + j] + 1];
      }
    kept[k++] = a;
    kept[k++] = b;
    kept[k++] = c;
  }
  return {
    positions: out.slice(0, 3 * count),
    indices: kept.slice(0, k),
    ...(corners ? { cornerUvs: corners.slice(0, 2 * k) } : {}),
  };
}

/** Flip, in place, the triangles of every edge-connected part whose signed volume is negative
 *  (a part modelled inside out, or a whole file with clockwise winding), their cornerUvs with
 *  them. Returns how many parts there are and how many were flipped. */
export function orientPartsOutward(mesh: IndexedTriangles): { parts: number; flipped: number } {
  const { positions: P, indices: I } = mesh;
  const vertices = P.length / 3;
  const parent = new Int32Array(vertices);
  for (let v = 0; v < vertices; v++) parent[v] = v;
  const find = (v: number): number => {
    while (parent[v] !== v) {
      parent[v] = parent[parent[v]];
      v = parent[v];
    }
    return v;
  };
  for (let t = 0; t < I.length; t += 3) {
    const a = find(I[t]);
    const b = find(I[t + 1]);
    const c = find(I[t + 2]);
    if (a !== b) parent[b] = a;
    const a2 = find(a);
    if (a2 !== find(c)) parent[find(c)] = a2;
  }
  // reference point: the bounding-box centre (keeps the volume sums of open parts well scaled)
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < P.length; i++) {
    const axis = i % 3;
    if (P[i] < min[axis]) min[axis] = P[i];
    if (P[i] > max[axis]) max[axis] = P[i];
  }
  const o = [0, 1, 2].map((a) => (min[a] + max[a]) / 2);
  const volume = new Float64Array(vertices);
  const triangles = I.length / 3;
  const root = new Int32Array(triangles);
  for (let t = 0; t < triangles; t++) {
    const a = 3 * I[3 * t];
    const b = 3 * I[3 * t + 1];
    const c = 3 * I[3 * t + 2];
    const ax = P[a] - o[0];
    const ay = P[a + 1] - o[1];
    const az = P[a + 2] - o[2];
    const bx = P[b] - o[0];
    const by = P[b + 1] - o[1];
    const bz = P[b + 2] - o[2];
    const cx = P[c] - o[0];
    const cy = P[c + 1] - o[1];
    const cz = P[c + 2] - o[2];
    const r = find(I[3 * t]);
    root[t] = r;
    volume[r] += ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
  }
  let parts = 0;
  let flipped = 0;
  const seen = new Uint8Array(vertices);
  for (let t = 0; t < triangles; t++) {
    const r = root[t];
    if (seen[r]) continue;
    seen[r] = 1;
    parts++;
    if (volume[r] < 0) flipped++;
  }
  if (flipped > 0) {
    for (let t = 0; t < triangles; t++) {
      if (!(volume[root[t]] < 0)) continue;
      const b = I[3 * t + 1];
      I[3 * t + 1] = I[3 * t + 2];
      I[3 * t + 2] = b;
      const U = mesh.cornerUvs;
      if (U)
        for (let k = 0; k < 2; k++) {
          const u = U[6 * t + 2 + k];
          U[6 * t + 2 + k] = U[6 * t + 4 + k];
          U[6 * t + 4 + k] = u;
        }
    }
  }
  return { parts, flipped };
}
