// The Cards view end to end: a real click on the "Cards" display toggle draws the hair as the
// hair cards export cuts it (the status carries data-cards) and the view shows about as much
// hair as the strands did; the Export menu's "Card count" cuts them again (a count out of range
// is refused in words); a second click brings the strands back. With SHOT_DIR set, pictures of the strands
// and of the cards from the front and the side (for a person to look at).
import { expect, type Page, test } from '@playwright/test';
import { settled, watchConsole } from './helpers';

const SCENE = '/?preset=bob&strands=3000';

/** Pixels of the view dark enough to be hair (the bob's brown; the background and the head are
 *  far lighter), read from the WebGL canvas (its drawing buffer is preserved). */
async function hairPixels(page: Page): Promise<number> {
  await page.evaluate(() => window.hairsketch.idle());
  return page.getByTestId('viewport').evaluate((c: HTMLCanvasElement) => {
    const copy = document.createElement('canvas');
    copy.width = c.width;
    copy.height = c.height;
    const g = copy.getContext('2d') as CanvasRenderingContext2D;
    g.drawImage(c, 0, 0);
    const px = g.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < px.length; i += 4)
      if (0.2126 * px[i] + 0.7152 * px[i + 1] + 0.0722 * px[i + 2] < 110) n++;
    return n;
  });
}

async function shots(page: Page, name: string): Promise<void> {
  const dir = process.env.SHOT_DIR;
  if (!dir) return;
  const views: [string, [number, number, number]][] = [
    ['front', [0.6, 0.6, 7.5]],
    ['side', [7.5, 0.6, -0.4]],
  ];
  for (const [view, p] of views) {
    await page.evaluate(
      (q) => window.hairsketch.setCamera(q as [number, number, number], [0, -0.6, 0]),
      p,
    );
    await page.evaluate(() => window.hairsketch.idle());
    await page.getByTestId('viewport').screenshot({ path: `${dir}/${name}-${view}.png` });
  }
}

test('the Cards view shows the hair as cards and toggles back to strands', async ({ page }) => {
  const errors = watchConsole(page);
  await page.goto(SCENE);
  await settled(page);
  const strands = await hairPixels(page);
  expect(strands).toBeGreaterThan(10_000);
  const toggle = page.getByRole('checkbox', { name: 'Cards', exact: true });
  await toggle.click();
  await expect(toggle).toBeChecked();
  const status = page.getByTestId('status');
  await expect(status).toHaveAttribute('data-cards', /^[1-9][0-9]*$/);
  const cards = Number(await status.getAttribute('data-cards'));
  const triangles = Number(await status.getAttribute('data-card-triangles'));
  expect(cards).toBeGreaterThan(500); // the default count is 1,000 (3,000 strands: most clusters survive)
  expect(cards).toBeLessThanOrEqual(1000);
  expect(triangles).toBeGreaterThanOrEqual(4 * cards); // at least two quads per card
  // the cards cover about what the strands cover, seen from the same place
  const withCards = await hairPixels(page);
  expect(withCards).toBeGreaterThan(0.6 * strands);
  expect(withCards).toBeLessThan(1.6 * strands);
  await shots(page, 'cards');

  // the Export menu's card count cuts the cards again; a count out of range is refused in words
  await page.getByRole('button', { name: 'Export' }).click();
  const count = page.getByRole('spinbutton', { name: 'Card count' });
  await count.fill('50');
  await count.press('Enter');
  await expect(status).toContainText('The card count must be a whole number from 100 to 5,000');
  await expect(count).toHaveValue('1000');
  expect(Number(await status.getAttribute('data-cards'))).toBe(cards);
  await count.fill('300');
  await count.press('Enter');
  await expect(status).toHaveAttribute('data-cards', /^(2[0-9]{2}|300)$/);
  await page.keyboard.press('Escape');
  await toggle.click();
  await expect(status).not.toHaveAttribute('data-cards', /.*/);
  await shots(page, 'strands');
  expect(errors).toEqual([]);
});
