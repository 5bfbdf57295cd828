// glTF heads written by Blender's own exporter at test time (tests/support/blenderGltf.ts) open
// through Open head's real file chooser: a .gltf whose buffers and texture are data: URIs (the
// page's CSP allows no data: fetch, so they must be decoded in code), and a .gltf picked together
// with its .bin and texture; the .gltf picked without its .bin is refused in one sentence and
// changes nothing. Hair grows on each.
import { expect, type Page, test } from '@playwright/test';
import { blenderHeads } from '../support/blenderGltf';
import { settled, watchConsole } from './helpers';

type Files = Parameters<import('@playwright/test').FileChooser['setFiles']>[0];

async function pickHead(page: Page, files: Files): Promise<void> {
  const chosen = page.waitForEvent('filechooser');
  await page.getByRole('button', { name: 'Open head', exact: true }).click();
  const chooser = await chosen;
  expect(chooser.isMultiple()).toBe(true);
  await chooser.setFiles(files);
}

test('a .gltf with embedded buffers, and a .gltf with its .bin, open as heads', async ({
  page,
}) => {
  test.setTimeout(180_000);
  const errors = watchConsole(page);
  // Blender exports while the page loads
  const exporting = blenderHeads();
  exporting.catch(() => {}); // awaited below; this only keeps an early failure from going unhandled
  await page.goto('/?strands=1500');
  let s = await settled(page);
  const heads = await exporting;
  const triangles = heads.triangles;
  const mime = (name: string) =>
    name.endsWith('.gltf')
      ? 'model/gltf+json'
      : name.endsWith('.png')
        ? 'image/png'
        : 'application/octet-stream';
  const file = (name: string) => ({ name, mimeType: mime(name), buffer: heads.read(name) });
  const more = page.getByRole('button', { name: 'More' });
  const openMenu = async () => {
    if (!(await page.getByRole('button', { name: 'Open head', exact: true }).isVisible()))
      await more.click();
  };

  // without its .bin: one sentence, nothing changed
  const before = await page.evaluate(() => window.hairsketch.session());
  await openMenu();
  await pickHead(page, file('Head.gltf'));
  const status = page.getByTestId('status');
  await expect(status).toContainText('Could not open the head');
  expect(await status.textContent()).toMatch(/\(“Head\.bin”\): pick the \.gltf together with it/);
  expect(await page.evaluate(() => window.hairsketch.session())).toEqual(before);

  // embedded: buffers and texture as data: URIs
  await openMenu();
  await pickHead(page, file('Embedded.gltf'));
  await page.waitForFunction(() => {
    const h = window.hairsketch.head();
    return h.name === 'Embedded.gltf' && !h.loading;
  });
  expect((await page.evaluate(() => window.hairsketch.head())).triangles).toBe(triangles);
  expect(await status.textContent()).not.toMatch(/base64|data:/);
  s = await settled(page, s.revision);
  expect(s.strands).toBeGreaterThan(0);

  // the .gltf, its .bin and its texture picked together
  await openMenu();
  expect(heads.files.separate).toEqual(['Head.bin', 'Head.gltf', 'skin.png']);
  await pickHead(page, heads.files.separate.map(file));
  await page.waitForFunction(() => {
    const h = window.hairsketch.head();
    return h.name === 'Head.gltf' && !h.loading;
  });
  expect((await page.evaluate(() => window.hairsketch.head())).triangles).toBe(triangles);
  s = await settled(page, s.revision);
  expect(s.strands).toBeGreaterThan(0);
  expect(errors).toEqual([]);
});
