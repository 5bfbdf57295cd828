// End to end in Debian's Chromium: real pointer events, waits on the status attributes only.
import { expect, type Page, test } from '@playwright/test';
import { settled, status, strokeFromScalp, visibleCurvePoint, watchConsole } from './helpers';

const SCENE = '/?strands=2500'; // SwiftShader renders slowly: a small strand count keeps it quick

const hairHash = (page: Page) => page.evaluate(() => window.hairsketch.hairHash());

test('loads to ready with hair and a non-blank canvas, without console errors', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto(SCENE);
  const s = await settled(page, -1, { drawn: true });
  expect(s.strands).toBeGreaterThan(500);
  expect(s.curves).toBeGreaterThanOrEqual(4);
  // Not blank: the canvas holds many distinct colours (head shading + hair + background).
  const colours = await page.getByTestId('viewport').evaluate((c: HTMLCanvasElement) => {
    const probe = document.createElement('canvas');
    probe.width = 160;
    probe.height = 120;
    const ctx = probe.getContext('2d') as CanvasRenderingContext2D;
    ctx.drawImage(c, 0, 0, probe.width, probe.height);
    const data = ctx.getImageData(0, 0, probe.width, probe.height).data;
    const set = new Set<number>();
    for (let i = 0; i < data.length; i += 4)
      set.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
    return set.size;
  });
  expect(colours).toBeGreaterThan(50);
  const session = (await page.evaluate(() => window.hairsketch.session())) as {
    curves: { type: string }[];
  };
  expect(session.curves.every((c) => c.type === 'stream')).toBe(true);
  expect(errors).toEqual([]);
});

test('a stroke from the scalp adds a curve and changes the hair; undo and redo restore', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto(SCENE);
  const before = await settled(page);
  const hashBefore = await hairHash(page);
  await page.getByRole('button', { name: 'Stream curve' }).click();
  await strokeFromScalp(page, 35, 20, 140, 190);
  await page.waitForFunction((n) => {
    const el = document.querySelector('[data-testid="status"]') as HTMLElement;
    return Number(el.dataset.curves) === n;
  }, before.curves + 1);
  const after = await settled(page, before.revision);
  const hashAfter = await hairHash(page);
  expect(hashAfter).not.toBe(hashBefore);
  const session = (await page.evaluate(() => window.hairsketch.session())) as {
    curves: { type: string; points: number[][] }[];
  };
  const added = session.curves[session.curves.length - 1];
  expect(added.type).toBe('stream');
  expect(added.points.length).toBeGreaterThan(5);

  await page.getByRole('button', { name: 'Undo' }).click();
  const undone = await settled(page, after.revision);
  expect(undone.curves).toBe(before.curves);
  expect(await hairHash(page)).toBe(hashBefore);
  expect(undone.strands).toBe(before.strands);

  await page.keyboard.press('Control+Shift+Z');
  const redone = await settled(page, undone.revision);
  expect(redone.curves).toBe(before.curves + 1);
  expect(await hairHash(page)).toBe(hashAfter);

  await page.keyboard.press('Control+Z');
  await settled(page, redone.revision);
  expect(await hairHash(page)).toBe(hashBefore);
  expect(errors).toEqual([]);
});

test('a stroke that does not start on the scalp creates nothing and says why', async ({ page }) => {
  await page.goto(`${SCENE}&preset=empty`);
  const s = await settled(page);
  expect(s.curves).toBe(0);
  const box = await page.getByTestId('viewport').boundingBox();
  if (!box) throw new Error('no viewport');
  await page.mouse.move(box.x + 20, box.y + 20); // background corner
  await page.mouse.down();
  await page.mouse.move(box.x + 80, box.y + 90);
  await page.mouse.up();
  await expect(page.getByTestId('status')).toContainText('must start on the scalp');
  expect((await status(page)).curves).toBe(0);
  // A click without motion on the scalp is a degenerate stroke: ignored, no error.
  const p = await page.evaluate(() => window.hairsketch.scalpToScreen(20, 0));
  if (!p) throw new Error('scalp point hidden');
  await page.mouse.click(p.x, p.y);
  await expect(page.getByTestId('status')).toContainText('ignored');
  const after = await status(page);
  expect(after.curves).toBe(0);
  expect(after.state).toBe('ready');
});

test('a selected curve can be deleted, and a crashed worker is restarted with the session', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto(SCENE);
  const s0 = await settled(page);
  await page.getByRole('button', { name: 'Select' }).click();
  // a click beside every curve (the canvas's top left corner) selects nothing and says so
  const box = await page.locator('canvas').first().boundingBox();
  if (!box) throw new Error('no canvas');
  await page.mouse.click(box.x + 12, box.y + 12);
  await expect(page.getByRole('status').first()).toContainText('No curve under the click');
  // Click on the middle of a visible curve.
  const target = await visibleCurvePoint(page);
  await page.mouse.click(target.x, target.y);
  await expect(page.getByRole('button', { name: 'Delete' })).toBeEnabled();
  await page.getByRole('button', { name: 'Delete' }).click();
  const s1 = await settled(page, s0.revision);
  expect(s1.curves).toBe(s0.curves - 1);

  await page.evaluate(() => window.hairsketch.crashWorker());
  const s2 = await settled(page, s1.revision);
  expect(s2.curves).toBe(s1.curves);
  expect(s2.strands).toBe(s1.strands);
  expect(errors).toEqual([]);
});
