// npm run bench:browser — drives the built app in Debian's Chromium and measures, per grid preset
// and solver: page load -> first hair, five strokes (pointer-up -> first new hair on screen and
// -> the converged field's hair on screen (its first strands, posted before the rest) -> the
// final hair with every strand, preview updates per second while dragging), the wasm heap size,
// and where the time went (the worker's solve, growth and lighting; arrival; geometry build).
// Also, per config: the idle full-hair frame time (the view drawn with every strand, median of
// BENCH_FRAMES frames, GPU work included) and the lighting precompute time of the final hair; and,
// unless BENCH_DENSE=0, the same two for a denser version of the session (roots every 0.55°
// instead of 1°: ~100K strands with the default preset).
// Writes bench-results/browser.{json,md} and prints the table. A benchmark, not a test: it asserts
// nothing about speed. The drag is paced like a hand (a pointer event due every 16 ms; one that
// came late, as the page acknowledges events only between frames, is not followed by a wait).
// Each stroke's row also counts the frames drawn while drawing by where they started (the frame
// cache: cached head and hair / cached head / nothing).
// BENCH_PRESET=<name> opens that preset instead of the default (empty: a new session, with the
// shape rules of docs/natural-fall.md).
// BENCH_DIST=<dir> serves another build (vite build --outDir <dir>) instead of dist/.
// BENCH_QUALITY=fast|high sets the Quality (else the app's Auto) and writes
// bench-results/browser-<quality>.{json,md}.
// BENCH_LABEL=<label> appends -<label> to that name (e.g. before/after runs of one change).
// BENCH_TOOL=Braid draws the strokes with the Braid tool (its previews solve the braid being
// drawn) and writes bench-results/browser-braid.{json,md}.
import { type ChildProcess, spawn } from 'node:child_process';
import { chromium, type Page } from '@playwright/test';
import { writeBenchResults } from './benchResults.mjs';
import { waitServer } from './previewServer';

const PORT = Number(process.env.BENCH_PORT ?? 4190);
const BASE = `http://127.0.0.1:${PORT}`;
const configs = (process.env.BENCH_CONFIGS ?? '25k:fast,50k:fast,250k:fast,25k:exact,50k:exact')
  .split(',')
  .map((c) => {
    const [grid, solver] = c.split(':');
    return { grid, solver };
  });
const STROKES = Number(process.env.BENCH_STROKES ?? 5);
const FRAMES = Number(process.env.BENCH_FRAMES ?? 5);
const DENSE = process.env.BENCH_DENSE !== '0';
const TOOL = process.env.BENCH_TOOL ?? 'Stream curve';
const QUALITY = process.env.BENCH_QUALITY;
const PRESET = process.env.BENCH_PRESET;
const trace = (m: string): void => {
  if (process.env.BENCH_TRACE)
    console.error(`[bench ${new Date().toISOString().slice(11, 23)}] ${m}`);
};

/** Where a revision's time went, from pointer-up: the worker's solve, growth and lighting, the
 *  result's arrival on the page, and its first frame. */
interface Breakdown {
  solveMs: number;
  growMs: number;
  lightMs: number;
  arrivedMs: number;
  buildMs: number;
  shownMs: number;
}

interface StrokeResult {
  firstMs: number | null;
  convergedMs: number | null;
  /** Pointer-up -> the final hair (every strand) reached the screen. */
  fullMs: number | null;
  first: Breakdown | null;
  converged: Breakdown | null;
  full: Breakdown | null;
  /** Medians over the previews shown while drawing. */
  preview: (Omit<Breakdown, 'arrivedMs' | 'shownMs'> & { arrivedToShownMs: number }) | null;
  previewsPerSecond: number;
  method: string;
  /** Frames drawn while the stroke was drawn, by where each started (viewer/frameCache.ts):
   *  from the cached head and hair (only overlays drawn), the cached head, or nothing. */
  frames: { hair: number; static: number; none: number } | null;
}

/** The app's frame counts by source (absent in builds before the frame cache). */
const frameSources = (page: Page) =>
  page.evaluate(() => {
    const api = window.hairsketch as unknown as {
      frameSources?: () => { hair: number; static: number; none: number };
    };
    return api.frameSources ? api.frameSources() : null;
  });

const median = (xs: number[]): number | null => {
  const v = xs.filter((x) => Number.isFinite(x)).sort((a, b) => a - b);
  if (v.length === 0) return null;
  const m = v.length >> 1;
  return v.length % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
};

