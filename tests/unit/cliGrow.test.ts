// `hairsketch grow`: bad input gives exit 2, one line naming the problem and no file (nor a
// temporary one) left behind; a good run prints one JSON line whose counts match the file
// actually written (parsed back here); the same session gives byte-identical files, whether it
// comes from a saved file, a share link or an earlier export.
import { execFileSync, spawnSync } from 'node:child_process';
import {
  mkdirSync,
  mkdtempSync,
  readdirSync,
  readFileSync,
  statSync,
  writeFileSync,
} from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { beforeAll, beforeEach, describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import { encodeSessionLink } from '../../web/model/sessionLink';
import { captureOutput } from './captureOutput';
import { bundledCli } from './cliBundle';

// The bundled command line (what `npx hairsketch` runs), built from web/cli/.
const { main } = await bundledCli();

const head = Head.builtin();
const session = presetSession('default', head, '25k', 0);
const HEAD_VERTICES = head.mesh.positions.length / 3;

let dir: string;
let sessionFile: string;
let out: string[] = [];
let err: string[] = [];

beforeAll(() => {
  dir = mkdtempSync(join(tmpdir(), 'hs-grow-'));
  sessionFile = join(dir, 'default.hairsketch.json');
  // as "Save" writes it: the session and the camera
  writeFileSync(sessionFile, JSON.stringify({ ...session, camera: session.curves[0].viewpoint }));
});

beforeEach(() => {
  out = [];
  err = [];
});
captureOutput(
  (s) => out.push(s),
  (s) => err.push(s),
);

/** A fresh directory holding only what the test puts there. */
function freshDir(): string {
  return mkdtempSync(join(dir, 'case-'));
}

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
  const lines = r.stdout.trim().split('\n');
  expect(lines).toHaveLength(1);
  const report = JSON.parse(lines[0]);
  expect(Object.keys(report).sort()).toEqual(
    ['bytes', 'file', 'format', 'growMs', 'hairHash', 'points', 'solveMs', 'strands'].sort(),
  );
  return report as {
    strands: number;
    points: number;
    bytes: number;
    solveMs: number;
    growMs: number;
    format: string;
    file: string;
  };
}

/** Curve and point counts of a .usda export, read from its text. */
function usdaCounts(text: string) {
  const m = /int\[\] curveVertexCounts = \[([^\]]*)\]/.exec(text);
  if (!m) throw new Error('no curveVertexCounts');
  const counts = m[1].split(',').map((s) => Number(s.trim()));
  return { strands: counts.length, points: counts.reduce((a, b) => a + b, 0) };
}

/** Counts of an OBJ: vertices and `l` lines (and the indices the lines use). */
function objCounts(text: string) {
  let v = 0;
  let l = 0;
  let used = 0;
  let faces = 0;
  for (const line of text.split('\n')) {
    if (line.startsWith('v ')) v++;
    else if (line.startsWith('l ')) {
      l++;
      used += line.trim().split(/\s+/).length - 1;
    } else if (line.startsWith('f ')) faces++;
  }
  return { v, l, used, faces };
}

