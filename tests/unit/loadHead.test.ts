// Open head (issue 13, part 1): one generated head written by hand as OBJ, GLB, binary PLY and
// binary STL, in mm, cm and m, Y-up and Z-up, loads to the same normalised head; a head with
// separate parts and holes gets a sensible inside test; bad files are refused with a reason;
// and the load of a 100K- and a 1M-triangle head is timed.
import * as THREE from 'three';
import { MeshBVH } from 'three-mesh-bvh';
import { beforeAll, describe, expect, it } from 'vitest';
import { buildHead } from '../../web/head/buildHead';
import { Head, type HeadMesh } from '../../web/head/head';
import {
  BUILTIN_CRANIUM,
  type LoadedHead,
  type LoadHeadResult,
  loadHeadFile,
  rotateLoadedHead,
} from '../../web/head/loadHead';
import { meshInside } from '../../web/head/meshInside';
import { markScalpTriangles } from '../../web/head/scalpRegion';
import type { Vec3 } from '../../web/model/vec3';
import { ellipsoidHead, toObj } from '../support/generatedHead';

interface Soup {
  positions: Float32Array;
  indices: Uint32Array;
}

// ---------------------------------------------------------------------------------------------
// Writers (by hand, as a user's tool would)

function toStl(m: Soup): ArrayBuffer {
  const n = m.indices.length / 3;
  const buf = new ArrayBuffer(84 + 50 * n);
  const view = new DataView(buf);
  view.setUint32(80, n, true);
  let o = 84;
  for (let t = 0; t < n; t++) {
    o += 12; // normal left zero, as many exporters do
    for (let k = 0; k < 3; k++) {
      const v = m.indices[3 * t + k];
      for (let a = 0; a < 3; a++) view.setFloat32(o + 4 * a, m.positions[3 * v + a], true);
      o += 12;
    }
    o += 2;
  }
  return buf;
}

function toPly(m: Soup): ArrayBuffer {
  const nv = m.positions.length / 3;
  const nf = m.indices.length / 3;
  const header = new TextEncoder().encode(
    `ply\nformat binary_little_endian 1.0\ncomment generated head\nelement vertex ${nv}\n` +
      'property float x\nproperty float y\nproperty float z\n' +
      `element face ${nf}\nproperty list uchar int vertex_indices\nend_header\n`,
  );
  const buf = new ArrayBuffer(header.length + 12 * nv + 13 * nf);
  new Uint8Array(buf).set(header);
  const view = new DataView(buf);
  let o = header.length;
  for (let i = 0; i < m.positions.length; i++, o += 4) view.setFloat32(o, m.positions[i], true);
  for (let t = 0; t < nf; t++) {
    view.setUint8(o++, 3);
    for (let k = 0; k < 3; k++, o += 4) view.setInt32(o, m.indices[3 * t + k], true);
  }
  return buf;
}

