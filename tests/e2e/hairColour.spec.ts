// The Hair panel's colour model end to end: Grey (%), Redness and Melanin change the drawn hair
// the way their names say (greyer, redder, lighter), a Shade (Auburn) sets them in one edit, Undo
// restores it, and the link keeps it;
// Tips lighten the hair over a length typed in cm, and a session saved with the older fraction
// of the strand shows it as a length until one is typed.
// Real pointer events for clicks; waits on the test API's idle(), never on fixed sleeps.
import { expect, type Page, test } from '@playwright/test';
import { settled, watchConsole } from './helpers';

/** Mean RGB (0..255) of a 21 × 21 pixel box on the hair over the left temple. */
async function hairColour(page: Page): Promise<[number, number, number]> {
  // the whole hair drawn (a frame after a click may draw a sample of it first)
  await page.waitForFunction(() => window.hairsketch.hairDetail() === 1, null, { polling: 50 });
  return page.evaluate(async () => {
    await window.hairsketch.idle();
    const p = window.hairsketch.scalpToScreen(55, 35);
    if (!p) throw new Error('the top of the head is not in view');
    const canvas = document.querySelector('[data-testid="viewport"]') as HTMLCanvasElement;
    const gl = canvas.getContext('webgl2') as WebGL2RenderingContext;
    const r = canvas.getBoundingClientRect();
    const sx = gl.drawingBufferWidth / r.width;
    const x = Math.round((p.x - r.left) * sx);
    const y = Math.round(gl.drawingBufferHeight - (p.y - r.top) * sx);
    const px = new Uint8Array(4 * 21 * 21);
    gl.readPixels(x - 10, y - 10, 21, 21, gl.RGBA, gl.UNSIGNED_BYTE, px);
    const sum = [0, 0, 0];
    for (let i = 0; i < px.length; i += 4) for (let c = 0; c < 3; c++) sum[c] += px[i + c];
    return sum.map((v) => v / (21 * 21)) as [number, number, number];
  });
}

const luma = (c: number[]) => 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
const saturation = (c: number[]) => (Math.max(...c) - Math.min(...c)) / Math.max(...c, 1);

async function setNumber(page: Page, name: string, value: number): Promise<void> {
  const input = page.getByRole('spinbutton', { name, exact: true });
  await input.click();
  await input.fill(String(value));
  await input.press('Enter');
  await page.evaluate(() => window.hairsketch.idle());
}

/** The default preset at 4,000 strands, settled, with the Hair panel open: the panel. */
async function openHairPanel(page: Page) {
  await page.goto('/?strands=4000');
  await settled(page);
  await page.getByRole('button', { name: 'Detail' }).click();
  return page.getByRole('region', { name: 'Hair detail' });
}

test('Melanin, Redness, Grey and Shade change the hair as named; Undo restores; the link keeps it', async ({
  page,
}) => {
  const errors = watchConsole(page);
  const panel = await openHairPanel(page);
  await expect(panel.getByRole('checkbox', { name: 'Natural colour' })).toBeChecked();

  // a change is drawn in the next frame: each check polls the drawn colour until it holds
  const start = await hairColour(page);
  await setNumber(page, 'Grey (%)', 90);
  await expect
    .poll(async () => saturation(await hairColour(page)))
    .toBeLessThan(0.8 * saturation(start));
  await page.getByRole('button', { name: 'Undo' }).click();
  await expect
    .poll(async () => Math.max(...(await hairColour(page)).map((v, c) => Math.abs(v - start[c]))))
    .toBeLessThan(3);

  await setNumber(page, 'Redness', 0.95);
  await expect
    .poll(async () => {
      const c = await hairColour(page);
      return c[0] / c[2];
    })
    .toBeGreaterThan((1.1 * start[0]) / start[2]);
  const red = await hairColour(page);

  await setNumber(page, 'Melanin', 0.1);
  await expect.poll(async () => luma(await hairColour(page))).toBeGreaterThan(1.3 * luma(red));
  const look = (await page.evaluate(() => window.hairsketch.session())) as {
    hairLook: Record<string, unknown>;
  };
  expect(look.hairLook).toMatchObject({ melanin: 0.1, redness: 0.95, grey: 0 });

  // a named Shade sets the pigment in one edit: Auburn is redder than the start's medium brown
  // (red over green 1.20 times the start's when first measured)
  const shade = panel.getByRole('combobox', { name: 'Shade' });
  await expect(shade).toHaveValue('');
  await shade.click();
  await shade.selectOption({ label: 'Auburn' });
  await expect(panel.getByRole('combobox', { name: 'Shade' })).toHaveValue('auburn');
  await expect(page.getByTestId('status')).toContainText('Hair colour: Auburn');
  await expect
    .poll(async () => {
      const c = await hairColour(page);
      return c[0] / c[1];
    })
    .toBeGreaterThan((1.15 * start[0]) / start[1]);
  await page.getByRole('button', { name: 'Undo' }).click();
  await expect(panel.getByRole('combobox', { name: 'Shade' })).toHaveValue('');
  expect(
    ((await page.evaluate(() => window.hairsketch.session())) as typeof look).hairLook,
  ).toEqual(look.hairLook);
  await page.getByRole('button', { name: 'Redo' }).click();
  await expect(panel.getByRole('combobox', { name: 'Shade' })).toHaveValue('auburn');
  const auburn = (await page.evaluate(() => window.hairsketch.session())) as typeof look;
  expect(auburn.hairLook).toMatchObject({ melanin: 0.3, redness: 1, dye: '#ff8070', grey: 0 });

  // the link (Share link writes it to the address bar too) reopens it
  await page.getByRole('button', { name: 'Share link' }).click();
  await expect(page.getByTestId('status')).toContainText('Link');
  const href = await page.evaluate(() => window.location.href);
  const other = await page.context().newPage();
  await other.goto(href);
  await settled(other);
  const again = (await other.evaluate(() => window.hairsketch.session())) as typeof look;
  expect(again.hairLook).toEqual(auburn.hairLook);
  expect(errors).toEqual([]);
});

