// `hairsketch render`: a still picture of a session, drawn by the app's own embeddable viewer
// (embed.html, from the built app in dist/) in the system's Chromium and captured as Export →
// PNG captures the view (viewer/viewCapture.ts), so the picture is what the app shows.
//   hairsketch render SESSION|LINK --out FILE.png [--view front|side|back] [--size WxH]
//                     [--max-seconds N]
// The browser launcher (playwright-core, a dev dependency) is loaded only here, when a picture
// is asked for.
import { existsSync, renameSync, statSync, unlinkSync, writeFileSync } from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { QualitySetting } from '../app/quality';
import type { HairLook } from '../model/hairLook';
import type { SessionState } from '../model/session';
import type { HeadFileData } from '../model/sessionFile';
import { encodeSessionLink } from '../model/sessionLink';
import { isViewName, VIEW_NAMES, type ViewName } from '../viewer/namedViews';
import { CliError, parseSeconds } from './errors';
import { readSessionArg } from './grow';
import { serveDirectory } from './staticServer';

export const RENDER_USAGE =
  'usage: hairsketch render SESSION|LINK --out FILE.png [--view front|side|back] [--size WxH] [--max-seconds N]';
export const MIN_SIZE = 16;
export const MAX_SIZE = 4096;

export interface RenderArgs {
  session: string;
  out: string;
  view: ViewName;
  width: number;
  height: number;
  maxSeconds: number;
}

export function parseRenderArgs(argv: readonly string[]): RenderArgs {
  let session = '';
  let out = '';
  let view = 'front';
  let size = '800x600';
  let maxSeconds = 300;
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--out' || a === '--view' || a === '--size' || a === '--max-seconds') {
      const v = argv[++i];
      if (v === undefined) throw new CliError(`${a} needs a value; ${RENDER_USAGE}`);
      if (a === '--out') out = v;
      else if (a === '--view') view = v;
      else if (a === '--size') size = v;
      else maxSeconds = parseSeconds(a, v);
    } else if (a.startsWith('--')) {
      throw new CliError(`unknown option "${a.slice(0, 40)}"; ${RENDER_USAGE}`);
    } else if (!session) session = a;
    else throw new CliError(`unexpected argument "${a.slice(0, 40)}"; ${RENDER_USAGE}`);
  }
  if (!session) throw new CliError(`no session or link given; ${RENDER_USAGE}`);
  if (!out) throw new CliError(`no --out FILE.png given; ${RENDER_USAGE}`);
  if (!/\.png$/i.test(out))
    throw new CliError(`--out must name a .png file, not "${basename(out).slice(0, 60)}"`);
  if (!isViewName(view))
    throw new CliError(`unknown view "${view.slice(0, 40)}" (one of ${VIEW_NAMES.join(', ')})`);
  const m = /^(\d{1,5})x(\d{1,5})$/.exec(size);
  const width = m ? Number(m[1]) : Number.NaN;
  const height = m ? Number(m[2]) : Number.NaN;
  const fits = (n: number) => n >= MIN_SIZE && n <= MAX_SIZE;
  if (!(fits(width) && fits(height)))
    throw new CliError(
      `--size must be WIDTHxHEIGHT in pixels, each ${MIN_SIZE} to ${MAX_SIZE} (e.g. 800x600), not "${size.slice(0, 40)}"`,
    );
  return { session, out, view, width, height, maxSeconds };
}

/** Pictures of a session (one per view asked for), and what they took. */
export interface Still {
  png: Uint8Array[];
  strands: number;
  /** The head drawn: 'builtin' or the loaded head's file name. */
  head: string;
  ms: number;
}

export interface StillOptions {
  /** The views drawn, in order (the hair is grown once). */
  views: readonly ViewName[];
  width: number;
  height: number;
  /** Give up after this long (default 300 s). */
  timeoutMs?: number;
  /** The app's Quality setting (default Auto: Fast on a software rasteriser). */
  quality?: QualitySetting;
  /** The loaded head's file, for a session on one (a saved session file embeds it). */
  headFile?: HeadFileData;
  /** Colour looks (hairLook.ts; null: the colour box's colour) drawn on the same hair, each from
   *  every view, instead of the session's own: png is then look by look, view by view. */
  looks?: readonly (HairLook | null)[];
  /** Qualities drawn on the same hair, one after another, instead of `quality` alone (the page
   *  starts in the first): png is then quality by quality, look by look, view by view. */
  qualities?: readonly QualitySetting[];
}

export interface StillRenderer {
  /** `session` seen from each of `views` at width × height pixels. */
  render(session: SessionState, o: StillOptions): Promise<Still>;
  close(): Promise<void>;
}

/** The built app the pictures are drawn by: HAIRSKETCH_DIST, else dist/ at the repository's top
 *  (two levels above both web/cli/ and the bundle's build/cli/). */
function distDirectory(): string {
  const here = dirname(fileURLToPath(import.meta.url));
  return process.env.HAIRSKETCH_DIST ?? resolve(here, '../../dist');
}

/** Debian's Chromium without its UI (package chromium-headless-shell) where it is installed: the
 *  same engine, and a still starts in 3.5 s instead of 4.4 s (the page load dominates a small
 *  still's time); else the browser itself. */
function defaultChromium(): string {
  const shell = '/usr/lib/chromium/chromium-headless-shell';
  return existsSync(shell) ? shell : '/usr/bin/chromium';
}

/** Serves the built app and starts Chromium (CHROMIUM_PATH, default Debian's headless shell or
 *  /usr/bin/chromium, defaultChromium)
 *  with software WebGL, as the app's browser tests run it. */
