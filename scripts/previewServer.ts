// Shared by the browser benchmarks: wait until `vite preview` answers at `base`.
import http from 'node:http';
import type { Page } from '@playwright/test';

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
