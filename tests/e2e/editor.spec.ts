// The editor as a new user meets it: curve after curve from the scalp, the shortcuts overlay,
// plain-words status, Reset view, the surface mode's label, and a phone-sized screen. Real
// pointer events; waits on the status attributes and the session, never on fixed sleeps.
import { expect, type Page, test } from '@playwright/test';
import { settled, status, strokeFromScalp, watchConsole } from './helpers';

type V3 = [number, number, number];
interface Session {
  curves: { id: string; type: string; points: V3[] }[];
  selected: string | null;
  camera: { position: V3; target: V3 };
}
const session = (page: Page) => page.evaluate(() => window.hairsketch.session() as Session);

async function dragPath(page: Page, pts: { x: number; y: number }[]) {
  await page.mouse.move(pts[0].x, pts[0].y);
  await page.mouse.down();
  for (const p of pts.slice(1)) await page.mouse.move(p.x, p.y);
  await page.mouse.up();
}

test('four curves drawn in a row at 50K, each starting a few pixels from the last, make four curves', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto('/?preset=empty&grid=50k&strands=1500');
  await page.waitForFunction(() => {
    const el = document.querySelector('[data-testid="status"]') as HTMLElement;
    return el.dataset.state === 'ready';
  });
  await page.getByRole('button', { name: 'Stream curve' }).click();
  const first = await page.evaluate(() => window.hairsketch.scalpToScreen(25, 25));
  if (!first) throw new Error('scalp hidden');
  let start = first;
  for (let k = 0; k < 4; k++) {
    // along the scalp and down past it, as a hand draws hair; alternately running alongside the
    // last curve and leaving it
    const dx = k % 2 === 0 ? 4 : 2;
    const pts: { x: number; y: number }[] = [];
    for (let i = 0; i <= 30; i++) pts.push({ x: start.x + dx * i, y: start.y + 8 * i });
    await dragPath(page, pts);
    await page.waitForFunction(
      (n) => (window.hairsketch.session() as Session).curves.length === n,
      k + 1,
    );
    const s = await session(page);
    expect(s.selected).toBe(s.curves[k].id); // the new curve is selected: the next stroke still makes one
    // orbit a little (right-drag, as the Stream tool allows), then start the next stroke on
    // this curve's image, a pixel beside its second point: its supporting surface is under the
    // pointer there
    const box = await page.getByTestId('viewport').boundingBox();
    if (!box) throw new Error('no viewport');
    const o = { x: box.x + 60, y: box.y + box.height - 60 };
    await page.mouse.move(o.x, o.y);
    await page.mouse.down({ button: 'right' });
    for (let i = 1; i <= 8; i++) await page.mouse.move(o.x + (k % 2 === 0 ? 10 : -10) * i, o.y);
    await page.mouse.up({ button: 'right' });
    const p1 = await page.evaluate(
      (p) => window.hairsketch.worldToScreen(p),
      s.curves[k].points[1],
    );
    if (!p1) throw new Error('the new curve is hidden');
    start = { x: p1.x + 1, y: p1.y };
  }
  const final = await settled(page);
  expect(final.curves).toBe(4);
  const s = await session(page);
  expect(new Set(s.curves.map((c) => c.id)).size).toBe(4);
  expect(final.text).not.toContain('Hint:');
  expect(errors).toEqual([]);
});

test('"?" lists every shortcut; Escape closes it', async ({ page }) => {
  await page.goto('/?strands=1000');
  await settled(page);
  await page.keyboard.press('?');
  const dialog = page.getByRole('dialog', { name: 'Keyboard shortcuts' });
  await expect(dialog).toBeVisible();
  for (const text of ['Ctrl+Z', 'Ctrl+Shift+Z', 'Stream curve', 'Reset view', 'Delete']) {
    await expect(dialog).toContainText(text);
  }
  await page.keyboard.press('Escape');
  await expect(dialog).toBeHidden();
});

