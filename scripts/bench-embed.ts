// npm run bench:embed — what the embeddable viewer (embed.html) costs against the editor
// (index.html) for the same share link: the bytes each page downloads until its hair is final
// (JavaScript raw and gzip-compressed, wasm, everything; counted from the responses the browser
// received), whether the embed loaded any of the editor's own chunks, and the time from
// navigation to the first hair on screen (the first look) and to the final hair. The built app
// (dist/) is served without cross-origin isolation, as a page framing the embed usually is, so
// both run the single-threaded solver. Debian's Chromium with software WebGL; BENCH_RUNS runs per
// page (default 3), medians printed. Writes bench-results/embed.{json,md}.
//   npx tsx scripts/bench-embed.ts [preset]      (default bob, every strand)
import { gzipSync } from 'node:zlib';
import { chromium } from '@playwright/test';
import { presetSession } from '../web/cli/presetSession';
import { serveDirectory } from '../web/cli/staticServer';
import { Head } from '../web/head/head';
import { PRESET_NAMES, type PresetName } from '../web/model/presets';
import { encodeSessionLink } from '../web/model/sessionLink';
import { writeBenchResults } from './benchResults.mjs';

const RUNS = Math.max(1, Number(process.env.BENCH_RUNS ?? 3));
const preset = (process.argv[2] ?? 'bob') as PresetName;
if (!PRESET_NAMES.includes(preset)) {
  console.error(`unknown preset ${preset}; known: ${PRESET_NAMES.join(', ')}`);
  process.exit(2);
}

interface Run {
  firstHairMs: number;
  finalHairMs: number;
  strands: number;
  js: number;
  jsGzip: number;
  wasm: number;
  total: number;
  files: string[];
}

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const kb = (n: number) => `${(n / 1024).toFixed(0)} KB`;

async function main(): Promise<void> {
  const link = await encodeSessionLink(presetSession(preset, Head.builtin()));
  const server = await serveDirectory('dist');
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--no-first-run'],
  });
  const pages = { embed: '/embed.html', editor: '/' } as const;
  const runs: Record<keyof typeof pages, Run[]> = { embed: [], editor: [] };
  try {
    for (let r = 0; r < RUNS; r++)
      for (const [which, path] of Object.entries(pages) as [keyof typeof pages, string][]) {
        // a fresh context: nothing cached
        const context = await browser.newContext({ viewport: { width: 800, height: 600 } });
        const page = await context.newPage();
        const bodies: Promise<{ url: string; bytes: Buffer } | null>[] = [];
        page.on('response', (res) =>
          bodies.push(
            res.body().then(
              (bytes) => ({ url: res.url(), bytes }),
              () => null,
            ),
          ),
        );
        await page.goto(`${server.base}${path}#${link.replace(/^#/, '')}`);
        const at = (test: string) =>
          page
            .waitForFunction(
              (t) => {
                const el = document.querySelector('[data-testid="status"]') as HTMLElement | null;
                if (!el) return false;
                if (el.dataset.state === 'error') throw new Error(el.textContent ?? 'error');
                const shown = Number(el.dataset.strands) > 0;
                return (t === 'first' ? shown : shown && el.dataset.state === 'ready')
                  ? performance.now()
                  : false;
              },
              test,
              { timeout: 600_000, polling: 20 },
            )
            .then((h) => h.jsonValue() as Promise<number>);
        const firstHairMs = await at('first');
        const finalHairMs = await at('final');
        const strands = Number(await page.getByTestId('status').getAttribute('data-strands'));
        const got = (await Promise.all(bodies)).filter((b) => b !== null);
        const isJs = (u: string) => /\.(m?js)$/.test(new URL(u).pathname);
        const js = got.filter((b) => isJs(b.url));
        runs[which].push({
          firstHairMs,
          finalHairMs,
          strands,
          js: js.reduce((n, b) => n + b.bytes.length, 0),
          jsGzip: js.reduce((n, b) => n + gzipSync(b.bytes).length, 0),
          wasm: got.filter((b) => b.url.endsWith('.wasm')).reduce((n, b) => n + b.bytes.length, 0),
          total: got.reduce((n, b) => n + b.bytes.length, 0),
          files: got.map((b) => new URL(b.url).pathname).sort(),
        });
        console.log(
          `${which} run ${r + 1}: first hair ${firstHairMs.toFixed(0)} ms, final ${finalHairMs.toFixed(0)} ms (${strands} strands)`,
        );
        await context.close();
      }
  } finally {
    await browser.close();
    await server.close();
  }
  // the editor's own chunks: its entry and what only it loads
  const embedFiles = new Set(runs.embed[0].files);
  const editorOnly = runs.editor[0].files.filter((f) => !embedFiles.has(f));
  const editorCodeInEmbed = runs.embed[0].files.filter((f) => /\/assets\/main-[^/]+\.js$/.test(f));
  const rows = (Object.keys(pages) as (keyof typeof pages)[]).map((which) => {
    const rs = runs[which];
    const m = (k: keyof Run) => median(rs.map((x) => x[k] as number));
    return {
      page: which,
      js: m('js'),
      jsGzip: m('jsGzip'),
      wasm: m('wasm'),
      total: m('total'),
      firstHairMs: Math.round(m('firstHairMs')),
      finalHairMs: Math.round(m('finalHairMs')),
      strands: m('strands'),
      files: rs[0].files,
    };
  });
  const table = [
    '| page | JavaScript | JavaScript, gzip | wasm | all bytes | first hair | final hair | strands |',
    '| --- | --- | --- | --- | --- | --- | --- | --- |',
    ...rows.map(
      (r) =>
        `| ${r.page} | ${kb(r.js)} | ${kb(r.jsGzip)} | ${kb(r.wasm)} | ${kb(r.total)} | ${r.firstHairMs} ms | ${r.finalHairMs} ms | ${r.strands} |`,
    ),
    '',
    `Loaded by the editor only: ${editorOnly.map((f) => `\`${f}\``).join(', ') || 'nothing'}.`,
    `The editor's entry chunk loaded by the embed: ${editorCodeInEmbed.length ? editorCodeInEmbed.join(', ') : 'no'}.`,
  ].join('\n');
  console.log(table);
  writeBenchResults('embed', {
    title: 'The embeddable viewer against the editor: bytes and time to hair',
    script: 'scripts/bench-embed.ts',
    command: 'npm run bench:embed',
    measures:
      `The \`${preset}\` preset's share link opened in embed.html and in the editor (index.html), ` +
      'each in a fresh browser context (nothing cached), from the built app served without ' +
      'cross-origin isolation (single-threaded solver), Debian Chromium with software WebGL, ' +
      '800 x 600. Bytes: every response body until the final hair (JavaScript also gzip-' +
      'compressed here, as a server would send it). Times from navigation start: first hair ' +
      '(the first look on screen) and final hair (the converged hair drawn). Medians of ' +
      `${RUNS} runs.`,
    config: { preset, runs: RUNS, viewport: [800, 600], isolation: false },
    results: { rows, editorOnly, editorCodeInEmbed },
    table,
  });
}

await main();
