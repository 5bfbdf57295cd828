// Content safety: the app is served with a Content-Security-Policy that forbids inline script,
// and every string that comes from a file or a link reaches the page only as text. Script and
// HTML payloads are put into every string field of a session (and the file's name): nothing
// runs, nothing is injected, and the user's session is kept when the file is refused.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { expect, test } from '@playwright/test';
import { settled, status, watchConsole } from './helpers';

const PAYLOADS = [
  '<img src=x onerror="window.__xss=1">',
  '"><script>window.__xss=2</script>',
  "javascript:window.__xss=3//'",
  '<svg onload=window.__xss=4>',
];

test('served with a Content-Security-Policy that forbids inline script; the app runs under it', async ({
  page,
}) => {
  const errors = watchConsole(page);
  const response = await page.goto('/?strands=800');
  const csp = response?.headers()['content-security-policy'] ?? '';
  expect(csp).toContain("script-src 'self'");
  expect(csp).not.toContain("'unsafe-inline' 'self' 'wasm"); // no inline script allowed
  expect(csp).toMatch(/script-src[^;]*'wasm-unsafe-eval'/);
  expect(csp.split(';').find((d) => d.trim().startsWith('script-src'))).not.toContain(
    'unsafe-inline',
  );
  await settled(page);
  // an inline script injected now is refused by the policy
  const ran = await page.evaluate(async () => {
    const w = window as unknown as { __inline?: number };
    const s = document.createElement('script');
    s.textContent = 'window.__inline = 1';
    document.body.append(s);
    await new Promise((r) => setTimeout(r, 50));
    return w.__inline ?? 0;
  });
  expect(ran).toBe(0);
  // the app itself caused no violation or error (the injected script's refusal aside)
  expect(errors.filter((e) => !e.includes('inline script'))).toEqual([]);
});

test('script and HTML payloads in every string of a session file and its name only ever show as text', async ({
  page,
}) => {
  await page.goto('/?strands=800');
  await settled(page);
  const good = (await page.evaluate(() => window.hairsketch.session())) as Record<string, unknown>;
  const dir = mkdtempSync(join(tmpdir(), 'hairsketch-xss-'));
  const curves = good.curves as Record<string, unknown>[];
  for (const [i, payload] of PAYLOADS.entries()) {
    // every string field of the session gets the payload
    const bad = {
      ...good,
      head: payload,
      grid: payload,
      hairColor: payload,
      curves: curves.map((c) => ({ ...c, id: payload, type: c.type, surfaceMode: payload })),
    };
    const name = `x${i}<img src=x onerror=window.__xss=9>.json`;
    const file = join(dir, `payload-${i}.json`);
    writeFileSync(file, JSON.stringify(bad));
    await page.getByLabel('Session file').setInputFiles({
      name,
      mimeType: 'application/json',
      buffer: Buffer.from(JSON.stringify(bad)),
    });
    await expect(page.getByTestId('status')).toContainText('Could not open');
    // the name shows as text, literally
    await expect(page.getByTestId('status')).toContainText(name);
  }
  // the same payloads in the curve ids alone (the field most likely to be drawn somewhere)
  const onlyIds = {
    ...good,
    curves: curves.map((c, k) => ({ ...c, id: PAYLOADS[k % PAYLOADS.length] })),
  };
  await page.getByLabel('Session file').setInputFiles({
    name: 'ids.json',
    mimeType: 'application/json',
    buffer: Buffer.from(JSON.stringify(onlyIds)),
  });
  await expect(page.getByTestId('status')).toContainText('ids.json');
  const probe = await page.evaluate(() => ({
    xss: (window as unknown as { __xss?: number }).__xss ?? 0,
    // the Styles dialog's own pictures (styles/<id>.png) aside
    imgs: [...document.querySelectorAll('img')].filter(
      (i) => !(i.closest('#styles-dialog') && /\/styles\/[a-z-]+\.png$/.test(i.src)),
    ).length,
    svgs: document.querySelectorAll('svg').length,
    scripts: [...document.querySelectorAll('script')].filter((s) => !s.src).length,
  }));
  expect(probe).toEqual({ xss: 0, imgs: 0, svgs: 0, scripts: 0 });
  // the session the user had is still there (a refused file changes nothing)
  const now = (await page.evaluate(() => window.hairsketch.session())) as { curves: unknown[] };
  expect(now.curves.length).toBeGreaterThan(0);
});

test('payloads in a link only ever show as text, and the preset loads instead', async ({
  page,
}) => {
  await page.goto('/?strands=800');
  await settled(page);
  const link = await page.evaluate(async (payload) => {
    // a v1 link: base64url of deflate-raw JSON, with a payload as the hair colour and a curve id
    const s = window.hairsketch.session() as Record<string, unknown>;
    const curves = (s.curves as Record<string, unknown>[]).map((c) => ({ ...c, id: payload }));
    const json = JSON.stringify({ ...s, hairColor: payload, curves });
    const cs = new CompressionStream('deflate-raw');
    const bytes = new Uint8Array(
      await new Response(new Blob([json]).stream().pipeThrough(cs)).arrayBuffer(),
    );
    let bin = '';
    for (const b of bytes) bin += String.fromCharCode(b);
    return `#s=${btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '')}`;
  }, PAYLOADS[0]);
  // pasted into the address bar of the open app (a hash change): refused, the work stays
  const before = await settled(page);
  await page.goto(`/?strands=800${link}`);
  await expect(page.getByTestId('status')).toContainText('Nothing changed');
  expect((await status(page)).curves).toBe(before.curves);
  // opened in a fresh page: refused, the preset loads
  await page.goto('about:blank');
  await page.goto(`/?strands=800${link}`);
  await settled(page);
  const probe = await page.evaluate(() => ({
    xss: (window as unknown as { __xss?: number }).__xss ?? 0,
    // the Styles dialog's own pictures (styles/<id>.png) aside
    imgs: [...document.querySelectorAll('img')].filter(
      (i) => !(i.closest('#styles-dialog') && /\/styles\/[a-z-]+\.png$/.test(i.src)),
    ).length,
    curves: (window.hairsketch.session() as { curves: unknown[] }).curves.length,
  }));
  expect(probe.xss).toBe(0);
  expect(probe.imgs).toBe(0);
  expect(probe.curves).toBeGreaterThan(0);
});
