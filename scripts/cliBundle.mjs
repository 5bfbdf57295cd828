// The bundled command line (build/cli/, vite.cli.config.ts): where it is, whether it is older than
// what it is built from, and its build. Used by scripts/hairsketch.mjs and the unit tests' set-up.
import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync, statSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
export const cliBundle = join(root, 'build/cli/hairsketch.mjs');

/** Newest modification time of the files the bundle is built from. */
function newestSource() {
  let newest = 0;
  const visit = (dir) => {
    for (const e of readdirSync(dir, { withFileTypes: true })) {
      const p = join(dir, e.name);
      if (e.isDirectory()) visit(p);
      else if (/\.(ts|mjs|wasm)$/.test(e.name)) newest = Math.max(newest, statSync(p).mtimeMs);
    }
  };
  if (existsSync(join(root, 'web'))) visit(join(root, 'web'));
  for (const f of ['vite.cli.config.ts', 'package-lock.json']) {
    const p = join(root, f);
    if (existsSync(p)) newest = Math.max(newest, statSync(p).mtimeMs);
  }
  return newest;
}

/** Why the bundle must be built ('not built yet', 'older than its sources'), or null. */
export function cliBundleStale() {
  if (!existsSync(cliBundle)) return 'not built yet';
  return statSync(cliBundle).mtimeMs < newestSource() ? 'older than its sources' : null;
}

/** Builds the bundle (`npm run build:cli`); its output goes to stderr. Returns an error or null. */
export function buildCliBundle() {
  const vite = join(root, 'node_modules/vite/bin/vite.js');
  if (!existsSync(vite) || !existsSync(join(root, 'web/generated/hairsolver.wasm')))
    return 'it needs the npm packages and the wasm module: run `npm ci`, `npm run build:wasm`, then `npm run build:cli` in the hairsketch checkout';
  const r = spawnSync(process.execPath, [vite, 'build', '-c', 'vite.cli.config.ts'], {
    cwd: root,
    stdio: ['ignore', 2, 2],
  });
  return r.status === 0 ? null : 'vite build -c vite.cli.config.ts failed (npm run build:cli)';
}
