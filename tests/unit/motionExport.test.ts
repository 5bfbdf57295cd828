// The motion export: `hairsketch grow --motion` writes a .usda whose hair points and head
// transform are time samples (usd-core reads them: tests/usd/check_motion.py; Blender plays them:
// tests/usd/check_blender.py --motion), whose first frame
// is the static export's hair; the app's pipeline (growSessionHair then simulateMotion, as the
// export worker runs it) gives the same groom bytes; bad --motion / --frames are refused.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { headForGrow } from '../../web/cli/head';
import { presetSession } from '../../web/cli/presetSession';
import { growSessionHair } from '../../web/export/growSession';
import { simulateMotion } from '../../web/export/motionExport';
import { writeExport } from '../../web/export/writeExport';
import { Head } from '../../web/head/head';
import { gridForSession } from '../../web/model/grid';
import { hangLength } from '../../web/model/session';
import { readSessionFile } from '../../web/model/sessionFile';
import { loadSolverEngine } from '../../web/solver/wasmEngine';
import { captureOutput } from './captureOutput';
import { bundledCli } from './cliBundle';

const { main } = await bundledCli();
const PYTHON = fileURLToPath(new URL('../../build/usd-venv/bin/python', import.meta.url));
const CHECK = fileURLToPath(new URL('../usd/check_motion.py', import.meta.url));
const BPY = fileURLToPath(new URL('../../build/bpy-venv/bin/python', import.meta.url));
const CHECK_BLENDER = fileURLToPath(new URL('../usd/check_blender.py', import.meta.url));
const wasmPath = fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url));

const head = Head.builtin();
const session = presetSession('long', head, '25k', 0);
const STRANDS = '300';
const FRAMES = 4;

let dir: string;
let sessionFile: string;
let err: string[] = [];
captureOutput(
  () => {},
  (s) => err.push(s),
);

beforeAll(() => {
  dir = mkdtempSync(join(tmpdir(), 'hs-motion-'));
  sessionFile = join(dir, 'long.hairsketch.json');
  writeFileSync(sessionFile, JSON.stringify({ ...session, camera: session.curves[0].viewpoint }));
});

async function grow(...args: string[]): Promise<number> {
  err = [];
  return main(['grow', sessionFile, '--strands', STRANDS, '--progress-seconds', '100000', ...args]);
}

/** The file from `def Xform "hairsketch"` on (after the layer header with the session). */
const body = (text: string) => text.slice(text.indexOf('def Xform "hairsketch"'));

describe('motion export', () => {
  it('usd-core reads the time samples; the first frame is the static export; the app pipeline writes the same groom', async () => {
    const motionFile = join(dir, 'turn.usda');
    const staticFile = join(dir, 'still.usda');
    expect(
      await grow('--out', motionFile, '--motion', 'head-turn', '--frames', String(FRAMES)),
    ).toBe(0);
    const noHeadFile = join(dir, 'turn-no-head.usda');
    expect(
      await grow(
        '--out',
        noHeadFile,
        '--no-head',
        '--motion',
        'head-turn',
        '--frames',
        String(FRAMES),
      ),
    ).toBe(0);
    expect(await grow('--out', staticFile)).toBe(0);
    const r = JSON.parse(execFileSync(PYTHON, [CHECK, motionFile, staticFile]).toString());
    const codes = [0, 1, 2, 3];
    expect(r.start).toBe(0);
    expect(r.end).toBe(FRAMES - 1);
    expect(r.perSecond).toBe(24);
    expect(r.hairSamples).toEqual(codes);
    expect(r.guideSamples).toEqual(codes);
    expect(r.headSamples).toEqual(codes);
    expect(r.firstEqualsStatic).toBe(true);
    expect(r.defaultEqualsStatic).toBe(true);
    expect(r.moved).toBeGreaterThan(0.01);
    // Blender plays it: frames 0..3 at 24 fps, the hair's points and the head's turn animated
    const b = JSON.parse(
      execFileSync(BPY, [CHECK_BLENDER, '--motion', motionFile], {
        stdio: ['ignore', 'pipe', 'ignore'],
      })
        .toString()
        .trim()
        .split('\n')
        .at(-1) as string,
    );
    expect(b.frames).toEqual([0, FRAMES - 1]);
    expect(b.fps).toBe(24);
    expect(b.hair.type).toBe('CURVES');
    expect(b.hair.samples[2]).not.toEqual(b.hair.samples[0]);
    expect(b.head.type).toBe('MESH');
    expect(b.head.samples[2]).not.toEqual(b.head.samples[0]);

    // the app's export worker: growSessionHair, simulateMotion, writeExport('usda')
    const text = readFileSync(noHeadFile, 'utf8');
    const read = await readSessionFile(JSON.parse(readFileSync(sessionFile, 'utf8')));
    if (!read.ok) throw new Error(read.error);
    const s = read.value.session;
    const engine = await loadSolverEngine({ wasmBinary: new Uint8Array(readFileSync(wasmPath)) });
    try {
      // the scalp as the app's exporter hands it (the session's painted mask, the body)
      const { scalp } = await headForGrow(s, undefined, null);
      const hair = growSessionHair(engine, s, scalp, {
        grid: gridForSession(s.grid, s.curves, undefined, hangLength(s)),
        solver: 'fast',
        maxStrands: Number(STRANDS),
      });
      const motion = simulateMotion(engine, hair.strands, s, 'head-turn', FRAMES);
      const chunks: Uint8Array[] = [];
      for (const c of writeExport('usda', {
        strands: hair.strands,
        session: s,
        head: null,
        motion,
      }))
        chunks.push(c.slice());
      const app = Buffer.concat(chunks).toString('utf8');
      expect(body(app).length).toBe(body(text).length);
      expect(body(app) === body(text)).toBe(true);
    } finally {
      engine.dispose();
    }
  });

  it('refuses an unknown motion, frames that are not a positive whole number, past the cap, or a motion in another format', async () => {
    const out = join(dir, 'bad.usda');
    for (const [args, words] of [
      [['--motion', 'spin'], 'unknown motion "spin"'],
      [['--motion', 'nod', '--frames', '0'], 'positive whole number'],
      [['--motion', 'nod', '--frames', '2.5'], 'positive whole number'],
      [['--motion', 'nod', '--frames', '99999'], 'at most 1440'],
      [['--frames', '10'], '--frames needs --motion'],
    ] as const) {
      expect(await grow('--out', out, ...args)).toBe(2);
      expect(err.join('')).toContain(words);
      expect(existsSync(out)).toBe(false);
    }
    expect(await grow('--out', join(dir, 'bad.obj'), '--motion', 'nod')).toBe(2);
    expect(err.join('')).toContain('--motion needs --format usda');
  });
});
