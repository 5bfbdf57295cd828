// Records, from a build of the app, each listed preset's session and the hash of the hair it
// grows, into tests/fixtures/hair-<label>.json; tests/e2e/oldSessions.spec.ts opens those sessions
// in the current build and expects the same hair, byte for byte.
//   RECORD_DIST=<dir> RECORD_LABEL=<label> npx tsx scripts/record-hair-fixtures.ts [preset ...]
// RECORD_DIST is a `vite build --outDir <dir>` of the build to record (e.g. a worktree of an older
// commit); the label names what it is (e.g. v3, the last session version before natural fall).
import { writeFileSync } from 'node:fs';
import { openWhenHairReady, previewAndBrowser, waitServer } from './previewServer';

const PORT = Number(process.env.RECORD_PORT ?? 4197);
const BASE = `http://127.0.0.1:${PORT}`;
const STRANDS = 2000;

async function main(): Promise<void> {
  const dist = process.env.RECORD_DIST;
  const label = process.env.RECORD_LABEL;
  if (!dist || !label || !/^[a-z0-9-]+$/.test(label)) {
    console.error('RECORD_DIST=<dir> and RECORD_LABEL=<[a-z0-9-]+> are needed');
    process.exit(2);
  }
  const presets = process.argv.slice(2).length
    ? process.argv.slice(2)
    : ['default', 'fig8', 'curly'];
  const { server, browser } = await previewAndBrowser(dist, PORT);
  const out: { preset: string; strands: number; session: unknown; hairHash: string }[] = [];
  try {
    await waitServer(BASE);
    for (const preset of presets) {
      const page = await openWhenHairReady(browser, `${BASE}/?preset=${preset}&strands=${STRANDS}`);
      const session = await page.evaluate(() => window.hairsketch.session());
      const hairHash = await page.evaluate(() => window.hairsketch.hairHash());
      const strands = Number(await page.getByTestId('status').getAttribute('data-strands'));
      if (!hairHash) throw new Error(`${preset}: no hair`);
      out.push({ preset, strands, session, hairHash });
      console.log(`${preset}: ${strands} strands, hair ${hairHash}`);
      await page.close();
    }
  } finally {
    await browser.close();
    server.kill();
  }
  const file = `tests/fixtures/hair-${label}.json`;
  writeFileSync(file, `${JSON.stringify(out, null, 1)}\n`);
  console.log(`wrote ${file}`);
}

await main();
