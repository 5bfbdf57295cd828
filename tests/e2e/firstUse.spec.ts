// First use (user report): every preset starts with the Stream curve tool; Delete with nothing
// selected says what to do (button and key); a head opened from a file in metres is framed in
// the view below the toolbar (an eased move, as Reset view), and Built-in head frames the
// built-in one again. Real pointer and keyboard events; waits on the status attributes.
import { expect, type Page, test } from '@playwright/test';
import { settled, watchConsole } from './helpers';

// one of each kind of start: a plain preset, none, ponytails (fig8), partings and a ponytail (fig1)
const PRESETS = ['default', 'empty', 'fig8', 'fig1'];

type Vec3 = [number, number, number];
interface SessionProbe {
  selected: string | null;
  camera: { position: Vec3; target: Vec3 };
}
const sessionOf = (page: Page) =>
  page.evaluate(() => window.hairsketch.session()) as Promise<SessionProbe>;

test('every preset starts with the Stream curve tool', async ({ page }) => {
  test.setTimeout(240_000);
  const errors = watchConsole(page);
  for (const preset of PRESETS) {
    await page.goto(`/?preset=${preset}&strands=500`);
    await settled(page);
    await expect(page.getByRole('button', { name: 'Stream curve' })).toHaveAttribute(
      'aria-pressed',
      'true',
    );
    await expect(page.getByRole('button', { name: 'Select', exact: true })).toHaveAttribute(
      'aria-pressed',
      'false',
    );
  }
  expect(errors).toEqual([]);
});

test('Delete with nothing selected says to select a curve first (key and button)', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto('/?preset=default&strands=500');
  const s0 = await settled(page);
  expect((await sessionOf(page)).selected).toBeNull();
  const status = page.getByTestId('status');
  await page.keyboard.press('Delete');
  await expect(status).toContainText('Select a curve first');
  // another sentence in between, then the button
  await page.keyboard.press(']');
  await expect(status).not.toContainText('Select a curve first');
  await page.getByRole('button', { name: 'Delete' }).click();
  await expect(status).toContainText('Select a curve first');
  await expect(status).toHaveAttribute('data-curves', String(s0.curves));
  await expect(status).toHaveAttribute('data-state', 'ready');
  expect(errors).toEqual([]);
});

/** A UV sphere of radius `r` metres centred at `c` (metres), as an OBJ. */
function sphereObj(r: number, c: [number, number, number], rings = 24): Buffer {
  const lines: string[] = ['# test head: a sphere in metres'];
  const segs = 2 * rings;
  for (let i = 0; i <= rings; i++) {
    const t = (Math.PI * i) / rings;
    for (let j = 0; j < segs; j++) {
      const p = (2 * Math.PI * j) / segs;
      lines.push(
        `v ${(c[0] + r * Math.sin(t) * Math.sin(p)).toFixed(6)} ${(c[1] + r * Math.cos(t)).toFixed(6)} ${(c[2] + r * Math.sin(t) * Math.cos(p)).toFixed(6)}`,
      );
    }
  }
  const at = (i: number, j: number) => i * segs + (j % segs) + 1;
  for (let i = 0; i < rings; i++)
    for (let j = 0; j < segs; j++) {
      const [a, b, cc, d] = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
      if (i > 0) lines.push(`f ${a} ${b} ${d}`);
      if (i < rings - 1) lines.push(`f ${b} ${cc} ${d}`);
    }
  return Buffer.from(`${lines.join('\n')}\n`);
}

/** Where the head's top and bottom are on screen, and the toolbar's bottom edge. */
async function headOnScreen(page: Page) {
  const b = (await page.evaluate(() => window.hairsketch.head())).bounds;
  const cx = (b.min[0] + b.max[0]) / 2;
  const cz = (b.min[2] + b.max[2]) / 2;
  const top = await page.evaluate((p) => window.hairsketch.worldToScreen(p), [
    cx,
    b.max[1],
    cz,
  ] as Vec3);
  const bottom = await page.evaluate((p) => window.hairsketch.worldToScreen(p), [
    cx,
    b.min[1],
    cz,
  ] as Vec3);
  const toolbar = await page.getByRole('toolbar', { name: 'Tools' }).boundingBox();
  const view = await page.getByTestId('viewport').boundingBox();
  if (!top || !bottom || !toolbar || !view) throw new Error('head or toolbar not on screen');
  return { top: top.y, bottom: bottom.y, toolbarBottom: toolbar.y + toolbar.height, view, b };
}

