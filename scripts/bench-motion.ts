// npm run bench:motion — playback of a motion in the built app, in Debian's Chromium: for the
// `long` preset grown at 3,000, 30,000 and 100,000 strands (BENCH_MOTION_STRANDS=a,b,… overrides),
// Head turn is played with a real click on Play for BENCH_MOTION_SECONDS (8) seconds, and the app's
// own readout (window.hairsketch.motion(), docs/testing.md) gives: the time from the click to the
// first moving frame on screen, frames drawn a second, the motion's frames advanced a second, the
// strands drawn in the last frame against the groom's and every how many of their points, and
// (medians of samples every 250 ms) the page's wait for a frame (workerMs), the worker's own step
// (stepMs) and the page's geometry time (buildMs). Then Stop. BENCH_DIST=<dir> measures another
// build (before and after in one run). Writes bench-results/motion.json and .md
// (BENCH_LABEL=<label>: motion-<label>) and prints the table. A benchmark, not a test: it asserts
// nothing about speed.
import { resolve } from 'node:path';
import type { Page } from '@playwright/test';
import { presetSession } from '../web/cli/presetSession';
import { Head } from '../web/head/head';
import { growthForStrands } from '../web/ui/detailPanel';
import { writeBenchResults } from './benchResults.mjs';
import { openWhenHairReady, previewAndBrowser, waitServer } from './previewServer';

const PORT = Number(process.env.BENCH_PORT ?? 4192);
const BASE = `http://127.0.0.1:${PORT}`;
const COUNTS = (process.env.BENCH_MOTION_STRANDS ?? '3000,30000,100000').split(',').map(Number);
const SECONDS = Number(process.env.BENCH_MOTION_SECONDS ?? 8);
const LABEL = process.env.BENCH_LABEL;

const median = (v: number[]): number => {
  if (v.length === 0) return Number.NaN;
  const s = [...v].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};

type Motion = ReturnType<Window['hairsketch']['motion']>;
const motionOf = (page: Page): Promise<Motion> => page.evaluate(() => window.hairsketch.motion());

async function playOnce(page: Page, strands: number) {
  const session = presetSession('long', Head.builtin(), '25k');
  const growth = { ...session.growth, ...growthForStrands(strands) };
  await page.evaluate((s) => window.hairsketch.replaceSession(s), { ...session, growth });
  await page.waitForFunction(
    (n) => {
      const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
      return !!el && el.dataset.state === 'ready' && Number(el.dataset.strands) >= 0.9 * n;
    },
    strands,
    { timeout: 600_000, polling: 100 },
  );
  await page.evaluate(() => window.hairsketch.idle(true));
  await page.getByLabel('Motion').selectOption('head-turn');
  const t0 = Date.now();
  await page.getByRole('button', { name: 'Play' }).click();
  await page.waitForFunction(
    () => {
      const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
      return !!el && !!el.dataset.motion && Number(el.dataset.motionFrame) >= 1;
    },
    null,
    { timeout: 120_000, polling: 10 },
  );
  const firstFrameMs = Date.now() - t0;
  const first = await motionOf(page);
  const worker: number[] = [];
  const step: number[] = [];
  const build: number[] = [];
  const end = Date.now() + SECONDS * 1000;
  let last = first;
  while (Date.now() < end) {
    await page.waitForTimeout(250);
    last = await motionOf(page);
    if (last.workerMs > 0) worker.push(last.workerMs);
    if (last.buildMs > 0) build.push(last.buildMs);
    // (builds before the worker reported its own time have no stepMs)
    if (last.stepMs > 0) step.push(last.stepMs);
  }
  const elapsed = (Date.now() - t0) / 1000;
  await page.getByRole('button', { name: 'Stop' }).click();
  return {
    strands: last.strands,
    firstFrameMs,
    framesDrawnPerSecond: last.fps,
    motionFramesPerSecond: last.frame / elapsed,
    drawnStrands: last.drawnStrands,
    workerMs: median(worker),
    stepMs: median(step),
    buildMs: median(build),
    rebuilds: last.rebuilds,
    pointStride: last.pointStride ?? 1,
  };
}

async function main(): Promise<void> {
  // the headless shell, as the figures in bench-results/motion.md were measured with
  process.env.CHROMIUM_PATH ??= '/usr/lib/chromium/chromium-headless-shell';
  const { server, browser } = await previewAndBrowser(
    resolve(process.env.BENCH_DIST ?? 'dist'),
    PORT,
  );
  const rows: Awaited<ReturnType<typeof playOnce>>[] = [];
  try {
    await waitServer(BASE);
    for (const n of COUNTS) {
      const page = await openWhenHairReady(browser, `${BASE}/?preset=long`);
      const r = await playOnce(page, n);
      rows.push(r);
      console.log(
        `${n} strands asked (${r.strands} grown): first frame ${r.firstFrameMs} ms after Play; ${r.framesDrawnPerSecond.toFixed(2)} frames drawn a second (motion ${r.motionFramesPerSecond.toFixed(2)} frames a second); last frame drew ${r.drawnStrands} strands; worker ${r.workerMs.toFixed(0)} ms, geometry ${r.buildMs.toFixed(0)} ms a frame (medians)`,
      );
      await page.close();
    }
  } finally {
    await browser.close();
    server.kill();
  }
  const table = [
    '| strands | first frame after Play (ms) | frames drawn / s | motion frames / s | strands drawn | every how many points | wait for the worker, ms / frame | worker step, ms / frame | page geometry ms / frame |',
    '| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |',
    ...rows.map(
      (r) =>
        `| ${r.strands} | ${r.firstFrameMs} | ${r.framesDrawnPerSecond.toFixed(2)} | ${r.motionFramesPerSecond.toFixed(2)} | ${r.drawnStrands} | ${r.pointStride} | ${r.workerMs.toFixed(0)} | ${Number.isNaN(r.stepMs) ? '-' : r.stepMs.toFixed(1)} | ${r.buildMs.toFixed(0)} |`,
    ),
  ].join('\n');
  console.log(table);
  writeBenchResults(LABEL ? `motion-${LABEL}` : 'motion', {
    title: 'Motion playback: Head turn on the long preset',
    script: 'scripts/bench-motion.ts',
    command: 'npm run bench:motion',
    measures:
      "Per strand count: ms from the click on Play to the first moving frame drawn; frames drawn a second and motion frames advanced a second over the run; the strands the last frame drew and every how many of their points; medians, sampled every 250 ms (window.hairsketch.motion()), of the page's wait for a frame from the worker, the worker's own step time and the page's geometry (or guide upload) time per frame.",
    config: {
      counts: COUNTS,
      seconds: SECONDS,
      preset: 'long',
      motion: 'head-turn',
      dist: process.env.BENCH_DIST ?? 'dist',
    },
    results: rows,
    table,
  });
}

await main();
