// Sessions as links: the address bar carries the session, a shared link reopens it, a damaged
// link says so and keeps the app usable.
import { expect, test } from '@playwright/test';
import { settled, strokeFromScalp, watchConsole } from './helpers';

interface SessionJson {
  curves: { id: string; type: string; points: number[][] }[];
  hairColor: string;
}

test('the link in the address bar reopens the session in a new page', async ({ page, context }) => {
  const errors = watchConsole(page);
  await page.goto('/?strands=2000');
  const s0 = await settled(page);
  await page.getByRole('button', { name: 'Stream curve' }).click();
  await strokeFromScalp(page, 35, 20, 140, 190);
  await settled(page, s0.revision);
  const made = (await page.evaluate(() => window.hairsketch.session())) as SessionJson;
  expect(made.curves.length).toBe(s0.curves + 1);
  // The address bar follows the session (debounced); wait for it to carry this one.
  await page.waitForFunction(() => window.location.hash.startsWith('#s='));
  await page.getByRole('button', { name: 'Share link' }).click();
  await expect(page.getByTestId('status')).toContainText('Link');
  const href = await page.evaluate(() => window.location.href);

  const other = await context.newPage();
  await other.goto(href);
  await settled(other);
  const opened = (await other.evaluate(() => window.hairsketch.session())) as SessionJson;
  expect(opened.curves.map((c) => c.id)).toEqual(made.curves.map((c) => c.id));
  const a = made.curves[made.curves.length - 1].points;
  const b = opened.curves[opened.curves.length - 1].points;
  expect(b.length).toBe(a.length);
  for (let i = 0; i < a.length; i++)
    for (let k = 0; k < 3; k++) expect(Math.abs(b[i][k] - a[i][k])).toBeLessThan(1e-5);
  expect(await other.evaluate(() => window.hairsketch.session())).toMatchObject({
    hairColor: made.hairColor,
  });
  expect(errors).toEqual([]);
});

test('New starts an empty head as a new session does, and Undo brings the work back', async ({
  page,
  context,
}) => {
  await page.goto('/?strands=2000');
  const s0 = await settled(page);
  expect(s0.curves).toBeGreaterThan(0);
  // Mirror, a view setting, stays on through New, and the status line says so
  await page.keyboard.press('x');
  await expect(page.getByRole('button', { name: 'Mirror' })).toHaveAttribute(
    'aria-pressed',
    'true',
  );
  await page.getByRole('button', { name: 'New', exact: true }).click();
  const s1 = await settled(page, s0.revision);
  expect(s1.curves).toBe(0);
  expect(s1.text).toContain('New session: an empty head; Mirror is on (X turns it off)');
  // the same session the app opens with ?preset=empty (the camera aside)
  const other = await context.newPage();
  await other.goto('/?strands=2000&preset=empty');
  await settled(other);
  const [made, fresh] = await Promise.all(
    [page, other].map((p) => p.evaluate(() => JSON.stringify(window.hairsketch.session()))),
  );
  expect(made).toBe(fresh);
  await page.keyboard.press('Control+z');
  const s2 = await settled(page, s1.revision);
  expect(s2.curves).toBe(s0.curves);
});

test('a damaged link says what is wrong and the preset still loads', async ({ page }) => {
  await page.goto('/?strands=2000#s=bm90LWRlZmxhdGU');
  const s = await settled(page);
  expect(s.text).toContain('Could not open the link');
  expect(s.curves).toBeGreaterThan(0); // the default preset
});

test('Save writes a session file that Open reads back; a bad file changes nothing', async ({
  page,
}) => {
  await page.goto('/?strands=2000&preset=fig7');
  const s0 = await settled(page);
  const made = (await page.evaluate(() => window.hairsketch.session())) as SessionJson;
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: 'Save' }).click(),
  ]);
  const file = await download.path();

  await page.goto('/?strands=2000&preset=empty');
  const e0 = await settled(page);
  expect(e0.curves).toBe(0);
  await page.getByLabel('Session file').setInputFiles({
    name: 'bad.json',
    mimeType: 'application/json',
    buffer: Buffer.from('{"version": 1, "curves": [{"id": "c1", "type": "spiral"}]}'),
  });
  await expect(page.getByTestId('status')).toContainText('Could not open bad.json');
  expect((await page.evaluate(() => window.hairsketch.session())) as SessionJson).toMatchObject({
    curves: [],
  });

  await page.getByLabel('Session file').setInputFiles(file);
  const opened = await settled(page, e0.revision);
  expect(opened.curves).toBe(s0.curves);
  const got = (await page.evaluate(() => window.hairsketch.session())) as SessionJson;
  expect(got.curves).toEqual(made.curves);
  // the hair equals the original page's: the same curves and seed grow the same strands
  expect(opened.strands).toBe(s0.strands);
  await page.getByRole('button', { name: 'Undo' }).click();
  const undone = await settled(page, opened.revision);
  expect(undone.curves).toBe(0);
});
