// npm run bench:settle — what the page does after the view stops moving, at full strand density:
// on a software rasteriser the hair is drawn at interactive detail while things move and in full
// once they stop, and that full-detail frame takes seconds. An orbit (a right-drag of 80 px) is
// made with real pointer events; from the button's release the benchmark records every animation
// frame the page runs (requestAnimationFrame timestamps) until the hair is drawn in full
// (hairDetail() 1, no holds): the longest gap between frames (how long the page could not paint:
// a freeze) and the time to the full-detail frame. BENCH_RUNS orbits (default 5) per preset
// (BENCH_PRESETS, default 'default,long'); BENCH_DIST=a,b measures several builds in one run
// (before and after). Writes bench-results/settle.{json,md}. A benchmark, not a test.
import { resolve } from 'node:path';
import { writeBenchResults } from './benchResults.mjs';
import { previewAndBrowser, settled, waitServer } from './previewServer';

const PORT = Number(process.env.BENCH_PORT ?? 4194);
const BASE = `http://127.0.0.1:${PORT}`;
const RUNS = Number(process.env.BENCH_RUNS ?? 5);
const PRESETS = (process.env.BENCH_PRESETS ?? 'default,long').split(',');
const DISTS = (process.env.BENCH_DIST ?? 'dist').split(',').map((d) => resolve(d));

const median = (a: number[]) => {
  const s = [...a].sort((x, y) => x - y);
  return s.length ? s[Math.floor(s.length / 2)] : Number.NaN;
};

const rows: Record<string, string | number>[] = [];
for (const dist of DISTS) {
  const { server, browser } = await previewAndBrowser(dist, PORT);
  try {
    await waitServer(BASE);
    for (const preset of PRESETS) {
      const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
      await page.goto(preset === 'default' ? `${BASE}/` : `${BASE}/?preset=${preset}`);
      await settled(page);
      const full = () =>
        page.waitForFunction(
          () => window.hairsketch.hairDetail() === 1 && window.hairsketch.viewHolds().length === 0,
          null,
          { timeout: 300_000, polling: 50 },
        );
      await full();
      // a string: a function declared inside an evaluated arrow gets tsx's __name helper
      await page.evaluate(
        'window.frames_ = []; (function tick() { window.frames_.push(performance.now()); requestAnimationFrame(tick); })();',
      );
      const gaps: number[] = [];
      const fulls: number[] = [];
      for (let i = 0; i < RUNS; i++) {
        await page.mouse.move(640, 400);
        await page.mouse.down({ button: 'right' });
        for (let k = 1; k <= 10; k++) await page.mouse.move(640 + (i % 2 ? -8 : 8) * k, 400);
        const up = await page.evaluate(() => {
          (window as unknown as { frames_: number[] }).frames_ = [];
          return performance.now();
        });
        await page.mouse.up({ button: 'right' });
        await full();
        const r = await page.evaluate((t0) => {
          const t = [t0, ...(window as unknown as { frames_: number[] }).frames_];
          let gap = 0;
          for (let k = 1; k < t.length; k++) gap = Math.max(gap, t[k] - t[k - 1]);
          return { gap, full: performance.now() - t0 };
        }, up);
        gaps.push(r.gap);
        fulls.push(r.full);
        console.error(
          `${dist} ${preset} run ${i}: longest gap ${r.gap.toFixed(0)} ms, full ${r.full.toFixed(0)} ms`,
        );
      }
      const strands = Number(await page.getByTestId('status').getAttribute('data-strands'));
      rows.push({
        build: dist,
        preset,
        strands,
        longestGapMs: Math.round(median(gaps)),
        fullDetailMs: Math.round(median(fulls)),
      });
      await page.close();
    }
  } finally {
    await browser.close();
    server.kill();
  }
}
const table = [
  '| build | preset | strands | longest gap between frames (ms, median) | to the full-detail frame (ms, median) |',
  '| --- | --- | --- | --- | --- |',
  ...rows.map(
    (r) => `| ${r.build} | ${r.preset} | ${r.strands} | ${r.longestGapMs} | ${r.fullDetailMs} |`,
  ),
].join('\n');
console.log(table);
writeBenchResults('settle', {
  title: 'After the view stops: the longest freeze and the time to the full-detail frame',
  script: 'scripts/bench-settle.ts',
  command: 'npm run bench:settle (BENCH_DIST=a,b: several builds in one run)',
  measures:
    'From the release of an orbit (a right-drag of 80 px, real pointer events, 1280×800, SwiftShader) until ' +
    'the hair is drawn in full: the longest time between two animation frames (the page could not paint) and ' +
    `the time to the full-detail frame; medians of ${RUNS} orbits.`,
  config: { runs: RUNS, presets: PRESETS, dists: DISTS },
  results: rows,
  table,
});
