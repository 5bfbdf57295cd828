// The bundled command line (build/cli/) runs with plain node: it imports nothing but Node's own
// modules and its chunks (and `render`, on demand, the browser launcher playwright-core), and
// what `solve` loads holds no three.js (the head code that needs it is in the chunk `grow` loads
// on demand) and no browser launcher, so the command starts fast.
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
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

/** Every module of the bundle reachable from `entry`, following static imports only or all. */
function graph(entry: string, followDynamic: boolean): string[] {
  const seen = new Set<string>();
  const visit = (file: string) => {
    if (seen.has(file)) return;
    seen.add(file);
    const { statics, dynamics } = importsOf(file);
    for (const s of followDynamic ? [...statics, ...dynamics] : statics)
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

  it('loads no three.js for solve; grow brings it on demand', () => {
    const solve = graph(CLI_BUNDLE, false);
    for (const f of solve) expect(hasThree(f), `${f} holds three.js`).toBe(false);
    // the check finds three.js where it is: in what grow loads
    expect(graph(CLI_BUNDLE, true).some(hasThree)).toBe(true);
  });
});
