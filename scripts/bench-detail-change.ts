// npm run bench:detail-change — from a whole-head detail change in the Hair panel to the hair on
// screen, at ~30K strands (the default preset's 1° sampling) and 100K (typed into the panel's
// Strands box). The change is made as a user makes it: the panel's "Curl radius" (or, with
// BENCH_DETAIL=clump, "Clump factor") box is filled and Enter pressed; the clock starts at the
// input's change event (a capturing listener on the document, performance.now()) and stops when
// a frame first drew the new hair (window.hairsketch.hairLog(), performance.now() too): the first
// hair shown after the change and the final hair (every strand); and, as the app draws a sample
// of the hair's segments while busy on a slow GPU (hairDetail < 1: SwiftShader here), the first
// frame after it that drew every segment. BENCH_CHANGES changes per strand count (default 5),
// each to a new value. Writes bench-results/detail-change.{json,md} and prints the table. A
// benchmark, not a test: it asserts nothing about speed.
// BENCH_STRANDS=default,100000 overrides the strand counts ('default': the preset's own);
// BENCH_DIST=<dir> serves another build than dist/.
import { resolve } from 'node:path';
import type { Page } from '@playwright/test';
import { writeBenchResults } from './benchResults.mjs';
import { previewAndBrowser, revision, settled, waitServer } from './previewServer';

const PORT = Number(process.env.BENCH_PORT ?? 4192);
const BASE = `http://127.0.0.1:${PORT}`;
const COUNTS = (process.env.BENCH_STRANDS ?? 'default,100000').split(',');
const CHANGES = Number(process.env.BENCH_CHANGES ?? 5);
const DETAIL = process.env.BENCH_DETAIL === 'clump' ? 'clump' : 'curl';
/** The block's checkbox, the box changed and the values typed into it, in turn. */
const CONTROL =
  DETAIL === 'clump'
    ? { block: 'Clump', input: 'Clump factor', values: [0.5, 0.6, 0.7, 0.8, 0.9, 0.4, 0.3] }
    : { block: 'Curl', input: 'Curl radius', values: [1.5, 2, 2.5, 3, 3.5, 4, 4.5] };
const trace = (m: string): void => {
  if (process.env.BENCH_TRACE)
    console.error(`[bench ${new Date().toISOString().slice(11, 23)}] ${m}`);
};

interface Sample {
  value: number;
  /** Change event -> the first new hair drawn, and -> the final hair (every strand) drawn. */
  firstMs: number | null;
  finalMs: number | null;
  /** Change event -> the first frame after the final hair's that drew every segment of it (on a
   *  slow GPU the app draws a sample of the segments while busy; the final hair's first frame
   *  can be one of those). */
  fullMs: number | null;
  /** Hair revisions drawn between the change and the final hair (itself included). */
  revisions: number;
  /** The final hair's times: the worker's solve, growth and lighting, its arrival on the page
   *  (from the change) and the main thread's geometry build. */
  final: {
    solveMs: number;
    growMs: number;
    lightMs: number;
    arrivedMs: number;
    buildMs: number;
  } | null;
  strands: number;
  /** Playwright's fill and Enter: from asking for them to the change event. */
  fillMs: number;
  /** From the change event until the page was ready and idle again with the hair drawn in full
   *  (as the benchmark waits before the next change). */
  idleMs: number;
}

const median = (xs: Array<number | null>): number | null => {
  const v = xs.filter((x): x is number => x !== null && Number.isFinite(x)).sort((a, b) => a - b);
  if (v.length === 0) return null;
  const m = v.length >> 1;
  return v.length % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
};

const strandsShown = async (page: Page) =>
  Number(await page.getByTestId('status').getAttribute('data-strands'));

/** Waits until the app is settled past `after` and its last frame drew every segment of the
 *  hair (the full-detail frame that follows a settled view drawn at interactive detail on a
 *  slow GPU; idle() does not wait for it, and it can hold the main thread for seconds). */
async function settledInFull(page: Page, after: number): Promise<void> {
  await settled(page, after);
  await page.waitForFunction(() => window.hairsketch.hairDetail() === 1, null, {
    timeout: 300_000,
    polling: 50,
  });
  await page.evaluate(() => window.hairsketch.idle());
}

/** Fills a box of the Hair panel, presses Enter (the box commits on change) and waits for the
 *  hair that answers it, drawn in full. */
