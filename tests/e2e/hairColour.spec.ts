// The Hair panel's colour model end to end: Grey (%), Redness and Melanin change the drawn hair
// the way their names say (greyer, redder, lighter), Undo restores it, and the link keeps it.
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

test('Melanin, Redness and Grey change the hair as named; Undo restores; the link keeps it', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto('/?strands=12000');
  await settled(page);
  await page.getByRole('button', { name: 'Detail' }).click();
  const panel = page.getByRole('region', { name: 'Hair detail' });
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

  // the link (Share link writes it to the address bar too) reopens it
  await page.getByRole('button', { name: 'Share link' }).click();
  await expect(page.getByTestId('status')).toContainText('Link');
  const href = await page.evaluate(() => window.location.href);
  const other = await page.context().newPage();
  await other.goto(href);
  await settled(other);
  const again = (await other.evaluate(() => window.hairsketch.session())) as typeof look;
  expect(again.hairLook).toEqual(look.hairLook);
  expect(errors).toEqual([]);
});