/** Field-by-field medians of the strokes' breakdowns. */
function medianBreakdown<T extends object>(xs: Array<T | null>): Record<string, number | null> {
  const have = xs.filter((x): x is T => x !== null);
  const out: Record<string, number | null> = {};
  if (have.length === 0) return out;
  for (const k of Object.keys(have[0]))
    out[k] = median(have.map((x) => (x as Record<string, number>)[k]));
  return out;
}

async function settled(page: Page, timeout = 600_000): Promise<void> {
  await page.waitForFunction(
    () => {
      const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
      return !!el && (el.dataset.state === 'ready' || el.dataset.state === 'error');
    },
    null,
    { timeout, polling: 20 },
  );
  await page.evaluate(() => window.hairsketch.idle());
}

/** Strands shown, the idle full-hair frame time and the final hair's lighting precompute time. */
async function frameFigures(
  page: Page,
): Promise<{ strands: number; frameMs: number; lightingMs: number | null }> {
  const strands = Number(await page.getByTestId('status').getAttribute('data-strands'));
  const frameMs = await page.evaluate((n) => window.hairsketch.frameMs(n), FRAMES);
  // the lighting probe exists once the worker precomputes lighting
  const lightingMs = await page.evaluate(() => {
    const api = window.hairsketch as unknown as { lightingMs?: () => number | null };
    return api.lightingMs ? api.lightingMs() : null;
  });
  return { strands, frameMs, lightingMs };
}

/** Replaces the session with a denser growth (roots every `stepDeg`°) and waits for its hair. */
async function densify(page: Page, stepDeg: number): Promise<void> {
  const before = Number(await page.getByTestId('status').getAttribute('data-revision'));
  await page.evaluate((step) => {
    const s = window.hairsketch.session() as { growth: Record<string, number> };
    s.growth.thetaStepDeg = step;
    s.growth.phiStepDeg = step;
    window.hairsketch.replaceSession(s);
  }, stepDeg);
  await page.waitForFunction(
    (r) =>
      Number(document.querySelector('[data-testid="status"]')?.getAttribute('data-revision')) > r,
    before,
    { timeout: 600_000 },
  );
  await settled(page);
}

async function stroke(page: Page, i: number): Promise<StrokeResult> {
  const theta = 28 + 6 * i;
  const phi = -50 + 25 * i;
  const start = await page.evaluate(
    ([t, p]) => window.hairsketch.scalpToScreen(t, p),
    [theta, phi],
  );
  if (!start) throw new Error(`scalp point (${theta}, ${phi}) hidden`);
  const before = await page.evaluate(() => window.hairsketch.hairLog().length);
  await page.mouse.move(start.x, start.y);
  await page.mouse.down();
  const t0 = await page.evaluate(() => performance.now());
  const f0 = await frameSources(page);
  // a hand's pace: move k is due 16 ms after move k − 1 was (about 60 events per second); a
  // move that is late (the page acknowledges each one only when its main thread is free) is not
  // followed by a further wait
  const n = 60;
  const due = Date.now();
  for (let k = 1; k <= n; k++) {
    await page.mouse.move(start.x + ((90 * k) / n) * (i % 2 ? -1 : 1), start.y + (170 * k) / n);
    const wait = due + 16 * k - Date.now();
    if (wait > 0) await page.waitForTimeout(wait);
  }
  const t1 = await page.evaluate(() => performance.now());
  const f1 = await frameSources(page);
  await page.mouse.up();
  trace(`stroke ${i}: pointer up`);
  await settled(page);
  trace(`stroke ${i}: settled`);
  const r = await page.evaluate(
    ([from]) => ({
      log: window.hairsketch.hairLog().slice(from),
      up: window.hairsketch.lastPointerUp(),
      // the solver method is in the status line's details tooltip
      text: (document.querySelector('[data-testid="status"]') as HTMLElement | null)?.title ?? '',
    }),
    [before],
  );
  const duringLog = r.log.filter((e) => e.time > t0 && e.time <= r.up);
  const during = duringLog.length;
  // hair answering the finished stroke: results that reached the page after pointer-up (a
  // preview that arrived before it but was drawn after it does not count)
  const after = r.log.filter((e) => e.time > r.up && e.arrived > r.up);
  const first = after[0];
  // converged: the converged field's hair on screen (its light growth, when the worker posts
  // one, is the first); full: the final hair with every strand
  const converged = after.find((e) => e.converged ?? e.final);
  const full = after.find((e) => e.final);
  type Entry = (typeof r.log)[number];
  const breakdown = (e: Entry | undefined): Breakdown | null =>
    e
      ? {
          solveMs: e.solveMs,
          growMs: e.growMs,
          lightMs: e.lightMs,
          arrivedMs: e.arrived - r.up,
          buildMs: e.buildMs,
          shownMs: e.time - r.up,
        }
      : null;
  const med = (f: (e: Entry) => number) => median(duringLog.map(f)) ?? Number.NaN;
  const preview =
    during > 0
      ? {
          solveMs: med((e) => e.solveMs),
          growMs: med((e) => e.growMs),
          lightMs: med((e) => e.lightMs),
          buildMs: med((e) => e.buildMs),
          arrivedToShownMs: med((e) => e.time - e.arrived),
        }
      : null;
  const method = /(mg-pcg|auto:[a-z-]+|update|refactor|factor|cg|rhs)/.exec(r.text)?.[1] ?? '?';
  return {
    firstMs: first ? first.time - r.up : null,
    convergedMs: converged ? converged.time - r.up : null,
    fullMs: full ? full.time - r.up : null,
    first: breakdown(first),
    converged: breakdown(converged),
    full: breakdown(full),
    preview,
    previewsPerSecond: during / ((t1 - t0) / 1000),
    method,
    frames:
      f0 && f1
        ? { hair: f1.hair - f0.hair, static: f1.static - f0.static, none: f1.none - f0.none }
        : null,
  };
}

