#!/usr/bin/env node
// Entry of the `hairsketch` command: runs the bundled command line (build/cli/hairsketch.mjs,
// built from web/cli/ by `npm run build:cli` with vite.cli.config.ts) with plain node. When the
// bundle is missing or older than its sources it is built first (that needs the dev
// dependencies and the wasm module, and says so when they are missing).
import { pathToFileURL } from 'node:url';
import { buildCliBundle, cliBundle, cliBundleStale } from './cliBundle.mjs';

const stale = cliBundleStale();
if (stale) {
  process.stderr.write(`hairsketch: the command line bundle is ${stale}; building it\n`);
  const error = buildCliBundle();
  if (error) {
    process.stderr.write(`hairsketch: cannot build ${cliBundle}: ${error}\n`);
    process.exit(1);
  }
}
const { main } = await import(pathToFileURL(cliBundle).href);
process.exitCode = await main(process.argv.slice(2));
