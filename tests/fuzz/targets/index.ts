// Fuzz targets, one file each in this folder (listed below, in report order): everything that
// reads what comes in from outside (a session file, a share link, a CLI problem, an exported
// file) and every export writer, each with its arbitraries and its property ("nothing a user
// makes is lost, whatever comes in"):
//   - no throw escapes a reader or a writer;
//   - accepted inputs round-trip (a session read back after JSON, a link re-encoded, the
//     session carried by an export);
//   - rejected inputs say what is wrong on one short line (the session reader names a field).
// tests/unit/fuzz.test.ts runs each with a fixed seed and a bounded count (npm test);
// tests/fuzz/run.ts (npm run fuzz) runs 100,000 cases each with random seeds and counts.
import { makeContext } from '../context';
import type { FuzzTarget } from '../outcomes';
import { exportReadTarget } from './exportReader';
import { exportTarget } from './exportWriters';
import { linkTarget } from './link';
import { problemTarget } from './problem';
import { sessionTarget } from './session';
import { sessionFileTarget } from './sessionFile';

/** All targets, in report order. */
export async function loadTargets(): Promise<FuzzTarget<never>[]> {
  const ctx = await makeContext();
  return [
    sessionTarget(ctx),
    sessionFileTarget(ctx),
    linkTarget(ctx),
    problemTarget(ctx),
    exportTarget(ctx),
    exportReadTarget(ctx),
  ] as unknown as FuzzTarget<never>[];
}
