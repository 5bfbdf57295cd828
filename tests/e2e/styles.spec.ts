// The style library with real clicks: "Styles" opens a dialog listing every style with its
// picture; each loads as one undoable edit with hair and no page error (at the session's strand
// count); Undo returns to the work before; the link reopens a loaded style; Escape closes the
// dialog without a change; the keyboard reaches the styles; each style's hair in the browser is
// the hair `hairsketch grow` grows from its file (hashes).
import { execFile } from 'node:child_process';
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { expect, test } from '@playwright/test';
import { STYLE_LIBRARY } from '../../web/model/styleLibrary';
import { settled, watchConsole } from './helpers';

const execFileAsync = promisify(execFile);

/** `hairsketch grow` on each style's file at `strands` strands (beside the browser's work): each
 *  style's hairHash from its report. The bundled command line's main runs once per style in one
 *  Node process (the command's own code, without a Node start and a wasm compile per style). */
async function cliHashes(strands: number): Promise<Map<string, string>> {
  const dir = mkdtempSync(join(tmpdir(), 'styles-'));
  const runs = STYLE_LIBRARY.map((st) => [
    'grow',
    `public/styles/${st.id}.json`,
    '--out',
    join(dir, `${st.id}.hair`),
    '--strands',
    String(strands),
  ]);
  const script = `
    import { buildCliBundle, cliBundle, cliBundleStale } from './scripts/cliBundle.mjs';
    const error = cliBundleStale() && buildCliBundle();
    if (error) throw new Error('cannot build the command line bundle: ' + error);
    const { main } = await import(cliBundle);
    for (const argv of ${JSON.stringify(runs)}) if ((await main(argv)) !== 0) process.exit(1);`;
  const { stdout } = await execFileAsync('node', ['--input-type=module', '-e', script], {
    maxBuffer: 1 << 20,
  });
  const lines = stdout.trim().split('\n');
  expect(lines).toHaveLength(STYLE_LIBRARY.length);
  const out = new Map<string, string>();
  for (const [i, st] of STYLE_LIBRARY.entries())
    out.set(st.id, (JSON.parse(lines[i]) as { hairHash: string }).hairHash);
  return out;
}

interface SessionJson {
  curves: { id: string; type: string }[];
  growth: { maxStrands: number };
}

test('Styles lists every style with its picture; each loads with hair, Undo returns, a link reopens it', async ({
  page,
  context,
}) => {
  test.setTimeout(600_000);
  const errors = watchConsole(page);
  // the command line grows every style meanwhile: the same hair as the browser's (hashes)
  const cli = cliHashes(1200);
  cli.catch(() => {}); // awaited below; no unhandled rejection meanwhile
  const browser = new Map<string, string | null>();
  await page.goto('/?strands=1200');
  let s = await settled(page);
  const before = (await page.evaluate(() => window.hairsketch.session())) as SessionJson;

  const dialog = page.getByRole('dialog', { name: 'Styles' });
  await page.getByRole('button', { name: 'Styles' }).click();
  await expect(dialog).toBeVisible();
  const buttons = dialog.locator('button.style-button');
  await expect(buttons).toHaveCount(STYLE_LIBRARY.length);
  for (const st of STYLE_LIBRARY)
    await expect(dialog.getByRole('button', { name: st.name, exact: true })).toBeVisible();
  // every picture loaded (lazy ones once scrolled to)
  for (let i = 0; i < STYLE_LIBRARY.length; i++) {
    const img = buttons.nth(i).locator('img');
    await img.scrollIntoViewIfNeeded();
    await expect
      .poll(() => img.evaluate((el: HTMLImageElement) => el.complete && el.naturalWidth))
      .toBeGreaterThan(0);
  }
  // Escape closes it and changes nothing
  await page.keyboard.press('Escape');
  await expect(dialog).toBeHidden();
  expect(((await page.evaluate(() => window.hairsketch.session())) as SessionJson).curves).toEqual(
    before.curves,
  );

  for (const [i, st] of STYLE_LIBRARY.entries()) {
    await page.getByRole('button', { name: 'Styles' }).click();
    await dialog.getByRole('button', { name: st.name, exact: true }).click();
    await expect(dialog).toBeHidden();
    s = await settled(page, s.revision);
    const file = (await (await page.request.get(`/styles/${st.id}.json`)).json()) as SessionJson;
    const now = (await page.evaluate(() => window.hairsketch.session())) as SessionJson;
    expect(
      now.curves.map((c) => c.id),
      st.id,
    ).toEqual(file.curves.map((c) => c.id));
    expect(now.growth.maxStrands, st.id).toBe(1200);
    expect(s.strands, st.id).toBeGreaterThan(300);
    expect(s.text).toContain(`Started from the style “${st.name}”`);
    browser.set(st.id, await page.evaluate(() => window.hairsketch.hairHash()));
    if (i === 0) {
      // one Undo brings back the work before
      await page.keyboard.press('Control+z');
      s = await settled(page, s.revision);
      const back = (await page.evaluate(() => window.hairsketch.session())) as SessionJson;
      expect(back.curves).toEqual(before.curves);
      await page.keyboard.press('Control+Shift+z');
      s = await settled(page, s.revision);
    }
  }

  // the keyboard reaches a style: Tab from Close to the first style, Enter loads it
  await page.getByRole('button', { name: 'Styles' }).click();
  await dialog.getByRole('button', { name: 'Close' }).focus();
  await page.keyboard.press('Tab');
  await page.keyboard.press('Enter');
  s = await settled(page, s.revision);
  const first = (await page.evaluate(() => window.hairsketch.session())) as SessionJson;
  expect(first.curves.length).toBeGreaterThan(0);

  // the link carries it
  await page.waitForFunction(() => window.location.hash.startsWith('#s='));
  await expect
    .poll(async () => {
      const other = await context.newPage();
      await other.goto(await page.evaluate(() => window.location.href));
      await settled(other);
      const opened = (await other.evaluate(() => window.hairsketch.session())) as SessionJson;
      await other.close();
      return opened.curves.map((c) => c.id).join(',');
    })
    .toBe(first.curves.map((c) => c.id).join(','));
  expect(errors).toEqual([]);
  expect(new Set(browser.values()).size, 'a hash of its own per style').toBe(STYLE_LIBRARY.length);
  expect(Object.fromEntries(browser)).toEqual(Object.fromEntries(await cli));
});