async function main(): Promise<void> {
  const server: ChildProcess = spawn(
    'node_modules/.bin/vite',
    [
      'preview',
      '--port',
      String(PORT),
      '--strictPort',
      ...(process.env.BENCH_DIST ? ['--outDir', process.env.BENCH_DIST] : []),
    ],
    { stdio: ['ignore', 'ignore', 'inherit'] },
  );
  server.on('exit', (code) => {
    if (code) console.error(`vite preview exited with code ${code}`);
  });
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    args: [
      '--no-sandbox',
      '--disable-gpu',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      '--no-first-run',
      '--disable-quic',
      '--enable-unsafe-swiftshader',
    ],
  });
  const rows: Array<Record<string, unknown>> = [];
  try {
    await waitServer(BASE);
    trace('server up');
    for (const { grid, solver } of configs) {
      const page = await browser.newPage({ viewport: { width: 1000, height: 750 } });
      await page.goto(`${BASE}/?grid=${grid}&solver=${solver}${PRESET ? `&preset=${PRESET}` : ''}`);
      trace(`${grid} ${solver}: loading`);
      await settled(page);
      if (QUALITY) {
        await page.evaluate((q) => window.hairsketch.setQuality(q as 'fast' | 'high'), QUALITY);
        await page.evaluate(() => window.hairsketch.idle());
      }
      trace('loaded');
      const state = await page.getByTestId('status').getAttribute('data-state');
      const load = await page.evaluate(() => window.hairsketch.hairLog()[0]?.time ?? null);
      if (state === 'error') {
        const text = await page.getByTestId('status').textContent();
        rows.push({ grid, solver, error: text });
        console.log(`${grid} ${solver}: ${text}`);
        await page.close();
        continue;
      }
      const idle = await frameFigures(page);
      trace(`idle frame ${idle.frameMs.toFixed(0)} ms`);
      await page.getByRole('button', { name: TOOL, exact: true }).click();
      await page.evaluate(() => window.hairsketch.idle());
      const strokes: StrokeResult[] = [];
      for (let i = 0; i < STROKES; i++) strokes.push(await stroke(page, i));
      const heap = await page.evaluate(() => window.hairsketch.heapBytes());
      let dense: Awaited<ReturnType<typeof frameFigures>> | null = null;
      if (DENSE) {
        await densify(page, 0.55);
        dense = await frameFigures(page);
        trace(`dense: ${dense.strands} strands, frame ${dense.frameMs.toFixed(0)} ms`);
      }
      const row = {
        grid,
        solver,
        loadToFirstHairMs: load,
        firstHairMedianMs: median(strokes.map((s) => s.firstMs ?? Number.NaN)),
        convergedMedianMs: median(strokes.map((s) => s.convergedMs ?? Number.NaN)),
        fullHairMedianMs: median(strokes.map((s) => s.fullMs ?? Number.NaN)),
        previewsPerSecondMedian: median(strokes.map((s) => s.previewsPerSecond)),
        framesWhileDrawing: strokes.map((s) => s.frames),
        heapMB: heap / 2 ** 20,
        strands: idle.strands,
        idleFrameMs: idle.frameMs,
        lightingMs: idle.lightingMs,
        denseStrands: dense?.strands ?? null,
        denseIdleFrameMs: dense?.frameMs ?? null,
        denseLightingMs: dense?.lightingMs ?? null,
        methods: strokes.map((s) => s.method),
        firstBreakdown: medianBreakdown(strokes.map((s) => s.first)),
        convergedBreakdown: medianBreakdown(strokes.map((s) => s.converged)),
        fullBreakdown: medianBreakdown(strokes.map((s) => s.full)),
        previewBreakdown: medianBreakdown(strokes.map((s) => s.preview)),
        strokes,
      };
      rows.push(row);
      console.log(JSON.stringify(row));
      await page.close();
    }
  } finally {
    await browser.close();
    server.kill();
  }
  const f = (x: unknown) => (typeof x === 'number' ? x.toFixed(x < 10 ? 1 : 0) : String(x ?? '—'));
  const out: string[] = [
    '| grid | solver | load → first hair ms | pointer-up → first new hair ms (median) | → converged ms (median) | → full hair ms (median) | previews/s while drawing | wasm heap MB | strands | idle full-hair frame ms | lighting precompute ms | dense strands | dense frame ms | dense lighting ms |',
    '| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |',
  ];
  for (const r of rows)
    out.push(
      r.error
        ? `| ${r.grid} | ${r.solver} | ${String(r.error).slice(0, 80)} | | | | | | | | | | | |`
        : `| ${r.grid} | ${r.solver} | ${f(r.loadToFirstHairMs)} | ${f(r.firstHairMedianMs)} | ${f(r.convergedMedianMs)} | ${f(r.fullHairMedianMs)} | ${f(r.previewsPerSecondMedian)} | ${f(r.heapMB)} | ${f(r.strands)} | ${f(r.idleFrameMs)} | ${f(r.lightingMs)} | ${f(r.denseStrands)} | ${f(r.denseIdleFrameMs)} | ${f(r.denseLightingMs)} |`,
    );
  const b = (x: unknown) =>
    Object.entries((x ?? {}) as Record<string, number | null>)
      .map(([k, v]) => `${k.replace(/Ms$/, '')} ${f(v)}`)
      .join(', ');
  out.push(
    '',
    'Where the time went (ms, medians over the strokes; from pointer-up for first/converged):',
    '',
  );
  for (const r of rows)
    if (!r.error)
      out.push(
        `- ${r.grid} ${r.solver}: first look: ${b(r.firstBreakdown)}; converged: ${b(r.convergedBreakdown)}; full hair: ${b(r.fullBreakdown)}; previews: ${b(r.previewBreakdown)}`,
      );
  console.log(`\n${out.join('\n')}`);
  const name = TOOL === 'Braid' ? 'browser-braid' : 'browser';
  const label = process.env.BENCH_LABEL ? `-${process.env.BENCH_LABEL}` : '';
  writeBenchResults(`${QUALITY ? `${name}-${QUALITY}` : name}${label}`, {
    title: 'Browser: from a stroke to hair on screen, per grid and solver',
    script: 'scripts/bench-browser.ts',
    command: 'npm run bench:browser',
    measures:
      "The built app in Debian's Chromium (headless, software WebGL through SwiftShader), " +
      `${PRESET ? `the ${PRESET} preset` : 'default preset'}, ${STROKES} strokes per configuration drawn at a hand's pace with the ` +
      `${TOOL} tool. Per ` +
      'configuration: page load → first hair; pointer-up → first new hair, → the converged ' +
      "field's hair, → the final hair with every strand (medians, from the page's data-revision " +
      'stamps taken when drawn); preview updates per second while drawing; the wasm heap; the ' +
      `idle frame with every strand (median of ${FRAMES}, GPU work included) and the lighting ` +
      'precompute, for the session and (unless BENCH_DENSE=0) a denser one with roots every ' +
      "0.55°; and where the time went (the worker's solve, growth, lighting, arrival, geometry " +
      'build, on screen).',
    config: {
      configs,
      strokes: STROKES,
      frames: FRAMES,
      dense: DENSE,
      tool: TOOL,
      dist: process.env.BENCH_DIST ?? 'dist',
      label: process.env.BENCH_LABEL ?? null,
      preset: PRESET ?? 'default',
    },
    results: rows,
    table: out.join('\n'),
  });
}

await main();
