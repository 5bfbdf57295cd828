// Root UVs from a loaded head's own UVs: a generated head written here as OBJ (vt) and as GLB
// (TEXCOORD_0, top-left origin as glTF says) whose UVs are a known affine function of the file
// position on each side of a seam down the middle (x = 0), one side's u beyond 1. The USD export's
// groom_root_uv at each root (read from the file's text) must be that function at the root's
// position in the file's space (wrapped into [0, 1]); on the seam either side's value will do.
// The same head as STL (no UVs) gets the projection, and the export says which.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { groomNote } from '../../web/app/exporter';
import { SurfaceUvLookup, type UvSurface } from '../../web/export/surfaceUv';
import type { GroomSummary } from '../../web/export/usdWriter';
import { writeExport } from '../../web/export/writeExport';
import { type LoadedHead, loadHeadFile, rotateLoadedHead } from '../../web/head/loadHead';
import { emptySession, type SessionState } from '../../web/model/session';
import { ellipsoidHead } from '../support/generatedHead';
import { rng } from '../support/seededRandom';

/** The head in metres (a head-sized ellipsoid, y up, face +z). */
const soup = (() => {
  const m = ellipsoidHead(20);
  return { positions: m.positions.map((v) => 0.1 * v), indices: m.indices };
})();
const T = soup.indices.length / 3;

/** The side of the seam a triangle is on: its centroid's x. */
const sideOf = (t: number) => {
  let x = 0;
  for (let k = 0; k < 3; k++) x += soup.positions[3 * soup.indices[3 * t + k]];
  return x >= 0 ? 0 : 1;
};

/** The UV (v up) on `side` at file position p (metres); side 1's u runs from 1.67 to 1.93. */
function uvOf(side: number, p: number[]): [number, number] {
  const u = (side === 0 ? 0.1 : 1.9) + 2 * p[0] + 0.3 * p[1];
  const v = 0.5 + 2 * p[2] + 0.5 * p[1];
  return [u, v];
}

/** As OBJ; `clockwise`: every face wound the other way (the loader turns the head outward). */
function toObj(withUv: boolean, clockwise = false): ArrayBuffer {
  const lines = ['# a head with its own UVs, metres'];
  for (let i = 0; i < soup.positions.length; i += 3)
    lines.push(`v ${soup.positions[i]} ${soup.positions[i + 1]} ${soup.positions[i + 2]}`);
  for (let t = 0; t < T; t++) {
    const c = (clockwise ? [0, 2, 1] : [0, 1, 2]).map((k) => soup.indices[3 * t + k]);
    if (!withUv) {
      lines.push(`f ${c.map((v) => v + 1).join(' ')}`);
      continue;
    }
    for (const v of c) {
      const [u, w] = uvOf(sideOf(t), [...soup.positions.subarray(3 * v, 3 * v + 3)]);
      lines.push(`vt ${u} ${w}`);
    }
    lines.push(`f ${c.map((v, k) => `${v + 1}/${3 * t + k + 1}`).join(' ')}`);
  }
  return new TextEncoder().encode(`${lines.join('\n')}\n`).buffer as ArrayBuffer;
}

/** A GLB with a vertex per corner (glTF keeps one UV a vertex, so seams split vertices) and
 *  TEXCOORD_0 = (u, 1 − v): glTF's texture origin is the image's top left. */
