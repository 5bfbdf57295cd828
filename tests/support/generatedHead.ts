// A generated head for tests (not the built-in one): an ellipsoid with a nose bump, and the OBJ
// a user's tool would write for it. Shared by the loader's unit tests and the Playwright tests
// of Open head.
import type { Vec3 } from '../../web/model/vec3';

export interface Soup {
  positions: Float32Array;
  indices: Uint32Array;
}

/** An ellipsoid head with a nose bump, `rings` × 2·`rings` quads (≈ 4·rings² triangles),
 *  optionally without the triangles whose centroid direction is near `holes`. */
export function ellipsoidHead(rings: number, holes: { dir: Vec3; cosMin: number }[] = []): Soup {
  const segments = 2 * rings;
  const R: Vec3 = [0.8, 1.1, 0.95];
  const positions = new Float32Array(3 * ((rings + 1) * segments));
  let v = 0;
  for (let i = 0; i <= rings; i++) {
    const theta = (Math.PI * i) / rings;
    for (let j = 0; j < segments; j++) {
      const phi = (2 * Math.PI * j) / segments;
      const d: Vec3 = [
        Math.sin(theta) * Math.sin(phi),
        Math.cos(theta),
        Math.sin(theta) * Math.cos(phi),
      ];
      // nose: a bump around θ = 100°, φ = 0 (toward +z)
      const c = d[0] * 0 + d[1] * -0.17 + d[2] * 0.985;
      const bump = 1 + 0.22 * Math.exp(-(1 - c) / 0.004);
      positions[v++] = R[0] * d[0] * bump;
      positions[v++] = R[1] * d[1] * bump;
      positions[v++] = R[2] * d[2] * bump;
    }
  }
  const idx: number[] = [];
  const at = (i: number, j: number) => i * segments + (j % segments);
  const keep = (a: number, b: number, c: number) => {
    if (holes.length === 0) return true;
    const m = [0, 1, 2].map(
      (k) => positions[3 * a + k] + positions[3 * b + k] + positions[3 * c + k],
    );
    const len = Math.hypot(m[0], m[1], m[2]);
    return holes.every(
      (h) => (m[0] * h.dir[0] + m[1] * h.dir[1] + m[2] * h.dir[2]) / len < h.cosMin,
    );
  };
  for (let i = 0; i < rings; i++) {
    for (let j = 0; j < segments; j++) {
      const a = at(i, j);
      const b = at(i + 1, j);
      const c = at(i + 1, j + 1);
      const d = at(i, j + 1);
      // counter-clockwise seen from outside
      if (i > 0 && keep(a, b, d)) idx.push(a, b, d);
      if (i < rings - 1 && keep(d, b, c)) idx.push(d, b, c);
    }
  }
  return { positions, indices: Uint32Array.from(idx) };
}

export function toObj(m: Soup): ArrayBuffer {
  const lines: string[] = ['# generated head', 'o head'];
  const P = m.positions;
  for (let i = 0; i < P.length; i += 3) lines.push(`v ${P[i]} ${P[i + 1]} ${P[i + 2]}`);
  const I = m.indices;
  for (let t = 0; t < I.length; t += 3) lines.push(`f ${I[t] + 1} ${I[t + 1] + 1} ${I[t + 2] + 1}`);
  return new TextEncoder().encode(`${lines.join('\n')}\n`).buffer as ArrayBuffer;
}
