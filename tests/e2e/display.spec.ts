// Display toggles (method S6.2) end to end: real clicks on the checkboxes and the 1–5 shortcuts,
// checked through window.hairsketch.display() / displayInfo(), with the app staying ready.
import { expect, type Page, test } from '@playwright/test';
import { settled, visibleCurvePoint, watchConsole } from './helpers';

const SCENE = '/?strands=2000'; // SwiftShader renders slowly: a small strand count keeps it quick

/** Waits until the app is ready and idle with a hair revision past `after`; its revision. */
const ready = async (page: Page, after = -1): Promise<number> =>
  (await settled(page, after)).revision;

const display = (page: Page) => page.evaluate(() => window.hairsketch.display());
const info = (page: Page) => page.evaluate(() => window.hairsketch.displayInfo());
/** The selected curve's id (null: none). */
const selected = async (page: Page): Promise<string | null> =>
  ((await page.evaluate(() => window.hairsketch.session())) as { selected: string | null })
    .selected;

test('each display toggle switches with a click and with its shortcut, and the app stays ready', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto(SCENE);
  let rev = await ready(page);
  expect(await display(page)).toEqual({
    curves: true,
    constraints: false,
    surface: false,
    field: false,
    box: false,
    cards: false,
  });
  const box = (name: string) => page.getByRole('checkbox', { name, exact: true });
  await expect(box('Curves')).toBeChecked();

  // Constraints: drawn from the result already on screen.
  await box('Constraints').click();
  await expect(box('Constraints')).toBeChecked();
  expect((await display(page)).constraints).toBe(true);
  expect((await info(page)).constraints).toBeGreaterThan(50);

  // Box.
  await box('Box').click();
  expect((await display(page)).box).toBe(true);

  // Field: asks the solver for the field, then draws glyphs (capped).
  await box('Field').click();
  expect((await display(page)).field).toBe(true);
  await page.waitForFunction(() => window.hairsketch.displayInfo().glyphs > 0);
  rev = await ready(page, -1);
  const glyphs = (await info(page)).glyphs;
  expect(glyphs).toBeGreaterThan(100);
  expect(glyphs).toBeLessThanOrEqual(12_000);

  // Surface: none until a curve is selected, then the selected curve's.
  await box('Surface').click();
  expect((await display(page)).surface).toBe(true);
  expect((await info(page)).surfaceTriangles).toBe(0);
  await page.getByRole('button', { name: 'Select' }).click();
  const target = await visibleCurvePoint(page);
  await page.mouse.click(target.x, target.y);
  await expect.poll(() => selected(page)).toBe(target.id);
  const tris = (await info(page)).surfaceTriangles;
  expect(tris).toBeGreaterThanOrEqual(2);

  // Curves off.
  await box('Curves').click();
  await expect(box('Curves')).not.toBeChecked();
  expect((await display(page)).curves).toBe(false);
  // a hidden curve cannot be picked
  await page.keyboard.press('Escape');
  await expect.poll(() => selected(page)).toBeNull();
  await page.mouse.click(target.x, target.y);
  await page.evaluate(() => window.hairsketch.idle());
  expect(await selected(page)).toBeNull();
  // and the click says why nothing was picked
  await expect(page.getByTestId('status')).toContainText('curves are hidden');
  expect((await info(page)).surfaceTriangles).toBe(0);

  // Shortcuts 1–5 flip each toggle back (also with the focus on a checkbox).
  await box('Box').focus();
  for (const key of ['1', '2', '3', '4', '5']) await page.keyboard.press(key);
  expect(await display(page)).toEqual({
    curves: true,
    constraints: false,
    surface: false,
    field: false,
    box: false,
    cards: false,
  });
  for (const name of ['Constraints', 'Surface', 'Field', 'Box'])
    await expect(box(name)).not.toBeChecked();
  expect(await info(page)).toEqual({ constraints: 0, glyphs: 0, surfaceTriangles: 0, guides: 0 });

  // Not in the undo history: undo still removes nothing (no edit was made).
  await expect(page.getByRole('button', { name: 'Undo' })).toBeDisabled();
  await ready(page, -1);
  expect(rev).toBeGreaterThan(0);
  expect(errors).toEqual([]);
});