function toGlb(): ArrayBuffer {
  const P = new Float32Array(9 * T);
  const UV = new Float32Array(6 * T);
  for (let t = 0; t < T; t++)
    for (let k = 0; k < 3; k++) {
      const v = soup.indices[3 * t + k];
      const p = [...soup.positions.subarray(3 * v, 3 * v + 3)];
      P.set(p, 9 * t + 3 * k);
      const [u, w] = uvOf(sideOf(t), p);
      UV[6 * t + 2 * k] = u;
      UV[6 * t + 2 * k + 1] = 1 - w;
    }
  const min = [0, 1, 2].map((a) => Math.min(...P.filter((_, i) => i % 3 === a)));
  const max = [0, 1, 2].map((a) => Math.max(...P.filter((_, i) => i % 3 === a)));
  const json = {
    asset: { version: '2.0', generator: 'headUvRoots.test' },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0 }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0, TEXCOORD_0: 1 } }] }],
    accessors: [
      { bufferView: 0, componentType: 5126, count: 3 * T, type: 'VEC3', min, max },
      { bufferView: 1, componentType: 5126, count: 3 * T, type: 'VEC2' },
    ],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: P.byteLength },
      { buffer: 0, byteOffset: P.byteLength, byteLength: UV.byteLength },
    ],
    buffers: [{ byteLength: P.byteLength + UV.byteLength }],
  };
  const text = new TextEncoder().encode(JSON.stringify(json));
  const jsonLength = Math.ceil(text.length / 4) * 4;
  const binLength = P.byteLength + UV.byteLength;
  const total = 12 + 8 + jsonLength + 8 + binLength;
  const buf = new ArrayBuffer(total);
  const view = new DataView(buf);
  const bytes = new Uint8Array(buf);
  view.setUint32(0, 0x46546c67, true);
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, 0x4e4f534a, true);
  bytes.fill(0x20, 20, 20 + jsonLength);
  bytes.set(text, 20);
  view.setUint32(20 + jsonLength, binLength, true);
  view.setUint32(24 + jsonLength, 0x004e4942, true);
  bytes.set(new Uint8Array(P.buffer), 28 + jsonLength);
  bytes.set(new Uint8Array(UV.buffer), 28 + jsonLength + P.byteLength);
  return buf;
}

/** A binary PLY with a vertex per corner and per-vertex `s`, `t` (v up, as PLY tools write). */
function toPly(): ArrayBuffer {
  const header = new TextEncoder().encode(
    `ply\nformat binary_little_endian 1.0\nelement vertex ${3 * T}\n` +
      'property float x\nproperty float y\nproperty float z\nproperty float s\nproperty float t\n' +
      `element face ${T}\nproperty list uchar int vertex_indices\nend_header\n`,
  );
  const buf = new ArrayBuffer(header.length + 20 * 3 * T + 13 * T);
  new Uint8Array(buf).set(header);
  const view = new DataView(buf);
  let o = header.length;
  for (let t = 0; t < T; t++)
    for (let k = 0; k < 3; k++) {
      const v = soup.indices[3 * t + k];
      const p = [...soup.positions.subarray(3 * v, 3 * v + 3)];
      for (const x of [...p, ...uvOf(sideOf(t), p)]) {
        view.setFloat32(o, x, true);
        o += 4;
      }
    }
  for (let t = 0; t < T; t++) {
    view.setUint8(o, 3);
    for (let k = 0; k < 3; k++) view.setInt32(o + 1 + 4 * k, 3 * t + k, true);
    o += 13;
  }
  return buf;
}

function toStl(): ArrayBuffer {
  const buf = new ArrayBuffer(84 + 50 * T);
  const view = new DataView(buf);
  view.setUint32(80, T, true);
  let o = 84;
  for (let t = 0; t < T; t++) {
    o += 12;
    for (let k = 0; k < 3; k++) {
      const v = soup.indices[3 * t + k];
      for (let a = 0; a < 3; a++) view.setFloat32(o + 4 * a, soup.positions[3 * v + a], true);
      o += 12;
    }
    o += 2;
  }
  return buf;
}

async function load(name: string, bytes: ArrayBuffer): Promise<LoadedHead> {
  const r = await loadHeadFile(name, bytes);
  if (!r.ok) throw new Error(r.error);
  expect(r.head.up).toBe('y');
  return r.head;
}

/** `n` roots on the loaded head's scalp triangles (seeded), each pushed `lift` app units out
 *  along its triangle's normal, as two-point strands growing outwards. */