export async function openStillRenderer(): Promise<StillRenderer> {
  const dist = distDirectory();
  if (!existsSync(join(dist, 'embed.html')))
    throw new CliError(`render needs the built app (no ${dist}/embed.html): run npm run build`);
  const executablePath = process.env.CHROMIUM_PATH ?? defaultChromium();
  if (!existsSync(executablePath))
    throw new CliError(
      `render needs Chromium at ${executablePath} (apt-get install chromium, or set CHROMIUM_PATH)`,
    );
  let launcher: typeof import('playwright-core');
  try {
    launcher = await import('playwright-core');
  } catch {
    throw new CliError('render needs the dev dependencies (playwright-core): run npm ci');
  }
  const server = await serveDirectory(dist);
  let browser: Awaited<ReturnType<typeof launcher.chromium.launch>>;
  try {
    browser = await launcher.chromium.launch({
      executablePath,
      args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--no-first-run'],
    });
  } catch (e) {
    await server.close();
    throw new CliError(
      `Chromium at ${executablePath} did not start (${String(e instanceof Error ? e.message : e).split('\n')[0]})`,
    );
  }
  return {
    async render(
      session,
      { views, width, height, timeoutMs = 300_000, quality = 'auto', headFile, looks, qualities },
    ) {
      const drawn = qualities?.length ? qualities : [quality];
      if (session.head !== 'builtin' && headFile?.hash !== session.head.hash)
        throw new CliError(
          `this session needs the head file “${session.head.name}”: render the saved session file that embeds it`,
        );
      const t0 = performance.now();
      const link = await encodeSessionLink(session);
      const page = await browser.newPage({ viewport: { width, height }, deviceScaleFactor: 1 });
      // every step waits as long as the time cap (not Playwright's 30 s): on a busy machine a
      // page drawing 30,000 strands in software answers late
      page.setDefaultTimeout(timeoutMs);
      try {
        if (headFile) {
          // into the page's head store, where the embed looks for the head the link names
          await page.goto(`${server.base}/embed.html?still`);
          await page.evaluate(
            ([name, hash, base64]) => window.hairsketchEmbed?.storeHead(name, hash, base64),
            [headFile.name, headFile.hash, Buffer.from(headFile.bytes).toString('base64')],
          );
        }
        await page.goto(
          `${server.base}/embed.html?still&view=${views[0]}&quality=${drawn[0]}#${link.replace(/^#/, '')}`,
        );
        const status = page.getByTestId('status');
        try {
          await page.waitForFunction(
            () => {
              const s = document.querySelector('[data-testid="status"]') as HTMLElement | null;
              return s?.dataset.state === 'ready' || s?.dataset.state === 'error';
            },
            null,
            { timeout: timeoutMs, polling: 100 },
          );
        } catch {
          throw new CliError(
            `stopped at the time cap of ${Math.round(timeoutMs / 1000)} s (--max-seconds) before the hair was drawn`,
            3,
          );
        }
        if ((await status.getAttribute('data-state')) === 'error')
          throw new CliError(`the viewer could not draw it: ${await status.textContent()}`);
        const strands = Number(await status.getAttribute('data-strands'));
        const drawnOn = await status.getAttribute('data-head');
        const wanted = session.head === 'builtin' ? 'builtin' : session.head.name;
        if (drawnOn !== wanted)
          throw new Error(`the viewer drew the head “${drawnOn}” instead of “${wanted}”`);
        const png: Uint8Array[] = [];
        for (const [k, q] of drawn.entries()) {
          for (const look of looks ?? [undefined]) {
            for (const view of views) {
              const base64 = await page.evaluate(
                ([v, l, q]) => {
                  const embed = window.hairsketchEmbed;
                  if (!embed) throw new Error('the viewer has no capture');
                  if (q !== undefined) embed.setQuality(q);
                  if (l !== undefined) embed.setLook(l);
                  return embed.capture(1, v);
                },
                [view, look, k > 0 ? q : undefined] as const,
              );
              png.push(new Uint8Array(Buffer.from(base64, 'base64')));
            }
          }
        }
        return { png, strands, head: wanted, ms: performance.now() - t0 };
      } finally {
        await page.close();
      }
    },
    async close() {
      await browser.close();
      await server.close();
    },
  };
}

/** Runs `hairsketch render`; prints one JSON line: file, width, height, view, strands, head,
 *  ms. */
export async function runRender(argv: readonly string[], print: (line: string) => void) {
  const args = parseRenderArgs(argv);
  const out = resolve(args.out);
  let outDir: ReturnType<typeof statSync> | null = null;
  try {
    outDir = statSync(dirname(out));
  } catch {
    // reported below
  }
  if (!outDir?.isDirectory())
    throw new CliError(`cannot write ${args.out}: its directory does not exist`);
  const { session, headFile } = await readSessionArg(args.session);
  const t0 = performance.now();
  const renderer = await openStillRenderer();
  try {
    const still = await renderer.render(session, {
      views: [args.view],
      width: args.width,
      height: args.height,
      timeoutMs: 1000 * args.maxSeconds,
      headFile,
    });
    // written beside FILE and renamed into place: a failed run leaves no half-written picture
    const temp = join(dirname(out), `.${basename(out)}.${process.pid}.tmp`);
    try {
      writeFileSync(temp, still.png[0]);
      renameSync(temp, out);
    } catch (e) {
      if (existsSync(temp)) unlinkSync(temp);
      throw new CliError(`cannot write ${args.out}: ${(e as NodeJS.ErrnoException).code ?? e}`);
    }
    print(
      JSON.stringify({
        file: args.out,
        width: args.width,
        height: args.height,
        view: args.view,
        strands: still.strands,
        head: still.head,
        ms: Math.round(performance.now() - t0),
      }),
    );
  } finally {
    await renderer.close();
  }
}
