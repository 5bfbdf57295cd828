// Reference pictures end to end, with pictures made here (solid colour PNGs written with Node's
// zlib): "Reference image" with a real file chooser places a picture behind the head, and its
// colour is found in a screenshot of the view; a stroke drawn over it makes a curve; Hide removes
// it and Undo brings it back; it survives a reload (the link names it, IndexedDB holds it) and a
// Save/Open round trip into a browser that never saw it, and a link alone says which picture it
// needs. Bad files (not an image, over 50 megapixels, a damaged PNG) say why and change nothing.
import { readFileSync } from 'node:fs';
import { expect, type Locator, type Page, test } from '@playwright/test';
import { pngFile, pngHeaderOnly } from '../support/pictureFiles';
import { settled, strokeFromScalp } from './helpers';

/** A colour nothing else in the app draws. */
const MAGENTA: [number, number, number] = [255, 0, 255];
const wide = pngFile(120, 60, () => MAGENTA);
const FRONT: [number, number, number] = [0, -0.55, 9];

/** Pixels of the view's screenshot within `tol` of `rgb` in every channel. */
async function countColour(page: Page, rgb: [number, number, number], tol = 10): Promise<number> {
  await page.evaluate(() => window.hairsketch.idle());
  return countInPng(page, await page.getByTestId('viewport').screenshot(), rgb, tol);
}

/** Pixels of a PNG within `tol` of `rgb` in every channel (decoded by the browser's own PNG
 *  decoder). */
async function countInPng(
  page: Page,
  png: Buffer,
  rgb: [number, number, number],
  tol: number,
): Promise<number> {
  return page.evaluate(
    async ([b64, c, t]) => {
      const bytes = Uint8Array.from(atob(b64 as string), (ch) => ch.charCodeAt(0));
      const image = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
      const canvas = new OffscreenCanvas(image.width, image.height);
      const g = canvas.getContext('2d') as OffscreenCanvasRenderingContext2D;
      g.drawImage(image, 0, 0);
      const px = g.getImageData(0, 0, image.width, image.height).data;
      const [r, gr, b] = c as number[];
      let n = 0;
      for (let i = 0; i < px.length; i += 4)
        if (
          Math.abs(px[i] - r) <= (t as number) &&
          Math.abs(px[i + 1] - gr) <= (t as number) &&
          Math.abs(px[i + 2] - b) <= (t as number)
        )
          n++;
      return n;
    },
    [png.toString('base64'), rgb, tol] as const,
  );
}

const panel = (page: Page): Locator => page.getByTestId('references');

async function front(page: Page): Promise<void> {
  await page.evaluate((p) => window.hairsketch.setCamera(p, [0, -0.55, 0]), FRONT);
}