function rootsOn(head: LoadedHead, n: number, lift: number) {
  const { positions: P, indices: I, scalp } = head.mesh;
  const onScalp: number[] = [];
  for (let t = 0; t < scalp.length; t++) if (scalp[t]) onScalp.push(t);
  expect(onScalp.length).toBeGreaterThan(50);
  const rand = rng(7);
  const points = new Float32Array(6 * n);
  const strandStart = new Uint32Array(n + 1);
  for (let s = 0; s < n; s++) {
    const t = onScalp[Math.floor(rand() * onScalp.length)];
    let a = rand();
    let b = rand();
    if (a + b > 1) [a, b] = [1 - a, 1 - b];
    const c = [0, 1, 2].map((k) => P.subarray(3 * I[3 * t + k], 3 * I[3 * t + k] + 3));
    const e1 = [0, 1, 2].map((x) => c[1][x] - c[0][x]);
    const e2 = [0, 1, 2].map((x) => c[2][x] - c[0][x]);
    const nrm = [
      e1[1] * e2[2] - e1[2] * e2[1],
      e1[2] * e2[0] - e1[0] * e2[2],
      e1[0] * e2[1] - e1[1] * e2[0],
    ];
    const len = Math.hypot(nrm[0], nrm[1], nrm[2]);
    for (let x = 0; x < 3; x++) {
      const r = c[0][x] + a * e1[x] + b * e2[x] + (lift * nrm[x]) / len;
      points[6 * s + x] = r;
      points[6 * s + 3 + x] = r + (0.1 * nrm[x]) / len;
    }
    strandStart[s + 1] = 2 * (s + 1);
  }
  return { points, strandStart };
}

const sessionOn = (head: LoadedHead): SessionState => ({
  ...emptySession('25k'),
  head: {
    kind: 'mesh',
    name: head.name,
    hash: '0'.repeat(64),
    format: head.format,
    up: head.up,
    turns: [],
  } as SessionState['head'],
});

const surfaceOf = (head: LoadedHead): UvSurface | null =>
  head.mesh.cornerUvs
    ? { positions: head.mesh.positions, indices: head.mesh.indices, cornerUvs: head.mesh.cornerUvs }
    : null;

/** The USD text, the groom summary, and the hair prim's roots and root UVs read from the text. */
function exportUsd(head: LoadedHead, strands: ReturnType<typeof rootsOn>, withHead: boolean) {
  let groom: GroomSummary | null = null;
  const m = head.mesh;
  const parts = [
    ...writeExport('usda', {
      strands,
      session: sessionOn(head),
      head: withHead ? { positions: m.positions, indices: m.indices, normals: m.normals } : null,
      headUv: surfaceOf(head),
      onGroom: (g) => {
        groom = g;
      },
    }),
  ];
  const text = new TextDecoder().decode(Buffer.concat(parts));
  const numbers = (re: RegExp) =>
    (re.exec(text)?.[1].match(/-?[\d.]+(e-?\d+)?/g) ?? []).map(Number);
  const points = numbers(/point3f\[\] points = \[([^\]]*)\]/);
  const uv = numbers(/float2\[\] primvars:groom_root_uv = \[([^\]]*)\]/);
  return { text, groom: groom as GroomSummary | null, points, uv };
}

/** App position → file position: the loader scales and moves a Y-up file (no turn), so the
 *  bounding boxes give the map. */
function toFile(head: LoadedHead) {
  const fmin = [0, 1, 2].map((a) => Math.min(...soup.positions.filter((_, i) => i % 3 === a)));
  const fmax = [0, 1, 2].map((a) => Math.max(...soup.positions.filter((_, i) => i % 3 === a)));
  const { min, max } = head.mesh.bounds;
  const s = (max[1] - min[1]) / (fmax[1] - fmin[1]);
  return { scale: s, at: (p: number[]) => p.map((v, a) => fmin[a] + (v - min[a]) / s) };
}

const wrap = (x: number) => (x >= 0 && x <= 1 ? x : x - Math.floor(x));

/** Largest difference between the exported root UVs and the function at each root (either
 *  side's value within `seam` metres of the seam). */
function maxUvError(head: LoadedHead, points: number[], uv: number[], seam: number): number {
  const map = toFile(head);
  const n = uv.length / 2;
  let worst = 0;
  for (let s = 0; s < n; s++) {
    const p = map.at(points.slice(6 * s, 6 * s + 3));
    const sides = Math.abs(p[0]) <= seam ? [0, 1] : [p[0] >= 0 ? 0 : 1];
    let err = Infinity;
    for (const side of sides) {
      const want = uvOf(side, p).map(wrap);
      err = Math.min(
        err,
        Math.max(Math.abs(uv[2 * s] - want[0]), Math.abs(uv[2 * s + 1] - want[1])),
      );
    }
    worst = Math.max(worst, err);
  }
  return worst;
}