/** A minimal GLB: one node (with an optional transform) holding one indexed mesh. */
function toGlb(m: Soup, node: Record<string, unknown> = {}): ArrayBuffer {
  const P = m.positions;
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < P.length; i++) {
    min[i % 3] = Math.min(min[i % 3], P[i]);
    max[i % 3] = Math.max(max[i % 3], P[i]);
  }
  const posBytes = P.byteLength;
  const idxBytes = m.indices.byteLength;
  const json = {
    asset: { version: '2.0', generator: 'loadHead.test' },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0, ...node }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1 }] }],
    accessors: [
      { bufferView: 0, componentType: 5126, count: P.length / 3, type: 'VEC3', min, max },
      { bufferView: 1, componentType: 5125, count: m.indices.length, type: 'SCALAR' },
    ],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: posBytes, target: 34962 },
      { buffer: 0, byteOffset: posBytes, byteLength: idxBytes, target: 34963 },
    ],
    buffers: [{ byteLength: posBytes + idxBytes }],
  };
  let jsonBytes = new TextEncoder().encode(JSON.stringify(json));
  const jsonPadded = Math.ceil(jsonBytes.length / 4) * 4;
  const padded = new Uint8Array(jsonPadded).fill(0x20);
  padded.set(jsonBytes);
  jsonBytes = padded;
  const binLength = Math.ceil((posBytes + idxBytes) / 4) * 4;
  const total = 12 + 8 + jsonPadded + 8 + binLength;
  const buf = new ArrayBuffer(total);
  const view = new DataView(buf);
  view.setUint32(0, 0x46546c67, true); // 'glTF'
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, jsonPadded, true);
  view.setUint32(16, 0x4e4f534a, true); // 'JSON'
  new Uint8Array(buf, 20, jsonPadded).set(jsonBytes);
  view.setUint32(20 + jsonPadded, binLength, true);
  view.setUint32(24 + jsonPadded, 0x004e4942, true); // 'BIN\0'
  const bin = new Uint8Array(buf, 28 + jsonPadded, binLength);
  bin.set(new Uint8Array(P.buffer, P.byteOffset, posBytes), 0);
  bin.set(new Uint8Array(m.indices.buffer, m.indices.byteOffset, idxBytes), posBytes);
  return buf;
}

// ---------------------------------------------------------------------------------------------
// Transforms of the generated head

/** Scale (app units → file units) and optionally turn Y-up/+z-front into Z-up/-y-front. */
function exportAs(m: Soup, unitsPerAppUnit: number, zUp = false, offset: Vec3 = [0, 0, 0]): Soup {
  const P = new Float32Array(m.positions.length);
  for (let i = 0; i < P.length; i += 3) {
    const x = m.positions[i];
    const y = m.positions[i + 1];
    const z = m.positions[i + 2];
    const q: Vec3 = zUp ? [x, -z, y] : [x, y, z];
    for (let a = 0; a < 3; a++) P[i + a] = q[a] * unitsPerAppUnit + offset[a];
  }
  return { positions: P, indices: m.indices };
}

function flipWinding(m: Soup): Soup {
  const I = m.indices.slice();
  for (let t = 0; t < I.length; t += 3) [I[t + 1], I[t + 2]] = [I[t + 2], I[t + 1]];
  return { positions: m.positions, indices: I };
}

function sphere(center: Vec3, r: number, rings: number): Soup {
  const s = ellipsoidHead(rings);
  // undo the ellipsoid radii and the bump: project each vertex to the sphere
  const P = s.positions;
  for (let i = 0; i < P.length; i += 3) {
    const len = Math.hypot(P[i], P[i + 1], P[i + 2]);
    for (let a = 0; a < 3; a++) P[i + a] = center[a] + (r * P[i + a]) / len;
  }
  return s;
}

function concat(...parts: Soup[]): Soup {
  const nv = parts.reduce((n, p) => n + p.positions.length, 0);
  const ni = parts.reduce((n, p) => n + p.indices.length, 0);
  const positions = new Float32Array(nv);
  const indices = new Uint32Array(ni);
  let ov = 0;
  let oi = 0;
  for (const p of parts) {
    positions.set(p.positions, ov);
    for (let i = 0; i < p.indices.length; i++) indices[oi + i] = p.indices[i] + ov / 3;
    ov += p.positions.length;
    oi += p.indices.length;
  }
  return { positions, indices };
}

async function mustLoad(name: string, bytes: ArrayBuffer, options = {}): Promise<LoadedHead> {
  const r: LoadHeadResult = await loadHeadFile(name, bytes, options);
  if (!r.ok) throw new Error(r.error);
  return r.head;
}

