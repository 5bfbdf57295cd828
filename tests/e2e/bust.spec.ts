// Hair rests on the bust (issue 37): long hair drawn with Mirror on an empty head lies on the
// shoulders and slides off them, the front of the scalp's in front and the back's behind; a
// stroke drawn over the front of the shoulder brings the hair there forward.
import { expect, type Page, test } from '@playwright/test';
import { settled, shoot, strokeFromScalp, watchConsole } from './helpers';

/** The shoulders' ridge (head/bodySdf.ts: the trapezius and deltoids run along z ≈ -0.3) and
 *  the height below which a strand's tip has passed the top of the shoulders. */
const RIDGE_Z = -0.32;
const BELOW_SHOULDERS = -2.7;

/** Of the strands whose tips hang below the shoulders' top, those rooted in front (z > 0.3) and
 *  behind (z < -0.5) the ear line: the share of each whose tip is on its own side of the ridge;
 *  and the share of the side strands (rooted |x| > 0.55 between them) whose tip is in front. */
async function sides(page: Page) {
  return page.evaluate(
    ([ridge, below]) => {
      const s = window.hairsketch.strands();
      if (!s) throw new Error('no hair');
      const count = { front: 0, frontOk: 0, back: 0, backOk: 0, side: 0, sideFront: 0 };
      for (let k = 0; k + 1 < s.strandStart.length; k++) {
        const a = s.strandStart[k];
        const b = s.strandStart[k + 1] - 1;
        if (b <= a || s.points[3 * b + 1] > below) continue;
        const rootX = s.points[3 * a];
        const rootZ = s.points[3 * a + 2];
        const tipInFront = s.points[3 * b + 2] > ridge;
        if (rootZ > 0.3) {
          count.front++;
          if (tipInFront) count.frontOk++;
        } else if (rootZ < -0.5) {
          count.back++;
          if (!tipInFront) count.backOk++;
        } else if (Math.abs(rootX) > 0.55) {
          count.side++;
          if (tipInFront) count.sideFront++;
        }
      }
      return {
        ...count,
        front: count.front,
        frontShare: count.frontOk / Math.max(1, count.front),
        backShare: count.backOk / Math.max(1, count.back),
        sideFrontShare: count.sideFront / Math.max(1, count.side),
      };
    },
    [RIDGE_Z, BELOW_SHOULDERS],
  );
}

/** Types 60 into the Hair panel's "Max length (cm)" and waits for the hair. */
async function longHair(page: Page, revision: number) {
  await page.getByRole('button', { name: 'Detail' }).click();
  const input = page.getByRole('region', { name: 'Hair detail' }).getByLabel('Max length (cm)');
  await input.click();
  await page.keyboard.press('Control+A');
  await page.keyboard.type('60');
  await page.keyboard.press('Tab');
  const s = await settled(page, revision);
  await page.getByRole('button', { name: 'Detail' }).click();
  return s;
}

test('long hair drawn with Mirror rests on the shoulders: front in front, back behind; a stroke over the front of a shoulder brings hair forward', async ({
  page,
}) => {
  test.setTimeout(240_000);
  const errors = watchConsole(page);
  await page.goto('/?preset=empty&strands=2500');
  let s = await settled(page);
  s = await longHair(page, s.revision);
  await page.getByRole('button', { name: 'Mirror' }).click();
  // the head's left side (key L): the face to the left of the screen, the back to the right;
  // one stroke from the crown's side down behind the ear, mirrored to the other side (from
  // behind the ear line, phi 110: hair beside a stroke that goes behind an ear goes behind it
  // with it, so from phi 95 the stroke took the front hair near it behind the shoulders too)
  await page.keyboard.press('l');
  await expect(page.getByTestId('view-label')).toContainText('left');
  await page.evaluate(() => window.hairsketch.idle());
  await strokeFromScalp(page, 35, 110, 60, 300);
  s = await settled(page, s.revision);
  expect(s.curves).toBe(2);
  // its hair (and with the shape rules the hair around it) grows on to the maximum length
  await page.getByRole('checkbox', { name: 'Extend past the end' }).check();
  s = await settled(page, s.revision);
  const m = await sides(page);
  console.log(
    `[bust] strands below the shoulders' top: rooted in front ${m.front}, ${(100 * m.frontShare).toFixed(1)} % end in front of the shoulders; rooted behind ${m.back}, ${(100 * m.backShare).toFixed(1)} % end behind them`,
  );
  expect(m.front).toBeGreaterThan(20);
  expect(m.back).toBeGreaterThan(20);
  expect(m.frontShare).toBeGreaterThanOrEqual(0.9);
  expect(m.backShare).toBeGreaterThanOrEqual(0.9);
  await shoot(page, 'bust-long-mirror', 'bust');
  // back to the left view (the pictures move the camera)
  await page.keyboard.press('l');
  await expect(page.getByTestId('view-label')).toContainText('left');
  await page.evaluate(() => window.hairsketch.idle());

  // zoomed out to see the shoulders (the wheel over the picture)
  const box = await page.getByTestId('viewport').boundingBox();
  if (!box) throw new Error('no viewport');
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  for (let k = 0; k < 4; k++) await page.mouse.wheel(0, 240);
  await page.evaluate(() => window.hairsketch.idle());
  // from the side of the head above the ear, down over the front of the shoulder: the stroke
  // ends in front of the chest, below the shoulder's top (the left side is +x)
  const [a, b] = await page.evaluate(() => [
    window.hairsketch.scalpToScreen(50, 90),
    window.hairsketch.worldToScreen([0.75, -3.0, 0.9]),
  ]);
  if (!a || !b)
    throw new Error(`the ends of the stroke are not on screen: ${JSON.stringify([a, b])}`);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  for (let i = 1; i <= 30; i++) {
    // down first, then forward: over the shoulder, not over the face
    const t = i / 30;
    await page.mouse.move(a.x + (b.x - a.x) * t * t, a.y + (b.y - a.y) * Math.sqrt(t));
  }
  await page.mouse.up();
  s = await settled(page, s.revision);
  expect(s.curves).toBe(4);
  const after = await sides(page);
  console.log(
    `[bust] side strands whose tips end in front of the shoulders: ${(100 * m.sideFrontShare).toFixed(1)} % -> ${(100 * after.sideFrontShare).toFixed(1)} % after a stroke over the front of each`,
  );
  await shoot(page, 'bust-forward', 'bust');
  expect(after.sideFrontShare).toBeGreaterThan(m.sideFrontShare + 0.15);
  expect(errors).toEqual([]);
});
