// `hairsketch grow` on a user's head: a ball written here as an OBJ in mm. With
// --head the hair's roots lie on that ball (distance to its mesh by three-mesh-bvh's closest
// point), not on the built-in head; a session file that embeds the ball grows the same bytes
// without --head; the session's scalp strokes erase roots where they say; a head file that is
// not the session's, a missing one and a bad one are refused on one line (exit 2) and leave no
// file. The Node-specific part (a textured glTF needs `self`) is checked on its own.
import { createHash } from 'node:crypto';
import { existsSync, mkdtempSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { loadHeadUnderNode } from '../../web/cli/headFile';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import { type LoadedHead, loadHeadFile } from '../../web/head/loadHead';
import type { HeadRef, SessionState } from '../../web/model/session';
import { writeSessionFile } from '../../web/model/sessionFile';
import type { Vec3 } from '../../web/model/vec3';
import { captureOutput } from './captureOutput';
import { bundledCli } from './cliBundle';

// The bundled command line (what `npx hairsketch` runs), built from web/cli/.
const { main } = await bundledCli();

const builtin = Head.builtin();
const base = presetSession('default', builtin, '25k', 0);

/** A UV ball (radius r mm around c), counter-clockwise seen from outside, as OBJ text. */
function ballObj(r: number, c: Vec3, rings = 48): string {
  const lines = ['# a ball head, mm', 'o ball'];
  const segs = 2 * rings;
  lines.push(`v ${c[0]} ${c[1] + r} ${c[2]}`);
  for (let i = 1; i < rings; i++) {
    const th = (Math.PI * i) / rings;
    for (let j = 0; j < segs; j++) {
      const ph = (2 * Math.PI * j) / segs;
      lines.push(
        `v ${c[0] + r * Math.sin(th) * Math.cos(ph)} ${c[1] + r * Math.cos(th)} ${c[2] - r * Math.sin(th) * Math.sin(ph)}`,
      );
    }
  }
  lines.push(`v ${c[0]} ${c[1] - r} ${c[2]}`);
  const bottom = 2 + (rings - 1) * segs;
  const at = (i: number, j: number) => 2 + (i - 1) * segs + (j % segs);
  for (let j = 0; j < segs; j++) lines.push(`f 1 ${at(1, j)} ${at(1, j + 1)}`);
  for (let i = 1; i < rings - 1; i++)
    for (let j = 0; j < segs; j++) {
      lines.push(`f ${at(i, j)} ${at(i + 1, j)} ${at(i + 1, j + 1)}`);
      lines.push(`f ${at(i, j)} ${at(i + 1, j + 1)} ${at(i, j + 1)}`);
    }
  for (let j = 0; j < segs; j++)
    lines.push(`f ${at(rings - 1, j)} ${bottom} ${at(rings - 1, j + 1)}`);
  return `${lines.join('\n')}\n`;
}

const sha256 = (b: Uint8Array | string) => createHash('sha256').update(b).digest('hex');

let dir: string;
let ballFile: string;
let ballBytes: Uint8Array;
let otherBall: string;
let ball: LoadedHead;
let ref: HeadRef;
let out: string[] = [];
let err: string[] = [];

beforeAll(async () => {
  dir = mkdtempSync(join(tmpdir(), 'hs-grow-head-'));
  ballFile = join(dir, 'ball.obj');
  ballBytes = new TextEncoder().encode(ballObj(92, [12, 1650, -25]));
  writeFileSync(ballFile, ballBytes);
  otherBall = join(dir, 'other.obj');
  writeFileSync(otherBall, ballObj(88, [0, 0, 0]));
  const r = await loadHeadFile('ball.obj', ballBytes.slice().buffer as ArrayBuffer);
  if (!r.ok) throw new Error(r.error);
  ball = r.head;
  ref = {
    kind: 'mesh',
    name: 'ball.obj',
    hash: sha256(ballBytes),
    format: 'obj',
    up: 'y',
    turns: [],
  };
});

captureOutput(
  (s) => out.push(s),
  (s) => err.push(s),
);

async function grow(...args: string[]) {
  out = [];
  err = [];
  const code = await main(['grow', ...args]);
  return { code, stdout: out.join(''), stderr: err.join('') };
}

async function growOk(...args: string[]) {
  // no progress lines on stderr however slow the machine (progress has its own test)
  const r = await grow(...args, '--progress-seconds', '100000');
  expect(r.stderr).toBe('');
  expect(r.code).toBe(0);
  return JSON.parse(r.stdout.trim()) as { strands: number; file: string };
}

/** The first point of every strand of an OBJ export. */
function rootsOf(objText: string): Vec3[] {
  const v: Vec3[] = [];
  const roots: Vec3[] = [];
  for (const line of objText.split('\n')) {
    if (line.startsWith('v ')) {
      const [, x, y, z] = line.split(' ');
      v.push([Number(x), Number(y), Number(z)]);
    } else if (line.startsWith('l ')) roots.push(v[Number(line.split(' ')[1]) - 1]);
  }
  return roots;
}

/** A session file (as "Save" writes it) in a fresh directory. */
async function sessionFile(s: SessionState, headBytes?: Uint8Array): Promise<string> {
  const d = mkdtempSync(join(dir, 'case-'));
  const f = join(d, 'session.hairsketch.json');
  writeFileSync(
    f,
    await writeSessionFile(s, {
      headBytes: headBytes && (headBytes.slice().buffer as ArrayBuffer),
    }),
  );
  return f;
}

const STRANDS = '1500';

describe('hairsketch grow --head', () => {
  let plain: string;
  let roots: Vec3[];

  it('grows hair whose roots lie on the given head, not on the built-in one', async () => {
    const f = await sessionFile(base);
    const o = join(dir, 'on-ball.obj');
    const report = await growOk(f, '--out', o, '--head', ballFile, '--strands', STRANDS);
    expect(report.strands).toBeGreaterThan(500);
    plain = readFileSync(o, 'utf8');
    roots = rootsOf(plain);
    expect(roots.length).toBe(report.strands);
    let worst = 0;
    let offBuiltin = 0;
    for (const p of roots) {
      worst = Math.max(worst, ball.head.closest(p).distance);
      if (Math.abs(builtin.signedDistance(p)) > 0.02) offBuiltin++;
    }
    // on the ball's mesh (the OBJ keeps 6 digits), on its scalp (the upper back of the ball)
    expect(worst).toBeLessThan(1e-4);
    expect(offBuiltin / roots.length).toBeGreaterThan(0.5);
    // (a root on a triangle's edge may be closest to its neighbour across the scalp's border)
    const onScalp = roots.filter((p) => ball.head.mesh.scalp[ball.head.closest(p).triangle] === 1);
    expect(onScalp.length / roots.length).toBeGreaterThan(0.99);
  });

  it('a session file that embeds the head grows the same bytes without --head', async () => {
    const f = await sessionFile({ ...base, head: ref }, ballBytes);
    const o = join(dir, 'embedded.obj');
    await growOk(f, '--out', o, '--strands', STRANDS);
    expect(readFileSync(o, 'utf8')).toBe(plain);
  });

  it("applies the session's scalp strokes: an erase dab leaves no root under it", async () => {
    // the dab at the root nearest the top of the ball
    const top = roots.reduce((a, b) => (b[1] > a[1] ? b : a));
    const radius = 0.25;
    const painted: SessionState = {
      ...base,
      head: ref,
      scalpPaint: [{ erase: true, radius, points: [top] }],
    };
    const f = await sessionFile(painted); // no head inside: --head gives it (same hash)
    const o = join(dir, 'erased.obj');
    const report = await growOk(f, '--out', o, '--head', ballFile, '--strands', STRANDS);
    expect(report.strands).toBeGreaterThan(100);
    // a triangle is erased when its centroid is within the radius: no root closer than the
    // radius less the largest triangle of the ball (its edges are under 1.3 cm)
    const near = (p: Vec3) => Math.hypot(p[0] - top[0], p[1] - top[1], p[2] - top[2]);
    const before = roots.filter((p) => near(p) < radius - 0.13).length;
    expect(before).toBeGreaterThan(10);
    const after = rootsOf(readFileSync(o, 'utf8')).filter((p) => near(p) < radius - 0.13);
    expect(after).toEqual([]);
  });
});

describe('hairsketch grow --head: refusals (exit 2, one line, no file)', () => {
  const refused = async (args: string[], why: RegExp) => {
    const d = mkdtempSync(join(dir, 'bad-'));
    const o = join(d, 'hair.obj');
    const r = await grow(...args, '--out', o);
    expect(r.code).toBe(2);
    expect(r.stdout).toBe('');
    expect(r.stderr).toMatch(/^hairsketch: [^\n]+\n$/);
    expect(r.stderr).toMatch(why);
    expect(existsSync(o)).toBe(false);
    expect(readdirSync(d)).toEqual([]);
  };

  it('a session on a head it does not carry, without --head', async () => {
    const f = await sessionFile({ ...base, head: ref });
    await refused(
      [f],
      new RegExp(
        `on the head "ball\\.obj" \\(SHA-256 ${ref.hash}\\), which it does not carry: give that file with --head FILE`,
      ),
    );
  });

  it("a --head file that is not the session's head names both hashes", async () => {
    const f = await sessionFile({ ...base, head: ref });
    const other = sha256(readFileSync(otherBall));
    await refused(
      [f, '--head', otherBall],
      new RegExp(
        `head .*other\\.obj is not the session's head: its SHA-256 is ${other}, the session's head "ball\\.obj" is ${ref.hash}`,
      ),
    );
  });

  it('a missing, unreadable or bad head file', async () => {
    const f = await sessionFile(base);
    await refused([f, '--head', join(dir, 'nope.obj')], /cannot read head .*nope\.obj: ENOENT/);
    await refused([f, '--head', dir], /cannot read head .*: it is a directory/);
    const garbage = join(dir, 'garbage.stl');
    writeFileSync(garbage, 'this is not a mesh at all');
    await refused([f, '--head', garbage], /Cannot open garbage\.stl: not a readable STL/);
    const empty = join(dir, 'empty.obj');
    writeFileSync(empty, '# nothing\n');
    await refused([f, '--head', empty], /Cannot open empty\.obj: /);
    const r = await grow(f, '--out', join(dir, 'never.obj'), '--head');
    expect([r.code, r.stderr]).toEqual([
      2,
      expect.stringMatching(/^hairsketch: --head needs a value/),
    ]);
  });

  it("an embedded head whose bytes are not its hash's", async () => {
    const f = await sessionFile({ ...base, head: ref }, ballBytes);
    const json = JSON.parse(readFileSync(f, 'utf8'));
    const forged = join(dir, 'forged.json');
    // a valid deflate stream of other bytes, under the ball's name and hash
    const { deflateRawSync } = await import('node:zlib');
    json.headFile.data = deflateRawSync(readFileSync(otherBall)).toString('base64');
    writeFileSync(forged, JSON.stringify(json));
    await refused([forged], /session\.headFile\.hash: does not match the data/);
  });
});

describe('three.js loaders under Node (cli/headFile.ts)', () => {
  it('a textured GLB loads (its image is skipped), and the globals are put back', async () => {
    const glb = texturedGlb(ball.head.mesh.positions, ball.head.mesh.indices);
    const hadSelf = 'self' in globalThis;
    const consoleError = console.error;
    const r = await loadHeadUnderNode(() => loadHeadFile('textured.glb', glb));
    expect(r.ok ? r.head.mesh.indices.length : r.error).toBe(ball.head.mesh.indices.length);
    expect('self' in globalThis).toBe(hadSelf);
    expect(console.error).toBe(consoleError);
  });
});

/** A GLB whose one mesh has a base colour texture (a 1×1 PNG in a buffer view). */
function texturedGlb(P: Float32Array, I: Uint32Array): ArrayBuffer {
  const png = Uint8Array.from(
    atob(
      'iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8DwHwAFBQIAX8jx0gAAAABJRU5ErkJggg==',
    ),
    (c) => c.charCodeAt(0),
  );
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < P.length; i++) {
    min[i % 3] = Math.min(min[i % 3], P[i]);
    max[i % 3] = Math.max(max[i % 3], P[i]);
  }
  const uv = new Float32Array((P.length / 3) * 2);
  const pad = (n: number) => Math.ceil(n / 4) * 4;
  const o1 = P.byteLength;
  const o2 = o1 + I.byteLength;
  const o3 = o2 + uv.byteLength;
  const binLength = pad(o3 + png.length);
  const json = {
    asset: { version: '2.0' },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0 }],
    meshes: [
      { primitives: [{ attributes: { POSITION: 0, TEXCOORD_0: 2 }, indices: 1, material: 0 }] },
    ],
    materials: [{ pbrMetallicRoughness: { baseColorTexture: { index: 0 } } }],
    textures: [{ source: 0 }],
    images: [{ bufferView: 3, mimeType: 'image/png' }],
    accessors: [
      { bufferView: 0, componentType: 5126, count: P.length / 3, type: 'VEC3', min, max },
      { bufferView: 1, componentType: 5125, count: I.length, type: 'SCALAR' },
      { bufferView: 2, componentType: 5126, count: P.length / 3, type: 'VEC2' },
    ],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: o1 },
      { buffer: 0, byteOffset: o1, byteLength: I.byteLength },
      { buffer: 0, byteOffset: o2, byteLength: uv.byteLength },
      { buffer: 0, byteOffset: o3, byteLength: png.length },
    ],
    buffers: [{ byteLength: binLength }],
  };
  const j = new TextEncoder().encode(JSON.stringify(json));
  const jsonLength = pad(j.length);
  const buf = new ArrayBuffer(28 + jsonLength + binLength);
  const view = new DataView(buf);
  const u8 = new Uint8Array(buf);
  view.setUint32(0, 0x46546c67, true); // 'glTF'
  view.setUint32(4, 2, true);
  view.setUint32(8, buf.byteLength, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, 0x4e4f534a, true); // 'JSON'
  u8.fill(0x20, 20, 20 + jsonLength);
  u8.set(j, 20);
  view.setUint32(20 + jsonLength, binLength, true);
  view.setUint32(24 + jsonLength, 0x004e4942, true); // 'BIN\0'
  const b = 28 + jsonLength;
  u8.set(new Uint8Array(P.buffer, P.byteOffset, P.byteLength), b);
  u8.set(new Uint8Array(I.buffer, I.byteOffset, I.byteLength), b + o1);
  u8.set(png, b + o3);
  return buf;
}
