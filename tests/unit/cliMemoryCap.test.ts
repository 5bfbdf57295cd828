// `hairsketch solve` on grids past the memory cap: refused by the solver's estimate with one
// line and exit 2 (no allocation), and the --max-seconds time cap of long iterative solves.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { bundledCli } from './cliBundle';

// The bundled command line (what `npx hairsketch` runs), built from web/cli/.
const { EXIT_TIME_CAP, main } = await bundledCli();

let err: string[] = [];
beforeEach(() => {
  err = [];
  vi.spyOn(process.stderr, 'write').mockImplementation((s) => {
    err.push(String(s));
    return true;
  });
  vi.spyOn(process.stdout, 'write').mockImplementation(() => true);
});
afterEach(() => vi.restoreAllMocks());

function problem(grid: [number, number, number], set: number[][]): string {
  const dir = mkdtempSync(join(tmpdir(), 'hs-cap-'));
  const file = join(dir, 'p.json');
  writeFileSync(file, JSON.stringify({ grid, steps: [{ set }] }));
  return file;
}

describe('hairsketch solve: memory cap and time cap', () => {
  for (const [grid, solvers] of [
    [
      [158, 158, 158],
      ['exact', 'fast', 'auto'],
    ],
    [
      [2, 2, 1_000_000],
      ['exact', 'fast', 'auto'],
    ],
  ] as Array<[[number, number, number], string[]]>)
    for (const solver of solvers)
      it(`${grid.join('x')} with ${solver}: one line with the figures, exit 2`, async () => {
        const file = problem(grid, [[0, 0, 1, 0, 0, 1]]);
        const out = mkdtempSync(join(tmpdir(), 'hs-cap-out-'));
        const code = await main(['solve', file, '--out', out, '--solver', solver]);
        expect(code).toBe(2);
        expect(err.join('')).toMatch(
          /^hairsketch: .*over the memory cap \(needs ~\d+ MB, cap \d+ MB\)\n$/,
        );
      });

  it('cg stops at --max-seconds with a clear message and exit 3, printing progress', async () => {
    const file = problem(
      [60, 60, 60],
      [
        [30, 30, 5, 0, 0, 1],
        [30, 30, 55, 1, 0, 0],
      ],
    );
    const out = mkdtempSync(join(tmpdir(), 'hs-cap-out-'));
    const args = ['solve', file, '--out', out, '--solver', 'cg', '--max-seconds', '1'];
    const code = await main([...args, '--progress-seconds', '0.2']);
    expect(code).toBe(EXIT_TIME_CAP);
    const text = err.join('');
    expect(text).toMatch(/stopped at the time cap of 1 s \(--max-seconds\) in step 0 after \d+/);
  });

  it('rejects a bad --max-seconds', async () => {
    const file = problem([4, 4, 4], [[1, 1, 1, 0, 0, 1]]);
    expect(await main(['solve', file, '--out', tmpdir(), '--max-seconds', 'soon'])).toBe(2);
    expect(err.join('')).toMatch(/--max-seconds must be a number of seconds > 0/);
  });
});
