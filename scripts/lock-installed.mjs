// Exit 0 when node_modules holds exactly what package-lock.json pins (as npm recorded in
// node_modules/.package-lock.json after installing), else 1. Compared by content, not by file
// times: a fresh checkout's lock file is newer than anything, yet may match what is installed.
// Optional packages for other platforms are in the lock but never installed, so only packages
// that are installed or not optional must match.
import { readFileSync } from 'node:fs';

const read = (f) => {
  try {
    return JSON.parse(readFileSync(f, 'utf8')).packages ?? {};
  } catch {
    return null;
  }
};
const want = read('package-lock.json');
const have = read('node_modules/.package-lock.json');
const same = (a, b) => a.version === b.version && a.integrity === b.integrity;
const ok =
  want !== null &&
  have !== null &&
  Object.entries(have).every(([k, v]) => want[k] && same(want[k], v)) &&
  Object.entries(want).every(([k, v]) => k === '' || v.optional || (have[k] && same(have[k], v)));
process.exit(ok ? 0 : 1);
