// The sketching tools end to end, with real pointer strokes (page.mouse down/move/up): hint
// strokes on a stream curve, a dividing curve, a ponytail, the Avoid scalp toggle, and the presets.
// Waits only on the status attributes and the session, never on fixed sleeps.
import { expect, type Page, test } from '@playwright/test';
import { settled as settledAfter } from './helpers';

type V3 = [number, number, number];
interface Curve {
  id: string;
  type: string;
  points: V3[];
  normals?: V3[];
  circles?: { centre: V3; axis: V3; radius: number }[];
  surfaceMode?: string;
  [k: string]: unknown;
}
interface Session {
  curves: Curve[];
  avoidScalp?: boolean;
  selected: string | null;
}

const SCENE = '/?strands=1500';

const session = (page: Page) => page.evaluate(() => window.hairsketch.session() as Session);

function watchConsole(page: Page): string[] {
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(String(e)));
  return errors;
}

/** Ready and idle (solver answered, no stroke, frame drawn) with at least `minStrands` strands
 *  (a bald head, preset=empty, shows none). */
async function settled(page: Page, minStrands = 1): Promise<void> {
  await page.waitForFunction((min) => {
    const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
    return !!el && el.dataset.state === 'ready' && Number(el.dataset.strands) >= min;
  }, minStrands);
  await page.evaluate(() => window.hairsketch.idle());
  await page.waitForFunction(() => {
    const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
    return !!el && el.dataset.state === 'ready';
  });
}

/** Waits until the session's curve `id` has a point count other than `n`, then settles. */
async function pointsChanged(page: Page, id: string, n: number): Promise<Curve> {
  await page.waitForFunction(
    ([cid, count]) => {
      const s = window.hairsketch.session() as Session;
      const c = s.curves.find((x) => x.id === cid);
      return !!c && c.points.length !== count;
    },
    [id, n] as const,
  );
  await settled(page);
  const s = await session(page);
  return s.curves.find((c) => c.id === id) as Curve;
}

async function toScreen(page: Page, p: V3): Promise<{ x: number; y: number }> {
  const s = await page.evaluate((q) => window.hairsketch.worldToScreen(q), p);
  if (!s) throw new Error(`point ${p} is off screen`);
  return s;
}

/** A real drag through screen points (the first is the press). */
async function drag(
  page: Page,
  pts: { x: number; y: number }[],
  button: 'left' | 'right' = 'left',
) {
  await page.mouse.move(pts[0].x, pts[0].y);
  await page.mouse.down({ button });
  for (const p of pts.slice(1)) await page.mouse.move(p.x, p.y);
  await page.mouse.up({ button });
}

const lerp2 = (a: { x: number; y: number }, b: { x: number; y: number }, n: number) =>
  Array.from({ length: n + 1 }, (_, i) => ({
    x: a.x + ((b.x - a.x) * i) / n,
    y: a.y + ((b.y - a.y) * i) / n,
  }));

/** Screen tangent and normal of the curve at point i. */
async function screenFrame(page: Page, c: Curve, i: number) {
  const p = await toScreen(page, c.points[i]);
  const a = await toScreen(page, c.points[Math.max(0, i - 1)]);
  const b = await toScreen(page, c.points[Math.min(c.points.length - 1, i + 1)]);
  const l = Math.hypot(b.x - a.x, b.y - a.y);
  const t = { x: (b.x - a.x) / l, y: (b.y - a.y) / l };
  return { p, t, n: { x: -t.y, y: t.x } };
}

async function scalpPath(page: Page, angles: [number, number][]) {
  const out: { x: number; y: number }[] = [];
  for (const [t, p] of angles) {
    const s = await page.evaluate(([a, b]) => window.hairsketch.scalpToScreen(a, b), [t, p]);
    if (!s) throw new Error(`scalp point (${t}, ${p}) hidden`);
    out.push(s);
  }
  // densify: a move every few pixels, as a hand would
  const dense: { x: number; y: number }[] = [out[0]];
  for (let i = 1; i < out.length; i++) dense.push(...lerp2(out[i - 1], out[i], 6).slice(1));
  return dense;
}