test("Enter in a panel's number field commits it and gives the keys back to the shortcuts", async ({
  page,
}) => {
  // a helper typed a Max length, pressed Enter and chose a Curl type: then H, X and L did
  // nothing (the field kept the focus) and the next strokes went on in the view before
  await page.goto('/?preset=empty&strands=1000');
  let s = await settled(page);
  await page.getByRole('button', { name: 'Detail' }).click();
  const panel = page.getByRole('region', { name: 'Hair detail' });
  const maxLength = panel.getByLabel('Max length (cm)');
  await maxLength.click();
  await page.keyboard.press('Control+A');
  await page.keyboard.type('30');
  await page.keyboard.press('Enter');
  s = await settled(page, s.revision);
  expect(await maxLength.inputValue()).toBe('30');
  await page.keyboard.press('l');
  await expect(page.getByTestId('view-label')).toHaveText('View: left');
  // Escape puts back what was there and leaves the field too
  await maxLength.click();
  await page.keyboard.press('Control+A');
  await page.keyboard.type('45');
  await page.keyboard.press('Escape');
  expect(await maxLength.inputValue()).toBe('30');
  await page.keyboard.press('Shift+F');
  await expect(page.getByTestId('view-label')).toHaveText('View: back');
  // a Curl type chosen from its list leaves the keys to the shortcuts as well
  await panel.getByLabel('Curl type').selectOption('3A');
  await settled(page, s.revision);
  await page.keyboard.press('f');
  await expect(page.getByTestId('view-label')).toHaveText('View: front');
  // a view key: data-detail leaves full at once and is full again only once the camera is there
  // (at 1,000 strands every moving frame draws every strand: it read full mid-way, "View: free")
  await page.keyboard.press('l');
  await expect(page.getByTestId('status')).toHaveAttribute('data-detail', 'full');
  expect(await page.getByTestId('view-label').textContent()).toBe('View: left');
  // the Hair and Head panels share the left edge: opening one (G, H) closes the other
  const head = page.getByRole('region', { name: 'Head' });
  await page.keyboard.press('g');
  await expect(head).toBeVisible();
  await expect(panel).toBeHidden();
  await page.keyboard.press('h');
  await expect(panel).toBeVisible();
  await expect(head).toBeHidden();
});

test('the status line speaks plainly: strand count with separators, no strands on a bald head', async ({
  page,
}) => {
  await page.goto('/?strands=2500');
  const s = await settled(page);
  expect(s.strands).toBeGreaterThan(1000);
  expect(s.text).toContain(`Ready — ${s.strands.toLocaleString('en-US')} strands`);
  expect(s.text).not.toMatch(/mg-pcg|iterations|\bit\./);
  await page.goto('/?preset=empty');
  await page.waitForFunction(() => {
    const el = document.querySelector('[data-testid="status"]') as HTMLElement;
    return el.dataset.state === 'ready';
  });
  const bald = await status(page);
  expect(bald.strands).toBe(0);
  expect(bald.text).not.toMatch(/\d strands/);
  expect(bald.text).toContain('no hair yet');
});

