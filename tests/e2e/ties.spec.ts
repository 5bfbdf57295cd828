// Ties and sections from an empty head with real pointer events, the gestures the user guide
// gives (half-up, ponytails, pigtails, a bun, braids). The fractions are measured from the
// strands' roots against the side of the drawn parting they grow on, not from the app's own
// sections; each tail's end against its stroke's end. Waits on the status attributes.
import { expect, type Page, test } from '@playwright/test';
import { dragThrough, scalpAt, settled, shoot, status } from './helpers';

type V3 = [number, number, number];
interface Hair {
  points: number[];
  strandStart: number[];
  tailCurves: number[];
}

test.use({ viewport: { width: 1280, height: 800 } });

const curveCount = (page: Page, n: number) =>
  page.waitForFunction(
    (k) => (window.hairsketch.session() as { curves: unknown[] }).curves.length === k,
    n,
  );

/** An empty head at 3000 strands; with `maxLength`, typed into the Hair panel (cm). */
async function emptyHead(page: Page, maxLength?: number) {
  await page.goto('/?preset=empty&strands=3000');
  const s0 = await settled(page);
  if (maxLength === undefined) return s0;
  await page.getByRole('button', { name: 'Detail' }).click();
  const input = page.getByRole('region', { name: 'Hair detail' }).getByLabel('Max length (cm)');
  await input.click();
  await page.keyboard.press('Control+A');
  await page.keyboard.type(String(maxLength));
  await page.keyboard.press('Tab');
  const s = await settled(page, s0.revision);
  await page.getByRole('button', { name: 'Detail' }).click();
  return s;
}

/** A named view by its key, waiting until the view control names it. */
async function view(page: Page, key: string, name: string) {
  await page.keyboard.press(key);
  await expect(page.getByTestId('view-label')).toContainText(name);
  await page.evaluate(() => window.hairsketch.idle());
}

const hair = async (page: Page) => (await page.evaluate(() => window.hairsketch.strands())) as Hair;

function roots(h: Hair): V3[] {
  const out: V3[] = [];
  for (let s = 0; s + 1 < h.strandStart.length; s++) {
    const k = 3 * h.strandStart[s];
    out.push([h.points[k], h.points[k + 1], h.points[k + 2]]);
  }
  return out;
}

/** The parting's z (its back-most) at x, seen from above; null outside its x range. */
function partingZ(line: V3[], x: number): number | null {
  let z: number | null = null;
  for (let k = 0; k + 1 < line.length; k++) {
    const [a, b] = [line[k], line[k + 1]];
    if ((a[0] - x) * (b[0] - x) > 0 || a[0] === b[0]) continue;
    const t = (x - a[0]) / (b[0] - a[0]);
    const zz = a[2] + t * (b[2] - a[2]);
    z = z === null ? zz : Math.min(z, zz);
  }
  return z;
}

test('half-up: the user guide gesture (a parting from above one ear round the crown, a bun on top) gathers the top alone and says what the parting did', async ({
  page,
}) => {
  test.setTimeout(120_000);
  await emptyHead(page, 45);
  await view(page, 't', 'top');
  await page.getByRole('button', { name: 'Dividing curve' }).click();
  const at: [number, number][] = [
    [82, 84],
    [75, 80],
    [62, 105],
    [52, 140],
    [48, 180],
    [52, 220],
    [62, 255],
    [75, 280],
    [82, 276],
  ];
  const screen = [];
  for (const [t, f] of at) screen.push(await scalpAt(page, t, f));
  const before = await status(page);
  await dragThrough(page, screen);
  await curveCount(page, 1);
  const parted = await settled(page, before.revision);
  console.log(`half-up: the status after the parting: "${parted.text}"`);
  expect(parted.text).toMatch(/c1 splits the scalp: top \d+ %, rest \d+ %/);
  // the Bun tool shows the sections over the hair
  await page.getByRole('button', { name: 'Bun' }).click();
  await page.waitForFunction(() => window.hairsketch.sectionsOverHair() > 0);
  const c = await scalpAt(page, 15, 0);
  await dragThrough(
    page,
    Array.from({ length: 33 }, (_, i) => ({
      x: c.x + 30 * Math.cos((2 * Math.PI * i) / 32),
      y: c.y + 30 * Math.sin((2 * Math.PI * i) / 32),
    })),
  );
  await curveCount(page, 2);
  await settled(page, parted.revision);
  const s = (await page.evaluate(() => window.hairsketch.session())) as {
    curves: { type: string; points: V3[] }[];
  };
  const line = s.curves[0].points;
  const xs = line.map((p) => p[0]);
  const [x0, x1] = [Math.min(...xs) + 0.1, Math.max(...xs) - 0.1];
  const h = await hair(page);
  let top = 0;
  let topIn = 0;
  let rest = 0;
  let restDown = 0;
  roots(h).forEach((r, i) => {
    if (r[0] < x0 || r[0] > x1) return;
    const z = partingZ(line, r[0]);
    if (z === null) return;
    if (r[2] > z + 0.15) {
      top++;
      if (h.tailCurves[i] === 1) topIn++;
    } else if (r[2] < z - 0.15) {
      rest++;
      if (h.tailCurves[i] < 0) restDown++;
    }
  });
  console.log(
    `half-up: ${((100 * topIn) / top).toFixed(1)} % of ${top} strands in front of the parting in the bun, ${((100 * restDown) / rest).toFixed(1)} % of ${rest} behind it down`,
  );
  expect(topIn / top).toBeGreaterThanOrEqual(0.95);
  expect(restDown / rest).toBeGreaterThanOrEqual(0.95);
  await shoot(page, 'ties-half-up-sections');
  await page.getByRole('button', { name: 'Stream curve' }).click();
  await page.waitForFunction(() => window.hairsketch.sectionsOverHair() === 0);
  await shoot(page, 'ties-half-up', 'bust');
});