test('a picture shows behind the head, under strokes, through reload and Save/Open', async ({
  page,
  browser,
}) => {
  test.setTimeout(240_000);
  await page.goto('/?preset=empty&strands=2000');
  const s0 = await settled(page);
  await front(page);
  expect(await countColour(page, MAGENTA)).toBe(0);

  await page.getByLabel('Reference image file').setInputFiles({
    name: 'wide.png',
    mimeType: 'image/png',
    buffer: wide,
  });
  await expect(panel(page)).toHaveAttribute('data-shown', '1');
  await expect(page.getByTestId('status')).toContainText('for the front view');
  const placed = (await page.evaluate(() => window.hairsketch.session())) as {
    references: { name: string; hash: string; view: string; width: number; height: number }[];
  };
  expect(placed.references).toHaveLength(1);
  expect(placed.references[0]).toMatchObject({ name: 'wide.png', view: 'front', width: 120 });
  // fully opaque, the picture's own colour shows around the head
  await panel(page).getByLabel('Opacity (%)').fill('100');
  await panel(page).getByLabel('Opacity (%)').press('Tab');
  await page.waitForFunction(
    () =>
      (window.hairsketch.session() as { references: { opacity: number }[] }).references[0]
        .opacity === 1,
  );
  const shown = await countColour(page, MAGENTA);
  expect(shown).toBeGreaterThan(5000);
  // pictures are no part of the hair: no solve ran for them
  const s1 = await settled(page);
  expect(s1.revision).toBe(s0.revision);

  // a stroke drawn over it makes a curve (the picture catches no ray)
  await page.getByRole('button', { name: 'Stream curve' }).click();
  await strokeFromScalp(page, 30, 40, 160, 120);
  const s2 = await settled(page, s1.revision);
  expect(s2.curves).toBe(1);
  expect(s2.strands).toBeGreaterThan(100);

  // Hide removes it; Undo brings it back
  await panel(page).getByRole('button', { name: 'Hide' }).click();
  await expect(panel(page)).toHaveAttribute('data-shown', '0');
  expect(await countColour(page, MAGENTA)).toBeLessThan(20);
  await page.getByRole('button', { name: 'Undo' }).click();
  await expect(panel(page)).toHaveAttribute('data-shown', '1');
  const withStroke = await countColour(page, MAGENTA);
  expect(withStroke).toBeGreaterThan(5000);
  // the PNG export is the hair, not the picture behind it
  await page.getByRole('button', { name: 'Export' }).click();
  const [png] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('menuitem', { name: 'PNG image', exact: true }).click(),
  ]);
  const exported = readFileSync(await png.path());
  expect(exported.subarray(1, 4).toString()).toBe('PNG');
  expect(await countInPng(page, exported, MAGENTA, 60)).toBe(0);
  if (process.env.SHOT_DIR)
    await page
      .getByTestId('viewport')
      .screenshot({ path: `${process.env.SHOT_DIR}/reference-front.png` });

  // reload: the link names the picture, IndexedDB holds it
  await page.getByRole('button', { name: 'Share link' }).click();
  await expect(page.getByTestId('status')).toContainText('link', { ignoreCase: true });
  const href = await page.evaluate(() => window.location.href);
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: 'Save' }).click(),
  ]);
  const file = await download.path();
  await page.reload();
  await settled(page);
  await expect(panel(page)).toHaveAttribute('data-shown', '1');
  await front(page);
  expect(await countColour(page, MAGENTA)).toBeGreaterThan(withStroke * 0.9);
  // it fades as the camera leaves the front: gone 60° round (the plane itself is still in view)
  const a = Math.PI / 3;
  await page.evaluate((p) => window.hairsketch.setCamera(p, [0, -0.55, 0]), [
    9 * Math.sin(a),
    -0.55,
    9 * Math.cos(a),
  ] as [number, number, number]);
  expect(await countColour(page, MAGENTA, 60)).toBe(0);

  // Save / Open into a browser that never stored the picture
  const other = await (await browser.newContext()).newPage();
  await other.goto('/?preset=empty&strands=2000');
  await settled(other);
  await other.getByLabel('Session file').setInputFiles(file);
  await expect(panel(other)).toHaveAttribute('data-shown', '1');
  const opened = (await other.evaluate(() => window.hairsketch.session())) as typeof placed;
  expect(opened.references).toEqual(
    ((await page.evaluate(() => window.hairsketch.session())) as typeof placed).references,
  );
  await front(other);
  expect(await countColour(other, MAGENTA)).toBeGreaterThan(withStroke * 0.9);

  // a link alone, in a browser without the picture, says which picture it needs
  const third = await (await browser.newContext()).newPage();
  await third.goto(href);
  await expect(panel(third)).toHaveAttribute('data-missing', '1');
  await expect(third.getByTestId('status')).toContainText('needs the picture “wide.png”');
  // opening that file fills it in (it is not placed a second time)
  const linked = await third.evaluate(() => window.hairsketch.session());
  await third.getByLabel('Reference image file').setInputFiles({
    name: 'wide.png',
    mimeType: 'image/png',
    buffer: wide,
  });
  await expect(panel(third)).toHaveAttribute('data-shown', '1');
  await expect(panel(third)).toHaveAttribute('data-missing', '0');
  expect(await third.evaluate(() => window.hairsketch.session())).toEqual(linked);
  await third.context().close();
  await other.context().close();
});