test('a stream curve is edited by hint strokes: concatenate, insert, cut; a stroke that fits none changes nothing', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto(`${SCENE}&preset=empty`);
  await settled(page, 0);
  await page.getByRole('button', { name: 'Stream curve' }).click();
  const start = await page.evaluate(() => window.hairsketch.scalpToScreen(30, 20));
  if (!start) throw new Error('scalp hidden');
  await drag(page, lerp2(start, { x: start.x + 230, y: start.y + 280 }, 40));
  await page.waitForFunction(() => (window.hairsketch.session() as Session).curves.length === 1);
  await settled(page);
  let c = (await session(page)).curves[0];
  expect(c.type).toBe('stream');
  expect((await session(page)).selected).toBe(c.id);
  const n0 = c.points.length;
  expect(n0).toBeGreaterThan(12);

  // the strip mode faces the view the curve was drawn from: hint strokes from this view
  await page.getByRole('button', { name: 'Surface mode' }).click();
  await page.waitForFunction(
    () => (window.hairsketch.session() as Session).curves[0].surfaceMode === 'strip',
  );
  await settled(page);

  // concatenate: from the end, onward along the curve
  {
    const f = await screenFrame(page, c, n0 - 1);
    const from = { x: f.p.x - 3 * f.t.x, y: f.p.y - 3 * f.t.y };
    await drag(page, lerp2(from, { x: f.p.x + 90 * f.t.x, y: f.p.y + 90 * f.t.y }, 20));
    c = await pointsChanged(page, c.id, n0);
    await expect(page.getByTestId('status')).toContainText('Hint: concatenate');
    expect(c.points.length).toBeGreaterThan(n0);
  }
  // insert: from one point of the curve to another, bulging sideways between
  {
    const n1 = c.points.length;
    const i1 = Math.round(n1 * 0.45);
    const i2 = Math.round(n1 * 0.8);
    const a = await screenFrame(page, c, i1);
    const b = await screenFrame(page, c, i2);
    const pts = lerp2(a.p, b.p, 30).map((q, k) => {
      const bulge = 45 * Math.sin((Math.PI * k) / 30);
      return { x: q.x + bulge * a.n.x, y: q.y + bulge * a.n.y };
    });
    await drag(page, pts);
    c = await pointsChanged(page, c.id, n1);
    await expect(page.getByTestId('status')).toContainText('Hint: insert');
    expect(c.points.length).toBeGreaterThan(n1);
  }
  // a stroke beside the curve that never crosses it: no operation, nothing changes
  {
    const n2 = c.points.length;
    const f = await screenFrame(page, c, Math.round(n2 * 0.6));
    const from = { x: f.p.x + 70 * f.n.x, y: f.p.y + 70 * f.n.y };
    await drag(page, lerp2(from, { x: from.x + 40 * f.t.x, y: from.y + 40 * f.t.y }, 12));
    await expect(page.getByTestId('status')).toContainText('Hint: no operation');
    expect((await session(page)).curves[0].points.length).toBe(n2);
  }
  // cut: across the curve, far on both sides
  {
    const n2 = c.points.length;
    const i = Math.round(n2 * 0.6);
    const f = await screenFrame(page, c, i);
    const a = { x: f.p.x - 70 * f.n.x, y: f.p.y - 70 * f.n.y };
    const b = { x: f.p.x + 70 * f.n.x, y: f.p.y + 70 * f.n.y };
    await drag(page, lerp2(a, b, 30));
    c = await pointsChanged(page, c.id, n2);
    await expect(page.getByTestId('status')).toContainText('Hint: cut');
    expect(c.points.length).toBeLessThan(n2);
    expect(Math.abs(c.points.length - (i + 1))).toBeLessThanOrEqual(2);
  }
  // every edit is undoable
  await page.getByRole('button', { name: 'Undo' }).click();
  await page.waitForFunction(
    (n) => (window.hairsketch.session() as Session).curves[0].points.length > n,
    c.points.length,
  );
  expect(errors).toEqual([]);
});