/** The points of the strands tie `curve` laid, each from its point nearest `band` on (the tail,
 *  not the hair combed to it). */
function tailPoints(h: Hair, curve: number, band: V3): V3[] {
  const out: V3[] = [];
  for (let s = 0; s + 1 < h.strandStart.length; s++) {
    if (h.tailCurves[s] !== curve) continue;
    let nearest = h.strandStart[s];
    let best = Infinity;
    for (let q = h.strandStart[s]; q < h.strandStart[s + 1]; q++) {
      const d = Math.hypot(
        h.points[3 * q] - band[0],
        h.points[3 * q + 1] - band[1],
        h.points[3 * q + 2] - band[2],
      );
      if (d < best) {
        best = d;
        nearest = q;
      }
    }
    for (let q = nearest; q < h.strandStart[s + 1]; q++)
      out.push([h.points[3 * q], h.points[3 * q + 1], h.points[3 * q + 2]]);
  }
  return out;
}

interface Tie {
  type: string;
  points: V3[];
  circles?: { centre: V3 }[];
}

test('a high ponytail in one stroke: the spine lifts off the crown and falls; the tail hangs below its band, centred', async ({
  page,
}) => {
  test.setTimeout(120_000);
  const s0 = await emptyHead(page);
  await view(page, 'l', 'left');
  await page.getByRole('button', { name: 'Ponytail' }).click();
  // from the back of the crown, 1 cm off the middle: up and back, then down behind the head
  const root = await scalpAt(page, 30, 170);
  await dragThrough(page, [
    root,
    { x: root.x + 30, y: root.y - 20 },
    { x: root.x + 60, y: root.y - 8 },
    { x: root.x + 85, y: root.y + 50 },
    { x: root.x + 100, y: root.y + 200 },
    { x: root.x + 95, y: root.y + 330 },
  ]);
  await curveCount(page, 1);
  const s = await settled(page, s0.revision);
  console.log(`high ponytail: "${s.text}"`);
  const tie = ((await page.evaluate(() => window.hairsketch.session())) as { curves: Tie[] })
    .curves[0];
  expect(tie.type).toBe('ponytail');
  // drawn 1 cm off the middle, put on it
  for (const p of tie.points) expect(Math.abs(p[0])).toBeLessThan(1e-6);
  const band = tie.circles?.[0].centre as V3;
  const h = await hair(page);
  const tail = tailPoints(h, 0, band);
  const below = tail.filter((p) => p[1] < band[1]).length / tail.length;
  const meanX = tail.reduce((m, p) => m + p[0], 0) / tail.length;
  const gathered = h.tailCurves.filter((t) => t === 0).length / h.tailCurves.length;
  console.log(
    `high ponytail: ${(100 * gathered).toFixed(1)} % of the strands gathered; ${(100 * below).toFixed(1)} % of the tail below its band (${band.map((x) => x.toFixed(2)).join(', ')}); mean x ${(10 * meanX).toFixed(2)} cm`,
  );
  await page.getByRole('button', { name: 'Stream curve' }).click();
  await shoot(page, 'ties-high-ponytail', 'bust');
  expect(gathered).toBeGreaterThan(0.95);
  expect(below).toBeGreaterThanOrEqual(0.8);
  expect(Math.abs(meanX)).toBeLessThan(0.1);
});
