// The Quality setting end to end: the button cycles Auto → Fast → High → Auto, the drawing path
// follows (Auto is Fast on a software rasteriser such as this SwiftShader, High on a GPU), High
// (strips, deep opacity maps, order-independent blending) draws without GL errors even here and
// its blending does not depend on the drawing order, the setting survives a reload
// (view state, not the session), and the hair arrives with its precomputed lighting.
import { expect, type Page, test } from '@playwright/test';
import { settled, watchConsole } from './helpers';

const SCENE = '/?strands=1500'; // SwiftShader renders slowly: a small strand count keeps it quick

const quality = (page: Page) => page.evaluate(() => window.hairsketch.quality());

/** The WebGL error flag of the app's canvas after the next frame (0 = none). */
const glError = (page: Page) =>
  page.evaluate(async () => {
    await window.hairsketch.idle();
    const canvas = document.querySelector('[data-testid="viewport"]') as HTMLCanvasElement;
    const gl = canvas.getContext('webgl2') as WebGL2RenderingContext;
    return gl.getError();
  });

/** Pixels of the centre of the view that differ from the background (the hair and head). */
const drawnPixels = (page: Page) =>
  page.evaluate(() => {
    const canvas = document.querySelector('[data-testid="viewport"]') as HTMLCanvasElement;
    const gl = canvas.getContext('webgl2') as WebGL2RenderingContext;
    const w = 64;
    const px = new Uint8Array(4 * w * w);
    gl.readPixels(
      (gl.drawingBufferWidth - w) >> 1,
      (gl.drawingBufferHeight - w) >> 1,
      w,
      w,
      gl.RGBA,
      gl.UNSIGNED_BYTE,
      px,
    );
    let n = 0;
    for (let i = 0; i < px.length; i += 4) if (Math.abs(px[i] - 0xe9) > 8) n++;
    return n;
  });

test('Quality switches the drawing path, High draws without GL errors, and the setting persists', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto(SCENE);
  await page.evaluate(() => localStorage.removeItem('hairsketch.quality'));
  await page.reload();
  await settled(page);

  const first = await quality(page);
  expect(first.setting).toBe('auto');
  const software = /swiftshader|llvmpipe|softpipe|software/i.test(first.renderer);
  expect(first.active).toBe(software ? 'fast' : 'high');
  const button = page.getByRole('button', { name: /^Quality/ });
  await expect(button).toHaveText(`Quality: Auto (${software ? 'Fast' : 'High'})`);
  // the worker lit the hair
  expect(await page.evaluate(() => window.hairsketch.lightingMs())).not.toBeNull();

  const checkFast = async () => {
    await expect(button).toHaveText('Quality: Fast');
    expect(await quality(page)).toMatchObject({ setting: 'fast', active: 'fast' });
    expect(await glError(page)).toBe(0);
    expect(await drawnPixels(page)).toBeGreaterThan(500);
    // Fast's lines blend order-independently: their segments drawn in reverse change (next to) no
    // pixel, where plain blending of the same lines changes many
    const linesOrder = await page.evaluate(() => window.hairsketch.blendOrder());
    expect(linesOrder).not.toBeNull();
    expect(linesOrder?.oit).toBeLessThan(0.001);
    expect(linesOrder?.unsorted).toBeGreaterThan(0.005); // 1.6 % here at 1,500 strands
    // the settled hair's depth makes the style curves under it faint, as behind the head
    const depth = await page.evaluate(() => window.hairsketch.hairDepth());
    expect(depth).toBeGreaterThan(0.0005); // 0.2 % here (0 without the depth)
  };
  const checkHigh = async () => {
    await expect(button).toHaveText('Quality: High');
    expect(await quality(page)).toMatchObject({ setting: 'high', active: 'high' });
    expect(await glError(page)).toBe(0);
    expect(await drawnPixels(page)).toBeGreaterThan(500);
    expect((await page.getByTestId('status').getAttribute('data-state')) ?? '').toBe('ready');
    // High's strips blend order-independently: their triangles drawn in reverse change (next to)
    // no pixel, where plain blending of the same strips changes many
    const order = await page.evaluate(() => window.hairsketch.blendOrder());
    expect(order).not.toBeNull();
    expect(order?.oit).toBeLessThan(0.001);
    expect(order?.unsorted).toBeGreaterThan(0.005); // 1.7 % here at 1,500 strands
  };
  // each press changes the drawing: first to the path Auto does not draw here, then the other
  await button.click();
  await (software ? checkHigh() : checkFast());
  await button.click();
  await (software ? checkFast() : checkHigh());

  // view state: kept across a reload, not part of the session or its link
  await page.reload();
  await settled(page);
  const last = software ? 'fast' : 'high';
  expect(await quality(page)).toMatchObject({ setting: last, active: last });
  expect(await glError(page)).toBe(0);
  const session = JSON.stringify(await page.evaluate(() => window.hairsketch.session()));
  expect(session).not.toContain('quality');

  // the shortcut cycles on, back to Auto
  await page.keyboard.press('q');
  await expect(button).toHaveText(`Quality: Auto (${software ? 'Fast' : 'High'})`);
  expect((await quality(page)).active).toBe(software ? 'fast' : 'high');
  expect(await glError(page)).toBe(0);
  expect(errors.filter((e) => !/GPU stall|GL Driver Message/.test(e))).toEqual([]);
});
