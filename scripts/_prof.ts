import { resolve } from 'node:path';
import { openWhenHairReady, previewAndBrowser, waitServer } from './previewServer';

async function main() {
  const PORT = 4311;
  const { server, browser } = await previewAndBrowser(resolve('/work/main/dist'), PORT);
  try {
    await waitServer(`http://127.0.0.1:${PORT}`);
    const page = await openWhenHairReady(
      browser,
      `http://127.0.0.1:${PORT}/?preset=${process.env.P ?? 'long'}&strands=${process.env.N ?? 3000}`,
    );
    const q = await page.evaluate(() => window.hairsketch.quality());
    console.log('quality', JSON.stringify(q));
    console.log('frameMs settled', await page.evaluate(() => window.hairsketch.frameMs(3)));
    await page.getByLabel('Motion').selectOption('head-turn');
    await page.getByRole('button', { name: 'Play' }).click();
    const t0 = Date.now();
    for (let i = 0; i < 6; i++) {
      await page.waitForTimeout(1000);
      const m = await page.evaluate(() => window.hairsketch.motion());
      console.log(Date.now() - t0, JSON.stringify(m));
    }
    console.log('frameMs playing', await page.evaluate(() => window.hairsketch.frameMs(3)));
    await page.screenshot({ path: '/tmp/prof/play.png' });
  } finally {
    await browser.close();
    server.kill();
  }
}
main();