describe('hairsketch grow: bad input', () => {
  const badSession = (mutate: (s: Record<string, unknown>) => void) => {
    const d = freshDir();
    const s = JSON.parse(JSON.stringify(session));
    mutate(s);
    const f = join(d, 'bad.json');
    writeFileSync(f, JSON.stringify(s));
    return f;
  };

  it('exits 2 with one line naming the problem, and leaves no file', async () => {
    const cases: Array<[string, (d: string) => string[], RegExp]> = [
      [
        'missing session',
        (d) => [join(d, 'nope.json'), '--out', join(d, 'o.usda')],
        /cannot read session .*nope\.json: ENOENT/,
      ],
      [
        'session is a directory',
        (d) => [d, '--out', join(d, 'o.usda')],
        /cannot read session .*is a directory/,
      ],
      [
        'not JSON',
        (d) => {
          writeFileSync(join(d, 's.json'), '{"version": 1,');
          return [join(d, 's.json'), '--out', join(d, 'o.usda')];
        },
        /session .*s\.json is not JSON/,
      ],
      [
        'invalid session (growth field)',
        () => [
          badSession((s) => {
            (s.growth as Record<string, unknown>).maxStrands = -1;
          }),
          '--out',
          join(dir, 'never.usda'),
        ],
        /session\.growth\.maxStrands: must be between 0 and 1000000/,
      ],
      [
        'invalid session (curve point)',
        () => [
          badSession((s) => {
            ((s.curves as Array<Record<string, unknown>>)[0].points as unknown[])[1] = [0, 'x', 0];
          }),
          '--out',
          join(dir, 'never.usda'),
        ],
        /session\.curves\[0\]\.points\[1\]\[1\]: must be a finite number/,
      ],
      [
        'invalid session (version)',
        () => [
          badSession((s) => {
            s.version = 5;
          }),
          '--out',
          join(dir, 'never.usda'),
        ],
        /session\.version: must be an integer from 1 to 4; version 5 was made by a newer hairsketch/,
      ],
      [
        'an export with no session',
        (d) => {
          writeFileSync(
            join(d, 'other.usda'),
            '#usda 1.0\n(\n    upAxis = "Y"\n)\n\ndef Xform "x"\n{\n}\n',
          );
          return [join(d, 'other.usda'), '--out', join(d, 'o.obj')];
        },
        /carries no hairsketch session/,
      ],
      ['damaged link', (d) => ['#s=@@@', '--out', join(d, 'o.usda')], /session link is damaged/],
      [
        'link without a session',
        (d) => ['http://127.0.0.1:5173/#preset=fig6', '--out', join(d, 'o.usda')],
        /holds no session/,
      ],
      [
        'link that does not inflate',
        (d) => ['http://127.0.0.1:5173/#s=AAAA', '--out', join(d, 'o.usda')],
        /damaged|invalid/,
      ],
      [
        'unknown option',
        (d) => [sessionFile, '--out', join(d, 'o.usda'), '--frobnicate'],
        /unknown option "--frobnicate"/,
      ],
      [
        'unknown format',
        (d) => [sessionFile, '--out', join(d, 'o.usda'), '--format', 'fbx'],
        /unknown format "fbx"/,
      ],
      [
        'unknown extension',
        (d) => [sessionFile, '--out', join(d, 'o.txt')],
        /cannot tell the format .*"o\.txt"/,
      ],
      ['no extension', (d) => [sessionFile, '--out', join(d, 'hair')], /cannot tell the format/],
      [
        'bad grid',
        (d) => [sessionFile, '--out', join(d, 'o.usda'), '--grid', '30k'],
        /unknown grid "30k"/,
      ],
      [
        'bad solver',
        (d) => [sessionFile, '--out', join(d, 'o.usda'), '--solver', 'cg'],
        /unknown solver "cg"/,
      ],
      [
        'cards too few',
        (d) => [sessionFile, '--out', join(d, 'o.glb'), '--format', 'cards', '--cards', '99'],
        /--cards: the card count must be a whole number from 100 to 5,000, got "99"/,
      ],
      [
        'cards not a number',
        (d) => [sessionFile, '--out', join(d, 'o.glb'), '--format', 'cards', '--cards', '1e3'],
        /--cards: the card count .* got "1e3"/,
      ],
      [
        'cards without --format cards',
        (d) => [sessionFile, '--out', join(d, 'o.glb'), '--cards', '600'],
        /--cards needs --format cards/,
      ],
      [
        'strands 0',
        (d) => [sessionFile, '--out', join(d, 'o.usda'), '--strands', '0'],
        /--strands must be an integer from 1 to 1,000,000, got "0"/,
      ],
      [
        'strands too many',
        (d) => [sessionFile, '--out', join(d, 'o.usda'), '--strands', '1000001'],
        /--strands must be .*"1000001"/,
      ],
      [
        'strands not an integer',
        (d) => [sessionFile, '--out', join(d, 'o.usda'), '--strands', '2.5'],
        /--strands must be .*"2\.5"/,
      ],
      [
        'strands negative',
        (d) => [sessionFile, '--out', join(d, 'o.usda'), '--strands', '-5'],
        /--strands must be .*"-5"/,
      ],
      [
        'strands missing value',
        (d) => [sessionFile, '--out', join(d, 'o.usda'), '--strands'],
        /--strands needs a value/,
      ],
      ['no --out', () => [sessionFile], /no --out FILE/],
      ['no session', (d) => ['--out', join(d, 'o.usda')], /no SESSION/],
      [
        'two sessions',
        (d) => [sessionFile, sessionFile, '--out', join(d, 'o.usda')],
        /unexpected argument/,
      ],
      [
        'output directory missing',
        (d) => [sessionFile, '--out', join(d, 'no', 'such', 'o.usda')],
        /cannot write .*o\.usda: no directory/,
      ],
      [
        'output is a directory',
        (d) => {
          mkdirSync(join(d, 'x.usda'));
          return [sessionFile, '--out', join(d, 'x.usda')];
        },
        /cannot write .*x\.usda: it is a directory/,
      ],
    ];
    for (const [name, make, re] of cases) {
      const d = freshDir();
      const args = make(d);
      const before = readdirSync(d).sort();
      const r = await grow(...args);
      expect({ name, code: r.code }).toEqual({ name, code: 2 });
      expect(r.stdout, name).toBe('');
      expect(r.stderr, name).toMatch(/^hairsketch: [^\n]+\n$/);
      expect(r.stderr, name).toMatch(re);
      // nothing written: the directory holds what it held (no output, no temporary file)
      expect(readdirSync(d).sort(), name).toEqual(before);
    }
    expect(readdirSync(dir).filter((f) => f.endsWith('.usda') || f.endsWith('.tmp'))).toEqual([]);
  });

  it('a version 1 session with scalp-avoidance constraints grows as version 2 with avoidScalp, on any grid', async () => {
    const d = freshDir();
    const v1 = join(d, 'v1.json');
    writeFileSync(
      v1,
      JSON.stringify({ ...session, version: 1, avoid: { index: [5], target: [0, 0.3, 0] } }),
    );
    const v2 = join(d, 'v2.json');
    writeFileSync(v2, JSON.stringify({ ...session, avoidScalp: true }));
    await growOk(v1, '--out', join(d, 'v1.obj'), '--strands', '500');
    await growOk(v2, '--out', join(d, 'v2.obj'), '--strands', '500');
    await growOk(sessionFile, '--out', join(d, 'plain.obj'), '--strands', '500');
    const file = (n: string) => readFileSync(join(d, n));
    expect(file('v1.obj').equals(file('v2.obj'))).toBe(true);
    expect(file('v1.obj').equals(file('plain.obj'))).toBe(false); // the avoidance was applied
    // the constraints are no longer grid points: another grid is fine
    const other = await growOk(
      v1,
      '--out',
      join(d, 'v1-50k.obj'),
      '--strands',
      '300',
      '--grid',
      '50k',
    );
    // the strands that grew at least one segment, of the 300 roots asked for
    expect(other.strands).toBeGreaterThan(250);
    expect(other.strands).toBeLessThanOrEqual(300);
  });

  it('an existing output file is left as it was when the run fails', async () => {
    const d = freshDir();
    const target = join(d, 'hair.usda');
    writeFileSync(target, 'old');
    const r = await grow(sessionFile, '--out', target, '--strands', 'x');
    expect(r.code).toBe(2);
    expect(readFileSync(target, 'utf8')).toBe('old');
    expect(readdirSync(d)).toEqual(['hair.usda']);
  });
});

