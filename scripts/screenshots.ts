// npm run screenshots — loads each preset in the built app (Debian's Chromium) and saves the
// 3D view to docs/screenshots/<preset>-front.png, -side.png and -back.png once the final hair is
// drawn.
//   npx tsx scripts/screenshots.ts [preset ...]     (default: every preset in PRESET_NAMES)
// SHOT_QUALITY=fast|high|auto picks the Quality setting (default: the app's Auto); SHOT_OUT=<dir>
// writes elsewhere; SHOT_DIST=<dir> serves another build (vite build --outDir <dir>).
import { type ChildProcess, spawn } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import http from 'node:http';
import { chromium } from '@playwright/test';
import { PRESET_NAMES } from '../web/model/presets';

type V3 = [number, number, number];
const VIEWS: Array<[string, V3]> = [
  ['front', [2.6, 0.9, 7.0]],
  ['side', [7.4, 0.6, -0.6]],
  ['back', [-4.2, 1.6, -5.6]],
];
// Presets whose hair reaches far below the head are framed from farther away, aimed lower.
const FRAMING: Record<string, { scale: number; target: V3 }> = {
  long: { scale: 1.6, target: [0, -1.9, 0] },
  braid: { scale: 1.35, target: [0, -1.3, 0] },
  'pigtail-braids': { scale: 1.25, target: [0, -1.0, 0] },
};
const PORT = Number(process.env.SHOT_PORT ?? 4195);
const BASE = `http://127.0.0.1:${PORT}`;

async function waitServer(): Promise<void> {
  for (let i = 0; i < 300; i++) {
    const ok = await new Promise<boolean>((resolve) => {
      http
        .get(`${BASE}/`, (res) => {
          res.resume();
          resolve(res.statusCode === 200);
        })
        .on('error', () => resolve(false));
    });
    if (ok) return;
    await new Promise((r) => setTimeout(r, 200));
  }
  throw new Error('vite preview did not start');
}

async function main(): Promise<void> {
  const asked = process.argv.slice(2);
  const unknown = asked.filter((p) => !(PRESET_NAMES as readonly string[]).includes(p));
  if (unknown.length) {
    console.error(`unknown preset(s): ${unknown.join(', ')}; known: ${PRESET_NAMES.join(', ')}`);
    process.exit(2);
  }
  const presets = asked.length ? asked : PRESET_NAMES.filter((p) => p !== 'empty');
  const out = process.env.SHOT_OUT ?? 'docs/screenshots';
  mkdirSync(out, { recursive: true });
  const server: ChildProcess = spawn(
    'node_modules/.bin/vite',
    [
      'preview',
      '--port',
      String(PORT),
      '--strictPort',
      ...(process.env.SHOT_DIST ? ['--outDir', process.env.SHOT_DIST] : []),
    ],
    { stdio: ['ignore', 'ignore', 'inherit'] },
  );
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--no-first-run'],
  });
  try {
    await waitServer();
    for (const preset of presets) {
      const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
      await page.goto(`${BASE}/?preset=${preset}`);
      const q = process.env.SHOT_QUALITY;
      if (q === 'fast' || q === 'high' || q === 'auto') {
        const setting: 'fast' | 'high' | 'auto' = q;
        await page.evaluate((s) => window.hairsketch.setQuality(s), setting);
      }
      await page.waitForFunction(
        () => {
          const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
          return !!el && (el.dataset.state === 'ready' || el.dataset.state === 'error');
        },
        null,
        { timeout: 600_000, polling: 100 },
      );
      await page.evaluate(() => window.hairsketch.idle());
      const state = await page.getByTestId('status').getAttribute('data-state');
      if (state !== 'ready') {
        console.error(`${preset}: ${await page.getByTestId('status').textContent()}`);
        process.exitCode = 1;
      }
      // the hair alone (style curves are drawn over everything), from the front and the back
      await page.getByRole('checkbox', { name: 'Curves' }).uncheck();
      const frame = FRAMING[preset] ?? { scale: 1, target: [0, -0.55, 0] as V3 };
      for (const [view, position] of VIEWS) {
        const p = position.map((v) => v * frame.scale) as V3;
        await page.evaluate(([q, t]) => window.hairsketch.setCamera(q, t), [p, frame.target]);
        await page.evaluate(() => window.hairsketch.idle());
        const file = `${out}/${preset}-${view}.png`;
        await page.getByTestId('viewport').screenshot({ path: file });
        console.log(`${preset}: ${file}`);
      }
      await page.close();
    }
  } finally {
    await browser.close();
    server.kill();
  }
}

await main();