test('Reset view brings the camera back; Surface mode shows the mode that is on', async ({
  page,
}) => {
  await page.goto('/?strands=1000');
  await settled(page);
  const before = (await session(page)).camera;
  const box = await page.getByTestId('viewport').boundingBox();
  if (!box) throw new Error('no viewport');
  // orbit with the Select tool (every preset starts with Stream curve)
  await page.getByRole('button', { name: 'Select', exact: true }).click();
  await dragPath(page, [
    { x: box.x + box.width / 2, y: box.y + box.height / 2 },
    { x: box.x + box.width / 2 + 120, y: box.y + box.height / 2 + 10 },
    { x: box.x + box.width / 2 + 240, y: box.y + box.height / 2 + 20 },
  ]);
  const moved = (await session(page)).camera;
  expect(moved.position).not.toEqual(before.position);
  await expect(page.getByTestId('view-label')).toHaveText('View: free');
  await page.getByRole('button', { name: 'Reset view' }).click();
  await page.waitForFunction((p) => {
    const c = (window.hairsketch.session() as Session).camera.position;
    return Math.hypot(c[0] - p[0], c[1] - p[1], c[2] - p[2]) < 1e-3;
  }, before.position);
  // the starting view says which it is
  await expect(page.getByTestId('view-label')).toHaveText('View: three-quarter front');

  // named views at a key each (and the Front button): where the camera looks from, measured
  // from the camera (the unit direction from the target to the eye)
  const views: [string, string, (d: number[]) => number][] = [
    ['f', 'front', (d) => d[2]],
    ['Shift+F', 'back', (d) => -d[2]],
    ['l', 'left', (d) => d[0]],
    ['Shift+L', 'right', (d) => -d[0]],
    ['t', 'top', (d) => d[1]],
  ];
  /** The camera's height over its target, as a share of its distance (the sine of its
   *  elevation). */
  const height = async () => {
    const c = (await session(page)).camera;
    const v = c.position.map((x: number, i: number) => x - c.target[i]);
    return v[1] / Math.hypot(v[0], v[1], v[2]);
  };
  let frontHeight = Number.NaN;
  for (const [key, name, along] of views) {
    await page.keyboard.press(key);
    await expect(page.getByTestId('view-label')).toHaveText(`View: ${name}`);
    await page.evaluate(() => window.hairsketch.idle());
    const c = (await session(page)).camera;
    const v = c.position.map((x: number, i: number) => x - c.target[i]);
    const n = Math.hypot(v[0], v[1], v[2]);
    const deg = (Math.acos(along(v.map((x: number) => x / n))) * 180) / Math.PI;
    console.log(`${name} view (${key}): ${deg.toFixed(1)}° off the ${name} axis`);
    expect(deg).toBeLessThan(name === 'top' ? 2 : 10);
    if (name === 'front') frontHeight = await height();
  }
  // a drag begun while a named view's camera still eases (0.45 s) starts from that view, not
  // from part way there (fresh eyes pressed F and right-dragged at once, and orbited from above
  // the head): from the top view, F and at once a small right-drag sideways, which keeps the
  // camera's height: as high as the front view's, not part way up to the top
  const mid = { x: box.x + box.width / 2, y: box.y + box.height / 2 };
  await page.mouse.move(mid.x, mid.y);
  await page.keyboard.press('f');
  await page.mouse.down({ button: 'right' });
  await page.mouse.move(mid.x + 40, mid.y, { steps: 4 });
  await page.mouse.up({ button: 'right' });
  await page.evaluate(() => window.hairsketch.idle());
  const dragged = await height();
  console.log(
    `F and a drag at once: camera height ${dragged.toFixed(3)} (the front view's ${frontHeight.toFixed(3)})`,
  );
  expect(Math.abs(dragged - frontHeight)).toBeLessThan(0.03);
  await page.getByRole('button', { name: 'Front view' }).click();
  await expect(page.getByTestId('view-label')).toHaveText('View: front');
  await page.getByRole('button', { name: 'Reset view' }).click();
  await expect(page.getByTestId('view-label')).toHaveText('View: three-quarter front');

  // the wheel zooms towards the point under the pointer: a point on the plane through the orbit
  // target, 8 cm right of it and 3 cm up, stays under the pointer while the camera comes nearer
  // (zooming towards the middle moves it out by the zoom's factor: tens of pixels)
  await page.evaluate(() => window.hairsketch.idle());
  const c0 = (await session(page)).camera;
  const dir = c0.target.map((t, i) => t - c0.position[i]);
  const right = [-dir[2], 0, dir[0]];
  const rn = Math.hypot(...right);
  const r = right.map((x) => x / rn);
  const dn = Math.hypot(...dir);
  const d = dir.map((x) => x / dn);
  const up = [r[1] * d[2] - r[2] * d[1], r[2] * d[0] - r[0] * d[2], r[0] * d[1] - r[1] * d[0]];
  const w = c0.target.map((t, i) => t + 0.8 * r[i] + 0.3 * up[i]) as V3;
  const s0 = await page.evaluate((p) => window.hairsketch.worldToScreen(p), w);
  if (!s0) throw new Error('the point is not on screen');
  expect(
    Math.hypot(s0.x - (box.x + box.width / 2), s0.y - (box.y + box.height / 2)),
  ).toBeGreaterThan(80);
  await page.mouse.move(s0.x, s0.y);
  for (let k = 0; k < 3; k++) await page.mouse.wheel(0, -200);
  await page.waitForFunction((p) => {
    const c = (window.hairsketch.session() as Session).camera;
    const dist = Math.hypot(...c.position.map((x, i) => x - c.target[i]));
    return dist < 0.85 * p;
  }, dn);
  await page.evaluate(() => window.hairsketch.idle());
  const s1 = await page.evaluate((p) => window.hairsketch.worldToScreen(p), w);
  console.log(
    `zoom: the point under the pointer moved ${Math.hypot((s1?.x ?? 0) - s0.x, (s1?.y ?? 0) - s0.y).toFixed(1)} px`,
  );
  expect(Math.hypot((s1?.x ?? 0) - s0.x, (s1?.y ?? 0) - s0.y)).toBeLessThan(6);
  await page.getByRole('button', { name: 'Reset view' }).click();
  await expect(page.getByTestId('view-label')).toHaveText('View: three-quarter front');

  // select a stream curve: the surface mode button says which mode it is in
  const s = await session(page);
  await page.evaluate((id) => window.hairsketch.select(id), s.curves[0].id);
  const mode = page.getByRole('button', { name: 'Surface mode' });
  await expect(mode).toHaveText('Surface mode: ruled');
  await mode.click();
  await expect(mode).toHaveText('Surface mode: strip');
  await expect(mode).toHaveAttribute('aria-pressed', 'true');
});