describe('hairsketch grow: output', () => {
  it("usda (default head): the printed counts are the file's", async () => {
    const d = freshDir();
    const f = join(d, 'hair.usda');
    const rep = await growOk(sessionFile, '--out', f, '--strands', '1500');
    const text = readFileSync(f, 'utf8');
    expect(rep.format).toBe('usda');
    expect(rep.file).toBe(resolve(f));
    expect(rep.bytes).toBe(statSync(f).size);
    expect(rep.strands).toBe(1500);
    expect(usdaCounts(text)).toEqual({ strands: rep.strands, points: rep.points });
    expect(text).toMatch(/def Mesh "head"/);
    expect(rep.solveMs).toBeGreaterThan(0);
    expect(rep.growMs).toBeGreaterThan(0);
    expect(readdirSync(d)).toEqual(['hair.usda']);
  });

  it('obj (no head by default; --with-head adds it): v and l counts match', async () => {
    const d = freshDir();
    const bare = await growOk(sessionFile, '--out', join(d, 'a.obj'), '--strands', '800');
    const c = objCounts(readFileSync(join(d, 'a.obj'), 'utf8'));
    expect(c).toEqual({ v: bare.points, l: bare.strands, used: bare.points, faces: 0 });
    expect(bare.bytes).toBe(statSync(join(d, 'a.obj')).size);
    const withHead = await growOk(
      sessionFile,
      '--out',
      join(d, 'b.obj'),
      '--strands',
      '800',
      '--with-head',
    );
    const h = objCounts(readFileSync(join(d, 'b.obj'), 'utf8'));
    expect(withHead.points).toBe(bare.points);
    expect(h.l).toBe(withHead.strands);
    expect(h.used).toBe(withHead.points);
    // the default preset is on the bust: the head's triangles, then the bust's
    const body = head.body;
    if (!body) throw new Error('the built-in head has a bust');
    expect(h.v).toBe(withHead.points + HEAD_VERTICES + body.positions.length / 3);
    expect(h.faces).toBe(head.mesh.indices.length / 3 + body.indices.length / 3);
  });

  it(".hair: the header's strand and point counts and the file size", async () => {
    const d = freshDir();
    const f = join(d, 'x.hair');
    const rep = await growOk(sessionFile, '--out', f, '--strands', '700');
    const b = readFileSync(f);
    expect(b.subarray(0, 4).toString('latin1')).toBe('HAIR');
    const n = b.readUInt32LE(4);
    const p = b.readUInt32LE(8);
    expect([n, p]).toEqual([rep.strands, rep.points]);
    const flags = b.readUInt32LE(12);
    let size = 128;
    if (flags & 1) size += 2 * n;
    if (flags & 2) size += 12 * p;
    if (flags & 4) size += 4 * p;
    if (flags & 8) size += 4 * p;
    if (flags & 16) size += 12 * p;
    expect(b.length).toBe(size);
    expect(rep.bytes).toBe(b.length);
  });

  it('glb (--format overrides the name): a GLB of the printed size', async () => {
    const d = freshDir();
    const f = join(d, 'x.bin');
    const rep = await growOk(sessionFile, '--out', f, '--strands', '600', '--format', 'glb');
    const b = readFileSync(f);
    expect(rep.format).toBe('glb');
    expect(b.readUInt32LE(0)).toBe(0x46546c67);
    expect(b.readUInt32LE(8)).toBe(b.length);
    expect(rep.bytes).toBe(b.length);
  });

  it('cards (--format cards --cards N): a GLB with the cards asked for and the head', async () => {
    const d = freshDir();
    const f = join(d, 'cards.glb');
    const rep = await growOk(
      sessionFile,
      '--out',
      f,
      '--strands',
      '2000',
      '--format',
      'cards',
      '--cards',
      '150',
    );
    const b = readFileSync(f);
    expect(rep.format).toBe('cards');
    expect(b.readUInt32LE(0)).toBe(0x46546c67);
    expect(b.readUInt32LE(8)).toBe(b.length);
    expect(rep.bytes).toBe(b.length);
    const json = JSON.parse(b.subarray(20, 20 + b.readUInt32LE(12)).toString());
    const cards = json.asset.extras.hairsketch.cards;
    expect(cards.asked).toBe(150);
    expect(cards.made).toBeGreaterThan(120);
    expect(cards.made).toBeLessThanOrEqual(150);
    expect(json.meshes.map((m: { name: string }) => m.name)).toEqual(['cards', 'head']);
  });

  it("--strands caps the session's strands; without it the session's own cap applies", async () => {
    const d = freshDir();
    const capped = join(d, 'capped.json');
    writeFileSync(
      capped,
      JSON.stringify({ ...session, growth: { ...session.growth, maxStrands: 321 } }),
    );
    expect((await growOk(capped, '--out', join(d, 'a.obj'))).strands).toBe(321);
    expect((await growOk(capped, '--out', join(d, 'b.obj'), '--strands', '123')).strands).toBe(123);
  });

  it('is deterministic: two runs write byte-identical files; a link and an export reopen it', async () => {
    const d = freshDir();
    const args = ['--strands', '1000', '--grid', '25k', '--solver', 'fast'];
    const a = await growOk(sessionFile, '--out', join(d, 'a.usda'), ...args);
    const b = await growOk(sessionFile, '--out', join(d, 'b.usda'), ...args);
    const bytesA = readFileSync(join(d, 'a.usda'));
    expect(bytesA.equals(readFileSync(join(d, 'b.usda')))).toBe(true);
    expect([a.strands, a.points, a.bytes]).toEqual([b.strands, b.points, b.bytes]);
    // the export carries the session: growing from it gives the same file again
    await growOk(join(d, 'a.usda'), '--out', join(d, 'c.usda'), ...args);
    expect(readFileSync(join(d, 'c.usda')).equals(bytesA)).toBe(true);
    // so does a glb export
    await growOk(sessionFile, '--out', join(d, 'a.glb'), ...args);
    await growOk(join(d, 'a.glb'), '--out', join(d, 'd.usda'), ...args);
    expect(readFileSync(join(d, 'd.usda')).equals(bytesA)).toBe(true);
    // a share link (numbers rounded to 1e-5) grows the same number of strands
    const link = `http://127.0.0.1:5173/?grid=25k#${await encodeSessionLink(session)}`;
    const viaLink = await growOk(link, '--out', join(d, 'e.obj'), ...args);
    expect(viaLink.strands).toBe(a.strands);
    const bare = await growOk(
      `#${await encodeSessionLink(session)}`,
      '--out',
      join(d, 'f.obj'),
      ...args,
    );
    expect(readFileSync(join(d, 'f.obj')).equals(readFileSync(join(d, 'e.obj')))).toBe(true);
    expect(bare.bytes).toBe(viaLink.bytes);
  });
});

describe('hairsketch grow: the command', () => {
  it('exits 2 with one line on stderr and 0 with one JSON line on stdout (scripts/hairsketch.mjs)', () => {
    const d = freshDir();
    const bad = spawnSync(
      'node',
      ['scripts/hairsketch.mjs', 'grow', sessionFile, '--out', join(d, 'o.usda'), '--grid', 'huge'],
      { encoding: 'utf8' },
    );
    expect(bad.status).toBe(2);
    expect(bad.stdout).toBe('');
    expect(bad.stderr).toMatch(/^hairsketch: unknown grid "huge" [^\n]*\n$/);
    const good = execFileSync(
      'node',
      ['scripts/hairsketch.mjs', 'grow', sessionFile, '--out', join(d, 'o.obj'), '--strands', '50'],
      { encoding: 'utf8' },
    );
    const lines = good.trim().split('\n');
    expect(lines).toHaveLength(1);
    expect(JSON.parse(lines[0]).strands).toBe(50);
    expect(readdirSync(d)).toEqual(['o.obj']);
  });
});
