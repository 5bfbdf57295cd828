// Long hair (user report): "Max length (cm)" takes up to 100 cm, keeps what is typed, and the
// hair grows that long: the bounding volume grows downward to hold it (the tooltip says how many
// grid points it became) and the segment cap follows the length. A number out of range shows
// the limit and the status line says why. Real pointer and keyboard events throughout.
import { expect, type Page, test } from '@playwright/test';
import { settled, status, strokeFromScalp, watchConsole } from './helpers';

/** Longest displayed strand, world units (1 unit = 10 cm). */
async function longestStrand(page: Page): Promise<number> {
  return page.evaluate(() => {
    const s = window.hairsketch.strands();
    if (!s) return 0;
    const P = s.points;
    let best = 0;
    for (let i = 0; i + 1 < s.strandStart.length; i++) {
      let len = 0;
      for (let k = s.strandStart[i]; k + 1 < s.strandStart[i + 1]; k++)
        len += Math.hypot(
          P[3 * k + 3] - P[3 * k],
          P[3 * k + 4] - P[3 * k + 1],
          P[3 * k + 5] - P[3 * k + 2],
        );
      best = Math.max(best, len);
    }
    return best;
  });
}

async function growthOf(page: Page) {
  const s = (await page.evaluate(() => window.hairsketch.session())) as {
    growth: { maxLength: number; maxSegments: number };
  };
  return s.growth;
}

/** Types `text` into the Hair panel's "Max length (cm)" with the keyboard and commits it (Tab). */
async function typeMaxLength(page: Page, text: string) {
  const input = page.getByRole('region', { name: 'Hair detail' }).getByLabel('Max length (cm)');
  await input.click();
  await page.keyboard.press('Control+A');
  await page.keyboard.type(text);
  await page.keyboard.press('Tab');
  return input;
}

test('typing 60 in Max length keeps 60 and grows hair 60 cm long; 120 shows 100 and says why', async ({
  page,
}) => {
  test.setTimeout(240_000);
  const errors = watchConsole(page);
  await page.goto('/?preset=empty&strands=1500');
  const s0 = await settled(page);
  // one stream curve from the side of the head, hanging down (natural fall: its own hair ends
  // where it ends, "Extend past the end" off); the hair far from it hangs to the maximum length
  await strokeFromScalp(page, 45, 70, 10, 170);
  const s2 = await settled(page, s0.revision);
  expect(s2.curves).toBe(1);
  await expect(page.getByRole('checkbox', { name: 'Extend past the end' })).not.toBeChecked();
  const before = await longestStrand(page);
  const pointsBefore = await page.evaluate(() => window.hairsketch.gridPoints());

  await page.getByRole('button', { name: 'Detail' }).click();
  const input = await typeMaxLength(page, '60');
  const s3 = await settled(page, s2.revision);
  await expect(input).toHaveValue('60');
  const growth = await growthOf(page);
  expect(growth.maxLength).toBe(6);
  const longest = await longestStrand(page);
  const points = await page.evaluate(() => window.hairsketch.gridPoints());
  const title = await page.getByTestId('status').getAttribute('title');
  console.log(
    `[long hair] longest strand ${(before * 10).toFixed(1)} cm at the default 32 cm, ${(longest * 10).toFixed(1)} cm at 60 cm (maxSegments ${growth.maxSegments}); grid ${pointsBefore.toLocaleString('en-US')} -> ${points.toLocaleString('en-US')} points; tooltip: ${title?.split('\n').pop()}`,
  );
  expect(longest).toBeGreaterThan(5.7);
  expect(longest).toBeLessThanOrEqual(6 + 1e-4);
  expect(points).toBeGreaterThan(pointsBefore);
  expect(title).toContain(`bounding volume ${points.toLocaleString('en-US')} grid points`);
  expect(s3.text).not.toContain('maximum');

  // 120 is past the range: the input shows 100 and the status line says why
  await typeMaxLength(page, '120');
  const s4 = await settled(page, s3.revision);
  await expect(input).toHaveValue('100');
  expect(s4.text).toContain('Max length: 120 cm is above the maximum 100 cm; set to 100 cm.');
  const g100 = await growthOf(page);
  expect(g100.maxLength).toBe(10);
  const longest100 = await longestStrand(page);
  console.log(`[long hair] longest strand at 100 cm: ${(longest100 * 10).toFixed(1)} cm`);
  expect(longest100).toBeGreaterThan(9.5);

  // typing 120 again changes nothing in the session, and still says why
  await typeMaxLength(page, '120');
  await expect(input).toHaveValue('100');
  await expect(page.getByTestId('status')).toContainText('is above the maximum 100 cm');
  expect((await status(page)).state).not.toBe('error');
  expect(errors).toEqual([]);
});