const PYTHON = 'build/usd-venv/bin/python';

/** usd-core reads the file: tests/usd/check_usd.py passes (groom primvars, root UVs in
 *  [0, 1]) and the head's st is a faceVarying texCoord2f with one value per face corner. */
function readByUsdCore(text: string): void {
  if (!existsSync(PYTHON))
    throw new Error(`${PYTHON} is missing: run \`bash scripts/setup.sh test\` before vitest.`);
  const file = join(mkdtempSync(join(tmpdir(), 'hs-head-uv-')), 'head-uv.usda');
  writeFileSync(file, text);
  const box = ['-5', '-5', '-5', '5', '5', '5'];
  const check = spawnSync(PYTHON, ['tests/usd/check_usd.py', file, '--box', ...box], {
    encoding: 'utf8',
  });
  expect(check.stderr).toMatch(/^check_usd: ok, 3000 curves/);
  const script = [
    'import sys, json',
    'from pxr import Usd, UsdGeom',
    'stage = Usd.Stage.Open(sys.argv[1])',
    'm = UsdGeom.Mesh(stage.GetPrimAtPath("/hairsketch/head"))',
    'pv = UsdGeom.PrimvarsAPI(m).GetPrimvar("st")',
    'print(json.dumps([pv.GetInterpolation(), str(pv.GetTypeName()), len(pv.Get()), len(m.GetFaceVertexIndicesAttr().Get())]))',
  ].join('\n');
  const r = spawnSync(PYTHON, ['-c', script, file], { encoding: 'utf8' });
  expect(r.stderr).toBe('');
  const [interpolation, type, values, corners] = JSON.parse(r.stdout.trim());
  expect([interpolation, type]).toEqual(['faceVarying', 'texCoord2f[]']);
  expect(values).toBe(corners);
}

describe("root UVs from a loaded head's own UVs", () => {
  for (const [name, make] of [
    ['uv-head.obj', () => toObj(true)],
    ['uv-head-clockwise.obj', () => toObj(true, true)],
    ['uv-head.glb', toGlb],
    ['uv-head.ply', toPly],
  ] as const) {
    it(`${name}: every root's UV is the head's UV function at the root, across the seam`, async () => {
      const head = await load(name, make());
      expect(head.flippedParts).toBe(name.includes('clockwise') ? 1 : 0);
      expect(head.mesh.cornerUvs?.length).toBe(6 * (head.mesh.indices.length / 3));
      const strands = rootsOn(head, 3000, 0);
      const out = exportUsd(head, strands, true);
      expect(out.groom?.rootUv).toBe('head-uv');
      expect(groomNote(out.groom as GroomSummary)).toContain("root UVs from the head's own UV map");
      expect(out.uv.length).toBe(2 * 3000);
      expect(out.points.length).toBe(6 * 3000);
      // roots on both sides of the seam, and side 1's u wrapped from beyond 1
      const map = toFile(head);
      const xs = Array.from(
        { length: 3000 },
        (_, s) => map.at(out.points.slice(6 * s, 6 * s + 3))[0],
      );
      expect(xs.filter((x) => x > 0.01).length).toBeGreaterThan(300);
      expect(xs.filter((x) => x < -0.01).length).toBeGreaterThan(300);
      const err = maxUvError(head, out.points, out.uv, 1e-5);
      console.log(`${name}: max root UV error ${err.toExponential(2)} (roots on the surface)`);
      expect(err).toBeLessThan(2e-5);
      for (const v of out.uv) expect(v >= 0 && v <= 1).toBe(true);
      // roots 1 mm off the surface: the UV at the closest point, within the function's slope
      // (2 per metre) times the lift
      const lifted = exportUsd(head, rootsOn(head, 3000, 0.01), false);
      const liftM = 0.01 / map.scale;
      const errLift = maxUvError(head, lifted.points, lifted.uv, 2 * liftM);
      console.log(
        `${name}: max root UV error ${errLift.toExponential(2)} with roots 1 mm out (bound ${(2.1 * liftM).toExponential(2)})`,
      );
      expect(errLift).toBeLessThan(2.1 * liftM + 2e-5);
      // the head's Mesh carries the same UVs per corner
      const st =
        /texCoord2f\[\] primvars:st = \[([^\]]*)\] \(\s*interpolation = "faceVarying"/.exec(
          out.text,
        );
      expect(st).not.toBeNull();
      expect(lifted.text).not.toMatch(/primvars:st/);
      if (name === 'uv-head.obj') readByUsdCore(out.text);
      // a quarter turn moves the head, not its UVs
      const turned = rotateLoadedHead(head, 'y', 1);
      expect(turned.mesh.cornerUvs).toEqual(head.mesh.cornerUvs);
    });
  }

  it('a head without UVs (STL, OBJ without vt) gets the projection, and the status says so', async () => {
    for (const [name, bytes] of [
      ['plain.stl', toStl()],
      ['plain.obj', toObj(false)],
    ] as const) {
      const head = await load(name, bytes);
      expect(head.mesh.cornerUvs).toBeUndefined();
      const out = exportUsd(head, rootsOn(head, 200, 0), true);
      expect(out.groom?.rootUv).toBe('projection');
      expect(groomNote(out.groom as GroomSummary)).toContain('projected');
      expect(out.text).not.toMatch(/primvars:st/);
    }
  });
});

