// Braids and buns with real pointer strokes on an empty head: the Braid tool's stroke from the
// scalp and the Bun tool's loop on the head make curves the session holds, the hair changes, Undo
// takes them away; Mirror doubles a braid; a loop that leaves the head makes nothing and says why.
// Waits on the status attributes and the session, never on fixed sleeps.
import { expect, type Page, test } from '@playwright/test';
import { hairOf, settled, shoot, status, strokeFromScalp } from './helpers';

/** Of the hair shown, the share of the strands rooted where `side` says that curve `curve`'s tie
 *  laid (sections: a tie takes its whole section). */
async function tieShare(page: Page, curve: number, side: 'all' | 'left' | 'right' = 'all') {
  return page.evaluate(
    ([c, sd]) => {
      const h = window.hairsketch.strands();
      if (!h) return 0;
      let n = 0;
      let taken = 0;
      for (let s = 0; s + 1 < h.strandStart.length; s++) {
        const x = h.points[3 * h.strandStart[s]];
        if ((sd === 'left' && x < 0.05) || (sd === 'right' && x > -0.05)) continue;
        n++;
        if (h.tailCurves[s] === c) taken++;
      }
      return n ? taken / n : 0;
    },
    [curve, side] as const,
  );
}

type V3 = [number, number, number];
interface Curve {
  id: string;
  type: string;
  points: V3[];
  extend: boolean;
  mirror?: string;
  [param: string]: unknown;
}

const curves = (page: Page) =>
  page.evaluate(() => (window.hairsketch.session() as { curves: Curve[] }).curves);

/** An empty head seen from `camera`, settled; its hair's hash and status revision. */
async function emptyHead(page: Page, camera: { position: V3; target: V3 }) {
  await page.goto('/?preset=empty&strands=4000');
  await settled(page);
  await page.evaluate(
    ([p, t]) => window.hairsketch.setCamera(p as V3, t as V3),
    [camera.position, camera.target],
  );
  await page.evaluate(() => window.hairsketch.idle());
  const rev = (await status(page)).revision;
  const hash = await page.evaluate(() => window.hairsketch.hairHash());
  expect(hash).not.toBeNull();
  return { rev, hash };
}

const curveCount = (page: Page, n: number) =>
  page.waitForFunction(
    (k) => (window.hairsketch.session() as { curves: unknown[] }).curves.length === k,
    n,
  );

const SIDE = { position: [7.4, 0.8, -0.6] as V3, target: [0, -0.3, 0] as V3 };
const ABOVE = { position: [0, 7.2, -2.2] as V3, target: [0, 0.4, 0] as V3 };

test('a braid drawn from the scalp: the session holds it, the hair changes, Undo removes it', async ({
  page,
}) => {
  const empty = await emptyHead(page, SIDE);
  await page.getByRole('button', { name: 'Braid' }).click();
  await strokeFromScalp(page, 60, 150, 70, 240);
  await curveCount(page, 1);
  const after = await settled(page, empty.rev);
  const [braid] = await curves(page);
  expect(braid.type).toBe('braid');
  expect(braid.points.length).toBeGreaterThan(5);
  expect(braid.extend).toBe(false); // natural fall: the hair ends where the stroke ends
  expect([braid.width, braid.crossings, braid.tightness, braid.tailLength]).toEqual([
    0.5, 6, 0.5, 0.4,
  ]);
  const hash = await page.evaluate(() => window.hairsketch.hairHash());
  expect(hash).not.toBe(empty.hash);
  await shoot(page, 'hand-braid');
  // with no parting the braid gathers the whole head (sections)
  const all = await tieShare(page, 0);
  console.log(`one braid, no parting: ${(100 * all).toFixed(1)} % of the strands`);
  expect(all).toBeGreaterThanOrEqual(0.95);

  await page.getByRole('button', { name: 'Undo' }).click();
  await curveCount(page, 0);
  await settled(page, after.revision);
  expect(await page.evaluate(() => window.hairsketch.hairHash())).toBe(empty.hash);
});

