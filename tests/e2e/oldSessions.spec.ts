// Sessions made before natural fall (version 3) reopen to the very same hair: each fixture of
// tests/fixtures/hair-v3.json was recorded from the build before it (scripts/record-hair-fixtures.ts
// on commit eff00b9: the preset's session and the hash of its displayed strands); the current
// build opens the session and must grow the same bytes.
import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import { settled } from './helpers';

interface Fixture {
  preset: string;
  strands: number;
  session: { version: number; fall?: boolean };
  hairHash: string;
}
const fixtures = JSON.parse(readFileSync('tests/fixtures/hair-v3.json', 'utf8')) as Fixture[];

for (const f of fixtures)
  test(`a version 3 session (${f.preset}) grows the hair it grew before natural fall`, async ({
    page,
  }) => {
    expect(f.session.version).toBe(3);
    await page.goto(`/?preset=empty&strands=${f.strands}`);
    const s0 = await settled(page);
    await page.evaluate((j) => window.hairsketch.replaceSession(j), f.session);
    const s1 = await settled(page, s0.revision);
    const now = await page.evaluate(() => window.hairsketch.session() as { fall?: boolean });
    expect(now.fall).toBeUndefined();
    const hash = await page.evaluate(() => window.hairsketch.hairHash());
    console.log(
      `${f.preset} (version 3): ${s1.strands} strands, hair ${hash} (recorded ${f.hairHash})`,
    );
    expect(s1.strands).toBe(f.strands);
    expect(hash).toBe(f.hairHash);
  });
