import { readFile } from 'node:fs/promises';
import type { ServerResponse } from 'node:http';
import { availableParallelism } from 'node:os';
import { fileURLToPath } from 'node:url';
import type { Plugin } from 'vite';
import { defineConfig } from 'vitest/config';

// The app lives in web/ (index.html there); public/ is served as is; the build goes to dist/.
// Served with a Content-Security-Policy that forbids inline script (and eval; the wasm module
// is compiled under 'wasm-unsafe-eval'): strings from links and files can only ever be text.
const CSP = [
  "default-src 'self'",
  "script-src 'self' 'wasm-unsafe-eval'",
  "worker-src 'self'",
  "style-src 'self' 'unsafe-inline'",
  "img-src 'self' data: blob:",
  "connect-src 'self'",
  "object-src 'none'",
  "base-uri 'none'",
  "form-action 'none'",
  "frame-ancestors 'none'",
].join('; ');
// The embeddable viewer (embed.html) may be framed by any site; every other page refuses.
const EMBED_CSP = CSP.replace("frame-ancestors 'none'", 'frame-ancestors *');
// Cross-origin isolation (COOP + COEP): SharedArrayBuffer, hence the threaded solver module
// (web/worker/worker.ts). Everything the app loads is same-origin, so require-corp costs nothing.
// HAIRSKETCH_NO_ISOLATION=1 serves without them (the e2e fallback project: single-threaded).
const isolation: Record<string, string> =
  process.env.HAIRSKETCH_NO_ISOLATION === '1'
    ? {}
    : {
        'Cross-Origin-Opener-Policy': 'same-origin',
        'Cross-Origin-Embedder-Policy': 'require-corp',
      };
const headers = {
  'Content-Security-Policy': CSP,
  'X-Content-Type-Options': 'nosniff',
  ...isolation,
};

// vite dev serves JS through its transform, which adds ES imports: the threaded module's classic
// pthread worker script (and its loader, which that worker imports) must reach the browser as
// built, as `vite build` emits them (plain ?url assets).
const rawThreadedModule = (): Plugin => ({
  name: 'hairsketch-raw-threaded-module',
  apply: 'serve',
  configureServer(server) {
    server.middlewares.use(async (req, res, next) => {
      // only the files themselves: `…?url` is vite's module naming them
      const path = req.url ?? '';
      const m = /^\/generated\/(hairsolver-mt\.(?:mjs|worker\.js|wasm))$/.exec(path);
      if (!m) return next();
      try {
        const body = await readFile(new URL(`./web/generated/${m[1]}`, import.meta.url));
        for (const [k, v] of Object.entries(headers)) res.setHeader(k, v);
        res.setHeader(
          'Content-Type',
          m[1].endsWith('.wasm') ? 'application/wasm' : 'text/javascript',
        );
        res.setHeader('Cache-Control', 'no-cache');
        res.end(body);
      } catch {
        next();
      }
    });
  },
});

// The embed's response carries EMBED_CSP (and may be loaded by an isolated framing page):
// whoever sets the CSP header later (vite's static server applies `headers` as it sends the
// file) sets the embed's instead.
const framableEmbed = (): Plugin => {
  const use = (req: { url?: string }, res: ServerResponse, next: () => void): void => {
    const path = (req.url ?? '').split(/[?#]/)[0];
    if (path === '/embed.html') {
      const set = res.setHeader.bind(res);
      res.setHeader = (name, value) =>
        set(name, name.toLowerCase() === 'content-security-policy' ? EMBED_CSP : value);
      res.setHeader('Content-Security-Policy', EMBED_CSP);
      res.setHeader('Cross-Origin-Resource-Policy', 'cross-origin');
    }
    next();
  };
  return {
    name: 'hairsketch-framable-embed',
    configureServer: (server) => void server.middlewares.use(use),
    configurePreviewServer: (server) => void server.middlewares.use(use),
  };
};

/** Unit test files that mock modules or replace globals (see test.projects below). */
const ISOLATED_TESTS = [
  'tests/unit/cli.test.ts',
  'tests/unit/cliGrow.test.ts',
  'tests/unit/cliGrowFailure.test.ts',
  'tests/unit/cliGrowHead.test.ts',
  'tests/unit/cliGrowTimeCap.test.ts',
  'tests/unit/cliMemoryCap.test.ts',
  'tests/unit/cliRender.test.ts',
  'tests/unit/gltfBlender.test.ts',
  'tests/unit/wasmNative.test.ts',
];

export default defineConfig({
  plugins: [rawThreadedModule(), framableEmbed()],
  root: 'web',
  publicDir: '../public',
  build: {
    outDir: '../dist',
    emptyOutDir: true,
    target: 'es2022',
    // the editor, and the embeddable viewer with only what it needs (web/embed/)
    rollupOptions: {
      input: {
        main: fileURLToPath(new URL('./web/index.html', import.meta.url)),
        embed: fileURLToPath(new URL('./web/embed.html', import.meta.url)),
      },
    },
    // The threaded module's loader and pthread worker script stay files (a data: URL worker
    // would be cross-origin, and the CSP allows same-origin workers only).
    assetsInlineLimit: (file: string) => (/hairsolver/.test(file) ? false : undefined),
  },
  worker: { format: 'es' },
  server: { host: '127.0.0.1', port: 5173, strictPort: false, headers },
  preview: { host: '127.0.0.1', port: 4173, strictPort: false, headers },
  test: {
    root: '.',
    // CLI tests run the bundled command line: built here when missing or stale.
    globalSetup: ['tests/unit/cliBundleSetup.ts'],
    environment: 'node',
    // a time allowance catches a hang, it is not a speed check: tests that take 30-40 s alone
    // took up to 61 s with the suite's other lanes beside them on two cores
    testTimeout: 240_000,
    // a beforeAll that opens a browser or parses a head waited past 10 s on a loaded machine
    hookTimeout: 120_000,
    // vitest's default is one worker fewer than the cores: one on a two-core machine, which
    // leaves a core idle whenever the unit tests are all that is left of npm test (160 CPU-s of
    // tests took 135 s on one worker, 84 s on two).
    maxWorkers: Math.max(2, availableParallelism() - 1),
    // Most test files share a worker's module cache (isolate: false): each file would otherwise
    // import three.js, the model and the engine afresh. Files that mock modules or replace
    // globals (vi.mock, vi.stubGlobal, vi.spyOn on process.stdout, directly or through
    // captureOutput.ts) run isolated, so nothing they change reaches another file.
    projects: [
      {
        extends: true,
        test: { name: 'unit', include: ['tests/unit/**/*.test.ts'], exclude: ISOLATED_TESTS },
      },
      { extends: true, test: { name: 'unit-isolated', include: ISOLATED_TESTS, isolate: true } },
    ],
    isolate: false,
  },
});
