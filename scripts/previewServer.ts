// Shared by the browser benchmarks: start `vite preview` and Chromium, wait for the server and
// for the app to settle.

import { type ChildProcess, spawn } from 'node:child_process';
import http from 'node:http';
import { type Browser, chromium, type Page } from '@playwright/test';

export async function waitServer(base: string): Promise<void> {
  for (let i = 0; i < 300; i++) {
    const ok = await new Promise<boolean>((resolve) => {
      const req = http.get(`${base}/`, (res) => {
        res.resume();
        resolve(res.statusCode === 200);
      });
      req.on('error', () => resolve(false));
    });
    if (ok) return;
    await new Promise((r) => setTimeout(r, 200));
  }
  throw new Error('vite preview did not start');
}

/** Opens `url` in a new 800 x 600 page and waits until the app is ready with hair and idle. */
export async function openWhenHairReady(
  browser: { newPage(o: { viewport: { width: number; height: number } }): Promise<Page> },
  url: string,
): Promise<Page> {
  const page = await browser.newPage({ viewport: { width: 800, height: 600 } });
  await page.goto(url);
  await page.waitForFunction(
    () => {
      const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
      return !!el && el.dataset.state === 'ready' && Number(el.dataset.strands) > 0;
    },
    null,
    { timeout: 300_000, polling: 100 },
  );
  await page.evaluate(() => window.hairsketch.idle());
  return page;
}

/** `vite preview` of the build in `dist` (an absolute path: vite's root is web/) on `port`, and
 *  Debian's Chromium (CHROMIUM_PATH overrides) with software WebGL, as the fixture recorders use
 *  them. */
export async function previewAndBrowser(
  dist: string,
  port: number,
): Promise<{ server: ChildProcess; browser: Browser }> {
  const server = spawn(
    'node_modules/.bin/vite',
    ['preview', '--port', String(port), '--strictPort', '--outDir', dist],
    { stdio: ['ignore', 'ignore', 'inherit'] },
  );
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--no-first-run'],
  });
  return { server, browser };
}

/** Waits until the app is ready (or failed) and idle, with a hair revision past `after`. */
export async function settled(page: Page, after = -1, timeout = 600_000): Promise<string> {
  await page.waitForFunction(
    (rev) => {
      const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
      if (!el) return false;
      if (el.dataset.state === 'error') return true;
      return el.dataset.state === 'ready' && Number(el.dataset.revision) > rev;
    },
    after,
    { timeout, polling: 50 },
  );
  await page.evaluate(() => window.hairsketch.idle());
  return (await page.getByTestId('status').getAttribute('data-state')) ?? '';
}

export const revision = async (page: Page) =>
  Number(await page.getByTestId('status').getAttribute('data-revision'));
