// npm run bench:avoid — time from a click on "Avoid scalp" to the converged hair on screen
// (hairLog), in the built app in Debian's Chromium: the first toggle of each page (later toggles
// of the same state come from the result cache).
// Writes bench-results/avoid.{json,md}.
//   npx tsx scripts/bench-avoid.ts [preset] [grid ...]     (default: fig6 25k 50k)
import { type ChildProcess, spawn } from 'node:child_process';
import { chromium, type Page } from '@playwright/test';
import { writeBenchResults } from './benchResults.mjs';
import { waitServer } from './previewServer';

const PORT = Number(process.env.BENCH_PORT ?? 4297);
const BASE = `http://127.0.0.1:${PORT}`;
const [preset = 'fig6', ...gridArgs] = process.argv.slice(2);
const grids = gridArgs.length ? gridArgs : ['25k', '50k'];

const readyAfter = (page: Page, rev: number) =>
  page.waitForFunction(
    (r) => {
      const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
      return !!el && el.dataset.state === 'ready' && Number(el.dataset.revision) > r;
    },
    rev,
    { timeout: 600_000, polling: 20 },
  );

async function main(): Promise<void> {
  const server: ChildProcess = spawn(
    'node_modules/.bin/vite',
    ['preview', '--port', String(PORT), '--strictPort'],
    { stdio: ['ignore', 'ignore', 'inherit'] },
  );
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader'],
  });
  const lines = [
    '| preset | grid | grid points | click → converged hair ms | solve ms (tooltip) |',
    '| --- | --- | --- | --- | --- |',
  ];
  const results: Array<{
    preset: string;
    grid: string;
    gridPoints: number;
    clickToConvergedHairMs: number;
    solveMs: number | null;
  }> = [];
  try {
    await waitServer(BASE);
    for (const l of lines) console.log(l);
    for (const grid of grids) {
      const page = await browser.newPage({ viewport: { width: 1000, height: 750 } });
      await page.goto(`${BASE}/?preset=${preset}&grid=${grid}`);
      await readyAfter(page, -1);
      await page.evaluate(() => window.hairsketch.idle());
      const rev = Number(await page.getByTestId('status').getAttribute('data-revision'));
      const t0 = await page.evaluate(() => performance.now());
      await page.getByRole('button', { name: 'Avoid scalp' }).click();
      await readyAfter(page, rev);
      const log = await page.evaluate(() => window.hairsketch.hairLog());
      const shown = log.filter((e) => e.final).at(-1)?.time ?? Number.NaN;
      const tip = (await page.getByTestId('status').getAttribute('title')) ?? '';
      const points = await page.evaluate(() => window.hairsketch.gridPoints());
      const solve = /solve (\d+) ms/.exec(tip)?.[1];
      const line = `| ${preset} | ${grid} | ${points} | ${(shown - t0).toFixed(0)} | ${solve ?? '?'} |`;
      console.log(line);
      lines.push(line);
      results.push({
        preset,
        grid,
        gridPoints: points,
        clickToConvergedHairMs: shown - t0,
        solveMs: solve === undefined ? null : Number(solve),
      });
      await page.close();
    }
  } finally {
    await browser.close();
    server.kill();
  }
  writeBenchResults('avoid', {
    title: 'Avoid scalp: from the click to the converged hair on screen',
    script: 'scripts/bench-avoid.ts',
    command: 'npm run bench:avoid',
    measures:
      "The built app in Debian's Chromium (headless, SwiftShader, 1000×750): the first click on " +
      '"Avoid scalp" of each page, timed to the converged hair on screen (the page\'s hair log), ' +
      "with the grid's point count and the solve time the status tooltip reports (both solves " +
      'and the avoidance).',
    config: { preset, grids },
    results,
    table: lines.join('\n'),
  });
}

void main();
