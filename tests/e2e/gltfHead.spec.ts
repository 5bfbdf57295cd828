// glTF heads written by Blender's own exporter at test time (tests/support/blenderGltf.ts) open
// through Open head's real file chooser: a .gltf whose buffers and texture are data: URIs (the
// page's CSP allows no data: fetch, so they must be decoded in code), and a .gltf picked together
// with its .bin and texture; the .gltf picked without its .bin is refused in one sentence and
// changes nothing. Hair grows on each; a USD export on the last takes its roots' UVs from the
// head's TEXCOORD_0, as `hairsketch grow` does.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
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

  // USD on this head (it has TEXCOORD_0): the roots' UVs are its own, the status says so, and
  // `hairsketch grow` on the saved session (which carries the head) writes the same bytes
  const dir = mkdtempSync(join(tmpdir(), 'hairsketch-gltf-uv-'));
  const sessionFile = join(dir, 'session.json');
  const [saved] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: 'Save', exact: true }).click(),
  ]);
  await saved.saveAs(sessionFile);
  await page.getByRole('button', { name: 'Export' }).click();
  const [usd] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('menuitem', { name: 'USD (.usda)', exact: true }).click(),
  ]);
  const browserUsd = readFileSync(await usd.path());
  await expect(status).toContainText("root UVs from the head's own UV map");
  const cliUsd = join(dir, 'cli.usda');
  execFileSync(process.execPath, ['scripts/hairsketch.mjs', 'grow', sessionFile, '--out', cliUsd], {
    encoding: 'utf8',
  });
  expect(readFileSync(cliUsd).equals(browserUsd), 'browser and CLI bytes differ').toBe(true);
  expect(errors).toEqual([]);
});
