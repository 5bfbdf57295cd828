// npm run bench:bare-scalp — scalp bare where hair should be (web/app/bareScalp.ts, through the
// test hook window.hairsketch.bareScalp()) for a few presets, with finished edges (the session
// setting `finish`) off and on: per preset, the share of the scalp points seen from the front,
// the side (+x), the back and the top that show through the hair although the hair round them
// (2 cm) hides the scalp. Each preset is loaded (/?preset=NAME), measured as it comes, then its
// session is replaced by the same one with `finish` switched (replaceSession) and measured again
// once that hair is shown. When the session reader does not accept `finish` (a build before it)
// that column says n/a. Two measures: as bareScalp defines it (any hair in front of a point,
// in its 2 mm cell or the 8 round it, covers it) and with its stricter cover (minOpacity
// BENCH_OPACITY, default 0.5: the hair's 0.5 mm lines must also hide that share of the point's
// own cell; a root alone no longer covers). Writes bench-results/bare-scalp.{json,md} and prints the table. A
// benchmark, not a test: it asserts nothing.
// BENCH_PRESETS=a,b overrides the presets; BENCH_DIST=<dir> serves another build than dist/.
import { resolve } from 'node:path';
import type { Page } from '@playwright/test';
import type { BareScalpResult } from '../web/app/bareScalp';
import { writeBenchResults } from './benchResults.mjs';
import { previewAndBrowser, revision, settled, waitServer } from './previewServer';

const PORT = Number(process.env.BENCH_PORT ?? 4191);
const BASE = `http://127.0.0.1:${PORT}`;
const PRESETS = (process.env.BENCH_PRESETS ?? 'default,bob,long,curly,bun,fig1').split(',');
const VIEWS = ['front', 'side', 'back', 'top'] as const;
const OPACITY = Number(process.env.BENCH_OPACITY ?? 0.5);

type Figures = BareScalpResult & { ms: number };
/** bareScalp as defined (`any`) and with minOpacity (`strict`), and the strands shown. */
interface Measured {
  any: Figures;
  strict: Figures;
  strands: number;
}
type Column = Measured | { na: string };

async function measure(page: Page): Promise<Measured> {
  const strands = Number(await page.getByTestId('status').getAttribute('data-strands'));
  const any = await page.evaluate(() => window.hairsketch.bareScalp());
  const strict = await page.evaluate(
    (o) => window.hairsketch.bareScalp({ minOpacity: o }),
    OPACITY,
  );
  return { any, strict, strands };
}

/** The session with `finish` on or off, as replaceSession takes it; the measure once its hair is
 *  shown, or why not. */
