// Long hair (user report): "Max length (cm)" takes up to 100 cm, keeps what is typed, and the
// hair grows that long: the bounding volume grows downward to hold it (the tooltip says how many
// grid points it became) and the segment cap follows the length. A number out of range shows
// the limit and the status line says why. Real pointer and keyboard events throughout.
import { expect, type Page, test } from '@playwright/test';
import { settled, shoot, status, strokeFromScalp, watchConsole } from './helpers';

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
  // where it ends, "Extend past the end" off); with it on, its hair grows on, and the hair
  // around it (the shape rules: length from the strokes around) to the maximum length
  await strokeFromScalp(page, 45, 70, 10, 170);
  const s1 = await settled(page, s0.revision);
  expect(s1.curves).toBe(1);
  const extend = page.getByRole('checkbox', { name: 'Extend past the end' });
  await expect(extend).not.toBeChecked();
  await extend.check();
  const s2 = await settled(page, s1.revision);
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

/** Tip heights (y) of all strands: 10th, 50th percentile and the lowest. */
function tipHeights(page: Page) {
  return page.evaluate(() => {
    const h = window.hairsketch.strands();
    if (!h) return [];
    const y: number[] = [];
    for (let k = 0; k + 1 < h.strandStart.length; k++)
      y.push(h.points[3 * (h.strandStart[k + 1] - 1) + 1]);
    y.sort((a, b) => a - b);
    const q = (f: number) => y[Math.floor(f * (y.length - 1))];
    return [q(0.1), q(0.5), y[0]];
  });
}

test('raising Max length by 20 cm on the curly preset lowers its hair by about 20 cm, without strays', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto('/?preset=curly&strands=3000');
  const s0 = await settled(page);
  const before = await tipHeights(page);
  const max0 = (await growthOf(page)).maxLength;
  await page.getByRole('button', { name: 'Detail' }).click();
  await typeMaxLength(page, String(Math.round(max0 * 10) + 20));
  const s1 = await settled(page, s0.revision);
  expect(s1.text).toContain('lengthened by 20 cm');
  const after = await tipHeights(page);
  console.log(
    `curly tips (10 %, median, lowest) at ${max0 * 10} cm ${before.map((v) => v.toFixed(3))}, at +20 cm ${after.map((v) => v.toFixed(3))}`,
  );
  // the stroked hair goes on with the cap: the median tip 20 cm lower (the curls take up some)
  expect(before[1] - after[1]).toBeGreaterThan(1.2);
  expect(before[1] - after[1]).toBeLessThan(2.2);
  // no strays: no strand hangs more than 8 cm below the lowest tenth
  expect(after[0] - after[2]).toBeLessThan(0.8);
  expect(errors).toEqual([]);
});

test('Longer lengthens a sketched bob by 10 cm with two clicks, without strays; Undo takes it back', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto('/?preset=bob&strands=3000');
  let s = await settled(page);
  /** Tip heights (y) of the strands rooted at the back, 10th, 50th, 90th percentile and lowest. */
  const backTips = () =>
    page.evaluate(() => {
      const h = window.hairsketch.strands();
      if (!h) return [];
      const y: number[] = [];
      for (let k = 0; k + 1 < h.strandStart.length; k++)
        if (h.points[3 * h.strandStart[k] + 2] < -0.3)
          y.push(h.points[3 * (h.strandStart[k + 1] - 1) + 1]);
      y.sort((a, b) => a - b);
      const q = (f: number) => y[Math.floor(f * (y.length - 1))];
      return [q(0.1), q(0.5), q(0.9), y[0]];
    });
  const before = await backTips();
  await page.getByRole('button', { name: 'Detail' }).click();
  const panel = page.getByRole('region', { name: 'Hair detail' });
  for (let i = 0; i < 2; i++) {
    await panel.getByRole('button', { name: '+5 cm: longer' }).click();
    s = await settled(page, s.revision);
  }
  expect(s.text).toContain('lengthened by 5 cm');
  const after = await backTips();
  console.log(
    `bob back tips (10/50/90 %, lowest) before ${before.map((v) => v.toFixed(3))}, after two Longer ${after.map((v) => v.toFixed(3))}`,
  );
  await shoot(page, 'bob-longer');
  // the cut line is 10 cm lower (the strokes fall on past their ends), within 3 cm
  expect(before[1] - after[1]).toBeGreaterThan(0.7);
  expect(before[1] - after[1]).toBeLessThan(1.3);
  // and still a line: no strand hangs more than 5 cm below the lowest tenth
  expect(after[0] - after[3]).toBeLessThan(0.5);
  await page.getByRole('button', { name: 'Undo' }).click();
  await page.getByRole('button', { name: 'Undo' }).click();
  await settled(page);
  const undone = await backTips();
  expect(undone[1]).toBeCloseTo(before[1], 3);
  expect(errors).toEqual([]);
});