describe('closest triangle through the grid', () => {
  it('is the brute-force closest, for points near the surface, inside and far outside', () => {
    const surface: UvSurface = {
      positions: soup.positions,
      indices: soup.indices,
      cornerUvs: new Float32Array(6 * T),
    };
    const lookup = new SurfaceUvLookup(surface);
    const P = soup.positions;
    const I = soup.indices;
    // squared distance to a triangle by dense sampling is too coarse; use the plane, edges and
    // corners directly: the minimum over the plane foot (when inside) and the three segments
    const d2 = (t: number, p: number[]) => {
      const c = [0, 1, 2].map((k) => [...P.subarray(3 * I[3 * t + k], 3 * I[3 * t + k] + 3)]);
      const sub = (a: number[], b: number[]) => a.map((v, i) => v - b[i]);
      const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      const seg = (a: number[], b: number[]) => {
        const ab = sub(b, a);
        const t0 = Math.min(1, Math.max(0, dot(sub(p, a), ab) / dot(ab, ab)));
        const q = a.map((v, i) => v + t0 * ab[i]);
        return dot(sub(p, q), sub(p, q));
      };
      let best = Math.min(seg(c[0], c[1]), seg(c[1], c[2]), seg(c[2], c[0]));
      const e1 = sub(c[1], c[0]);
      const e2 = sub(c[2], c[0]);
      const n = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
      ];
      const h = dot(sub(p, c[0]), n) / Math.sqrt(dot(n, n));
      const nn = n.map((v) => v / Math.sqrt(dot(n, n)));
      const f = p.map((v, i) => v - h * nn[i]);
      // inside when the foot is on the inner side of every edge
      const inside = [0, 1, 2].every((k) => {
        const a = c[k];
        const b = c[(k + 1) % 3];
        const e = sub(b, a);
        const x = [
          e[1] * (f[2] - a[2]) - e[2] * (f[1] - a[1]),
          e[2] * (f[0] - a[0]) - e[0] * (f[2] - a[2]),
          e[0] * (f[1] - a[1]) - e[1] * (f[0] - a[0]),
        ];
        return dot(x, n) >= 0;
      });
      if (inside) best = Math.min(best, h * h);
      return best;
    };
    const rand = rng(3);
    let wrong = 0;
    for (let q = 0; q < 90; q++) {
      const scale = q < 30 ? 0.11 : q < 60 ? 0.05 : 0.6; // near, inside, far outside
      const p = [0, 1, 2].map(() => (2 * rand() - 1) * scale);
      const t = lookup.closestTriangle(p[0], p[1], p[2]);
      let best = Infinity;
      for (let u = 0; u < T; u++) best = Math.min(best, d2(u, p));
      if (Math.abs(d2(t, p) - best) > 1e-9 * (1 + best)) wrong++;
    }
    expect(wrong).toBe(0);
  });
});
