// Share links, version 3 (web/model/sessionLink.ts): the default preset plus one stroke makes
// an address-bar link short enough for a chat (≤ 2,000 characters, URL-safe), and that link
// opened in a fresh page holds the identical session (the editor keeps every number on the
// link's grid, web/model/quantize.ts) and grows the identical hair (the same hairHash) with the
// default fast solver, whose final field is solved from zero (SolverEngine.forgetWarmStart), so
// it does not depend on the solves before it.
import { deflateRawSync } from 'node:zlib';
import { type BrowserContext, expect, type Page, test } from '@playwright/test';
import { settled, strokeFromScalp, watchConsole } from './helpers';

type Session = { curves: unknown[]; avoidScalp?: boolean; selected?: unknown };

/** Opens `scene`, draws a stroke, reads the link the address bar then carries, opens it in a
 *  fresh page; both pages settled. */
async function strokeAndReopen(page: Page, context: BrowserContext, scene: string) {
  const errors = watchConsole(page);
  await page.goto(scene);
  const s0 = await settled(page);
  const before = await page.evaluate(() => window.location.hash);
  await page.getByRole('button', { name: 'Stream curve' }).click();
  await strokeFromScalp(page, 35, 20, 140, 190);
  await page.waitForFunction((n) => {
    const el = document.querySelector('[data-testid="status"]') as HTMLElement;
    return Number(el.dataset.curves) === n;
  }, s0.curves + 1);
  await settled(page, s0.revision);
  // the address bar follows the session about 400 ms after an edit
  await page.waitForFunction(
    (old) => window.location.hash.startsWith('#s=3.') && window.location.hash !== old,
    before,
  );
  const { hash, href } = await page.evaluate(() => ({
    hash: window.location.hash,
    href: window.location.href,
  }));
  const made = (await page.evaluate(() => window.hairsketch.session())) as Session;
  expect(made.curves.length).toBe(s0.curves + 1);

  const other = await context.newPage();
  const otherErrors = watchConsole(other);
  await other.goto(href);
  const opened = await settled(other);
  expect(opened.text).toContain('Opened a shared session');
  const session = (await other.evaluate(() => window.hairsketch.session())) as Session;
  // the very same numbers (a link carries no selection)
  expect(session).toEqual({ ...made, selected: null });
  expect(await other.evaluate(() => window.location.hash)).toBe(hash);
  expect(errors).toEqual([]);
  expect(otherErrors).toEqual([]);
  return { hash, other };
}

// the exact solver's growth is as deterministic (tests/unit/growSession.test.ts): one solver here
test('the default preset with a stroke: a short link that reopens the identical hair', async ({
  page,
  context,
}) => {
  const { hash, other } = await strokeAndReopen(page, context, '/?strands=3000');
  console.log(`default preset + one stroke: link fragment ${hash.length} characters`);
  expect(hash).toMatch(/^#s=3\.[A-Za-z0-9_-]+$/);
  expect(hash.length).toBeLessThanOrEqual(2000);
  const a = await page.evaluate(() => window.hairsketch.hairHash());
  expect(a).not.toBeNull();
  expect(await other.evaluate(() => window.hairsketch.hairHash())).toBe(a);

  // a link pasted into the address bar of a tab already showing the app opens there too (fresh
  // eyes' pasted link kept the old session), as one undoable edit
  const withStroke = await page.evaluate(() => window.location.href);
  let s = await settled(page);
  await page.keyboard.press('Control+z');
  s = await settled(page, s.revision);
  // polled on a timer: this page is behind the other one, where animation frames do not run
  await page.waitForFunction((old) => window.location.href !== old, withStroke, { polling: 50 });
  const curvesBefore = s.curves;
  await page.goto(withStroke); // the same document: only the fragment changes
  s = await settled(page, s.revision);
  expect(s.curves).toBe(curvesBefore + 1);
  expect(await page.evaluate(() => window.hairsketch.hairHash())).toBe(a);
  await page.keyboard.press('Control+z');
  s = await settled(page, s.revision);
  expect(s.curves).toBe(curvesBefore);
});

test('a link cut short says so and the preset loads instead', async ({ page }) => {
  await page.goto('/?strands=2000');
  const s0 = await settled(page);
  await page.getByRole('button', { name: 'Stream curve' }).click();
  await strokeFromScalp(page, 35, 20, 140, 190);
  await settled(page, s0.revision);
  await page.waitForFunction(() => window.location.hash.startsWith('#s=3.'));
  const href = await page.evaluate(() => window.location.href);
  const other = await page.context().newPage();
  await other.goto(href.slice(0, -12));
  const s = await settled(other);
  expect(s.text).toContain('Could not open the link: the session link is damaged (it is cut short');
  expect(s.curves).toBe(s0.curves);
});

test('a deflate bomb link (1 GiB of zeros) is refused and the preset loads', async ({ page }) => {
  const bomb = deflateRawSync(Buffer.alloc(1 << 30), { level: 9 });
  const len: number[] = []; // the v2 length prefix: a varint of the deflated size
  for (let v = bomb.length; ; v = Math.floor(v / 128)) {
    len.push(v < 128 ? v : (v % 128) | 128);
    if (v < 128) break;
  }
  const data = Buffer.concat([Buffer.from(len), bomb]).toString('base64url');
  // in the page: ms from DOMContentLoaded to the status line naming the link's problem
  await page.addInitScript(() => {
    const w = window as unknown as { refusedAfter?: number };
    let ready = 0;
    document.addEventListener('DOMContentLoaded', () => {
      ready = performance.now();
    });
    new MutationObserver(() => {
      const el = document.querySelector('[data-testid="status"]');
      if (w.refusedAfter === undefined && el?.textContent?.includes('Could not open the link'))
        w.refusedAfter = performance.now() - ready;
    }).observe(document, { subtree: true, childList: true, characterData: true });
  });
  const refusal = async (fragment: string) => {
    await page.goto('about:blank'); // else only the fragment changes: no new load
    await page.goto(`/?strands=2000${fragment}`);
    await page.waitForFunction(
      () => (window as { refusedAfter?: number }).refusedAfter !== undefined,
    );
    const s = await settled(page);
    expect(s.curves).toBeGreaterThan(0); // the preset instead
    return {
      text: s.text,
      ms: await page.evaluate(() => (window as { refusedAfter?: number }).refusedAfter ?? 0),
    };
  };
  // (an address as long, refused from its length prefix before inflating: sessionLink.test)
  const big = await refusal(`#s=2.${data}`);
  expect(big.text).toContain('the session link is too large');
  console.log(
    `1 GiB zero bomb (${(data.length + 5).toLocaleString('en-US')} characters): refused ${big.ms.toFixed(0)} ms after DOMContentLoaded`,
  );
});