test('a dividing curve parts the hair: roots on its two sides grow to opposite sides', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto(`${SCENE}&preset=empty`);
  await settled(page, 0);
  await page.getByRole('button', { name: 'Dividing curve' }).click();
  const path = await scalpPath(page, [
    [12, 40],
    [25, 40],
    [38, 40],
    [50, 40],
  ]);
  await drag(page, path);
  await page.waitForFunction(() => (window.hairsketch.session() as Session).curves.length === 1);
  await settled(page);
  const s = await session(page);
  const c = s.curves[0];
  expect(c.type).toBe('dividing');
  expect(c.sigma).toBe(1);
  expect(c.h).toBe(0.5);
  expect(c.normals?.length).toBe(c.points.length);
  const result = await page.evaluate(
    (curve) => {
      const st = window.hairsketch.strands();
      if (!st) return null;
      const P = st.points;
      let agree = 0;
      let disagree = 0;
      const sub = (a: number[], b: number[]) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
      const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      const cross = (a: number[], b: number[]) => [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
      ];
      const pts = curve.points;
      for (let s = 0; s + 1 < st.strandStart.length; s++) {
        const k0 = st.strandStart[s];
        const k1 = st.strandStart[s + 1];
        if (k1 - k0 < 6) continue;
        const r = [P[3 * k0], P[3 * k0 + 1], P[3 * k0 + 2]];
        let best = -1;
        let bd = Number.POSITIVE_INFINITY;
        for (let i = 1; i + 1 < pts.length; i++) {
          const d = Math.hypot(...sub(r, pts[i]));
          if (d < bd) {
            bd = d;
            best = i;
          }
        }
        if (best < 0 || bd > 0.35) continue; // about three grid steps
        const across = cross(curve.normals[best], sub(pts[best + 1], pts[best - 1]));
        const side = Math.sign(dot(sub(r, pts[best]), across));
        const k = Math.min(k1 - 1, k0 + 5);
        const grow = Math.sign(dot(sub([P[3 * k], P[3 * k + 1], P[3 * k + 2]], r), across));
        if (side === 0) continue;
        if (grow === side) agree++;
        else disagree++;
      }
      return { agree, disagree };
    },
    c as { points: V3[]; normals: V3[] },
  );
  expect(result).not.toBeNull();
  if (!result) return;
  expect(result.agree).toBeGreaterThan(10);
  expect(result.agree).toBeGreaterThan(6 * result.disagree);

  // a tilt hint: a stroke starting just beside the selected curve, leaving it at a slant
  {
    const i = Math.round(c.points.length * 0.25);
    const f = await screenFrame(page, c, i);
    const from = { x: f.p.x + 10 * f.n.x, y: f.p.y + 10 * f.n.y };
    const to = {
      x: from.x + 50 * f.n.x + 40 * f.t.x,
      y: from.y + 50 * f.n.y + 40 * f.t.y,
    };
    await drag(page, lerp2(from, to, 12));
    await page.waitForFunction(() => {
      const d = (window.hairsketch.session() as Session).curves[0];
      return d.alpha0 !== 0;
    });
    await settled(page);
    await expect(page.getByTestId('status')).toContainText('Tilt: alpha0');
    expect((await session(page)).curves).toHaveLength(1); // no new curve
  }
  // the parameter panel edits σ; undo restores it
  await page.getByLabel('σ (grid steps)').fill('1.5');
  await page.getByLabel('σ (grid steps)').press('Enter');
  await page.waitForFunction(
    () => (window.hairsketch.session() as Session).curves[0].sigma === 1.5,
  );
  await settled(page);
  await page.getByRole('button', { name: 'Undo' }).click();
  await page.waitForFunction(() => (window.hairsketch.session() as Session).curves[0].sigma === 1);
  // Set viewpoint stores the current camera in the selected curve (undoable)
  const vp0 = JSON.stringify((await session(page)).curves[0].viewpoint);
  const box = await page.getByTestId('viewport').boundingBox();
  if (!box) throw new Error('no viewport');
  await drag(
    page,
    lerp2({ x: box.x + 60, y: box.y + 300 }, { x: box.x + 160, y: box.y + 300 }, 8),
    'right',
  );
  await page.getByRole('button', { name: 'Set viewpoint' }).click();
  await page.waitForFunction(
    (v) => JSON.stringify((window.hairsketch.session() as Session).curves[0].viewpoint) !== v,
    vp0,
  );
  await page.getByRole('button', { name: 'Undo' }).click();
  await page.waitForFunction(
    (v) => JSON.stringify((window.hairsketch.session() as Session).curves[0].viewpoint) === v,
    vp0,
  );
  await settled(page);
  expect(errors).toEqual([]);
});

