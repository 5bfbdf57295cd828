// Naive surface nets: polygonise the zero level set of a scalar field sampled on a uniform grid.
// One vertex per grid cell that the surface crosses (the mean of its edge crossings), one quad
// (two triangles, split along the shorter diagonal) per grid edge with a sign change, oriented
// so that triangles wind counter-clockwise seen from outside (field > 0 outside).

export interface SampledField {
  values: Float32Array; // values[i + nx * (j + ny * k)], negative inside
  dims: [number, number, number]; // nx, ny, nz grid points
  origin: [number, number, number]; // world position of point (0, 0, 0)
  step: number; // grid step h, world units
}

export interface TriangleMesh {
  positions: Float32Array; // positions[3 * vertex + axis]
  indices: Uint32Array; // indices[3 * triangle + corner]
}

/** Sample f on the grid. With `lipschitz` given (an upper bound L of |∇f|), f is first sampled
 *  on a grid 4× coarser and f is evaluated only at fine points that may lie within one fine step
 *  of the surface: a point p whose nearest coarse corner c has |f(c)| > L (|p − c| + step)
 *  gets the bound f(c) ∓ L |p − c| instead, which has the right sign, as do all its grid
 *  neighbours, so every grid edge crossing the surface has exact values at both ends. */
export function sampleField(
  f: (x: number, y: number, z: number) => number,
  dims: [number, number, number],
  origin: [number, number, number],
  step: number,
  lipschitz?: number,
): SampledField {
  const [nx, ny, nz] = dims;
  const values = new Float32Array(nx * ny * nz);
  if (lipschitz === undefined) {
    let p = 0;
    for (let k = 0; k < nz; k++) {
      const z = origin[2] + step * k;
      for (let j = 0; j < ny; j++) {
        const y = origin[1] + step * j;
        for (let i = 0; i < nx; i++) values[p++] = f(origin[0] + step * i, y, z);
      }
    }
    return { values, dims, origin, step };
  }
  const C = 4;
  const cx = Math.ceil((nx - 1) / C) + 1;
  const cy = Math.ceil((ny - 1) / C) + 1;
  const cz = Math.ceil((nz - 1) / C) + 1;
  const coarse = sampleField(f, [cx, cy, cz], origin, step * C).values;
  const L = lipschitz;
  const far = L * step * (C * Math.sqrt(3) + 1);
  const corners = new Float64Array(8);
  for (let K = 0; K < cz - 1; K++) {
    for (let J = 0; J < cy - 1; J++) {
      for (let I = 0; I < cx - 1; I++) {
        const b = I + cx * (J + cy * K);
        corners[0] = coarse[b];
        corners[1] = coarse[b + 1];
        corners[2] = coarse[b + cx];
        corners[3] = coarse[b + 1 + cx];
        corners[4] = coarse[b + cx * cy];
        corners[5] = coarse[b + 1 + cx * cy];
        corners[6] = coarse[b + cx + cx * cy];
        corners[7] = coarse[b + 1 + cx + cx * cy];
        let lo = corners[0];
        let hi = corners[0];
        for (let c = 1; c < 8; c++) {
          if (corners[c] < lo) lo = corners[c];
          if (corners[c] > hi) hi = corners[c];
        }
        const allFar = lo > far || hi < -far;
        // each fine point once: upper ends exclusive except in the last coarse cell
        const i1 = I === cx - 2 ? nx - 1 : Math.min(C * I + C - 1, nx - 1);
        const j1 = J === cy - 2 ? ny - 1 : Math.min(C * J + C - 1, ny - 1);
        const k1 = K === cz - 2 ? nz - 1 : Math.min(C * K + C - 1, nz - 1);
        for (let k = C * K; k <= k1; k++) {
          const dk = k - C * K;
          const ck = dk * 2 > C ? 1 : 0;
          const ek = dk - ck * C;
          const z = origin[2] + step * k;
          for (let j = C * J; j <= j1; j++) {
            const dj = j - C * J;
            const cj = dj * 2 > C ? 1 : 0;
            const ej = dj - cj * C;
            const y = origin[1] + step * j;
            let p = C * I + nx * (j + ny * k);
            for (let i = C * I; i <= i1; i++, p++) {
              const di = i - C * I;
              const ci = di * 2 > C ? 1 : 0;
              const ei = di - ci * C;
              const c = corners[ci + 2 * cj + 4 * ck];
              const d = L * step * Math.sqrt(ei * ei + ej * ej + ek * ek);
              if (allFar || Math.abs(c) > d + L * step) values[p] = c > 0 ? c - d : c + d;
              else values[p] = f(origin[0] + step * i, y, z);
            }
          }
        }
      }
    }
  }
  return { values, dims, origin, step };
}

