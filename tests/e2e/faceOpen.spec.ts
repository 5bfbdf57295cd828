// The face stays open (issue: "a stylist's hand"): on an empty head, two strokes drawn with
// Mirror from the temple back over the ear and down behind it leave the eyes-to-mouth region
// clear: no more than 2 % of the strands have a point in front of it.
import { expect, test } from '@playwright/test';
import { settled, shoot, strokeFromScalp, watchConsole } from './helpers';

/** Share of strands with a point in front of the face between the brows and the mouth (the
 *  built-in head: eyes at y = -0.2, mouth at y = -0.84, cheeks out to |x| = 0.55, the face's
 *  surface at z ≈ 0.6-1.2 there). */
async function overFace(page: import('@playwright/test').Page): Promise<number> {
  return page.evaluate(() => {
    const s = window.hairsketch.strands();
    if (!s) return 1;
    let over = 0;
    const n = s.strandStart.length - 1;
    for (let k = 0; k < n; k++)
      for (let p = s.strandStart[k]; p < s.strandStart[k + 1]; p++) {
        const [x, y, z] = [s.points[3 * p], s.points[3 * p + 1], s.points[3 * p + 2]];
        if (Math.abs(x) < 0.45 && y > -0.95 && y < -0.05 && z > 0.55) {
          over++;
          break;
        }
      }
    return n > 0 ? over / n : 1;
  });
}

test('two mirrored strokes behind the ears leave the face clear', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto('/?preset=empty&strands=6000');
  let s = await settled(page);
  await page.getByRole('button', { name: 'Mirror' }).click();
  // the head's left side (key L): the face to the left of the screen, the back to the right
  await page.keyboard.press('l');
  await expect(page.getByTestId('view-label')).toContainText('left');
  await page.evaluate(() => window.hairsketch.idle());
  // from the temple over the top of the ear, then down behind it to the jaw
  await strokeFromScalp(page, 45, 50, 150, 260);
  s = await settled(page, s.revision);
  // and from the crown's side down behind the ear
  await strokeFromScalp(page, 35, 95, 80, 280);
  s = await settled(page, s.revision);
  expect(s.curves).toBe(4);
  const share = await overFace(page);
  console.log(
    `strands with a point in front of the eyes-to-mouth region: ${(100 * share).toFixed(2)} %`,
  );
  expect(share).toBeLessThanOrEqual(0.02);
  await shoot(page, 'face-open-tucked');
  expect(errors).toEqual([]);
});