test('bad picture files say why and change nothing; PNG, JPEG and WebP place for the view', async ({
  page,
}) => {
  await page.goto('/?strands=1000');
  await settled(page);
  const before = await page.evaluate(() => window.hairsketch.session());
  const damaged = Buffer.from(pngFile(16, 16, () => MAGENTA));
  damaged[45] ^= 0x40; // a byte of the IDAT chunk: its CRC no longer matches
  const cases: [string, Buffer, string][] = [
    ['notes.png', Buffer.from('just some text, not a picture'), 'not a PNG, JPEG or WebP'],
    ['huge.png', pngHeaderOnly(10_000, 5_001), 'more than the 50 megapixels'],
    ['broken.png', damaged, 'damaged PNG'],
  ];
  for (const [name, buffer, why] of cases) {
    await page.getByLabel('Reference image file').setInputFiles({
      name,
      mimeType: 'image/png',
      buffer,
    });
    const status = page.getByTestId('status');
    await expect(status).toContainText(`Could not open the picture “${name}”`);
    await expect(status).toContainText(why);
    expect(await status.textContent()).not.toContain('\n');
    expect(await page.evaluate(() => window.hairsketch.session())).toEqual(before);
  }
  await expect(panel(page)).toBeHidden();

  // a good picture opened from the side faces the side; "Place for this view" turns it to the
  // front; a second picture is placed beside it
  await page.evaluate(() => window.hairsketch.setCamera([9, -0.55, 0.5], [0, -0.55, 0]));
  await page.getByLabel('Reference image file').setInputFiles({
    name: 'side.png',
    mimeType: 'image/png',
    buffer: pngFile(20, 30, () => [0, 200, 255]),
  });
  await expect(panel(page)).toHaveAttribute('data-shown', '1');
  const views = async () =>
    (
      (await page.evaluate(() => window.hairsketch.session())) as { references: { view: string }[] }
    ).references.map((r) => r.view);
  expect(await views()).toEqual(['side']);
  await front(page);
  await panel(page).getByRole('button', { name: 'Place for this view' }).click();
  await expect.poll(views).toEqual(['front']);
  await page.getByLabel('Reference image file').setInputFiles({
    name: 'wide.png',
    mimeType: 'image/png',
    buffer: wide,
  });
  await expect(panel(page)).toHaveAttribute('data-shown', '2');
  expect(await views()).toEqual(['front', 'front']);
  // a JPEG and a WebP as Chromium's own encoders write them
  for (const [type, name] of [
    ['image/jpeg', 'photo.jpg'],
    ['image/webp', 'photo.webp'],
  ] as const) {
    const b64 = await page.evaluate(async (t) => {
      const c = new OffscreenCanvas(48, 32);
      const g = c.getContext('2d') as OffscreenCanvasRenderingContext2D;
      g.fillStyle = '#20a0ff';
      g.fillRect(0, 0, 48, 32);
      const bytes = new Uint8Array(await (await c.convertToBlob({ type: t })).arrayBuffer());
      return btoa(String.fromCharCode(...bytes));
    }, type);
    await page.getByLabel('Reference image file').setInputFiles({
      name,
      mimeType: type,
      buffer: Buffer.from(b64, 'base64'),
    });
    await expect(page.getByTestId('status')).toContainText(
      `Placed the picture “${name}” (48 × 32)`,
    );
  }
  await expect(panel(page)).toHaveAttribute('data-shown', '4');
  const formats = (
    (await page.evaluate(() => window.hairsketch.session())) as { references: { format: string }[] }
  ).references.map((r) => r.format);
  expect(formats).toEqual(['png', 'png', 'jpeg', 'webp']);
  // none of it touched the hair: the curves and settings are those of the preset
  const after = (await page.evaluate(() => window.hairsketch.session())) as Record<string, unknown>;
  const { references: _r, camera: _c, ...rest } = after;
  const { camera: _c0, ...start } = before as Record<string, unknown>;
  expect(rest).toEqual(start);
});