async function commit(page: Page, name: string, text: string): Promise<void> {
  const before = await revision(page);
  const box = page
    .getByRole('region', { name: 'Hair detail' })
    .getByRole('spinbutton', { name, exact: true });
  await box.fill(text);
  await box.press('Enter');
  await settledInFull(page, before);
}

/** Watches, at every animation frame, the share of the hair's segments the last frame drew
 *  (hairDetail: below 1 while the app is busy on a slow GPU): window.benchDetail gets [time,
 *  share] at each frame where it changed. A string: tsx would wrap a named function passed to
 *  evaluate in a helper the page does not have. */
const WATCH_DETAIL = `(() => {
  const w = window;
  w.benchDetail = [];
  w.benchWatch = true;
  let last = -1;
  const tick = () => {
    if (!w.benchWatch) return;
    const d = w.hairsketch.hairDetail();
    if (d !== last) w.benchDetail.push([performance.now(), d]);
    last = d;
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
  return performance.now();
})()`;

async function change(page: Page, value: number): Promise<Sample> {
  await page.evaluate(() => {
    (window as unknown as { benchChangeAt: number }).benchChangeAt = Number.NaN;
  });
  const start = (await page.evaluate(WATCH_DETAIL)) as number;
  await commit(page, CONTROL.input, String(value));
  const r = await page.evaluate(() => {
    const w = window as unknown as {
      benchChangeAt: number;
      benchDetail: [number, number][];
      benchWatch: boolean;
    };
    w.benchWatch = false;
    return {
      t0: w.benchChangeAt,
      log: window.hairsketch.hairLog(),
      detail: w.benchDetail,
      idle: performance.now(),
    };
  });
  if (!Number.isFinite(r.t0)) throw new Error(`no change event from ${CONTROL.input}`);
  // hair that answers the change: results that reached the page after it
  const after = r.log.filter((e) => e.arrived >= r.t0 && e.time >= r.t0);
  const first = after[0];
  const k = after.findIndex((e) => e.final);
  const final = k >= 0 ? after[k] : undefined;
  // the first frame after the final hair's with every segment drawn (found at the next
  // animation frame: late by up to a frame)
  let fullMs: number | null = null;
  if (final) {
    const later = r.detail.filter(([t]) => t > final.time);
    const full = later.find(([, d]) => d === 1);
    const before = r.detail.filter(([t]) => t <= final.time).at(-1)?.[1] ?? 1;
    if (full) fullMs = full[0] - r.t0;
    else if (later.length === 0 && before === 1) fullMs = final.time - r.t0;
  }
  return {
    value,
    firstMs: first ? first.time - r.t0 : null,
    finalMs: final ? final.time - r.t0 : null,
    fullMs,
    revisions: k + 1,
    fillMs: r.t0 - start,
    idleMs: r.idle - r.t0,
    final: final
      ? {
          solveMs: final.solveMs,
          growMs: final.growMs,
          lightMs: final.lightMs,
          arrivedMs: final.arrived - r.t0,
          buildMs: final.buildMs,
        }
      : null,
    strands: await strandsShown(page),
  };
}