function sameHead(a: LoadedHead, b: LoadedHead, tol: number): void {
  expect(b.mesh.indices.length).toBe(a.mesh.indices.length);
  for (let k = 0; k < 3; k++) {
    expect(Math.abs(b.mesh.bounds.min[k] - a.mesh.bounds.min[k])).toBeLessThan(tol);
    expect(Math.abs(b.mesh.bounds.max[k] - a.mesh.bounds.max[k])).toBeLessThan(tol);
  }
  // every 97th vertex of a lies on b
  const P = a.mesh.positions;
  for (let v = 0; v < P.length / 3; v += 97) {
    const p: Vec3 = [P[3 * v], P[3 * v + 1], P[3 * v + 2]];
    expect(b.head.closest(p).distance).toBeLessThan(tol);
  }
  // and the same signed distance off the surface
  for (const p of [
    [0, 0, 0],
    [0.3, 1.4, -0.2],
    [-1.2, -0.5, 0.4],
    [0.1, -0.3, 1.6],
  ] as Vec3[]) {
    expect(Math.abs(b.signedDistance(p) - a.signedDistance(p))).toBeLessThan(tol);
  }
}

// ---------------------------------------------------------------------------------------------

let builtin: HeadMesh;
let reference: LoadedHead;

beforeAll(async () => {
  builtin = buildHead();
  reference = await mustLoad('builtin.obj', toObj(builtin));
});