test('a ponytail from four strokes gathers strands through its first cross-section circle', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto(`${SCENE}&preset=empty`);
  await settled(page, 0);
  await page.getByRole('button', { name: 'Ponytail' }).click();
  await expect(page.locator('#hint')).toContainText('spine');
  const start = await page.evaluate(() => window.hairsketch.scalpToScreen(60, 70));
  if (!start) throw new Error('scalp hidden');
  await drag(page, lerp2(start, { x: start.x + 60, y: start.y + 220 }, 40));
  await page.waitForFunction(() => window.hairsketch.ponytailStage() === 'cross');
  await expect(page.locator('#hint')).toContainText('cross-section');
  // orbit a little with the right button, as the paper's user does
  const box = await page.getByTestId('viewport').boundingBox();
  if (!box) throw new Error('no viewport');
  await drag(
    page,
    lerp2({ x: box.x + 40, y: box.y + 200 }, { x: box.x + 80, y: box.y + 200 }, 8),
    'right',
  );
  await page.evaluate(() => window.hairsketch.idle());
  const spine = (await page.evaluate(() => window.hairsketch.ponytailSpine())) as V3[];
  expect(spine.length).toBeGreaterThan(6);
  const sp: Curve = { id: 'spine', type: 'stream', points: spine };
  // cross-section across the spine near its root
  {
    const f = await screenFrame(page, sp, 2);
    await drag(
      page,
      lerp2(
        { x: f.p.x - 40 * f.n.x, y: f.p.y - 40 * f.n.y },
        { x: f.p.x + 40 * f.n.x, y: f.p.y + 40 * f.n.y },
        16,
      ),
    );
  }
  await page.waitForFunction(() => window.hairsketch.ponytailStage() === 'profileA');
  await expect(page.locator('#hint')).toContainText('first profile');
  for (const side of [1, -1]) {
    const pts: { x: number; y: number }[] = [];
    for (let i = 1; i < spine.length; i++) {
      const f = await screenFrame(page, sp, i);
      const w = 32 - (12 * i) / spine.length; // narrowing toward the tip
      pts.push({ x: f.p.x + side * w * f.n.x, y: f.p.y + side * w * f.n.y });
    }
    await drag(page, pts);
  }
  await page.waitForFunction(() => (window.hairsketch.session() as Session).curves.length === 1);
  expect(await page.evaluate(() => window.hairsketch.ponytailStage())).toBe('spine');
  await settled(page);
  const c = (await session(page)).curves[0];
  expect(c.type).toBe('ponytail');
  expect(c.tightness).toBe(0.6);
  const circles = c.circles ?? [];
  expect(circles.length).toBeGreaterThan(1);
  const c1 = circles[0];
  const through = await page.evaluate((circle) => {
    const st = window.hairsketch.strands();
    if (!st) return -1;
    const P = st.points;
    const a = circle.axis;
    const n = Math.hypot(a[0], a[1], a[2]);
    const w = (k: number) =>
      ((P[3 * k] - circle.centre[0]) * a[0] +
        (P[3 * k + 1] - circle.centre[1]) * a[1] +
        (P[3 * k + 2] - circle.centre[2]) * a[2]) /
      n;
    let count = 0;
    for (let s = 0; s + 1 < st.strandStart.length; s++) {
      for (let k = st.strandStart[s]; k + 1 < st.strandStart[s + 1]; k++) {
        const w0 = w(k);
        const w1 = w(k + 1);
        if (w0 > 0 || w1 <= 0) continue; // crossing C1's plane root -> tip
        const f = w0 / (w0 - w1);
        const x = [0, 1, 2].map((ax) => P[3 * k + ax] + f * (P[3 * k + 3 + ax] - P[3 * k + ax]));
        const d = Math.hypot(
          x[0] - circle.centre[0],
          x[1] - circle.centre[1],
          x[2] - circle.centre[2],
        );
        if (d <= circle.radius) {
          count++;
          break;
        }
      }
    }
    return count;
  }, c1);
  expect(through).toBeGreaterThan(20);
  // with no parting the ponytail takes the whole head's hair (sections)
  const gathered = await page.evaluate(() => {
    const st = window.hairsketch.strands();
    if (!st) return 0;
    return st.tailCurves.filter((c) => c === 0).length / (st.strandStart.length - 1);
  });
  console.log(`a ponytail, no parting: ${(100 * gathered).toFixed(1)} % of the strands`);
  expect(gathered).toBeGreaterThanOrEqual(0.95);
  expect(errors).toEqual([]);
});

