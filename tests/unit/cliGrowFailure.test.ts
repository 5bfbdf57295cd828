// `hairsketch grow` when writing fails half-way (the writer throws after its first chunk): exit
// code 1 (an internal error), one line on stderr, and neither the output nor its temporary file
// is left behind; an existing file at --out keeps its contents. It runs the sources, not the
// bundled command line: the failing writer is a mock of a source module.
import { mkdtempSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, expect, it, vi } from 'vitest';
import { main } from '../../web/cli/main';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';

vi.mock('../../web/export/writeExport', async (importOriginal) => {
  const real = await importOriginal<typeof import('../../web/export/writeExport')>();
  return {
    ...real,
    *writeExport() {
      yield new TextEncoder().encode('#usda 1.0\n(partial');
      throw new Error('the disk caught fire');
    },
  };
});

afterEach(() => vi.restoreAllMocks());

/** No progress lines on stderr however slow the machine (progress has its own test). */
const QUIET = ['--progress-seconds', '100000'];

it('a writer failing after its first chunk leaves no file, exit 1', async () => {
  const err: string[] = [];
  vi.spyOn(process.stderr, 'write').mockImplementation((s) => {
    err.push(String(s));
    return true;
  });
  vi.spyOn(process.stdout, 'write').mockImplementation(() => true);
  const d = mkdtempSync(join(tmpdir(), 'hs-grow-fail-'));
  writeFileSync(join(d, 's.json'), JSON.stringify(presetSession('default', Head.builtin())));
  const code = await main([
    'grow',
    join(d, 's.json'),
    '--out',
    join(d, 'new.usda'),
    '--strands',
    '20',
    ...QUIET,
  ]);
  expect(code).toBe(1);
  expect(err.join('')).toBe('hairsketch: the disk caught fire\n');
  expect(readdirSync(d)).toEqual(['s.json']);

  writeFileSync(join(d, 'old.usda'), 'old contents');
  err.length = 0;
  expect(
    await main([
      'grow',
      join(d, 's.json'),
      '--out',
      join(d, 'old.usda'),
      '--strands',
      '20',
      ...QUIET,
    ]),
  ).toBe(1);
  expect(readFileSync(join(d, 'old.usda'), 'utf8')).toBe('old contents');
  expect(readdirSync(d).sort()).toEqual(['old.usda', 's.json']);
});