// Cube corner c = (c & 1, (c >> 1) & 1, (c >> 2) & 1); the 12 cube edges as corner pairs.
const EDGES = [0, 1, 2, 3, 4, 5, 6, 7, 0, 2, 1, 3, 4, 6, 5, 7, 0, 4, 1, 5, 2, 6, 3, 7];

/** Polygonise the sampled field. The surface must not touch the grid's outer layer of points
 *  (all boundary values positive), so that the result is closed. */
export function surfaceNets(field: SampledField): TriangleMesh {
  const { dims, origin, step } = field;
  const [nx, ny, nz] = dims;
  const values = field.values.slice();
  disambiguateFaces(values, dims);
  const sx = 1;
  const sy = nx;
  const sz = nx * ny;
  const cellVertex = new Int32Array(nx * ny * nz).fill(-1); // indexed by the cell's min corner
  let positions = new Float32Array(3 * 65536);
  let vertexCount = 0;
  const corner = new Float64Array(8);
  const cornerOffset = [0, sx, sy, sx + sy, sz, sx + sz, sy + sz, sx + sy + sz];

  for (let k = 0; k < nz - 1; k++) {
    for (let j = 0; j < ny - 1; j++) {
      for (let i = 0; i < nx - 1; i++) {
        const base = i + nx * (j + ny * k);
        let mask = 0;
        for (let c = 0; c < 8; c++) {
          const v = values[base + cornerOffset[c]];
          corner[c] = v;
          if (v < 0) mask |= 1 << c;
        }
        if (mask === 0 || mask === 255) continue;
        let ax = 0;
        let ay = 0;
        let az = 0;
        let n = 0;
        for (let e = 0; e < 24; e += 2) {
          const c0 = EDGES[e];
          const c1 = EDGES[e + 1];
          const in0 = (mask >> c0) & 1;
          const in1 = (mask >> c1) & 1;
          if (in0 === in1) continue;
          const t = corner[c0] / (corner[c0] - corner[c1]);
          ax += (c0 & 1) + ((c1 & 1) - (c0 & 1)) * t;
          ay += ((c0 >> 1) & 1) + (((c1 >> 1) & 1) - ((c0 >> 1) & 1)) * t;
          az += ((c0 >> 2) & 1) + (((c1 >> 2) & 1) - ((c0 >> 2) & 1)) * t;
          n++;
        }
        if (3 * vertexCount + 3 > positions.length) {
          const grown = new Float32Array(positions.length * 2);
          grown.set(positions);
          positions = grown;
        }
        positions[3 * vertexCount] = origin[0] + step * (i + ax / n);
        positions[3 * vertexCount + 1] = origin[1] + step * (j + ay / n);
        positions[3 * vertexCount + 2] = origin[2] + step * (k + az / n);
        cellVertex[base] = vertexCount++;
      }
    }
  }

  const P = positions.subarray(0, 3 * vertexCount);
  // count the quads first, so the index array is allocated once
  let quads = 0;
  for (let k = 1; k < nz - 1; k++) {
    for (let j = 1; j < ny - 1; j++) {
      for (let i = 1; i < nx - 1; i++) {
        const p = i + nx * (j + ny * k);
        const inside = values[p] < 0;
        if (inside !== values[p + sx] < 0) quads++;
        if (inside !== values[p + sy] < 0) quads++;
        if (inside !== values[p + sz] < 0) quads++;
      }
    }
  }
  const indices = new Uint32Array(6 * quads);
  let o = 0;
  for (let k = 1; k < nz - 1; k++) {
    for (let j = 1; j < ny - 1; j++) {
      for (let i = 1; i < nx - 1; i++) {
        const p = i + nx * (j + ny * k);
        const inside = values[p] < 0;
        // x edge p → p + sx: cells (i, j-1..j, k-1..k); quad in the (y, z) plane, normal +x
        if (inside !== values[p + sx] < 0) {
          const a = cellVertex[p - sy - sz];
          const b = cellVertex[p - sz];
          const c = cellVertex[p];
          const d = cellVertex[p - sy];
          o = inside ? emitQuad(indices, o, P, a, b, c, d) : emitQuad(indices, o, P, d, c, b, a);
        }
        // y edge: cells (i-1..i, j, k-1..k); quad in the (z, x) plane, normal +y
        if (inside !== values[p + sy] < 0) {
          const a = cellVertex[p - sz - sx];
          const b = cellVertex[p - sx];
          const c = cellVertex[p];
          const d = cellVertex[p - sz];
          o = inside ? emitQuad(indices, o, P, a, b, c, d) : emitQuad(indices, o, P, d, c, b, a);
        }
        // z edge: cells (i-1..i, j-1..j, k); quad in the (x, y) plane, normal +z
        if (inside !== values[p + sz] < 0) {
          const a = cellVertex[p - sx - sy];
          const b = cellVertex[p - sy];
          const c = cellVertex[p];
          const d = cellVertex[p - sx];
          o = inside ? emitQuad(indices, o, P, a, b, c, d) : emitQuad(indices, o, P, d, c, b, a);
        }
      }
    }
  }
  return { positions: P, indices };
}