test('Avoid scalp is a toggle: on, the hair is solved again with it and no strand segment enters the head; undo turns it off', async ({
  page,
}) => {
  const errors = watchConsole(page);
  await page.goto(SCENE);
  const s0 = await settledAfter(page);
  const depth = 0.02; // world units (2 mm): the mesh the roots sit on vs the exact surface
  const before = await page.evaluate((d) => window.hairsketch.segmentsInsideHead(d), depth);
  expect(before.segments).toBeGreaterThan(1000);
  const hashBefore = await page.evaluate(() => window.hairsketch.hairHash());
  const button = page.getByRole('button', { name: 'Avoid scalp' });
  await expect(button).toHaveAttribute('aria-pressed', 'false');
  await button.click();
  await expect(button).toHaveAttribute('aria-pressed', 'true');
  expect((await session(page)).avoidScalp).toBe(true);
  // the hair is re-solved: a newer revision, with other strands
  await settledAfter(page, s0.revision);
  await expect(page.getByTestId('status')).toContainText('Avoid scalp');
  expect(await page.evaluate(() => window.hairsketch.hairHash())).not.toBe(hashBefore);
  const after = await page.evaluate((d) => window.hairsketch.segmentsInsideHead(d), depth);
  console.log(JSON.stringify({ before, after }));
  console.log(
    `segments inside the head: before ${before.inside}/${before.segments} (deepest ${before.deepest.toFixed(3)}), after ${after.inside}/${after.segments} (deepest ${after.deepest.toFixed(3)})`,
  );
  expect(after.segments).toBeGreaterThan(1000);
  expect(after.inside).toBe(0);
  await page.getByRole('button', { name: 'Undo' }).click();
  await expect(button).toHaveAttribute('aria-pressed', 'false');
  await page.waitForFunction(() => !(window.hairsketch.session() as Session).avoidScalp);
  await settled(page);
  await page.waitForFunction((h) => window.hairsketch.hairHash() === h, hashBefore);
  expect(errors).toEqual([]);
});

for (const [name, want] of [
  ['fig6', { stream: 10, dividing: 0, ponytail: 0 }],
  ['fig7', { stream: 7, dividing: 1, ponytail: 0 }],
  ['fig8', { stream: 8, dividing: 0, ponytail: 2 }],
  ['fig1', { stream: 13, dividing: 4, ponytail: 1 }],
] as const) {
  test(`preset ${name} loads to ready with hair and the figure's curves`, async ({ page }) => {
    const errors = watchConsole(page);
    await page.goto(`${SCENE}&preset=${name}`);
    await settled(page);
    const strands = await page
      .getByTestId('status')
      .evaluate((el: HTMLElement) => Number(el.dataset.strands));
    expect(strands).toBeGreaterThan(500);
    const s = await session(page);
    const count = (t: string) => s.curves.filter((c) => c.type === t).length;
    expect({
      stream: count('stream'),
      dividing: count('dividing'),
      ponytail: count('ponytail'),
    }).toEqual(want);
    if (process.env.SHOTS) await page.screenshot({ path: `/tmp/preset-${name}.png` });
    expect(errors).toEqual([]);
  });
}
