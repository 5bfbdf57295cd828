// The hair takes the shape the stylist draws (issue 48, docs/natural-fall.md "Shape"): the
// gestures that showed each fault, drawn with real pointer events on an empty head at 1280x800,
// measured from the strands. Every figure is printed; waits on the status attributes only.
import { writeFileSync } from 'node:fs';
import { expect, type Page, test } from '@playwright/test';
import { headSdf } from '../../web/head/headSdf';
import { settled, shoot, status } from './helpers';

test.use({ viewport: { width: 1280, height: 800 } });

type V3 = [number, number, number];
interface Strands {
  points: number[];
  strandStart: number[];
}
interface Curve {
  type: string;
  points: V3[];
}

const strands = (page: Page) =>
  page.evaluate(() => {
    const s = window.hairsketch.strands();
    if (!s) throw new Error('no hair');
    return { points: Array.from(s.points), strandStart: Array.from(s.strandStart) };
  }) as Promise<Strands>;

const curves = async (page: Page) =>
  ((await page.evaluate(() => window.hairsketch.session())) as { curves: Curve[] }).curves;

async function scalpAt(page: Page, theta: number, phi: number) {
  const p = await page.evaluate(([t, f]) => window.hairsketch.scalpToScreen(t, f), [theta, phi]);
  expect(p, `scalp point (${theta}, ${phi}) on screen`).not.toBeNull();
  return p as { x: number; y: number };
}

/** A drag from `a` in `moves` equal mouse moves of (dx, dy) each. */
async function dragBy(page: Page, a: { x: number; y: number }, moves: number, dx: number, dy: number) {
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  for (let i = 1; i <= moves; i++) await page.mouse.move(a.x + dx * i, a.y + dy * i);
  await page.mouse.up();
}

async function emptyHead(page: Page, opts: { mirror?: boolean; view?: string } = {}) {
  await page.goto('/?preset=empty&strands=6000');
  await settled(page);
  if (opts.mirror) await page.getByRole('button', { name: 'Mirror' }).click();
  if (opts.view) {
    await page.keyboard.press(opts.view);
    await page.evaluate(() => window.hairsketch.idle());
  }
  await page.getByRole('button', { name: 'Stream curve' }).click();
  return (await status(page)).revision;
}

/** With SHOT_DIR set, the pictures (helpers.ts shoot) and the session drawn, as a file. */
async function keep(page: Page, name: string) {
  await shoot(page, name);
  const dir = process.env.SHOT_DIR;
  if (!dir) return;
  const { camera: _c, selected: _s, ...session } = (await page.evaluate(() =>
    window.hairsketch.session(),
  )) as Record<string, unknown>;
  writeFileSync(`${dir}/${name}.json`, JSON.stringify(session));
}

const median = (v: number[]) => {
  const s = [...v].sort((a, b) => a - b);
  return s.length ? s[Math.floor(s.length / 2)] : Number.NaN;
};

function eachStrand(s: Strands, f: (pts: V3[]) => void) {
  for (let k = 0; k + 1 < s.strandStart.length; k++) {
    const pts: V3[] = [];
    for (let p = s.strandStart[k]; p < s.strandStart[k + 1]; p++)
      pts.push([s.points[3 * p], s.points[3 * p + 1], s.points[3 * p + 2]]);
    if (pts.length > 1) f(pts);
  }
}

const dist = (a: V3, b: V3) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

test('two short spikes up and away lift their own hair only', async ({ page }) => {
  let rev = await emptyHead(page, { view: 'l' });
  const centre = { x: 655, y: 370 };
  for (const [t, f] of [
    [30, 8],
    [70, 172],
  ]) {
    const a = await scalpAt(page, t, f);
    // away from the head's middle on screen, leaning back (the back is to the right)
    let ux = a.x - centre.x;
    let uy = a.y - centre.y;
    const n = Math.hypot(ux, uy);
    ux = ux / n + 0.35;
    uy /= n;
    const m = Math.hypot(ux, uy);
    await dragBy(page, a, 27, (5 * ux) / m, (5 * uy) / m);
    rev = (await settled(page, rev)).revision;
  }
  const cs = await curves(page);
  expect(cs.length).toBe(2);
  const starts = cs.map((c) => c.points[0]);
  const angles: number[] = [];
  let above = 0;
  eachStrand(await strands(page), (pts) => {
    if (starts.some((q) => dist(q, pts[0]) <= 0.4)) return;
    const r = pts[0];
    const t = pts[pts.length - 1];
    const v: V3 = [t[0] - r[0], t[1] - r[1], t[2] - r[2]];
    angles.push((Math.acos(Math.max(-1, Math.min(1, -v[1] / Math.hypot(...v)))) * 180) / Math.PI);
    if (t[1] > r[1]) above++;
  });
  const med = median(angles);
  const share = above / angles.length;
  console.log(
    `spikes: strands 4+ cm from both: ${angles.length}, median angle from down ${med.toFixed(1)} deg, ${(100 * share).toFixed(1)} % end above their root`,
  );
  await keep(page, 'shape-spikes');
  expect(med).toBeLessThanOrEqual(35);
  expect(share).toBeLessThanOrEqual(0.1);
});

test('a stroke down beside the face leaves the eyes clear', async ({ page }) => {
  const rev = await emptyHead(page, { mirror: true });
  const a = await scalpAt(page, 45, 70);
  await dragBy(page, a, 30, 1.5, 5);
  await settled(page, rev);
  let over = 0;
  let n = 0;
  eachStrand(await strands(page), (pts) => {
    n++;
    if (pts.some(([x, y, z]) => Math.abs(x) < 0.45 && y > -0.95 && y < -0.05 && z > 0.55)) over++;
  });
  console.log(`face: ${(100 * (over / n)).toFixed(2)} % of ${n} strands cross the face`);
  await keep(page, 'shape-face');
  expect(over / n).toBeLessThanOrEqual(0.01);
});
