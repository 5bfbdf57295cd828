// Faults and rough handling: the solver worker killed during a solve and during a stroke, the
// export worker killed during an export, rapid input (many strokes as fast as the pointer
// allows, hundreds of undo/redo during solves, display toggles), and a reload. Each ends with
// every curve there and the hair equal to what a fresh page grows from the same session.
import { type Browser, expect, type Page, test } from '@playwright/test';
import { settled, status, watchConsole } from './helpers';

type Session = { curves: { id: string; points: number[][] }[] };

async function session(page: Page): Promise<Session> {
  return (await page.evaluate(() => window.hairsketch.session())) as Session;
}

/** The hair a fresh page grows from `s` (its hairHash): the final field is solved from zero,
 *  so the same session gives bit-identical hair whatever came before it. */
async function freshHash(browser: Browser, url: string, s: Session): Promise<string | null> {
  const page = await browser.newPage();
  await page.goto(`${url}&preset=empty`);
  const s0 = await settled(page);
  await page.evaluate((j) => window.hairsketch.replaceSession(j), s);
  await settled(page, s0.revision);
  const hash = await page.evaluate(() => window.hairsketch.hairHash());
  await page.close();
  return hash;
}

async function expectFreshHair(page: Page, browser: Browser, url: string, s: Session) {
  const mine = await page.evaluate(() => window.hairsketch.hairHash());
  expect(mine).not.toBeNull();
  expect(await freshHash(browser, url, s)).toBe(mine);
}

async function scalpPoint(page: Page, t: number, p: number) {
  const s = await page.evaluate(([a, b]) => window.hairsketch.scalpToScreen(a, b), [t, p]);
  if (!s) throw new Error(`scalp point (${t}, ${p}) hidden`);
  return s;
}

test('the solver worker killed during a solve and during a stroke: every curve stays, the hair is a fresh solve', async ({
  page,
  browser,
}) => {
  test.slow();
  const url = '/?grid=50k&strands=1500';
  await page.goto(url);
  const s0 = await settled(page);
  await page.getByRole('button', { name: 'Stream curve' }).click();

  // 1: a stroke, then the worker dies while its solve runs
  let a = await scalpPoint(page, 35, 20);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  for (let i = 1; i <= 20; i++) await page.mouse.move(a.x + 6 * i, a.y + 9 * i);
  await page.mouse.up();
  await page.waitForFunction(
    (n) =>
      Number((document.querySelector('[data-testid="status"]') as HTMLElement).dataset.curves) ===
      n,
    s0.curves + 1,
  );
  await page.evaluate(() => window.hairsketch.crashWorker());

  // 2: the worker dies in the middle of a stroke (its previews are being solved)
  a = await scalpPoint(page, 40, -25);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++) await page.mouse.move(a.x - 6 * i, a.y + 8 * i);
  await page.evaluate(() => window.hairsketch.crashWorker());
  for (let i = 11; i <= 20; i++) await page.mouse.move(a.x - 6 * i, a.y + 8 * i);
  await page.mouse.up();

  const s2 = await settled(page, s0.revision);
  expect(s2.curves).toBe(s0.curves + 2);
  expect(s2.state).toBe('ready');
  const s = await session(page);
  expect(s.curves).toHaveLength(s0.curves + 2);
  await expectFreshHair(page, browser, url, s);
});

test('the export worker killed during an export: a clear message, the session unchanged, the next export works', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto('/?strands=1500');
  const s0 = await settled(page);
  const before = await session(page);
  await page.getByRole('button', { name: 'Export' }).click();
  await page.getByRole('menuitem', { name: 'USD (.usda)', exact: true }).click();
  await expect(page.getByTestId('status')).toContainText('Exporting hairstyle.usda');
  await page.evaluate(() => window.hairsketch.crashExport());
  await expect(page.getByTestId('status')).toContainText('Export USD failed');
  await expect(page.getByTestId('status')).toContainText('session is unchanged');
  expect(await session(page)).toEqual(before);
  expect((await status(page)).curves).toBe(s0.curves);
  // and the next export goes through
  await page.getByRole('button', { name: 'Export' }).click();
  const [d] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('menuitem', { name: 'USD (.usda)', exact: true }).click(),
  ]);
  expect(d.suggestedFilename()).toBe('hairstyle.usda');
  expect(errors).toEqual([]);
});

test('rapid input: 10 strokes as fast as the pointer allows, 40 undo/redo during solves and toggles end consistent', async ({
  page,
  browser,
}) => {
  test.slow();
  const errors = watchConsole(page);
  const url = '/?strands=1200';
  await page.goto(`${url}&preset=empty`);
  await settled(page);
  await page.getByRole('button', { name: 'Stream curve' }).click();
  const starts: { x: number; y: number }[] = [];
  for (let k = 0; k < 10; k++)
    starts.push(await scalpPoint(page, 20 + (k % 5) * 8, -60 + ((k * 7) % 120)));
  for (const a of starts) {
    await page.mouse.move(a.x, a.y);
    await page.mouse.down();
    for (let i = 1; i <= 6; i++) await page.mouse.move(a.x + 4 * i, a.y + 15 * i);
    await page.mouse.up();
  }
  await page.waitForFunction(
    () =>
      Number((document.querySelector('[data-testid="status"]') as HTMLElement).dataset.curves) ===
      10,
  );
  // 20 undos (past the first curve) and 20 redos while the solves run, display toggles between
  for (let i = 0; i < 20; i++) {
    await page.keyboard.press('Control+z');
    if (i % 4 === 0) await page.keyboard.press(String(1 + ((i / 4) % 5)));
  }
  for (let i = 0; i < 20; i++) await page.keyboard.press('Control+Shift+z');
  for (const k of ['1', '2', '3', '4', '5', '2', '3', '4', '5']) await page.keyboard.press(k);
  const s = await settled(page);
  expect(s.curves).toBe(10);
  const sess = await session(page);
  expect(sess.curves).toHaveLength(10);
  expect(new Set(sess.curves.map((c) => c.id)).size).toBe(10);
  await expectFreshHair(page, browser, url, sess);
  expect(errors).toEqual([]);
});

test('a reload keeps the work (the address bar carries the session)', async ({ page }) => {
  await page.goto('/?strands=1000&preset=empty');
  await settled(page);
  await page.waitForFunction(() => window.location.hash.startsWith('#s='));
  const h0 = await page.evaluate(() => window.location.hash);
  await page.getByRole('button', { name: 'Stream curve' }).click();
  const a = await scalpPoint(page, 30, 10);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  for (let i = 1; i <= 20; i++) await page.mouse.move(a.x + 5 * i, a.y + 10 * i);
  await page.mouse.up();
  await settled(page);
  const before = await session(page);
  expect(before.curves).toHaveLength(1);
  // the link follows the session a moment after the edit
  await page.waitForFunction((h) => window.location.hash !== h, h0);
  await page.reload();
  await settled(page);
  const after = await session(page);
  expect(after.curves.map((c) => c.id)).toEqual(before.curves.map((c) => c.id));
  const p = before.curves[0].points;
  const q = after.curves[0].points;
  expect(q).toHaveLength(p.length);
  for (let i = 0; i < p.length; i++)
    for (let k = 0; k < 3; k++) expect(Math.abs(q[i][k] - p[i][k])).toBeLessThan(1e-4);
});
