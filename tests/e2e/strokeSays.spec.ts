// The hair does what the stroke says (natural fall), with real pointer strokes on an empty head:
// a stroke's hair ends where the stroke ends, hair no curve governs hangs, a sweep across the
// forehead covers it, a ponytail spine drawn from the side hangs plumb seen from behind. Every
// figure is printed. Waits on the status attributes, never on fixed sleeps.
import { expect, type Page, test } from '@playwright/test';
import { settled, status } from './helpers';

type V3 = [number, number, number];
interface Curve {
  id: string;
  type: string;
  points: V3[];
  extend?: boolean;
}
interface Strands {
  points: number[];
  strandStart: number[];
}

const session = (page: Page) =>
  page.evaluate(() => window.hairsketch.session() as { curves: Curve[]; fall?: boolean });

/** A drag through screen points with real mouse events (24 moves per leg). */
async function drag(page: Page, pts: { x: number; y: number }[]): Promise<void> {
  await page.mouse.move(pts[0].x, pts[0].y);
  await page.mouse.down();
  for (let k = 1; k < pts.length; k++)
    for (let i = 1; i <= 24; i++)
      await page.mouse.move(
        pts[k - 1].x + ((pts[k].x - pts[k - 1].x) * i) / 24,
        pts[k - 1].y + ((pts[k].y - pts[k - 1].y) * i) / 24,
      );
  await page.mouse.up();
}

async function scalpAt(page: Page, theta: number, phi: number) {
  const p = await page.evaluate(([t, f]) => window.hairsketch.scalpToScreen(t, f), [theta, phi]);
  expect(p, `scalp point (${theta}, ${phi}) on screen`).not.toBeNull();
  return p as { x: number; y: number };
}

async function emptyHead(page: Page, camera?: { position: V3; target: V3 }): Promise<number> {
  await page.goto('/?preset=empty&strands=6000');
  await settled(page);
  if (camera)
    await page.evaluate(
      ([p, t]) => window.hairsketch.setCamera(p as V3, t as V3),
      [camera.position, camera.target],
    );
  await page.evaluate(() => window.hairsketch.idle());
  await page.getByRole('button', { name: 'Stream curve' }).click();
  return (await status(page)).revision;
}

const strandsOf = (page: Page) =>
  page.evaluate(() => window.hairsketch.strands() as Strands | null);

test('a stroke down the front ends its hair at its end; the hair behind hangs', async ({
  page,
}) => {
  const rev = await emptyHead(page, { position: [0.4, 0.2, 7.5], target: [0, -0.3, 0] });
  const start = await scalpAt(page, 40, 0);
  // down over the forehead and off the head, ending in the air in front of the face
  await drag(page, [start, { x: start.x, y: start.y + 200 }]);
  const after = await settled(page, rev);
  expect(after.curves).toBe(1);
  const s = await session(page);
  expect(s.fall).toBe(true);
  const curve = s.curves[0];
  expect(curve.extend).toBe(false);
  const first = curve.points[0];
  const end = curve.points[curve.points.length - 1];
  const hair = await strandsOf(page);
  if (!hair) throw new Error('no hair');
  const P = hair.points;
  const S = hair.strandStart;
  const near: number[] = []; // tip height below the stroke's end, strands rooted near its start
  const backAngles: number[] = [];
  for (let k = 0; k + 1 < S.length; k++) {
    const a = S[k];
    const b = S[k + 1] - 1;
    if (b <= a) continue;
    const root: V3 = [P[3 * a], P[3 * a + 1], P[3 * a + 2]];
    const tip: V3 = [P[3 * b], P[3 * b + 1], P[3 * b + 2]];
    if (Math.hypot(root[0] - first[0], root[1] - first[1], root[2] - first[2]) <= 0.3)
      near.push(end[1] - tip[1]);
    // rooted at the back: behind the head's centre plane, below the crown
    if (root[2] < -0.45 && root[1] < 0.9) {
      const d: V3 = [tip[0] - root[0], tip[1] - root[1], tip[2] - root[2]];
      const len = Math.hypot(...d);
      if (len > 0.2)
        backAngles.push((Math.acos(Math.max(-1, Math.min(1, -d[1] / len))) * 180) / Math.PI);
    }
  }
  near.sort((x, y) => x - y);
  backAngles.sort((x, y) => x - y);
  const ok = near.filter((d) => d <= 0.15).length / near.length;
  const median = backAngles[backAngles.length >> 1];
  console.log(
    `front stroke: ${near.length} strands rooted within 3 cm of its start; ${(100 * ok).toFixed(1)} % end no lower than 1.5 cm below its end (90th percentile ${(near[Math.floor(0.9 * near.length)] * 10).toFixed(2)} cm below); ${backAngles.length} strands rooted at the back, median angle to straight down ${median.toFixed(1)}°`,
  );
  expect(near.length).toBeGreaterThan(20);
  expect(ok).toBeGreaterThanOrEqual(0.9);
  expect(backAngles.length).toBeGreaterThan(200);
  expect(median).toBeLessThanOrEqual(35);
  // and nothing runs through the head
  expect(await page.evaluate(() => window.hairsketch.segmentsInsideHead(0.001).inside)).toBe(0);
});

