import { readFileSync } from 'node:fs';
import type { Plugin } from 'vite';
import { defineConfig } from 'vite';

// The `hairsketch` command line, bundled like the app: one ES module for Node (build/cli/
// hairsketch.mjs, exporting main) with every dependency inside, so scripts/hairsketch.mjs runs it
// with plain node. `grow` and the head code it brings (three.js) are a chunk of their own, loaded
// only by `grow`, so `solve` starts without them; `render` and its browser launcher likewise.
// The wasm module goes beside the bundle.
const WASM = 'hairsolver.wasm';

const wasmBeside = (): Plugin => ({
  name: 'hairsketch-cli-wasm',
  generateBundle() {
    this.emitFile({
      type: 'asset',
      fileName: WASM,
      source: readFileSync(new URL(`./web/generated/${WASM}`, import.meta.url)),
    });
  },
});

export default defineConfig({
  plugins: [wasmBeside()],
  publicDir: false,
  logLevel: 'warn',
  define: { __CLI_WASM_BESIDE__: JSON.stringify(WASM) },
  ssr: { noExternal: true, target: 'node' },
  build: {
    ssr: true,
    outDir: 'build/cli',
    emptyOutDir: true,
    target: 'node20',
    minify: false,
    reportCompressedSize: false,
    // Read from disk by node, never downloaded: the head-file chunk (three.js inside) is large.
    chunkSizeWarningLimit: 4096,
    rollupOptions: {
      // render's browser launcher stays a package import (it finds its own files at run time)
      external: ['playwright-core'],
      input: { hairsketch: 'web/cli/main.ts' },
      output: { format: 'es', entryFileNames: '[name].mjs', chunkFileNames: '[name]-[hash].mjs' },
    },
  },
});