async function main(): Promise<void> {
  const { server, browser } = await previewAndBrowser(
    resolve(process.env.BENCH_DIST ?? 'dist'),
    PORT,
  );
  server.on('exit', (code) => {
    if (code) console.error(`vite preview exited with code ${code}`);
  });
  const rows: Array<Record<string, unknown>> = [];
  try {
    await waitServer(BASE);
    for (const count of COUNTS) {
      const page = await browser.newPage({ viewport: { width: 1000, height: 750 } });
      await page.goto(`${BASE}/?preset=default`);
      if ((await settled(page)) === 'error') {
        const text = await page.getByTestId('status').textContent();
        rows.push({ count, error: text });
        console.log(`${count}: ${text}`);
        await page.close();
        continue;
      }
      await page.getByRole('button', { name: 'Detail' }).click();
      await page.getByRole('region', { name: 'Hair detail' }).waitFor();
      if (count !== 'default') {
        trace(`${count}: strands`);
        await commit(page, 'Strands', count);
      }
      // the whole head's curl (or clump) on, then changed CHANGES times
      trace(`${count}: ${CONTROL.block} on`);
      const before = await revision(page);
      await page
        .getByRole('region', { name: 'Hair detail' })
        .getByRole('checkbox', { name: CONTROL.block, exact: true })
        .check();
      await settledInFull(page, before);
      await page.evaluate(() => {
        document.addEventListener(
          'change',
          () => {
            (window as unknown as { benchChangeAt: number }).benchChangeAt = performance.now();
          },
          { capture: true },
        );
      });
      const samples: Sample[] = [];
      for (let i = 0; i < CHANGES; i++) {
        const s = await change(page, CONTROL.values[i % CONTROL.values.length]);
        trace(`${count}: ${CONTROL.input} ${s.value}: final ${s.finalMs?.toFixed(0)} ms`);
        samples.push(s);
      }
      const row = {
        count,
        strands: samples[0]?.strands ?? (await strandsShown(page)),
        control: CONTROL.input,
        firstMedianMs: median(samples.map((s) => s.firstMs)),
        finalMedianMs: median(samples.map((s) => s.finalMs)),
        fullDetailMedianMs: median(samples.map((s) => s.fullMs)),
        finalBreakdown: {
          solveMs: median(samples.map((s) => s.final?.solveMs ?? null)),
          growMs: median(samples.map((s) => s.final?.growMs ?? null)),
          lightMs: median(samples.map((s) => s.final?.lightMs ?? null)),
          arrivedMs: median(samples.map((s) => s.final?.arrivedMs ?? null)),
          buildMs: median(samples.map((s) => s.final?.buildMs ?? null)),
        },
        samples,
      };
      rows.push(row);
      console.log(JSON.stringify(row));
      await page.close();
    }
  } finally {
    await browser.close();
    server.kill();
  }
  const f = (x: unknown) => (typeof x === 'number' ? x.toFixed(0) : String(x ?? '—'));
  const out: string[] = [
    '| strands | change | → first hair ms (median) | → final hair ms (median) | final hair ms, every change | → final hair with every segment drawn ms (median) | every segment, every change | revisions drawn | → ready and idle ms (median) | fill + Enter → change event ms (median) |',
    '| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |',
  ];
  for (const r of rows) {
    if (r.error) {
      out.push(`| ${r.count} | ${String(r.error).slice(0, 80)} | | | | | | | | |`);
      continue;
    }
    const s = r.samples as Sample[];
    out.push(
      `| ${f(r.strands)} | ${r.control} | ${f(r.firstMedianMs)} | ${f(r.finalMedianMs)} | ${s.map((x) => f(x.finalMs)).join(', ')} | ${f(r.fullDetailMedianMs)} | ${s.map((x) => f(x.fullMs)).join(', ')} | ${s.map((x) => x.revisions).join(', ')} | ${f(median(s.map((x) => x.idleMs)))} | ${f(median(s.map((x) => x.fillMs)))} |`,
    );
  }
  out.push('', 'Where the final hair’s time went (ms, medians; arrived: from the change):', '');
  for (const r of rows)
    if (!r.error)
      out.push(
        `- ${f(r.strands)} strands: ${Object.entries(
          r.finalBreakdown as Record<string, number | null>,
        )
          .map(([k, v]) => `${k.replace(/Ms$/, '')} ${f(v)}`)
          .join(', ')}`,
      );
  console.log(`\n${out.join('\n')}`);
  writeBenchResults('detail-change', {
    title: 'Hair panel: from a whole-head detail change to the hair on screen',
    script: 'scripts/bench-detail-change.ts',
    command: 'npm run bench:detail-change',
    measures:
      "The built app in Debian's Chromium (headless, software WebGL through SwiftShader), " +
      'default preset, at its own ~30K strands and at 100K (typed into the Hair panel’s Strands ' +
      `box). With the whole head's ${DETAIL} on, ${CHANGES} changes of the panel's ` +
      `"${CONTROL.input}" box (filled, Enter), each to a new value; per change, from the box's ` +
      'change event to the first new hair drawn and to the final hair (every strand) drawn ' +
      "(the page's hairLog, performance.now()), to the first frame after that which drew every " +
      'segment (the app draws a sample of them while busy on a slow GPU; found by watching ' +
      'hairDetail() at every animation frame: late by up to a frame), and where the final ' +
      "hair's time went (the worker's solve, growth and lighting, arrival on the page, " +
      'geometry build). Also per change, medians: from the change event until the page is ' +
      'ready and idle again with the full-detail frame drawn (as the benchmark waits before ' +
      "the next change), and Playwright's fill and Enter up to the change event (not part of " +
      'the figures above).',
    config: {
      counts: COUNTS,
      changes: CHANGES,
      control: CONTROL,
      dist: process.env.BENCH_DIST ?? 'dist',
    },
    results: rows,
    table: out.join('\n'),
  });
}

await main();