test('a stroke swept across the forehead covers it', async ({ page }) => {
  const rev = await emptyHead(page, { position: [0, 0.4, 7.5], target: [0, 0, 0] });
  // from a side parting on the left of the head (its φ = 50) across the forehead to the far temple
  const a = await scalpAt(page, 35, 40);
  const mid = await scalpAt(page, 62, 0);
  const temple = await scalpAt(page, 80, -75);
  await drag(page, [a, { x: mid.x, y: mid.y + 25 }, { x: temple.x, y: temple.y + 30 }]);
  await settled(page, rev);
  expect((await status(page)).curves).toBe(1);
  const cov = await page.evaluate(() =>
    window.hairsketch.coverage('front', {
      theta: [55, 75],
      phi: [-20, 20],
      surface: 'any',
      radius: 0.02,
      layers: 1,
    }),
  );
  const hidden = 1 - cov.fraction;
  console.log(
    `sweep across the forehead: ${cov.points - cov.bare} of ${cov.points} forehead points hidden (${(100 * hidden).toFixed(1)} %)`,
  );
  expect(cov.points).toBeGreaterThan(20);
  expect(hidden).toBeGreaterThanOrEqual(0.9);
  expect(await page.evaluate(() => window.hairsketch.segmentsInsideHead(0.001).inside)).toBe(0);
});

test('a ponytail spine drawn from the side hangs plumb seen from behind', async ({ page }) => {
  // the side view, looking a little down (as the default camera does)
  await emptyHead(page, { position: [7.4, 2.2, -0.6], target: [0, -0.3, 0] });
  await page.getByRole('button', { name: 'Ponytail' }).click();
  const root = await scalpAt(page, 70, 170);
  await drag(page, [root, { x: root.x - 10, y: root.y + 40 }, { x: root.x - 14, y: root.y + 240 }]);
  await page.waitForFunction(() => window.hairsketch.ponytailStage() === 'cross');
  const spine = (await page.evaluate(() => window.hairsketch.ponytailSpine())) as V3[];
  // the part below the head's back (off the head): its lean seen from behind (x against y)
  const low = spine.filter((p) => p[1] < spine[0][1] - 0.6);
  expect(low.length).toBeGreaterThan(5);
  const top = low[0];
  const bottom = low[low.length - 1];
  const lean = (Math.atan2(Math.abs(bottom[0] - top[0]), top[1] - bottom[1]) * 180) / Math.PI;
  console.log(
    `ponytail spine drawn from the side: ${lean.toFixed(2)}° from vertical seen from behind`,
  );
  expect(lean).toBeLessThanOrEqual(5);
});