test('Tips: lighter tips over a length typed in cm; an older fraction shows as a length until one is set', async ({
  page,
}) => {
  const errors = watchConsole(page);
  const panel = await openHairPanel(page);
  const status = page.getByTestId('status');
  const hairLook = async () =>
    (
      (await page.evaluate(() => window.hairsketch.session())) as {
        hairLook: Record<string, unknown>;
      }
    ).hairLook;

  // Tips on: the tip colour over the last 8 cm of every strand, here a light blonde
  await panel.getByRole('checkbox', { name: 'Tips', exact: true }).click();
  const length = panel.getByRole('spinbutton', { name: 'Lighter tips over (cm)' });
  await expect(length).toHaveValue('8');
  await setNumber(page, 'Tip melanin', 0.05);
  const over8 = await hairColour(page);

  // typed with a fraction: whole centimetres, and the status line says so
  await length.click();
  await length.fill('99.6');
  await length.press('Enter');
  await expect(status).toContainText(
    'Lighter tips over: 99.6 cm is not a whole number; set to 100 cm.',
  );
  await expect(status).toHaveAttribute('data-state', 'ready');
  // the default's strands are at most 32 cm long: over 100 cm the blonde reaches their roots
  await expect.poll(async () => luma(await hairColour(page))).toBeGreaterThan(1.3 * luma(over8));
  const over100 = await hairColour(page);
  console.log(
    `temple luma with lighter tips over 8 cm ${luma(over8).toFixed(1)}, over 100 cm ${luma(over100).toFixed(1)}`,
  );
  const look = await hairLook();
  expect(look).toMatchObject({ tipLength: 10, tipMelanin: 0.05 });
  expect(look).not.toHaveProperty('tipStart');

  await page.getByRole('button', { name: 'Undo' }).click();
  await expect(length).toHaveValue('8');
  await expect
    .poll(async () => Math.max(...(await hairColour(page)).map((v, c) => Math.abs(v - over8[c]))))
    .toBeLessThan(3);

  // a session saved before lengths in cm: tips from half way along each strand, shown as the
  // length that gives the longest hair (half of Max length, 32 cm), until a length is typed
  await page.evaluate(() => {
    const s = window.hairsketch.session() as { hairLook: Record<string, unknown> };
    const { tipLength: _, ...older } = s.hairLook;
    window.hairsketch.replaceSession({ ...s, hairLook: { ...older, tipStart: 0.5 } });
  });
  await expect(panel).toContainText('Saved as the last 50 % of each strand');
  await expect(length).toHaveValue('16');
  expect(await hairLook()).toMatchObject({ tipStart: 0.5, tipLength: 0 });
  await setNumber(page, 'Lighter tips over (cm)', 12);
  await expect(panel).not.toContainText('Saved as the last');
  const replaced = await hairLook();
  expect(replaced).toMatchObject({ tipLength: 1.2 });
  expect(replaced).not.toHaveProperty('tipStart');

  // the link keeps the length
  await page.getByRole('button', { name: 'Share link' }).click();
  await expect(status).toContainText('Link');
  const other = await page.context().newPage();
  await other.goto(await page.evaluate(() => window.location.href));
  await settled(other);
  const again = (await other.evaluate(() => window.hairsketch.session())) as {
    hairLook: Record<string, unknown>;
  };
  expect(again.hairLook).toEqual(replaced);
  expect(errors).toEqual([]);
});
