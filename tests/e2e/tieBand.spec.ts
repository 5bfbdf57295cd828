// The ties' bands in the app: the braid preset lays its braid with ties, so it has a band; with
// `ties` off (a session made before ties) it has none, and on again its braid gets a band at its
// top, in the default band colour, drawn on screen; "Band colour" in the Hair panel recolours it
// as one edit that Undo takes back.
import { expect, test } from '@playwright/test';
import { settled, watchConsole } from './helpers';

test('a braid with ties gets a band; Band colour recolours it, Undo restores', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/?preset=braid&strands=3000');
  await settled(page);
  expect(await page.evaluate(() => window.hairsketch.tieBands().bands.length)).toBe(1);
  const revision = () =>
    page.evaluate(() =>
      Number(document.querySelector<HTMLElement>('[data-testid="status"]')?.dataset.revision),
    );
  const setTies = (on: boolean) =>
    page.evaluate((ties) => {
      const s = window.hairsketch.session() as Record<string, unknown>;
      window.hairsketch.replaceSession({ ...s, ties });
    }, on);
  let before = await revision();
  await setTies(false);
  await settled(page, before);
  expect(await page.evaluate(() => window.hairsketch.tieBands().bands.length)).toBe(0);

  before = await revision();
  await setTies(true);
  await settled(page, before);
  const shown = await page.evaluate(() => window.hairsketch.tieBands());
  expect(shown.bands).toHaveLength(1);
  expect(shown.colour).toBe('#1c1c1f');
  // about as wide as a braid (its width is 5 cm): 1 to 4 cm inside
  expect(shown.bands[0].radius).toBeGreaterThan(0.1);
  expect(shown.bands[0].radius).toBeLessThan(0.4);

  // the band is drawn: a point on its outer rim, seen from straight behind it, is dark
  const dark = await page.evaluate(() => {
    const b = window.hairsketch.tieBands().bands[0];
    const [ax, ay, az] = b.axis;
    // a direction square to the axis, the most towards the viewer's side (+x or −x)
    const side = Math.abs(ax) < 0.9 ? [1, 0, 0] : [0, 0, 1];
    const d = side.map((v, k) => v - (side[0] * ax + side[1] * ay + side[2] * az) * b.axis[k]);
    const l = Math.hypot(...d);
    const rim = b.centre.map((c, k) => c + ((b.radius + 0.03) * d[k]) / l) as [
      number,
      number,
      number,
    ];
    const eye = rim.map((c, k) => c + 6 * (d[k] / l)) as [number, number, number];
    window.hairsketch.setCamera(eye, rim);
    return rim;
  });
  await page.evaluate(() => window.hairsketch.idle());
  const pixel = await page.evaluate(async (rim) => {
    await window.hairsketch.idle();
    const p = window.hairsketch.worldToScreen(rim);
    if (!p) throw new Error('the band is not in view');
    const canvas = document.querySelector('[data-testid="viewport"]') as HTMLCanvasElement;
    const gl = canvas.getContext('webgl2') as WebGL2RenderingContext;
    const r = canvas.getBoundingClientRect();
    const sx = gl.drawingBufferWidth / r.width;
    const px = new Uint8Array(4);
    gl.readPixels(
      Math.round((p.x - r.left) * sx),
      Math.round(gl.drawingBufferHeight - (p.y - r.top) * sx),
      1,
      1,
      gl.RGBA,
      gl.UNSIGNED_BYTE,
      px,
    );
    return [px[0], px[1], px[2]];
  }, dark);
  // the dark elastic, lit: far darker than the blonde hair round it and the pale background
  expect(Math.max(...pixel)).toBeLessThan(90);

  await page.getByRole('button', { name: 'Detail' }).click();
  const input = page.getByRole('region', { name: 'Hair detail' }).getByLabel('Band colour');
  await expect(input).toHaveValue('#1c1c1f');
  await input.evaluate((el: HTMLInputElement) => {
    el.value = '#d02060';
    el.dispatchEvent(new Event('change'));
  });
  await expect.poll(() => page.evaluate(() => window.hairsketch.tieBands().colour)).toBe('#d02060');
  expect(
    await page.evaluate(() => (window.hairsketch.session() as { bandColor?: string }).bandColor),
  ).toBe('#d02060');
  await page.getByRole('button', { name: 'Undo' }).click();
  await expect.poll(() => page.evaluate(() => window.hairsketch.tieBands().colour)).toBe('#1c1c1f');
  expect(errors).toEqual([]);
});
