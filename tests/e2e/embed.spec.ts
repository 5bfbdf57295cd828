// The embeddable viewer: "Copy embed code" gives an <iframe> that a page on another origin can
// show, with the hair, orbit and zoom and no editing tools; the editor itself refuses framing.
import http from 'node:http';
import type { AddressInfo } from 'node:net';
import { expect, test } from '@playwright/test';
import { settled, watchConsole } from './helpers';

test('the embed shows the hair inside a page of another origin; the editor refuses framing', async ({
  page,
  context,
  request,
}) => {
  // the responses: only the embed may be framed
  const csp = async (path: string) =>
    (await request.get(path)).headers()['content-security-policy'] ?? '';
  expect(await csp('/')).toContain("frame-ancestors 'none'");
  expect(await csp('/embed.html')).toContain('frame-ancestors *');
  expect(await csp('/embed.html')).not.toContain("frame-ancestors 'none'");

  const errors = watchConsole(page);
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await page.goto('/?preset=bob&strands=1500');
  await settled(page);
  const editorHref = await page.evaluate(() => window.hairsketch.link());
  await page.getByRole('button', { name: 'Copy embed code' }).click();
  await expect(page.getByTestId('status')).toContainText('Embed code copied');
  const snippet = await page.evaluate(() => navigator.clipboard.readText());
  expect(snippet).toMatch(/^<iframe src="http:\/\/127\.0\.0\.1:\d+\/embed\.html#s=[^"]+"/);

  // a page on another origin (its own server, not cross-origin isolated) frames the embed
  const host = http.createServer((_req, res) => {
    res.setHeader('Content-Type', 'text/html');
    res.end(`<!doctype html><title>host</title><p>A page about hair</p>${snippet}`);
  });
  await new Promise<void>((r) => host.listen(0, '127.0.0.1', r));
  try {
    const { port } = host.address() as AddressInfo;
    const visitor = await context.newPage();
    const visitorErrors = watchConsole(visitor);
    await visitor.goto(`http://localhost:${port}/`);
    const frame = visitor.frameLocator('iframe');
    const status = frame.getByTestId('status');
    await expect(status).toHaveAttribute('data-state', 'ready', { timeout: 90_000 });
    expect(Number(await status.getAttribute('data-strands'))).toBeGreaterThan(0);
    // nothing to edit: no tool or menu buttons, no file inputs
    await expect(frame.getByRole('button')).toHaveCount(0);
    await expect(frame.locator('input')).toHaveCount(0);
    const open = frame.getByRole('link', { name: 'Open in hairsketch' });
    const editor = new URL(editorHref);
    expect(await open.getAttribute('href')).toBe(`${editor.origin}/${editor.hash}`);
    const inner = visitor.frames().find((f) => f.url().includes('/embed.html'));
    expect(await inner?.evaluate(() => crossOriginIsolated)).toBe(false);

    // orbit (a drag) and zoom (the wheel) change the picture
    const canvas = frame.getByTestId('viewport');
    const before = await canvas.screenshot();
    const box = await canvas.boundingBox();
    if (!box) throw new Error('no canvas');
    await visitor.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await visitor.mouse.down();
    for (let i = 1; i <= 10; i++)
      await visitor.mouse.move(box.x + box.width / 2 + 12 * i, box.y + box.height / 2);
    await visitor.mouse.up();
    const orbited = await canvas.screenshot();
    expect(orbited.equals(before)).toBe(false);
    await visitor.mouse.wheel(0, -400);
    await expect
      .poll(async () => (await canvas.screenshot()).equals(orbited), { timeout: 20_000 })
      .toBe(false);
    expect(visitorErrors).toEqual([]);
  } finally {
    host.close();
  }
  expect(errors).toEqual([]);
});
