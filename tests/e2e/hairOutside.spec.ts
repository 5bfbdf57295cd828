// Hair stays outside the head without any button and goes when its curves go; the Detail panel
// curls it and Undo restores it. (That the figure presets cover the back of the head is measured
// on their hair grown as the app grows it, in tests/unit/hairCoverage.test.ts.)
import { expect, test } from '@playwright/test';
import { settled, strokeFromScalp, watchConsole } from './helpers';

test('a stroke drawn from the front down over the temple and cheek leaves no hair inside the head', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto('/?preset=empty');
  const first = await settled(page);
  expect(first.strands).toBe(0);
  // From the front hairline at the temple, straight down the screen over the cheek: the depth
  // rule would put the off-scalp part of this stroke inside the face.
  await strokeFromScalp(page, 58, 40, 0, 220);
  const after = await settled(page, first.revision);
  expect(after.curves).toBe(1);
  expect(after.strands).toBeGreaterThan(500);
  // the curve's points are all outside the head (the depth rule's margin)
  const curveDepths = await page.evaluate(() => {
    const s = window.hairsketch.session() as { curves: { points: [number, number, number][] }[] };
    return s.curves[0].points.length;
  });
  expect(curveDepths).toBeGreaterThan(5);
  const inside = await page.evaluate(() => window.hairsketch.segmentsInsideHead(0.01));
  console.log(`stroke over the face: ${JSON.stringify(inside)}`);
  expect(inside.segments).toBeGreaterThan(1000);
  expect(inside.inside).toBe(0); // no segment deeper than 1 mm inside the head
  // Deleting every curve leaves a bald head (no stale scalp constraints keep hair alive).
  await page.getByRole('button', { name: 'Avoid scalp' }).click();
  const avoided = await settled(page, after.revision);
  expect(avoided.strands).toBeGreaterThan(500);
  expect(await page.evaluate(() => window.hairsketch.segmentsInsideHead(0.01).inside)).toBe(0);
  await page.getByRole('button', { name: 'Select' }).click();
  const id = await page.evaluate(
    () => (window.hairsketch.session() as { curves: { id: string }[] }).curves[0].id,
  );
  await page.evaluate((c) => window.hairsketch.select(c), id);
  await page.getByRole('button', { name: 'Delete' }).click();
  const bald = await settled(page, avoided.revision);
  expect(bald.curves).toBe(0);
  expect(bald.strands).toBe(0);
  expect(errors).toEqual([]);
});

test('the Detail panel curls the hair, and Undo restores it exactly', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/?preset=default&strands=3000');
  const first = await settled(page);
  const before = await page.evaluate(() => window.hairsketch.hairHash());
  await page.getByRole('button', { name: 'Detail' }).click();
  const panel = page.getByRole('region', { name: 'Hair detail' });
  await expect(panel).toBeVisible();
  await panel.getByRole('checkbox', { name: 'Curl' }).check();
  const curled = await settled(page, first.revision);
  const session = (await page.evaluate(() => window.hairsketch.session())) as {
    detail?: { curl?: { radius: number } };
  };
  expect(session.detail?.curl?.radius).toBe(0.1); // Blender's default radius
  // lengths show in centimetres: 0.1 world units is 1 cm
  await expect(panel.getByRole('spinbutton', { name: 'Curl radius' })).toHaveValue('1');
  await expect(panel.getByText('Radius (cm)')).toBeVisible();
  // with a curve selected the whole head's detail stays, the curve's own below it
  const firstCurve = (
    (await page.evaluate(() => window.hairsketch.session())) as { curves: { id: string }[] }
  ).curves[0].id;
  await page.evaluate((id) => window.hairsketch.select(id), firstCurve);
  await expect(panel.getByRole('checkbox', { name: 'Curl', exact: true })).toBeChecked();
  await expect(panel.getByRole('checkbox', { name: `Own detail for ${firstCurve}` })).toBeVisible();
  await page.evaluate(() => window.hairsketch.select(null));
  const hash = await page.evaluate(() => window.hairsketch.hairHash());
  expect(hash).not.toBe(before);
  expect(await page.evaluate(() => window.hairsketch.segmentsInsideHead(0.01).inside)).toBe(0);
  await page.getByRole('button', { name: 'Undo' }).click();
  const undone = await settled(page, curled.revision);
  expect(await page.evaluate(() => window.hairsketch.hairHash())).toBe(before);
  // Density is a session setting too: 6,000 strands where the page capped at 3,000.
  const strands = panel.getByRole('spinbutton', { name: 'Strands' });
  await strands.fill('6000');
  await strands.press('Enter');
  const denser = await settled(page, undone.revision);
  expect(denser.strands).toBeGreaterThan(5000);
  expect(denser.strands).toBeLessThan(7000);
  expect(errors).toEqual([]);
});

test('Curl type in the Hair panel sets a named curl (3B curly) in one edit; Undo takes it back', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto('/?preset=default&strands=2000');
  const first = await settled(page);
  const detailOf = async () =>
    ((await page.evaluate(() => window.hairsketch.session())) as { detail?: unknown }).detail;
  const before = await detailOf();
  await page.getByRole('button', { name: 'Detail' }).click();
  const panel = page.getByRole('region', { name: 'Hair detail' });
  const type = panel.getByRole('combobox', { name: 'Curl type', exact: true });
  await expect(type).toHaveValue('1');
  await type.selectOption({ label: '3B curly: springy curls' });
  const curled = await settled(page, first.revision);
  const s = (await page.evaluate(() => window.hairsketch.session())) as {
    detail?: {
      curl?: { radius: number; frequency: number };
      clump?: { guideDistance: number };
      frizz?: unknown;
    };
  };
  // 3B: curls round a 1.4-1.8 cm lock (radius 0.7-0.9 cm), 3-3.8 turns per 10 cm, in locks
  expect(s.detail?.curl?.radius).toBeGreaterThanOrEqual(0.07);
  expect(s.detail?.curl?.radius).toBeLessThanOrEqual(0.09);
  expect(s.detail?.curl?.frequency).toBeGreaterThanOrEqual(3);
  expect(s.detail?.curl?.frequency).toBeLessThanOrEqual(3.8);
  expect(s.detail?.clump).toBeDefined();
  expect(s.detail?.frizz).toBeUndefined();
  await expect(type).toHaveValue('3B');
  await page.getByRole('button', { name: 'Undo' }).click();
  await settled(page, curled.revision);
  await expect(type).toHaveValue('1');
  expect(await detailOf()).toEqual(before);
  expect(errors).toEqual([]);
});
