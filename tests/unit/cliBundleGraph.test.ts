// The bundled command line (build/cli/) runs with plain node: it imports nothing but Node's own
// modules and its chunks (and `render`, on demand, the browser launcher playwright-core), and
// neither `solve` nor `grow` on the built-in head loads three.js (only reading a head file does:
// cli/headFile.ts, a chunk loaded on demand), nor does `solve` load the browser launcher, so
// commands start fast.
import { readFileSync } from 'node:fs';
import { basename, dirname, join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { CLI_BUNDLE } from './cliBundle';

/** Static and dynamic import specifiers of a bundled module. */
function importsOf(file: string): { statics: string[]; dynamics: string[] } {
  const text = readFileSync(file, 'utf8');
  const statics = [...text.matchAll(/^\s*(?:import|export)\b[^'"]*?\bfrom\s*["']([^"']+)["']/gm)]
    .concat([...text.matchAll(/^\s*import\s*["']([^"']+)["']/gm)])
    .map((m) => m[1]);
  const dynamics = [...text.matchAll(/\bimport\(\s*["']([^"']+)["']\s*\)/g)].map((m) => m[1]);
  return { statics, dynamics };
}

/** Every module of the bundle reachable from `entry`, following static imports only or all
 *  (but for dynamic imports of chunks whose name starts with `skip`). */
function graph(entry: string, followDynamic: boolean, skip?: string): string[] {
  const seen = new Set<string>();
  const visit = (file: string) => {
    if (seen.has(file)) return;
    seen.add(file);
    const { statics, dynamics } = importsOf(file);
    const followed = followDynamic
      ? dynamics.filter((d) => !(skip && d.startsWith(`./${skip}`)))
      : [];
    for (const s of [...statics, ...followed])
      if (s.startsWith('./')) visit(join(dirname(file), s));
  };
  visit(entry);
  return [...seen];
}

// The bundle is not minified: three.js shows as its module paths (the bundler's comments) and its
// class names. The second test checks that these marks are found where three.js is.
const hasThree = (file: string) =>
  /node_modules\/three\/|\bclass BufferGeometry\b/.test(readFileSync(file, 'utf8'));

describe('the bundled command line', () => {
  it('imports only node: modules and its own chunks (and the browser launcher on demand)', () => {
    const all = graph(CLI_BUNDLE, true);
    expect(all.length).toBeGreaterThan(2); // grow's and render's chunks
    let launcher = 0;
    for (const f of all) {
      const { statics, dynamics } = importsOf(f);
      for (const s of statics) expect(s, `${f} imports ${s}`).toMatch(/^(node:|\.\/)/);
      for (const s of dynamics) {
        if (s === 'playwright-core') launcher++;
        else expect(s, `${f} imports ${s}`).toMatch(/^(node:|\.\/)/);
      }
    }
    expect(launcher).toBe(1);
  });

  it('loads no browser launcher for solve', () => {
    const solve = graph(CLI_BUNDLE, false);
    const mentions = (f: string) => /playwright/.test(readFileSync(f, 'utf8'));
    for (const f of solve) expect(mentions(f), `${f} mentions playwright`).toBe(false);
    expect(graph(CLI_BUNDLE, true).some(mentions)).toBe(true);
  });

  it('loads no three.js for solve or for grow on the built-in head; a head file brings it', () => {
    const solve = graph(CLI_BUNDLE, false);
    for (const f of solve) expect(hasThree(f), `${f} holds three.js`).toBe(false);
    const withoutHeadFiles = graph(CLI_BUNDLE, true, 'headFile');
    expect(
      withoutHeadFiles.some((f) => /\/grow-[^/]*\.mjs$/.test(f)),
      'grow is a chunk',
    ).toBe(true);
    for (const f of withoutHeadFiles) expect(hasThree(f), `${f} holds three.js`).toBe(false);
    // the check finds three.js where it is: in what reading a head file loads
    const all = graph(CLI_BUNDLE, true);
    expect(all.filter(hasThree).map((f) => basename(f))).toEqual([
      expect.stringMatching(/^headFile-.*\.mjs$/),
    ]);
  });
});
