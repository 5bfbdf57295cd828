// "Export" end to end: every menu item downloads its file; the USD and hair cards bytes equal
// `hairsketch grow` run on the same session saved through "Save"; "Open" on the exported USD and
// glTF restores the session; the PNG is twice the canvas's resolution. Real clicks; waits on downloads
// and the status attributes, never on fixed sleeps.
import { execFile } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { expect, type Page, test } from '@playwright/test';
import { settled, watchConsole } from './helpers';

const SCENE = '/?strands=1500';
const execFileAsync = promisify(execFile);

async function exportItem(page: Page, name: string): Promise<{ file: string; bytes: Buffer }> {
  await page.getByRole('button', { name: 'Export' }).click();
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('menuitem', { name, exact: true }).click(),
  ]);
  const file = await download.path();
  return { file: download.suggestedFilename(), bytes: readFileSync(file) };
}

async function openFile(page: Page, path: string) {
  await page.getByLabel('Session file').setInputFiles(path);
}

test('each export item downloads its file, equal to `hairsketch grow` on the saved session', async ({
  page,
}) => {
  test.slow(); // three solves from scratch plus the CLI's
  const errors = watchConsole(page);
  await page.goto(SCENE);
  await settled(page);
  const dir = mkdtempSync(join(tmpdir(), 'hairsketch-export-'));

  // the session as "Save" writes it
  const [saved] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: 'Save', exact: true }).click(),
  ]);
  const sessionFile = join(dir, 'session.json');
  await saved.saveAs(sessionFile);

  const expected: Record<string, string> = {
    'USD (.usda)': 'hairstyle.usda',
    'Cem Yuksel (.hair)': 'hairstyle.hair',
    'OBJ (.obj)': 'hairstyle.obj',
    'glTF (.glb)': 'hairstyle.glb',
    'Hair cards (.glb)': 'hairstyle-cards.glb',
  };
  const files: Record<string, Buffer> = {};
  for (const [item, name] of Object.entries(expected)) {
    const { file, bytes } = await exportItem(page, item);
    expect(file).toBe(name);
    expect(bytes.length).toBeGreaterThan(1000);
    files[name] = bytes;
    await expect(page.getByTestId('status')).toContainText(`Exported ${name}`);
    // the USD groom in the status line, as the worker wrote it
    if (name === 'hairstyle.usda')
      await expect(page.getByTestId('status')).toContainText(
        /groom of \d+ groups? \(hair\), [\d,]+ guides, root UVs from the built-in head's scalp UV layout/,
      );
  }
  expect(files['hairstyle.usda'].subarray(0, 5).toString()).toBe('#usda');
  expect(files['hairstyle.hair'].subarray(0, 4).toString()).toBe('HAIR');
  expect(files['hairstyle.glb'].subarray(0, 4).toString()).toBe('glTF');
  expect(files['hairstyle-cards.glb'].subarray(0, 4).toString()).toBe('glTF');

  // the command line on the saved session gives the same bytes (same wasm, same seeded growth):
  // the strands' export (the USD; .hair and glTF write the same strands with writers shared by
  // the app and the CLI) and the cards' (their own pipeline), both runs at once
  const names = ['hairstyle.usda', 'hairstyle-cards.glb'];
  const lines = await Promise.all(
    names.map(async (name) => {
      const format = name === 'hairstyle-cards.glb' ? ['--format', 'cards'] : [];
      const args = ['grow', sessionFile, '--out', join(dir, `cli-${name}`), '--grid', '25k'];
      const { stdout } = await execFileAsync(
        process.execPath,
        ['scripts/hairsketch.mjs', ...args, ...format],
        { encoding: 'utf8' },
      );
      return stdout;
    }),
  );
  names.forEach((name, i) => {
    expect(JSON.parse(lines[i].trim().split('\n').at(-1) ?? '{}').bytes).toBe(files[name].length);
    expect(
      readFileSync(join(dir, `cli-${name}`)).equals(files[name]),
      `${name}: browser and CLI bytes differ`,
    ).toBe(true);
  });

  // PNG: twice the canvas's resolution (its size in device pixels)
  const twice = await page
    .getByTestId('viewport')
    .evaluate((c: HTMLCanvasElement) => [
      Math.round(c.clientWidth * window.devicePixelRatio * 2),
      Math.round(c.clientHeight * window.devicePixelRatio * 2),
    ]);
  const { file, bytes } = await exportItem(page, 'PNG image');
  expect(file).toBe('hairstyle.png');
  expect(bytes.subarray(1, 4).toString()).toBe('PNG');
  expect([bytes.readUInt32BE(16), bytes.readUInt32BE(20)]).toEqual(twice);
  expect(errors).toEqual([]);
});

test('"Open" on an exported USD or glTF restores the session and its hair', async ({
  page,
  browser,
}) => {
  test.slow();
  await page.goto('/?preset=fig7&strands=1200');
  await settled(page);
  const dir = mkdtempSync(join(tmpdir(), 'hairsketch-open-'));
  const want = await page.evaluate(() => window.hairsketch.session() as { curves: unknown[] });
  const paths: Record<string, string> = {};
  for (const item of ['USD (.usda)', 'glTF (.glb)']) {
    await page.getByRole('button', { name: 'Export' }).click();
    const [d] = await Promise.all([
      page.waitForEvent('download'),
      page.getByRole('menuitem', { name: item, exact: true }).click(),
    ]);
    paths[item] = join(dir, d.suggestedFilename());
    await d.saveAs(paths[item]);
  }
  const [saved] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: 'Save', exact: true }).click(),
  ]);
  paths.json = join(dir, 'session.json');
  await saved.saveAs(paths.json);

  // each file opened on an empty head: the same curves, and the same hair as opening the
  // session file itself
  const hashes: Record<string, string | null> = {};
  for (const [key, path] of Object.entries(paths)) {
    const p = await browser.newPage();
    await p.goto('/?preset=empty&strands=1200');
    const s0 = await settled(p);
    await openFile(p, path);
    await settled(p, s0.revision);
    const got = await p.evaluate(() => window.hairsketch.session() as { curves: unknown[] });
    expect(got.curves, key).toEqual(want.curves);
    hashes[key] = await p.evaluate(() => window.hairsketch.hairHash());
    await p.close();
  }
  expect(hashes['USD (.usda)']).toBe(hashes.json);
  expect(hashes['glTF (.glb)']).toBe(hashes.json);
});
