// The solver's wasm module by isolation: served cross-origin isolated (COOP/COEP, the default
// project) the worker runs the threaded module; served without those headers (the
// "not-isolated" project: HAIRSKETCH_NO_ISOLATION=1) it falls back to the single-threaded one,
// and the app works the same. The status tooltip says which.
import { expect, test } from '@playwright/test';
import { settled, watchConsole } from './helpers';

const SCENE = '/?strands=2500';

test('the solver module follows cross-origin isolation and the tooltip says which', async ({
  page,
}, info) => {
  const isolatedProject = info.project.name !== 'not-isolated';
  const errors = watchConsole(page);
  const response = await page.goto(SCENE);
  const headers = response?.headers() ?? {};
  expect(headers['content-security-policy']).toContain("script-src 'self' 'wasm-unsafe-eval'");
  expect(await page.evaluate(() => typeof SharedArrayBuffer === 'function')).toBe(isolatedProject);
  expect(await page.evaluate(() => crossOriginIsolated)).toBe(isolatedProject);
  const s = await settled(page);
  expect(s.strands).toBeGreaterThan(500);
  const title = await page.getByTestId('status').getAttribute('title');
  if (isolatedProject) {
    expect(headers['cross-origin-opener-policy']).toBe('same-origin');
    expect(headers['cross-origin-embedder-policy']).toBe('require-corp');
    // threads: min(4, logical cores); this machine has 2 (1 solver worker + 1 pthread)
    const cores = await page.evaluate(() => navigator.hardwareConcurrency);
    expect(title).toContain(`threads: ${Math.max(1, Math.min(4, cores))}`);
  } else {
    expect(headers['cross-origin-opener-policy']).toBeUndefined();
    expect(title).toContain('single-threaded: not cross-origin isolated');
  }
  expect(errors).toEqual([]);
});