test('a head opened in metres is framed below the toolbar; Built-in head frames the built-in one', async ({
  page,
}) => {
  test.setTimeout(240_000);
  const errors = watchConsole(page);
  await page.goto('/?preset=empty&strands=1000');
  const s0 = await settled(page);
  const home = (await sessionOf(page)).camera;
  const builtin = await headOnScreen(page);
  expect(builtin.top).toBeGreaterThan(builtin.toolbarBottom);

  // a sphere 50 cm across, a metre up: read as metres, placed where the cranium goes, and
  // larger than the built-in head
  await page.getByLabel('Head file').setInputFiles({
    name: 'ball-in-metres.obj',
    mimeType: 'text/plain',
    buffer: sphereObj(0.25, [0, 1, 0]),
  });
  await page.waitForFunction(() => {
    const h = window.hairsketch.head();
    return h.name === 'ball-in-metres.obj' && !h.loading;
  });
  await settled(page, s0.revision); // idle() also waits for the camera to settle
  await expect(page.getByTestId('status')).toContainText('in m');
  const loaded = await headOnScreen(page);
  // where its top would be in the starting view (the camera the built-in head had)
  const camera = (await sessionOf(page)).camera;
  console.log(
    `[framing] toolbar bottom ${loaded.toolbarBottom.toFixed(0)} px; built-in head top ${builtin.top.toFixed(0)} px; loaded head (y ${loaded.b.min[1].toFixed(2)}..${loaded.b.max[1].toFixed(2)}) top ${loaded.top.toFixed(0)} px, bottom ${loaded.bottom.toFixed(0)} px of ${loaded.view.height.toFixed(0)}; camera ${camera.position.map((v: number) => v.toFixed(2)).join(', ')}`,
  );
  expect(loaded.top).toBeGreaterThan(loaded.toolbarBottom);
  expect(loaded.bottom).toBeLessThan(loaded.view.y + loaded.view.height);
  expect(camera.position).not.toEqual(home.position);

  // Reset view returns to that framing, not the built-in head's
  await page.mouse.move(loaded.view.x + 300, loaded.view.y + 400);
  await page.mouse.down({ button: 'right' });
  await page.mouse.move(loaded.view.x + 500, loaded.view.y + 450, { steps: 8 });
  await page.mouse.up({ button: 'right' });
  await page.getByRole('button', { name: 'Reset view' }).click();
  await page.evaluate(() => window.hairsketch.idle());
  const reset = (await sessionOf(page)).camera;
  for (let a = 0; a < 3; a++) expect(reset.position[a]).toBeCloseTo(camera.position[a], 3);

  // Built-in head: the camera frames the built-in head as at the start
  await page.getByRole('button', { name: 'Head', exact: true }).click();
  await page
    .getByRole('region', { name: 'Head' })
    .getByRole('button', { name: 'Built-in head' })
    .click();
  await page.waitForFunction(() => {
    const h = window.hairsketch.head();
    return h.name === 'builtin' && !h.loading;
  });
  await page.evaluate(() => window.hairsketch.idle());
  const back = (await sessionOf(page)).camera;
  for (let a = 0; a < 3; a++) {
    expect(back.position[a]).toBeCloseTo(home.position[a], 3);
    expect(back.target[a]).toBeCloseTo(home.target[a], 3);
  }
  // the loaded head's top in the built-in head's view: where it was shown before this change
  const topThen = await page.evaluate((p) => window.hairsketch.worldToScreen(p), [
    0,
    loaded.b.max[1],
    0,
  ] as Vec3);
  console.log(
    `[framing] in the built-in head's view the loaded head's top would be ${topThen ? `at ${topThen.y.toFixed(0)} px` : 'off screen'} (toolbar bottom ${loaded.toolbarBottom.toFixed(0)} px)`,
  );
  expect(errors).toEqual([]);
});