describe('normalisation', () => {
  it("the built-in head's cranium constants are measured on buildHead()", () => {
    const P = builtin.positions;
    let top = -Infinity;
    for (let i = 1; i < P.length; i += 3) top = Math.max(top, P[i]);
    let x0 = Infinity;
    let x1 = -Infinity;
    let z0 = Infinity;
    let z1 = -Infinity;
    for (let i = 0; i < P.length; i += 3) {
      if (P[i + 1] < top - BUILTIN_CRANIUM.band) continue;
      x0 = Math.min(x0, P[i]);
      x1 = Math.max(x1, P[i]);
      z0 = Math.min(z0, P[i + 2]);
      z1 = Math.max(z1, P[i + 2]);
    }
    expect(Math.abs(top - BUILTIN_CRANIUM.top)).toBeLessThan(1e-3);
    expect(Math.abs(x1 - x0 - BUILTIN_CRANIUM.width)).toBeLessThan(1e-3);
    expect(Math.abs((x0 + x1) / 2 - BUILTIN_CRANIUM.centerX)).toBeLessThan(1e-3);
    expect(Math.abs((z0 + z1) / 2 - BUILTIN_CRANIUM.centerZ)).toBeLessThan(1e-3);
  });

  it('the built-in head loaded from a file (app units) stays where it is, with the same scalp', () => {
    expect(reference.unit).toBe('dm');
    expect(reference.up).toBe('y');
    expect(reference.parts).toBe(1);
    expect(reference.flippedParts).toBe(0);
    expect(reference.mesh.indices.length).toBe(builtin.indices.length);
    for (let k = 0; k < 3; k++) {
      expect(Math.abs(reference.mesh.bounds.min[k] - builtin.bounds.min[k])).toBeLessThan(2e-3);
      expect(Math.abs(reference.mesh.bounds.max[k] - builtin.bounds.max[k])).toBeLessThan(2e-3);
    }
    expect(reference.mesh.center).toEqual([0, 0, 0]);
    // the default scalp is the built-in one (same triangles, same centre), minus nothing hidden
    const expected = markScalpTriangles(builtin, [0, 0, 0]);
    let differ = 0;
    let count = 0;
    for (let t = 0; t < expected.length; t++) {
      if (expected[t] !== reference.mesh.scalp[t]) differ++;
      count += reference.mesh.scalp[t];
    }
    expect(count).toBeGreaterThan(0.15 * expected.length);
    expect(differ).toBeLessThan(0.01 * count);
  });

  it('the default scalp lies on the upper back of the head', () => {
    const { positions: P, indices: I, scalp } = reference.mesh;
    let n = 0;
    let sy = 0;
    let sz = 0;
    for (let t = 0; t < scalp.length; t++) {
      if (!scalp[t]) continue;
      const a = 3 * I[3 * t];
      sy += P[a + 1];
      sz += P[a + 2];
      n++;
      expect(P[a + 1]).toBeGreaterThan(-1.2); // above the ears' lower end
    }
    expect(sy / n).toBeGreaterThan(0.3);
    expect(sz / n).toBeLessThan(0);
  });

  const variants: [string, string, () => ArrayBuffer][] = [
    ['head-mm.obj', 'mm', () => toObj(exportAs(builtin, 100))],
    ['head-m-zup.obj', 'm', () => toObj(exportAs(builtin, 0.1, true))],
    ['head-m.glb', 'm', () => toGlb(exportAs(builtin, 0.1))],
    // positions in mm under a node that scales them to m and moves them
    [
      'head-node.glb',
      'm',
      () =>
        toGlb(exportAs(builtin, 100), { scale: [0.001, 0.001, 0.001], translation: [3, 1, -2] }),
    ],
    ['head-mm-zup.ply', 'mm', () => toPly(exportAs(builtin, 100, true, [40, 25, 900]))],
    ['head-m.ply', 'm', () => toPly(exportAs(builtin, 0.1))],
    ['head-m-zup.stl', 'm', () => toStl(exportAs(builtin, 0.1, true))],
    [
      'head-cm-clockwise.stl',
      'cm',
      () => toStl(flipWinding(exportAs(builtin, 10, false, [-5, 3, 7]))),
    ],
  ];
  for (const [name, unit, make] of variants) {
    it(`${name} loads to the same normalised head`, async () => {
      const loaded = await mustLoad(name, make());
      expect(loaded.unit).toBe(unit);
      expect(loaded.up).toBe(name.includes('zup') ? 'z' : 'y');
      expect(loaded.flippedParts).toBe(name.includes('clockwise') ? 1 : 0);
      expect(loaded.message).toContain(name);
      sameHead(reference, loaded, 2e-3);
    });
  }

  it('a Y-up file taken as Z-up is put right by a quarter turn about x; four turns are none', async () => {
    const wrong = await mustLoad('head.obj', toObj(builtin), { up: 'z' });
    expect(wrong.up).toBe('z');
    expect(Math.abs(wrong.mesh.bounds.max[2] - wrong.mesh.bounds.min[2])).toBeGreaterThan(3);
    const fixed = rotateLoadedHead(wrong, 'x', 1);
    expect(fixed.turns).toEqual([{ axis: 'x', quarterTurns: 1 }]);
    sameHead(reference, fixed, 2e-3);
    let r = reference;
    for (let k = 0; k < 4; k++) r = rotateLoadedHead(r, 'y', 1);
    sameHead(reference, r, 2e-3);
    const back = rotateLoadedHead(rotateLoadedHead(reference, 'z', -1), 'z', 5);
    sameHead(reference, back, 2e-3);
    // facing -z: half a turn about y faces it forward again
    const turned = rotateLoadedHead(reference, 'y', 2);
    expect(turned.mesh.bounds.min[2]).toBeLessThan(-1.2); // the nose is at the back now
    sameHead(reference, rotateLoadedHead(turned, 'y', 2), 2e-3);
  });

  it('a head of no recognisable unit is scaled to the built-in width, and says so', async () => {
    const loaded = await mustLoad('odd.stl', toStl(exportAs(builtin, 2.5)));
    expect(loaded.unit).toBe('unknown');
    expect(loaded.message).toMatch(/not recognised/);
    sameHead(reference, loaded, 2e-3);
  });
});

