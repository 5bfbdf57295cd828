// Hair that moves: choose Head turn, click Play, the head turns and the strands move; Stop
// brings back the groom bit for bit. Frames per second while playing at 30K strands are printed
// (never asserted). With SHOT_DIR set, a strip of frames of `long` and `braid` turning, front
// and side.
import { expect, type Page, test } from '@playwright/test';
import { settled, watchConsole } from './helpers';

/** Waits (polling the status line's data-motion-frame) until the motion has drawn `frame`. */
async function motionFrame(page: Page, frame: number): Promise<void> {
  await page.waitForFunction(
    (f) => {
      const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
      return !!el && !!el.dataset.motion && Number(el.dataset.motionFrame) >= f;
    },
    frame,
    { polling: 50 },
  );
}

const drawn = (page: Page) => page.evaluate(() => window.hairsketch.strands());

test('Play with Head turn moves the strands; Stop restores them bit for bit', async ({ page }) => {
  test.setTimeout(180_000);
  const errors = watchConsole(page);
  await page.goto('/?preset=long&strands=30000');
  const s = await settled(page);
  const before = await drawn(page);
  expect(before).not.toBeNull();
  await page.getByLabel('Motion').selectOption('head-turn');
  await page.getByRole('button', { name: 'Play' }).click();
  await expect(page.getByRole('button', { name: 'Stop' })).toBeVisible();
  await motionFrame(page, 6);
  const playing = await drawn(page);
  expect(playing?.strandStart).toEqual(before?.strandStart);
  let moved = 0;
  for (let i = 0; i < (before?.points.length ?? 0); i++)
    if (playing?.points[i] !== before?.points[i]) moved++;
  expect(moved).toBeGreaterThan((before?.points.length ?? 0) / 4);
  const m = await page.evaluate(() => window.hairsketch.motion());
  console.log(
    `motion at ${s.strands} strands: ${m.fps.toFixed(1)} frames per second drawn (frame ${m.frame}; last frame: worker ${m.workerMs.toFixed(0)} ms, geometry ${m.buildMs.toFixed(0)} ms)`,
  );
  await expect(page.getByTestId('status')).toContainText('Playing Head turn');
  await page.getByRole('button', { name: 'Stop' }).click();
  await expect(page.getByRole('button', { name: 'Play' })).toBeVisible();
  const after = await drawn(page);
  expect(after?.points).toEqual(before?.points);
  expect(errors).toEqual([]);
});

for (const preset of ['long', 'braid']) {
  test(`pictures: ${preset} turning, front and side`, async ({ page }) => {
    test.skip(!process.env.SHOT_DIR, 'pictures only with SHOT_DIR');
    test.setTimeout(240_000);
    await page.goto(`/?preset=${preset}&strands=8000`);
    await settled(page);
    const dir = process.env.SHOT_DIR;
    const cams = {
      front: [0.8, 0.2, 10.5],
      side: [10.5, 0.2, -0.4],
    } as const;
    for (const [view, p] of Object.entries(cams)) {
      await page.evaluate(
        ([q, t]) =>
          window.hairsketch.setCamera(q as [number, number, number], t as [number, number, number]),
        [p, [0, -0.8, 0]],
      );
      await page.evaluate(() => window.hairsketch.idle());
      await page.getByLabel('Motion').selectOption('head-turn');
      await page.getByRole('button', { name: 'Play' }).click();
      for (const f of [6, 12, 18, 24, 30]) {
        await motionFrame(page, f);
        const at = await page.evaluate(() => window.hairsketch.motion().frame);
        await page
          .getByTestId('viewport')
          .screenshot({ path: `${dir}/${preset}-${view}-${String(at).padStart(2, '0')}.png` });
      }
      await page.getByRole('button', { name: 'Stop' }).click();
    }
  });
}
