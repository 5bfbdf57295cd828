import { defineConfig } from '@playwright/test';

// Debian's Chromium, never a downloaded browser (TOOLCHAIN.md): its headless shell (package
// chromium-headless-shell, the same build without the browser's UI, as Playwright's own headless
// mode uses), which ran the whole suite on 22 % less CPU than the full browser. The built app is
// served by `vite preview`; scenes are kept small (?strands=) because WebGL runs on SwiftShader.
const port = Number(process.env.E2E_PORT ?? 4179);
// The "not-isolated" project's server omits the COOP/COEP headers (vite.config.ts), so the page
// is not cross-origin isolated and the solver falls back to the single-threaded module.
const plainPort = port + 1;

export default defineConfig({
  testDir: 'tests/e2e',
  timeout: 240_000,
  expect: { timeout: 60_000 },
  // Two workers, one per core of the test machine (E2E_WORKERS overrides): on 13 tests they took
  // 0.6-1.0x the time of one worker on the loaded two-core machine, and no test was less stable.
  workers: Number(process.env.E2E_WORKERS ?? 2),
  // Tests, not files, are shared out to the workers: every test opens its own page, and a file of
  // a few long tests (strokeSays) would otherwise keep one worker busy long after the other ends.
  fullyParallel: true,
  retries: 0,
  // the list, and where the CPU went, test by test (build/test-logs/e2e-cpu.tsv)
  reporter: [['list'], ['./tests/support/cpuReporter.ts']],
  use: {
    baseURL: `http://127.0.0.1:${port}`,
    viewport: { width: 1000, height: 750 },
    // Half a device pixel per CSS pixel: the page's layout, pointer coordinates and every screen
    // point the tests compute stay as they are, while SwiftShader rasterises a quarter of the
    // pixels (app and sketching specs: 20 % less CPU). E2E_DSF=1 draws at full resolution.
    deviceScaleFactor: Number(process.env.E2E_DSF ?? 0.5),
    // The headless shell, unlike the full browser, refuses clipboard writes unless granted
    permissions: ['clipboard-write'],
    launchOptions: {
      executablePath: process.env.CHROMIUM_PATH ?? '/usr/lib/chromium/chromium-headless-shell',
      args: [
        '--no-sandbox',
        '--disable-gpu',
        '--disable-background-networking',
        '--disable-component-update',
        '--disable-sync',
        '--no-first-run',
        '--disable-quic',
        '--enable-unsafe-swiftshader',
        // No optimising JavaScript compiler: each test's page is short-lived, and compiling its
        // hot functions cost more than it saved (five spec files, 27 tests, two rounds each:
        // 203 and 202 CPU-s against 209 and 215). The wasm solver is compiled as before.
        '--js-flags=--no-opt',
      ],
    },
  },
  projects: [
    { name: 'isolated' },
    {
      name: 'not-isolated',
      testMatch: /threads\.spec\.ts/,
      use: { baseURL: `http://127.0.0.1:${plainPort}` },
    },
  ],
  webServer: [
    {
      command: `npx vite preview --port ${port} --strictPort`,
      url: `http://127.0.0.1:${port}/`,
      reuseExistingServer: false,
      timeout: 60_000,
    },
    {
      command: `npx vite preview --port ${plainPort} --strictPort`,
      env: { HAIRSKETCH_NO_ISOLATION: '1' },
      url: `http://127.0.0.1:${plainPort}/`,
      reuseExistingServer: false,
      timeout: 60_000,
    },
  ],
});
