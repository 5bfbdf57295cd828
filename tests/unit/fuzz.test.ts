// The bounded fuzz run of npm test: every target of tests/fuzz/targets/ (the session reader,
// the link codec, the CLI problem reader, the export writers, the reader of exports) with a fixed
// seed and a count sized for a few seconds each on a 2-core machine. The long run with random
// seeds and counts is `npm run fuzz` (tests/fuzz/run.ts).
import { test } from '@fast-check/vitest';
import { describe } from 'vitest';
import { loadTargets } from '../fuzz/targets';

const SEED = 20070807;

/** Cases per target (about 2 s each here). */
const RUNS: Record<string, number> = {
  'session reader': 1000,
  'session file reader': 1500,
  'link codec': 400,
  'CLI problem reader': 5000,
  'export writers': 450,
  'export reader': 4000,
};

const targets = await loadTargets();

describe('fuzz (fixed seed, bounded)', () => {
  for (const target of targets)
    test.prop([target.arbitrary], { seed: SEED, numRuns: RUNS[target.name] ?? 500 })(
      `${target.name}: no throw escapes, accepted inputs round-trip, rejections say what is wrong`,
      async (input) => {
        try {
          await target.run(input);
        } catch (e) {
          // the case spelled out (fast-check prints its description, shrunk)
          let what: string;
          try {
            what = target.explain(input);
          } catch {
            what = '(cannot explain)';
          }
          throw new Error(`${e instanceof Error ? e.message : String(e)}\n  input: ${what}`);
        }
      },
    );
});
