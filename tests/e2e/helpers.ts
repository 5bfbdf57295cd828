// Shared Playwright helpers: status attributes, settling, real pointer strokes.
import { expect, type Page } from '@playwright/test';

export interface StatusAttrs {
  state: string;
  strands: number;
  curves: number;
  revision: number;
  text: string;
}

export async function status(page: Page): Promise<StatusAttrs> {
  return page.getByTestId('status').evaluate((el: HTMLElement) => ({
    state: el.dataset.state ?? '',
    strands: Number(el.dataset.strands),
    curves: Number(el.dataset.curves),
    revision: Number(el.dataset.revision),
    text: el.textContent ?? '',
  }));
}

/** Waits until the app is ready and idle with a hair revision past `after`. Polls every 50 ms:
 *  polling at every animation frame (Playwright's default) would make an idle page draw frames
 *  for as long as a solve takes. The hair's full-detail frame is waited for only with `drawn`
 *  (tests that read pixels): SwiftShader takes 0.8 s over it at 3,000 strands, 16 s at 29,000. */
export async function settled(
  page: Page,
  after = -1,
  { drawn = false }: { drawn?: boolean } = {},
): Promise<StatusAttrs> {
  await page.waitForFunction(
    (rev) => {
      const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
      return !!el && el.dataset.state === 'ready' && Number(el.dataset.revision) > rev;
    },
    after,
    { polling: 50 },
  );
  await page.evaluate((d) => window.hairsketch.idle(d), drawn);
  return status(page);
}

export function watchConsole(page: Page): string[] {
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(String(e)));
  return errors;
}

/** Drags the mouse from the scalp point (θ0, φ0) along a screen path, with real events. */
export async function strokeFromScalp(
  page: Page,
  theta: number,
  phi: number,
  dx: number,
  dy: number,
) {
  const start = await page.evaluate(
    ([t, p]) => window.hairsketch.scalpToScreen(t, p),
    [theta, phi],
  );
  expect(start, `scalp point (${theta}, ${phi}) must be visible`).not.toBeNull();
  if (!start) return;
  await page.mouse.move(start.x, start.y);
  await page.mouse.down();
  const n = 24;
  for (let i = 1; i <= n; i++)
    await page.mouse.move(start.x + (dx * i) / n, start.y + (dy * i) / n);
  await page.mouse.up();
}

/** Screen point of the scalp point (θ, φ) in the current view; fails the test when hidden. */
export async function scalpAt(page: Page, theta: number, phi: number) {
  const p = await page.evaluate(([t, f]) => window.hairsketch.scalpToScreen(t, f), [theta, phi]);
  expect(p, `scalp point (${theta}, ${phi}) on screen`).not.toBeNull();
  return p as { x: number; y: number };
}

/** A drag through screen points with real mouse events: each leg in moves of at most 10 px (at
 *  most 24 per leg). Strokes are resampled at the grid's step, far coarser than that, and every
 *  move draws a frame, which costs a software rasteriser ~20 ms. */
export async function dragThrough(page: Page, pts: { x: number; y: number }[]): Promise<void> {
  await page.mouse.move(pts[0].x, pts[0].y);
  await page.mouse.down();
  for (let k = 1; k < pts.length; k++) {
    const dx = pts[k].x - pts[k - 1].x;
    const dy = pts[k].y - pts[k - 1].y;
    const n = Math.min(24, Math.max(1, Math.ceil(Math.hypot(dx, dy) / 10)));
    for (let i = 1; i <= n; i++)
      await page.mouse.move(pts[k - 1].x + (dx * i) / n, pts[k - 1].y + (dy * i) / n);
  }
  await page.mouse.up();
}

/** Client coordinates of the middle point of the first style curve on screen, and its id. */
export async function visibleCurvePoint(page: Page): Promise<{ id: string; x: number; y: number }> {
  const target = await page.evaluate(() => {
    const s = window.hairsketch.session() as {
      curves: { id: string; points: [number, number, number][] }[];
    };
    for (const c of s.curves) {
      const p = window.hairsketch.worldToScreen(c.points[Math.floor(c.points.length / 2)]);
      if (p) return { id: c.id, ...p };
    }
    return null;
  });
  if (!target) throw new Error('no curve on screen');
  return target;
}

/** With SHOT_DIR set, pictures of the hair from the front, the side and the back (for a person
 *  to look at; nothing is compared). */
/** The framing of shoot's pictures: the head (default), or head and shoulders (the bust). */
const FRAMINGS = {
  head: {
    target: [0, -0.6, 0],
    views: [
      ['front', [0.6, 0.6, 7.5]],
      ['side', [7.5, 0.6, -0.4]],
      ['back', [-0.6, 1.2, -7.5]],
    ],
  },
  bust: {
    target: [0, -1.5, 0],
    views: [
      ['front', [0.8, 0.2, 10.5]],
      ['side', [10.5, 0.2, -0.4]],
      ['back', [-0.8, 0.8, -10.5]],
    ],
  },
} as const;

export async function shoot(
  page: Page,
  name: string,
  framing: keyof typeof FRAMINGS = 'head',
): Promise<void> {
  const dir = process.env.SHOT_DIR;
  if (!dir) return;
  const { target, views } = FRAMINGS[framing];
  for (const [view, p] of views) {
    await page.evaluate(
      ([q, t]) =>
        window.hairsketch.setCamera(q as [number, number, number], t as [number, number, number]),
      [p, target],
    );
    await page.evaluate(() => window.hairsketch.idle());
    await page.getByTestId('viewport').screenshot({ path: `${dir}/${name}-${view}.png` });
  }
}

/** The hair drawn, taken out of the page as base64 (window.hairsketch.strandsPacked): the same
 *  arrays as strands() gives, typed. Taking 300,000 numbers as a plain array cost the test
 *  runner about a second of CPU per call in Playwright's protocol checks. */
export interface PageHair {
  points: Float32Array;
  strandStart: Uint32Array;
  tailCurves: Int32Array;
  rootSections: Uint8Array;
}

export async function hairOf(page: Page): Promise<PageHair | null> {
  const h = await page.evaluate(() => window.hairsketch.strandsPacked());
  if (!h) return null;
  const bytes = (b64: string) => {
    const b = Buffer.from(b64, 'base64');
    // a copy on its own buffer, aligned for the typed views
    return new Uint8Array(b).buffer;
  };
  return {
    points: new Float32Array(bytes(h.points)),
    strandStart: new Uint32Array(bytes(h.strandStart)),
    tailCurves: new Int32Array(bytes(h.tailCurves)),
    rootSections: new Uint8Array(bytes(h.rootSections)),
  };
}