/** Write quad a-b-c-d (counter-clockwise) as two triangles split along the shorter diagonal at
 *  indices[o…o+5]; returns o + 6. */
function emitQuad(
  indices: Uint32Array,
  o: number,
  P: Float32Array,
  a: number,
  b: number,
  c: number,
  d: number,
): number {
  if (dist2(P, a, c) <= dist2(P, b, d)) {
    indices[o] = a;
    indices[o + 1] = b;
    indices[o + 2] = c;
    indices[o + 3] = a;
    indices[o + 4] = c;
    indices[o + 5] = d;
  } else {
    indices[o] = a;
    indices[o + 1] = b;
    indices[o + 2] = d;
    indices[o + 3] = b;
    indices[o + 4] = c;
    indices[o + 5] = d;
  }
  return o + 6;
}

function dist2(pos: Float32Array, a: number, b: number): number {
  const dx = pos[3 * a] - pos[3 * b];
  const dy = pos[3 * a + 1] - pos[3 * b + 1];
  const dz = pos[3 * a + 2] - pos[3 * b + 2];
  return dx * dx + dy * dy + dz * dz;
}

/** Remove ambiguous grid faces (signs alternating around the face, which would make the dual
 *  edge between the two cells on either side part of four quads): flip the sign of the corner
 *  nearest to zero, moving the surface by less than one step there. Repeats until no face is
 *  ambiguous (flips can create new ambiguous faces nearby, rarely). Returns the flip count. */
export function disambiguateFaces(values: Float32Array, dims: [number, number, number]): number {
  const [nx, ny, nz] = dims;
  const sx = 1;
  const sy = nx;
  const sz = nx * ny;
  let flips = 0;
  for (let pass = 0; pass < 8; pass++) {
    let changed = 0;
    for (let k = 0; k < nz; k++) {
      for (let j = 0; j < ny; j++) {
        for (let i = 0; i < nx; i++) {
          const p = i + nx * (j + ny * k);
          if (i < nx - 1 && j < ny - 1) changed += fixFace(values, p, p + sx, p + sx + sy, p + sy);
          if (j < ny - 1 && k < nz - 1) changed += fixFace(values, p, p + sy, p + sy + sz, p + sz);
          if (k < nz - 1 && i < nx - 1) changed += fixFace(values, p, p + sz, p + sz + sx, p + sx);
        }
      }
    }
    flips += changed;
    if (changed === 0) break;
  }
  return flips;
}

/** Flip the corner nearest to zero of the face q0-q1-q2-q3 if its signs alternate; returns 1
 *  when flipped. */
function fixFace(values: Float32Array, q0: number, q1: number, q2: number, q3: number): number {
  const s0 = values[q0] < 0;
  if (s0 === values[q1] < 0 || s0 !== values[q2] < 0 || s0 === values[q3] < 0) return 0;
  let m = q0;
  if (Math.abs(values[q1]) < Math.abs(values[m])) m = q1;
  if (Math.abs(values[q2]) < Math.abs(values[m])) m = q2;
  if (Math.abs(values[q3]) < Math.abs(values[m])) m = q3;
  values[m] = values[m] < 0 ? 1e-9 : -1e-9;
  return 1;
}
