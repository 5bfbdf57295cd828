// npm run bench:export — export figures: in Debian's Chromium, the time from the menu click to
// the download and the file size per format, for the default preset's ~30K strands and a denser
// ~100K-strand version of it (roots every 0.55° instead of 1°); then `hairsketch grow` on the
// same sessions (wall time and size). A benchmark, not a test: it asserts nothing about speed.
// Writes bench-results/export.{json,md} and prints the table.
import { type ChildProcess, execFileSync, spawn } from 'node:child_process';
import { mkdtempSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium, type Page } from '@playwright/test';
import { writeBenchResults } from './benchResults.mjs';
import { waitServer } from './previewServer';

const PORT = Number(process.env.BENCH_PORT ?? 4192);
const BASE = `http://127.0.0.1:${PORT}`;
const ITEMS: Array<[string, string]> = [
  ['usda', 'USD (.usda)'],
  ['hair', 'Cem Yuksel (.hair)'],
  ['obj', 'OBJ (.obj)'],
  ['glb', 'glTF (.glb)'],
  ['cards', 'Hair cards (.glb)'],
];

async function ready(page: Page): Promise<void> {
  await page.waitForFunction(
    () =>
      (document.querySelector('[data-testid="status"]') as HTMLElement).dataset.state === 'ready',
    null,
    { timeout: 600_000 },
  );
  await page.evaluate(() => window.hairsketch.idle());
}

interface Row {
  strands: number;
  format: string;
  browserMs: number;
  browserBytes: number;
  cliMs: number;
  cliBytes: number;
}

async function main(): Promise<void> {
  const server: ChildProcess = spawn(
    'npx',
    ['vite', 'preview', '--port', String(PORT), '--strictPort'],
    // its own process group: npx starts vite as a child, and both must stop at the end
    { stdio: 'ignore', detached: true },
  );
  const dir = mkdtempSync(join(tmpdir(), 'hairsketch-bench-export-'));
  const rows: Row[] = [];
  try {
    await waitServer(BASE);
    const browser = await chromium.launch({
      executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
      args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader'],
    });
    for (const dense of [false, true]) {
      const page = await browser.newPage({ viewport: { width: 1000, height: 750 } });
      await page.goto(`${BASE}/`);
      await ready(page);
      if (dense) {
        const before = await page.evaluate(() =>
          Number(document.querySelector('[data-testid="status"]')?.getAttribute('data-revision')),
        );
        await page.evaluate(() => {
          const s = window.hairsketch.session() as { growth: Record<string, number> };
          s.growth.thetaStepDeg = 0.55;
          s.growth.phiStepDeg = 0.55;
          window.hairsketch.replaceSession(s);
        });
        await page.waitForFunction(
          (r) =>
            Number(
              document.querySelector('[data-testid="status"]')?.getAttribute('data-revision'),
            ) > r,
          before,
          { timeout: 600_000 },
        );
        await ready(page);
      }
      const strands = Number(await page.getByTestId('status').getAttribute('data-strands'));
      const sessionFile = join(dir, `session-${dense ? 'dense' : 'default'}.json`);
      writeFileSync(
        sessionFile,
        JSON.stringify(await page.evaluate(() => window.hairsketch.session())),
      );
      for (const [format, item] of ITEMS) {
        await page.getByRole('button', { name: 'Export' }).click();
        const t0 = Date.now();
        const [download] = await Promise.all([
          page.waitForEvent('download', { timeout: 600_000 }),
          page.getByRole('menuitem', { name: item, exact: true }).click(),
        ]);
        const path = await download.path();
        const browserMs = Date.now() - t0;
        const browserBytes = statSync(path).size;
        await ready(page);
        // hair cards are a .glb: the format is named, not told by the extension
        const out = join(dir, `cli-${strands}.${format === 'cards' ? 'glb' : format}`);
        const c0 = Date.now();
        execFileSync(
          process.execPath,
          ['scripts/hairsketch.mjs', 'grow', sessionFile, '--out', out, '--format', format],
          {
            stdio: 'ignore',
          },
        );
        const cliMs = Date.now() - c0;
        rows.push({
          strands,
          format,
          browserMs,
          browserBytes,
          cliMs,
          cliBytes: statSync(out).size,
        });
        console.log(JSON.stringify(rows[rows.length - 1]));
      }
      await page.close();
    }
    await browser.close();
  } finally {
    if (server.pid) process.kill(-server.pid);
  }
  const mb = (n: number) => (n / 1024 / 1024).toFixed(1);
  const out = [
    '| strands | format | browser click → download s | size MB | `hairsketch grow` s | size MB |',
    '| --- | --- | --- | --- | --- | --- |',
  ];
  for (const r of rows)
    out.push(
      `| ${r.strands.toLocaleString('en-US')} | ${r.format} | ${(r.browserMs / 1000).toFixed(1)} | ${mb(r.browserBytes)} | ${(r.cliMs / 1000).toFixed(1)} | ${mb(r.cliBytes)} |`,
    );
  console.log(`\n${out.join('\n')}`);
  writeBenchResults('export', {
    title: 'Export: time and size per format, in the browser and from the command line',
    script: 'scripts/bench-export.ts',
    command: 'npm run bench:export',
    measures:
      'The default preset (~30K strands) and a denser version of it (roots every 0.55°, ~100K ' +
      'strands). Browser: headless Chromium, from the click on the Export menu item to the ' +
      'download, the solve from scratch included. Command line: `hairsketch grow` wall time, ' +
      'Node start-up included. Sizes of both files (they are the same bytes). Hair cards: the ' +
      'default 1,000 cards, clustering and atlas included. One run.',
    config: { formats: ITEMS.map(([f]) => f) },
    results: rows,
    table: out.join('\n'),
  });
}

await main();
