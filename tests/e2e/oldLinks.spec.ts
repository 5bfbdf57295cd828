// Share links of every format ever written reopen to the very same hair: each fixture of
// tests/fixtures/links.json is a link made by the encoder of the build that wrote its format,
// with the hash of the hair it grew then (scripts/record-link-fixtures.ts); the current build
// opens the link and must grow the same bytes.
import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import { settled, watchConsole } from './helpers';

interface LinkFixture {
  name: string;
  format: number;
  covers: string;
  link: string;
  strands: number;
  hairHash: string;
}
const fixtures = JSON.parse(readFileSync('tests/fixtures/links.json', 'utf8')) as LinkFixture[];
// Each session once, by its oldest link: tests/unit/linkFixtures.test.ts shows that every version
// of a session's link opens to the very same session, and each fixture records the same hair.
const oldest = fixtures.filter((f, i) => fixtures.findIndex((g) => g.name === f.name) === i);

for (const f of oldest)
  test(`a version ${f.format} link (${f.name}) grows the hair it grew when it was made`, async ({
    page,
  }) => {
    const errors = watchConsole(page);
    await page.goto(`/?strands=${f.strands}${f.link}`);
    const s = await settled(page);
    const hash = await page.evaluate(() => window.hairsketch.hairHash());
    console.log(`${f.name} (link version ${f.format}): ${s.strands} strands, hair ${hash}`);
    expect(hash).toBe(f.hairHash);
    expect(errors).toEqual([]);
  });
