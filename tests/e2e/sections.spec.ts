// Sections and ties with real pointer strokes on an empty head: a tie gathers the hair of its
// whole scalp section (solver-cpp/src/scalp_sections.hpp). Half-up: an ear-to-ear parting over
// the crown and a bun on the top section (a braid, a bun and two braids with no parting:
// braidBun.spec.ts; Mirror pigtails: strokeSays.spec.ts); the fractions are measured
// from the strands' roots against the side of the parting they grow on (not from the app's own
// sections), and Undo, Redo and the link keep the hair. Waits on the status attributes.
import { expect, type Page, test } from '@playwright/test';
import { hairOf, type PageHair, settled, shoot, status } from './helpers';

type V3 = [number, number, number];
type Hair = PageHair;

async function drag(page: Page, pts: { x: number; y: number }[]): Promise<void> {
  await page.mouse.move(pts[0].x, pts[0].y);
  await page.mouse.down();
  for (const p of pts.slice(1)) await page.mouse.move(p.x, p.y);
  await page.mouse.up();
}

async function scalpAt(page: Page, theta: number, phi: number) {
  const p = await page.evaluate(([t, f]) => window.hairsketch.scalpToScreen(t, f), [theta, phi]);
  expect(p, `scalp point (${theta}, ${phi}) on screen`).not.toBeNull();
  return p as { x: number; y: number };
}

const line = (a: { x: number; y: number }, b: { x: number; y: number }, n = 24) =>
  Array.from({ length: n + 1 }, (_, i) => ({
    x: a.x + ((b.x - a.x) * i) / n,
    y: a.y + ((b.y - a.y) * i) / n,
  }));

const curveCount = (page: Page, n: number) =>
  page.waitForFunction(
    (k) => (window.hairsketch.session() as { curves: unknown[] }).curves.length === k,
    n,
  );

const hair = (page: Page) => hairOf(page);

/** Of the strands whose root passes `side`, the share tie `curve` laid. */
function share(h: Hair, curve: number, side: (r: V3) => boolean): number {
  let n = 0;
  let taken = 0;
  for (let s = 0; s + 1 < h.strandStart.length; s++) {
    const k = 3 * h.strandStart[s];
    if (!side([h.points[k], h.points[k + 1], h.points[k + 2]])) continue;
    n++;
    if (h.tailCurves[s] === curve) taken++;
  }
  return n ? taken / n : 0;
}

async function emptyHead(page: Page, camera: { position: V3; target: V3 }) {
  await page.goto('/?preset=empty&strands=2000');
  await settled(page);
  await page.evaluate(
    ([p, t]) => window.hairsketch.setCamera(p as V3, t as V3),
    [camera.position, camera.target],
  );
  await page.evaluate(() => window.hairsketch.idle());
  return (await status(page)).revision;
}

const ABOVE = { position: [0, 7.4, -1.2] as V3, target: [0, 0.4, 0] as V3 };

test('half-up: an ear-to-ear parting and a bun on the top section gather the top alone', async ({
  page,
}) => {
  const rev = await emptyHead(page, ABOVE);
  // the parting, from above one ear over the crown to above the other, a little behind the top
  await page.getByRole('button', { name: 'Dividing curve' }).click();
  await drag(page, line(await scalpAt(page, 72, 112), await scalpAt(page, 72, -112)));
  await curveCount(page, 1);
  // the bun on the top section, behind the crown
  await page.getByRole('button', { name: 'Bun' }).click();
  const c = await scalpAt(page, 10, 180);
  await drag(
    page,
    Array.from({ length: 33 }, (_, i) => ({
      x: c.x + 28 * Math.cos((2 * Math.PI * i) / 32),
      y: c.y + 28 * Math.sin((2 * Math.PI * i) / 32),
    })),
  );
  await curveCount(page, 2);
  await settled(page, rev);
  const s = (await page.evaluate(() => window.hairsketch.session())) as {
    curves: { type: string; points: V3[]; section?: number }[];
    sections?: boolean;
  };
  expect(s.sections).toBe(true);
  expect(s.curves.map((k) => k.type)).toEqual(['dividing', 'bun']);
  expect(s.curves[1].section).toBe(1);
  // the parting's plane: the vertical plane through its points (least squares on z = a + b x)
  const p = s.curves[0].points;
  const zAt = p.reduce((m, q) => m + q[2], 0) / p.length;
  const h = await hair(page);
  if (!h) throw new Error('no hair');
  const top = share(h, 1, (r) => r[2] > zAt + 0.06);
  const rest = share(h, 1, (r) => r[2] < zAt - 0.06);
  console.log(
    `half-up: the bun gathers ${(100 * top).toFixed(1)} % of the top section and ${(100 * rest).toFixed(1)} % of the rest (parting at z = ${zAt.toFixed(2)})`,
  );
  expect(top).toBeGreaterThanOrEqual(0.95);
  expect(rest).toBeLessThan(0.05);
  // hair at the parting goes the way it is combed: none flies loose from the line out past the
  // sides (the built-in head is 16 cm wide, |x| <= 0.79; loose hair falls within 5 cm of it)
  let flying = 0;
  for (let k = 0; k + 1 < h.strandStart.length; k++)
    for (let q = h.strandStart[k]; q < h.strandStart[k + 1]; q++)
      if (Math.abs(h.points[3 * q]) > 1.3) {
        flying++;
        break;
      }
  console.log(`half-up: ${flying} strands reach more than 5 cm past the sides of the head`);
  expect(flying).toBe(0);
  // the Bun tool is active: the scalp shows its sections; another tool: the head's own colours
  await page.waitForFunction(() => window.hairsketch.sectionsTinted() > 0);
  await shoot(page, 'sections-half-up-tinted');
  // with the style curves hidden (1, for clean pictures) the tint goes too, and comes back
  await page.keyboard.press('1');
  await page.waitForFunction(
    () => window.hairsketch.sectionsTinted() === 0 && window.hairsketch.sectionsOverHair() === 0,
  );
  await page.keyboard.press('1');
  await page.waitForFunction(() => window.hairsketch.sectionsOverHair() > 0);
  await page.getByRole('button', { name: 'Stream curve' }).click();
  await page.waitForFunction(() => window.hairsketch.sectionsTinted() === 0);
  await shoot(page, 'sections-half-up');

  // Undo takes the bun away, Redo brings back the same hair, a reload of the link keeps it
  const hash = await page.evaluate(() => window.hairsketch.hairHash());
  const done = await status(page);
  await page.keyboard.press('Control+z');
  await curveCount(page, 1);
  const undone = await settled(page, done.revision);
  expect(await page.evaluate(() => window.hairsketch.hairHash())).not.toBe(hash);
  await page.keyboard.press('Control+Shift+z');
  await curveCount(page, 2);
  await settled(page, undone.revision);
  expect(await page.evaluate(() => window.hairsketch.hairHash())).toBe(hash);
  // the link is written 400 ms after an edit: write it now, so the reload opens this session
  await page.evaluate(() => window.hairsketch.link());
  await page.reload();
  await settled(page);
  expect(await page.evaluate(() => window.hairsketch.hairHash())).toBe(hash);
});
