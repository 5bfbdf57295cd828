// `hairsketch grow` on a long run: --max-seconds stops it (exit 3, one line saying where, no
// file left) and --progress-seconds prints JSON progress lines on stderr meanwhile.
import { mkdtempSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, expect, it, vi } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import { bundledCli } from './cliBundle';

// The bundled command line (what `npx hairsketch` runs), built from web/cli/.
const { main } = await bundledCli();

afterEach(() => vi.restoreAllMocks());

it('stops at --max-seconds with exit 3 and no file; prints progress lines', async () => {
  const err: string[] = [];
  vi.spyOn(process.stderr, 'write').mockImplementation((s) => {
    err.push(String(s));
    return true;
  });
  vi.spyOn(process.stdout, 'write').mockImplementation(() => true);
  const d = mkdtempSync(join(tmpdir(), 'hs-grow-cap-'));
  // the 250k grid solves for seconds: a 0.3 s cap stops it while solving
  writeFileSync(
    join(d, 's.json'),
    JSON.stringify(presetSession('default', Head.builtin(), '250k')),
  );
  const code = await main([
    'grow',
    join(d, 's.json'),
    '--out',
    join(d, 'h.hair'),
    '--max-seconds',
    '0.3',
    '--progress-seconds',
    '0.05',
  ]);
  expect(code).toBe(3);
  const text = err.join('');
  expect(text).toMatch(
    /hairsketch: stopped at the time cap of 0\.3 s \(--max-seconds\) while solving/,
  );
  const progress = text
    .split('\n')
    .filter((l) => l.startsWith('{'))
    .map((l) => JSON.parse(l));
  expect(progress.length).toBeGreaterThan(0);
  expect(progress[0].phase).toBe('solve');
  expect(readdirSync(d)).toEqual(['s.json']);

  err.length = 0;
  expect(
    await main(['grow', join(d, 's.json'), '--out', join(d, 'h.hair'), '--max-seconds', 'x']),
  ).toBe(2);
  expect(err.join('')).toMatch(/--max-seconds must be a number of seconds > 0/);
});