async function withFinish(page: Page, on: boolean): Promise<Column> {
  const before = await revision(page);
  const error = await page.evaluate((finish) => {
    const s = window.hairsketch.session() as Record<string, unknown>;
    if (finish) s.finish = true;
    else delete s.finish;
    try {
      window.hairsketch.replaceSession(s);
    } catch (e) {
      return String(e instanceof Error ? e.message : e);
    }
    // a reader that drops keys it does not know would leave the session as it was
    const now = (window.hairsketch.session() as { finish?: boolean }).finish === true;
    return now === finish ? null : 'the session reader dropped `finish`';
  }, on);
  if (error) return { na: error };
  let state: string;
  try {
    state = await settled(page, before);
  } catch (e) {
    return { na: `no new hair: ${String(e instanceof Error ? e.message : e).slice(0, 120)}` };
  }
  if (state === 'error') return { na: (await page.getByTestId('status').textContent()) ?? 'error' };
  return measure(page);
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
    for (const preset of PRESETS) {
      const page = await browser.newPage({ viewport: { width: 1000, height: 750 } });
      await page.goto(`${BASE}/?preset=${encodeURIComponent(preset)}`);
      const state = await settled(page);
      if (state === 'error') {
        const text = await page.getByTestId('status').textContent();
        rows.push({ preset, error: text });
        console.log(`${preset}: ${text}`);
        await page.close();
        continue;
      }
      // the preset's own setting is measured as loaded, the other after switching it
      const own = await page.evaluate(
        () => (window.hairsketch.session() as { finish?: boolean }).finish === true,
      );
      const first = await measure(page);
      const other = await withFinish(page, !own);
      const off = own ? other : first;
      const on = own ? first : other;
      const row = { preset, presetFinish: own, off, on };
      rows.push(row);
      const brief = (m: Column) =>
        'na' in m
          ? `n/a (${m.na})`
          : `${pct(m.any.total.bareShare)} % bare where hair (covered ` +
            `${pct(m.any.total.coveredShare)} %; strict ${pct(m.strict.total.bareShare)} %, ` +
            `covered ${pct(m.strict.total.coveredShare)} %; ${m.any.total.points} points, ` +
            `${m.strands} strands, ${m.any.ms.toFixed(0)} ms)`;
      console.log(`${preset}: finish off ${brief(off)}; finish on ${brief(on)}`);
      await page.close();
    }
  } finally {
    await browser.close();
    server.kill();
  }
  const isMeasured = (m: unknown): m is Measured =>
    !!m && typeof m === 'object' && 'any' in m && 'strict' in m;
  const cols = (m: unknown, which: 'any' | 'strict'): string[] => {
    if (!isMeasured(m)) return ['n/a', 'n/a', 'n/a', 'n/a', 'n/a', 'n/a'];
    const r = m[which];
    return [
      pct(r.total.bareShare),
      ...VIEWS.map((v) => {
        const view = r.views.find((x) => x.view === v);
        return view ? pct(view.bareShare) : '—';
      }),
      pct(r.total.coveredShare),
    ];
  };
  const strands = (m: unknown) => (isMeasured(m) ? String(m.strands) : 'n/a');
  const table = (which: 'any' | 'strict'): string[] => {
    const t = [
      '| preset | finish in preset | strands off / on | off: total % | front | side | back | top | covered % | on: total % | front | side | back | top | covered % |',
      '| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |',
    ];
    for (const r of rows)
      t.push(
        r.error
          ? `| ${r.preset} | ${String(r.error).slice(0, 80)} | | | | | | | | | | | | | |`
          : `| ${r.preset} | ${r.presetFinish ? 'on' : 'off'} | ${strands(r.off)} / ${strands(r.on)} | ${cols(r.off, which).join(' | ')} | ${cols(r.on, which).join(' | ')} |`,
      );
    return t;
  };
  const na = rows
    .flatMap((r) => [r.off, r.on])
    .filter((m): m is { na: string } => !!m && typeof m === 'object' && 'na' in m)
    .map((m) => m.na);
  const out: string[] = [
    'Bare where hair should be, % of the scalp points seen (total: the four views together), and',
    'the covered share; finished edges (`finish`) off and on.',
    '',
    'As defined (any hair in front in the 2 mm cell or the 8 round it covers):',
    '',
    ...table('any'),
    '',
    `Stricter cover (minOpacity ${OPACITY}: the hair's 0.5 mm lines must also hide ${100 * OPACITY} % of the point's own cell):`,
    '',
    ...table('strict'),
    ...(na.length ? ['', `n/a: ${[...new Set(na)].join('; ')}`] : []),
  ];
  console.log(`\n${out.join('\n')}`);
  writeBenchResults('bare-scalp', {
    title: 'Scalp bare where hair should be, per preset, finished edges off and on',
    script: 'scripts/bench-bare-scalp.ts',
    command: 'npm run bench:bare-scalp',
    measures:
      "The built app in Debian's Chromium (headless, software WebGL through SwiftShader); per " +
      'preset (/?preset=NAME) the hair as loaded and with the session setting `finish` (finished ' +
      'edges) switched by replaceSession. Figures are window.hairsketch.bareScalp() ' +
      '(web/app/bareScalp.ts): orthographic views from the front (+z), the side (+x), the back ' +
      '(−z) and the top (+y); the samples are the centroids of the scalp triangles facing the ' +
      'view (normal · view > 0.2) the head does not hide; a sample is covered when hair drawn ' +
      'into a 2 mm depth raster lies in front of it in its cell or the 8 round it, and bare ' +
      'where hair should be when it is not covered but ≥ 75 % of the view’s other samples ' +
      'within 2 cm on screen are. Percentages are of the samples seen (total: of the four ' +
      "views' samples together). A second table asks in addition that the hair's lines, 0.5 mm " +
      `wide, hide ${100 * OPACITY} % of the point's own cell (minOpacity). The scalp itself ` +
      "follows `finish` (the built-in head's natural hairline when on), so the samples differ " +
      'between the columns.',
    config: { presets: PRESETS, minOpacity: OPACITY, dist: process.env.BENCH_DIST ?? 'dist' },
    results: rows,
    table: out.join('\n'),
  });
}

function pct(x: number): string {
  return (100 * x).toFixed(2);
}

await main();