test.describe('on a phone-sized screen', () => {
  test.use({ viewport: { width: 390, height: 844 }, hasTouch: true });

  test('no sideways scrolling, a toolbar of at most two rows, 40 px targets, every toggle reachable', async ({
    page,
  }) => {
    await page.goto('/?strands=800');
    await settled(page);
    const layout = await page.evaluate(() => {
      const main = document.querySelector('#toolbar .toolbar-main') as HTMLElement;
      // the buttons shown (a phone hides the first row's Styles: it is in More there)
      const buttons = [...main.querySelectorAll('button')]
        .map((b) => b.getBoundingClientRect())
        .filter((r) => r.width > 0);
      const tops = [...new Set(buttons.map((r) => Math.round(r.top)))];
      return {
        scrollWidth: document.documentElement.scrollWidth,
        width: window.innerWidth,
        rows: tops.length,
        smallest: Math.min(...buttons.map((r) => Math.min(r.width, r.height))),
      };
    });
    expect(layout.scrollWidth).toBeLessThanOrEqual(layout.width);
    expect(layout.rows).toBeLessThanOrEqual(2);
    expect(layout.smallest).toBeGreaterThanOrEqual(40);

    // everything else is in "More": each display toggle can be switched from there
    const more = page.getByRole('button', { name: 'More' });
    await more.click();
    for (const name of ['Curves', 'Constraints', 'Surface', 'Field', 'Box', 'Cards']) {
      const box = page.getByRole('checkbox', { name, exact: true });
      await expect(box).toBeVisible();
      const size = await box.evaluate((el) => {
        const r = (el.parentElement as HTMLElement).getBoundingClientRect();
        return Math.min(r.width, r.height);
      });
      expect(size).toBeGreaterThanOrEqual(40);
    }
    await page.getByRole('checkbox', { name: 'Box', exact: true }).click();
    await page.waitForFunction(() => window.hairsketch.display().box);
    await more.click(); // closes the menu
    await expect(page.getByRole('checkbox', { name: 'Box', exact: true })).toBeHidden();
    for (const name of [
      'Styles',
      'Surface mode',
      'Avoid scalp',
      'Share link',
      'Save',
      'Open',
      'Open head',
      'Head',
      'Reset view',
    ]) {
      await more.click();
      await expect(page.getByRole('button', { name, exact: true })).toBeVisible();
      await more.click(); // closes again
      await expect(page.getByRole('button', { name, exact: true })).toBeHidden();
    }
    const after = await page.evaluate(() => document.documentElement.scrollWidth);
    expect(after).toBeLessThanOrEqual(390);
  });
});

test('drawing a curve (it is selected, the curve buttons come on) does not move the 3D view', async ({
  page,
}) => {
  await page.setViewportSize({ width: 1280, height: 800 });
  await page.goto('/?preset=empty&strands=1000');
  const s0 = await settled(page);
  const before = await page.getByTestId('viewport').boundingBox();
  await strokeFromScalp(page, 30, 60, 20, 120);
  await settled(page, s0.revision);
  await expect(page.getByRole('button', { name: 'Surface mode' })).toHaveText(
    'Surface mode: ruled',
  );
  const after = await page.getByTestId('viewport').boundingBox();
  console.log(
    `viewport top ${before?.y} -> ${after?.y}, height ${before?.height} -> ${after?.height}`,
  );
  expect(after?.y).toBe(before?.y);
  expect(after?.height).toBe(before?.height);
});