describe('inside test and signed distance', () => {
  // an ellipsoid open at the neck and with a hole at the back, and two eyes sticking out of it
  const body = ellipsoidHead(40, [
    { dir: [0, -1, 0], cosMin: Math.cos((25 * Math.PI) / 180) },
    { dir: [0, 0, -1], cosMin: Math.cos((8 * Math.PI) / 180) },
  ]);
  const eyes = [sphere([0.35, 0.1, 0.85], 0.2, 12), sphere([-0.35, 0.1, 0.85], 0.2, 12)];
  const mesh = concat(body, ...eyes);

  it('points in the body and in an eye are inside; points outside are outside, even by a hole', () => {
    const min: Vec3 = [Infinity, Infinity, Infinity];
    const max: Vec3 = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < mesh.positions.length; i++) {
      min[i % 3] = Math.min(min[i % 3], mesh.positions[i]);
      max[i % 3] = Math.max(max[i % 3], mesh.positions[i]);
    }
    const head = new Head({
      ...mesh,
      normals: new Float32Array(mesh.positions.length),
      scalp: new Uint8Array(mesh.indices.length / 3),
      center: [0, 0, 0],
      bounds: { min, max },
    });
    const probe = meshInside(head.bvh, head.mesh.bounds);
    const inside: Vec3[] = [
      [0, 0, 0],
      [0.3, 0.5, -0.3],
      [0, 0.9, 0],
      [0.35, 0.1, 0.99], // in the eye, in front of the face
      [0.35, 0.1, 0.8], // in the eye and the body at once
      [-0.35, 0.05, 1.0],
      [0, 0, -0.5], // in front of the back hole
    ];
    const outside: Vec3[] = [
      [0, 0, -1.02], // just behind the back hole
      [0.05, 0.02, -1.0],
      [0, -1.15, 0], // below the neck opening
      [0.9, 0, 0],
      [0, 1.2, 0],
      [0.35, 0.1, 1.1], // in front of an eye
      [0, 0.1, 1.0], // between the eyes
      [1.5, 1.5, 1.5],
    ];
    for (const p of inside) expect(probe.inside(p), `inside ${p}`).toBe(true);
    for (const p of outside) expect(probe.inside(p), `outside ${p}`).toBe(false);
    // signed distance: negative inside, magnitude the distance to the closest surface
    expect(probe.signedDistance([0, 0, 0])).toBeLessThan(-0.7);
    expect(probe.signedDistance([0, 1.2, 0])).toBeCloseTo(0.1, 2);
    expect(probe.signedDistance([0, 1.0, 0])).toBeCloseTo(-0.1, 2);
    expect(probe.signedDistance([0.35, 0.1, 1.0])).toBeLessThan(0);
  });

  it('loaded from a file, the head keeps its three parts and its inside test', async () => {
    const loaded = await mustLoad('holes.obj', toObj(exportAs(mesh, 100)));
    expect(loaded.parts).toBe(3);
    // the eyes are not scalp
    const { scalp, indices: I, positions: P } = loaded.mesh;
    for (let t = body.indices.length / 3; t < scalp.length; t++) expect(scalp[t]).toBe(0);
    let n = 0;
    for (let t = 0; t < scalp.length; t++) if (scalp[t] && P[3 * I[3 * t] + 1] > 0) n++;
    expect(n).toBeGreaterThan(100);
    // map a few probe points through the placement: the placement is a translation (mm → app)
    const b = loaded.mesh.bounds;
    const shift = [(b.min[0] + b.max[0]) / 2, b.max[1] - 1.1, 0];
    expect(loaded.insideHead([shift[0], shift[1], b.min[2] + 0.95])).toBe(true);
    expect(loaded.insideHead([shift[0], b.max[1] + 0.01, 0])).toBe(false);
    expect(loaded.head.signedDistance([shift[0], shift[1], b.min[2] + 0.95])).toBeLessThan(-0.5);
  });
});