test('Mirror doubles a braid: two braids, twins of each other', async ({ page }) => {
  const empty = await emptyHead(page, SIDE);
  await page.getByRole('button', { name: 'Mirror' }).click();
  await page.getByRole('button', { name: 'Braid' }).click();
  await strokeFromScalp(page, 78, 135, 90, 230);
  await curveCount(page, 2);
  await settled(page, empty.rev);
  await shoot(page, 'hand-braids-mirrored');
  const [a, b] = await curves(page);
  // two braids share the head, each its own half (the nearer tie)
  const aSide = a.points[a.points.length - 1][0] > 0 ? 'left' : 'right';
  const bSide = aSide === 'left' ? 'right' : 'left';
  const own = [await tieShare(page, 0, aSide), await tieShare(page, 1, bSide)];
  const other = [await tieShare(page, 0, bSide), await tieShare(page, 1, aSide)];
  console.log(
    `two braids: each ${own.map((f) => (100 * f).toFixed(1)).join(' / ')} % of its side, ${other.map((f) => (100 * f).toFixed(1)).join(' / ')} % of the other`,
  );
  for (const f of own) expect(f).toBeGreaterThanOrEqual(0.95);
  for (const f of other) expect(f).toBeLessThan(0.05);
  expect([a.type, b.type]).toEqual(['braid', 'braid']);
  expect(a.mirror).toBe(b.id);
  expect(b.mirror).toBe(a.id);
  // the twin is the reflection across x = 0
  for (let i = 0; i < a.points.length; i++) {
    expect(b.points[i][0]).toBeCloseTo(-a.points[i][0], 4);
    expect(b.points[i][1]).toBeCloseTo(a.points[i][1], 4);
  }
});

test("a bun's hair has no flyaways: a new session's flyaways leave its coil as it was", async ({
  page,
}) => {
  // a round-10 helper saw a wiry grey halo round every bun: a new session's 1 % of flyaways
  // stood 1.2 cm off the coil. The bun's strands are the same with the Hair panel's Flyaway on
  // (the default) and off (44 of 4,000 moved before this rule)
  test.setTimeout(180_000);
  const empty = await emptyHead(page, ABOVE);
  await page.getByRole('button', { name: 'Bun' }).click();
  const c = await page.evaluate(() => window.hairsketch.scalpToScreen(20, 180));
  expect(c, 'the bun’s place on screen').not.toBeNull();
  if (!c) return;
  await page.mouse.move(c.x + 30, c.y);
  await page.mouse.down();
  for (let i = 1; i <= 48; i++) {
    const a = (2 * Math.PI * i) / 48;
    await page.mouse.move(c.x + 30 * Math.cos(a), c.y + 30 * Math.sin(a));
  }
  await page.mouse.up();
  await curveCount(page, 1);
  const withFlyaways = await settled(page, empty.rev);
  // per strand: whether the bun holds it, and its points
  const strands = async () => {
    const h = await hairOf(page);
    const out: { bun: boolean; points: Float32Array }[] = [];
    if (!h) return out;
    for (let s = 0; s + 1 < h.strandStart.length; s++)
      out.push({
        bun: h.tailCurves[s] === 0,
        points: h.points.slice(3 * h.strandStart[s], 3 * h.strandStart[s + 1]),
      });
    return out;
  };
  const on = await strands();
  await page.getByRole('button', { name: 'Detail' }).click();
  await page
    .getByRole('region', { name: 'Hair detail' })
    .getByLabel('Flyaway', { exact: true })
    .click();
  await settled(page, withFlyaways.revision);
  const off = await strands();
  expect(off.length).toBe(on.length);
  let bunStrands = 0;
  let bunMoved = 0;
  on.forEach((s, i) => {
    const same =
      s.points.length === off[i].points.length && s.points.every((v, k) => v === off[i].points[k]);
    if (!s.bun) return;
    bunStrands++;
    if (!same) bunMoved++;
  });
  console.log(
    `bun flyaways: ${bunMoved} of ${bunStrands} bun strands change when Flyaway goes off`,
  );
  expect(bunStrands).toBeGreaterThan(1000);
  expect(bunMoved).toBe(0);
});

