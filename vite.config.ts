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
// Cross-origin isolation (COOP + COEP): SharedArrayBuffer, hence the threaded solver module
// (web/solver/worker.ts). Everything the app loads is same-origin, so require-corp costs nothing.
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

export default defineConfig({
  root: 'web',
  publicDir: '../public',
  build: {
    outDir: '../dist',
    emptyOutDir: true,
    target: 'es2022',
    // The threaded module's loader and pthread worker script stay files (a data: URL worker
    // would be cross-origin, and the CSP allows same-origin workers only).
    assetsInlineLimit: (file: string) => (/hairsolver/.test(file) ? false : undefined),
  },
  worker: { format: 'es' },
  server: { host: '127.0.0.1', port: 5173, strictPort: false, headers },
  preview: { host: '127.0.0.1', port: 4173, strictPort: false, headers },
  test: {
    root: '.',
    include: ['tests/unit/**/*.test.ts'],
    environment: 'node',
    testTimeout: 60_000,
  },
});