describe('bad files are refused, saying why', () => {
  const garbage = (n: number, seed = 7) => {
    const b = new Uint8Array(n);
    let s = seed;
    for (let i = 0; i < n; i++) {
      s = (Math.imul(s, 1103515245) + 12345) >>> 0;
      b[i] = s >>> 24;
    }
    return b.buffer;
  };
  const nanHead = (): Soup => {
    const m = exportAs(builtin, 100);
    m.positions[3 * 17 + 1] = Number.NaN;
    return m;
  };
  const cases: [string, () => ArrayBuffer, RegExp][] = [
    ['empty.obj', () => new ArrayBuffer(0), /empty/],
    ['garbage.obj', () => garbage(5000), /binary|no triangles/],
    ['garbage.glb', () => garbage(5000), /not a GLB/],
    ['garbage.gltf', () => new TextEncoder().encode('{"asset": ').buffer, /bad JSON/],
    ['garbage.ply', () => garbage(5000), /not a PLY/],
    ['garbage.stl', () => garbage(5003), /not a readable STL/],
    ['unknown.xyz', () => garbage(100), /unsupported file type \.xyz/],
    [
      'points.obj',
      () => new TextEncoder().encode('v 0 0 0\nv 1 0 0\nv 0 1 0\n').buffer,
      /no triangles/,
    ],
    [
      'points.ply',
      () => toPly({ positions: builtin.positions, indices: new Uint32Array(0) }),
      /no faces/,
    ],
    [
      'empty.stl',
      () => toStl({ positions: new Float32Array(0), indices: new Uint32Array(0) }),
      /no triangles/,
    ],
    [
      'empty.glb',
      () => toGlb({ positions: new Float32Array(9), indices: new Uint32Array(0) }),
      /no triangles/,
    ],
    ['nan.obj', () => toObj(nanHead()), /non-finite/],
    ['nan.glb', () => toGlb(nanHead()), /non-finite/],
    ['nan.ply', () => toPly(nanHead()), /non-finite/],
    ['nan.stl', () => toStl(nanHead()), /non-finite/],
    [
      'flat.stl',
      () =>
        toStl({
          positions: Float32Array.of(0, 0, 0, 100, 0, 0, 0, 100, 0),
          indices: Uint32Array.of(0, 1, 2),
        }),
      /flat/,
    ],
    [
      'point.obj',
      () => toObj({ positions: new Float32Array(9), indices: Uint32Array.of(0, 1, 2) }),
      /zero size/,
    ],
    [
      'external.gltf',
      () =>
        new TextEncoder().encode(
          JSON.stringify({
            asset: { version: '2.0' },
            buffers: [{ uri: 'head.bin', byteLength: 12 }],
          }),
        ).buffer,
      /separate file \(“head\.bin”\): pick the \.gltf together with it/,
    ],
    [
      'draco.gltf',
      () =>
        new TextEncoder().encode(
          JSON.stringify({
            asset: { version: '2.0' },
            extensionsRequired: ['KHR_draco_mesh_compression'],
          }),
        ).buffer,
      /compressed/,
    ],
  ];
  for (const [name, make, why] of cases) {
    it(`${name}: ${why.source}`, async () => {
      const r = await loadHeadFile(name, make());
      expect(r.ok).toBe(false);
      if (r.ok) return;
      expect(r.error).toMatch(why);
      expect(r.error.startsWith(`Cannot open ${name}: `)).toBe(true);
      expect(r.error).not.toContain('\n');
    });
  }

  const big = () => exportAs(builtin, 100);
  const capped: [string, () => ArrayBuffer][] = [
    ['big.obj', () => toObj(big())],
    ['big.glb', () => toGlb(big())],
    ['big.ply', () => toPly(big())],
    ['big.stl', () => toStl(big())],
  ];
  for (const [name, make] of capped) {
    it(`${name}: over the triangle cap`, async () => {
      const r = await loadHeadFile(name, make(), { maxTriangles: 10_000 });
      expect(r.ok).toBe(false);
      if (!r.ok) expect(r.error).toMatch(/29,860 triangles, over the limit of 10,000/);
      // and loads under the cap
      expect((await loadHeadFile(name, make(), { maxTriangles: 30_000 })).ok).toBe(true);
    });
  }
});