test('a bun drawn as a loop on the head: the session holds it, the hair changes, Undo removes it; a loop off the head is refused', async ({
  page,
}) => {
  const empty = await emptyHead(page, ABOVE);
  await page.getByRole('button', { name: 'Bun' }).click();
  const c = await page.evaluate(() => window.hairsketch.scalpToScreen(20, 180));
  expect(c, 'the bun’s place on screen').not.toBeNull();
  if (!c) return;
  // a loop of 45 px round the bun's place, with real mouse events
  const loop = (r: number) => {
    const pts: { x: number; y: number }[] = [];
    for (let i = 0; i <= 48; i++) {
      const a = (2 * Math.PI * i) / 48;
      pts.push({ x: c.x + r * Math.cos(a), y: c.y + r * Math.sin(a) });
    }
    return pts;
  };
  const drag = async (pts: { x: number; y: number }[]) => {
    await page.mouse.move(pts[0].x, pts[0].y);
    await page.mouse.down();
    for (const p of pts.slice(1)) await page.mouse.move(p.x, p.y);
    await page.mouse.up();
  };
  await drag(loop(45));
  await curveCount(page, 1);
  const after = await settled(page, empty.rev);
  const [bun] = await curves(page);
  expect(bun.type).toBe('bun');
  expect([bun.radius, bun.height, bun.turns]).toEqual([0, 0.35, 2.5]);
  // the status line gives the loop's length round (the saved loop's, closed), not its points
  let round = 0;
  bun.points.forEach((p, i) => {
    const q = bun.points[(i + 1) % bun.points.length];
    round += Math.hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]);
  });
  expect(after.text).toContain(`a loop ${Math.round(10 * round)} cm round`);
  expect(await page.evaluate(() => window.hairsketch.hairHash())).not.toBe(empty.hash);
  // with no parting the bun coils the whole head's hair (sections)
  const all = await tieShare(page, 0);
  console.log(`one bun, no parting: ${(100 * all).toFixed(1)} % of the strands`);
  expect(all).toBeGreaterThanOrEqual(0.95);

  // a loop far larger than the head leaves it: nothing is made, the status line says why
  await drag(loop(2000).map((p) => ({ x: Math.max(2, p.x), y: Math.max(2, p.y) })));
  await expect(page.getByTestId('status')).toContainText(/bun/i);
  expect((await curves(page)).length).toBe(1);
  await shoot(page, 'hand-bun');

  await page.getByRole('button', { name: 'Undo' }).click();
  await curveCount(page, 0);
  await settled(page, after.revision);
  expect(await page.evaluate(() => window.hairsketch.hairHash())).toBe(empty.hash);
});

for (const preset of ['braid', 'bun', 'pigtail-braids']) {
  test(`${preset}: no hair inside the head, also with curl`, async ({ page }) => {
    await page.goto(`/?preset=${preset}&strands=3000`);
    const first = await settled(page);
    expect(first.strands).toBeGreaterThan(2000);
    const inside = await page.evaluate(() => window.hairsketch.segmentsInsideHead(0.01));
    console.log(`${preset}: ${JSON.stringify(inside)} segments deeper than 1 mm in the head`);
    expect(inside.inside).toBe(0);
    // detail on top of the laid tails keeps the same rule
    await page.getByRole('button', { name: 'Detail' }).click();
    await page
      .getByRole('region', { name: 'Hair detail' })
      .getByRole('checkbox', { name: 'Curl' })
      .check();
    await settled(page, first.revision);
    expect(await page.evaluate(() => window.hairsketch.segmentsInsideHead(0.01).inside)).toBe(0);
  });
}
