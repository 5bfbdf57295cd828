// `hairsketch render`: a preset's session becomes a PNG of the size asked for, drawn by the
// built app's embed in Chromium; the hair shows (its pixels differ from the bald head's, read
// back with a PNG reader of our own); bad arguments get one line and exit 2, writing nothing.

import { createHash } from 'node:crypto';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { beforeAll, beforeEach, describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import { writeSessionFile } from '../../web/model/sessionFile';
import { encodeSessionLink } from '../../web/model/sessionLink';
import { ellipsoidHead, toObj } from '../support/generatedHead';
import { captureOutput } from './captureOutput';
import { bundledCli } from './cliBundle';
import { readPng } from './pngPixels';

const { main } = await bundledCli();
const DIST_BUILT = existsSync(new URL('../../dist/embed.html', import.meta.url));

let dir: string;
let out: string[] = [];
let err: string[] = [];
let eggLink = '';

beforeAll(async () => {
  dir = mkdtempSync(join(tmpdir(), 'hs-render-'));
  const head = Head.builtin();
  for (const name of ['bob', 'empty'] as const)
    writeFileSync(
      join(dir, `${name}.json`),
      JSON.stringify(presetSession(name, head, '25k', 1500)),
    );
  // bob on a head of its own (an OBJ in mm), saved as "Save" writes it: the head file inside
  const soup = ellipsoidHead(24);
  const egg = toObj({ positions: soup.positions.map((v) => v * 100), indices: soup.indices });
  const onEgg = {
    ...presetSession('bob', head, '25k', 1500),
    head: {
      kind: 'mesh' as const,
      name: 'egg.obj',
      hash: createHash('sha256').update(new Uint8Array(egg)).digest('hex'),
      format: 'obj' as const,
      up: 'y' as const,
      turns: [],
    },
  };
  writeFileSync(join(dir, 'egg.json'), await writeSessionFile(onEgg, { headBytes: egg }));
  eggLink = await encodeSessionLink(onEgg);
});
beforeEach(() => {
  out = [];
  err = [];
});
captureOutput(
  (s) => out.push(s),
  (s) => err.push(s),
);

describe('hairsketch render', () => {
  it('refuses bad arguments in one line, writing nothing', async () => {
    const png = join(dir, 'never.png');
    for (const [args, says] of [
      [['render', join(dir, 'bob.json'), '--out', join(dir, 'x.jpg')], /must name a \.png/],
      [['render', join(dir, 'bob.json'), '--out', png, '--size', '10x10'], /--size must be/],
      [['render', join(dir, 'bob.json'), '--out', png, '--size', 'big'], /--size must be/],
      [['render', join(dir, 'bob.json'), '--out', png, '--view', 'top'], /unknown view "top"/],
      [['render', '--out', png], /no session or link/],
      [['render', join(dir, 'missing.json'), '--out', png], /cannot read session/],
      [['render', '#s=3.damaged', '--out', png], /link/],
    ] as const) {
      err = [];
      expect(await main([...args]), args.join(' ')).toBe(2);
      expect(err.join('').trim().split('\n')).toHaveLength(1);
      expect(err.join('')).toMatch(says);
    }
    expect(existsSync(png)).toBe(false);
  });

  it.runIf(DIST_BUILT)(
    'draws a preset at the size asked for; the hair changes the picture',
    async () => {
      const shot = async (name: string) => {
        const file = join(dir, `${name}.png`);
        out = [];
        const code = await main([
          'render',
          join(dir, `${name}.json`),
          '--out',
          file,
          '--size',
          '320x240',
          '--view',
          'side',
        ]);
        expect(code, err.join('')).toBe(0);
        const report = JSON.parse(out.join(''));
        expect(report).toMatchObject({ width: 320, height: 240, view: 'side', head: 'builtin' });
        expect(report.ms).toBeGreaterThan(0);
        return { report, pixels: readPng(readFileSync(file)) };
      };
      const hair = await shot('bob');
      const bald = await shot('empty');
      expect(hair.report.strands).toBeGreaterThan(1000);
      expect(bald.report.strands).toBe(0);
      for (const p of [hair.pixels, bald.pixels]) {
        expect([p.width, p.height]).toEqual([320, 240]);
        expect(p.rgba.length).toBe(320 * 240 * 4);
      }
      // the head alone is not a blank picture, and the hair covers a good part of it
      let differ = 0;
      let notBackground = 0;
      const a = hair.pixels.rgba;
      const b = bald.pixels.rgba;
      for (let i = 0; i < a.length; i += 4) {
        const d =
          Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]);
        if (d > 60) differ++;
        if (Math.abs(b[i] - b[4]) + Math.abs(b[i + 1] - b[5]) + Math.abs(b[i + 2] - b[6]) > 30)
          notBackground++;
      }
      expect(notBackground).toBeGreaterThan(0.03 * 320 * 240);
      expect(differ).toBeGreaterThan(0.03 * 320 * 240);
    },
    180_000,
  );

  it.runIf(DIST_BUILT)(
    'draws a session on a loaded head from the file that embeds it; a link alone is refused',
    async () => {
      const file = join(dir, 'egg.png');
      out = [];
      const code = await main(['render', join(dir, 'egg.json'), '--out', file, '--size', '64x48']);
      expect(code, err.join('')).toBe(0);
      expect(JSON.parse(out.join(''))).toMatchObject({ head: 'egg.obj', width: 64, height: 48 });
      expect(JSON.parse(out.join('')).strands).toBeGreaterThan(1000);
      expect(readPng(readFileSync(file)).width).toBe(64);
      err = [];
      expect(await main(['render', `#${eggLink.replace(/^#/, '')}`, '--out', file])).toBe(2);
      expect(err.join('')).toMatch(/needs the head file “egg\.obj”/);
    },
    180_000,
  );
});