// Load time and memory at scale, printed. The signed distance is checked on a coarse grid here
// (banded equals full); its cost on the solver's 50k grid, and a 1,000,000-triangle head, are
// measured by `npm run bench:head`.
describe('load time and memory of big heads', () => {
  for (const rings of [158]) {
    it(`a ${(4 * rings * rings).toLocaleString('en-US')}-triangle head in mm (binary STL)`, async () => {
      const mb = (n: number) => `${(n / 2 ** 20).toFixed(0)} MB`;
      const soup = exportAs(ellipsoidHead(rings), 100);
      const bytes = toStl(soup);
      globalThis.gc?.();
      const before = process.memoryUsage();
      const t0 = performance.now();
      const loaded = await mustLoad('big.stl', bytes);
      const t1 = performance.now();
      // signed distance on a 15³ (3,375-point) grid over the head's box plus a margin
      const b = loaded.mesh.bounds;
      const n = 15;
      let inside = 0;
      for (let i = 0; i < n; i++)
        for (let j = 0; j < n; j++)
          for (let k = 0; k < n; k++) {
            const p: Vec3 = [0, 1, 2].map((a) => {
              const u = [i, j, k][a] / (n - 1);
              return b.min[a] - 0.3 + u * (b.max[a] - b.min[a] + 0.6);
            }) as Vec3;
            if (loaded.head.signedDistance(p) < 0) inside++;
          }
      const t2 = performance.now();
      // the same within a 3 cm band (farther points get ±0.3): what scalp avoidance looks at
      let insideBand = 0;
      for (let i = 0; i < n; i++)
        for (let j = 0; j < n; j++)
          for (let k = 0; k < n; k++) {
            const p: Vec3 = [0, 1, 2].map((a) => {
              const u = [i, j, k][a] / (n - 1);
              return b.min[a] - 0.3 + u * (b.max[a] - b.min[a] + 0.6);
            }) as Vec3;
            if (loaded.signedDistance(p, 0.3) < 0) insideBand++;
          }
      const t3 = performance.now();
      expect(insideBand).toBe(inside);
      const after = process.memoryUsage();
      const triangles = loaded.mesh.indices.length / 3;
      // what the loaded head keeps: its arrays and the BVH's
      const m = loaded.mesh;
      const internals = loaded.head.bvh as unknown as {
        _roots: ArrayBuffer[];
        _indirectBuffer?: Uint32Array;
      };
      const kept =
        m.positions.byteLength +
        m.normals.byteLength +
        m.indices.byteLength +
        m.scalp.byteLength +
        internals._roots.reduce((n, r) => n + r.byteLength, 0) +
        (internals._indirectBuffer?.byteLength ?? 0);
      const t = loaded.timings;
      console.log(
        `[loadHead] ${triangles.toLocaleString('en-US')} triangles, ${(bytes.byteLength / 2 ** 20).toFixed(0)} MB STL: ` +
          `load ${(t1 - t0).toFixed(0)} ms (parse ${t.parseMs.toFixed(0)}, weld+place ${t.normaliseMs.toFixed(0)}, ` +
          `normals+BVH ${t.bvhMs.toFixed(0)}, scalp ${t.scalpMs.toFixed(0)}); signed distance at ${n ** 3} points ` +
          `${(t2 - t1).toFixed(0)} ms (${inside} inside), within a 0.3 band ${(t3 - t2).toFixed(0)} ms; ` +
          `kept: ${mb(kept)} (mesh arrays and BVH); memory: heap +${mb(after.heapUsed - before.heapUsed)}, ` +
          `array buffers +${mb(after.arrayBuffers - before.arrayBuffers)}, rss +${mb(after.rss - before.rss)} ` +
          `(rss ${mb(after.rss)})`,
      );
      expect(triangles).toBeGreaterThan(0.99 * 4 * rings * rings);
      expect(loaded.unit).toBe('mm');
      expect(inside).toBeGreaterThan(0.15 * n ** 3);
      // the BVH is what the app keeps: make sure it is alive until here
      expect(loaded.head.bvh).toBeInstanceOf(MeshBVH);
      void THREE;
    }, 300_000);
  }
});
