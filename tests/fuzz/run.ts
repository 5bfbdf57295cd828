// npm run fuzz: the long fuzz run. Every target of tests/fuzz/targets/ for FUZZ_RUNS cases
// (default 100,000) with a random seed (FUZZ_SEED to replay one; FUZZ_TARGETS=session,link to
// pick targets by a word of their name). It counts, per target, the cases, those accepted and
// rejected by the code under test, the throws that escaped it and the property violations,
// without stopping at the first (FUZZ_JOBS targets at once, default 2, one process each); when there are any it replays the same seed until the first
// failure, lets fast-check shrink it, and prints the counterexample. Exit code 1 on any failure.
import { spawn } from 'node:child_process';
import fc from 'fast-check';
import { EscapedThrow, type FuzzTarget, Violation } from './outcomes';
import { loadTargets } from './targets';

interface Counts {
  cases: number;
  accepted: number;
  rejected: number;
  escaped: number;
  violations: number;
  first: string[];
}

const runs = Number(process.env.FUZZ_RUNS ?? 100_000);
const fixedSeed = process.env.FUZZ_SEED === undefined ? null : Number(process.env.FUZZ_SEED);
const only = (process.env.FUZZ_TARGETS ?? '')
  .split(',')
  .map((s) => s.trim().toLowerCase())
  .filter((s) => s !== '');
if (!Number.isInteger(runs) || runs < 1) throw new Error('FUZZ_RUNS must be a positive integer');

function record<T>(counts: Counts, target: FuzzTarget<T>, input: T, e: unknown): void {
  if (e instanceof EscapedThrow) counts.escaped++;
  else counts.violations++;
  if (counts.first.length < 3) {
    let what: string;
    try {
      what = target.explain(input);
    } catch (x) {
      what = `(cannot explain: ${String(x)})`;
    }
    counts.first.push(`${e instanceof Error ? e.message : String(e)}\n      input: ${what}`);
  }
}

async function runTarget<T>(target: FuzzTarget<T>, seed: number): Promise<Counts> {
  const counts: Counts = {
    cases: 0,
    accepted: 0,
    rejected: 0,
    escaped: 0,
    violations: 0,
    first: [],
  };
  const count = (o: 'accepted' | 'rejected') => {
    counts[o]++;
  };
  const params = { seed, numRuns: runs };
  // Counting: the property itself never fails, it tallies.
  const property = fc.asyncProperty(target.arbitrary, async (input) => {
    counts.cases++;
    try {
      count(await target.run(input));
    } catch (e) {
      if (!(e instanceof EscapedThrow) && !(e instanceof Violation)) throw e;
      record(counts, target, input, e);
    }
  });
  await fc.assert(property, params);
  return counts;
}

/** Replays `seed` until the first failure and returns fast-check's report (shrunk). */
async function replay<T>(target: FuzzTarget<T>, seed: number): Promise<string> {
  const property = fc.asyncProperty(target.arbitrary, async (input) => {
    await target.run(input);
  });
  const details = await fc.check(property, {
    seed,
    numRuns: runs,
    interruptAfterTimeLimit: 120_000,
    markInterruptAsFailure: false,
  });
  if (!details.failed) return '(the replay did not fail again)';
  const report = fc.defaultReportMessage(details) ?? '';
  const explained =
    details.counterexample !== null ? target.explain(details.counterexample[0] as T) : '';
  const cut = (s: string, n: number) => (s.length > n ? `${s.slice(0, n)}…` : s);
  return `${cut(report, 3000)}\n    shrunk case: ${cut(explained, 1500)}`;
}

const pad = (s: string | number, n: number) => String(s).padStart(n);

interface Result {
  name: string;
  seed: number;
  counts: Counts;
  secs: number;
  failure: string | null;
}

/** One target in this process. */
async function runOne(target: FuzzTarget<unknown>, seed: number): Promise<Result> {
  const t = performance.now();
  const counts = await runTarget(target, seed);
  const secs = (performance.now() - t) / 1000;
  let failure: string | null = null;
  if (counts.escaped + counts.violations > 0) {
    const shrunk = await replay(target, seed);
    failure = `${target.name} (replay: FUZZ_SEED=${seed} FUZZ_TARGETS="${target.name}"):\n  first failures:\n    ${counts.first.join('\n    ')}\n  shrunk:\n    ${shrunk.replace(/\n/g, '\n    ')}`;
  }
  return { name: target.name, seed, counts, secs, failure };
}

/** One target in a child process (this script with FUZZ_CHILD set), so that FUZZ_JOBS targets
 *  run at once; the child prints its result as the last line of its output. */
function runChild(name: string, seed: number): Promise<Result> {
  return new Promise((resolve, reject) => {
    const child = spawn(process.execPath, [...process.execArgv, process.argv[1]], {
      env: { ...process.env, FUZZ_CHILD: name, FUZZ_SEED: String(seed) },
      stdio: ['ignore', 'pipe', 'inherit'],
    });
    let out = '';
    child.stdout.on('data', (d) => {
      out += d;
    });
    child.on('error', reject);
    child.on('close', (code) => {
      const line = out.trim().split('\n').pop() ?? '';
      if (!line.startsWith(RESULT)) reject(new Error(`${name}: the child exited ${code}: ${out}`));
      else resolve(JSON.parse(line.slice(RESULT.length)));
    });
  });
}

const RESULT = 'FUZZ_RESULT ';

function row(r: Result): string {
  const c = r.counts;
  return `${r.name.padEnd(20)} ${pad(r.seed, 11)} ${pad(c.cases, 8)} ${pad(c.accepted, 8)} ${pad(c.rejected, 8)} ${pad(c.escaped, 7)} ${pad(c.violations, 10)} ${pad(r.secs.toFixed(1), 7)}`;
}

async function main() {
  const t0 = performance.now();
  const all = await loadTargets();
  const child = process.env.FUZZ_CHILD;
  if (child !== undefined) {
    const target = all.find((t) => t.name === child);
    if (!target) throw new Error(`no target ${child}`);
    const r = await runOne(target, fixedSeed ?? 0);
    console.log(RESULT + JSON.stringify(r));
    return;
  }
  const targets = all.filter(
    (t) => only.length === 0 || only.some((w) => t.name.toLowerCase().includes(w)),
  );
  const jobs = Math.max(1, Number(process.env.FUZZ_JOBS ?? 2) | 0);
  console.log(`fuzz: ${runs} cases per target, ${jobs} at a time`);
  const results: Result[] = [];
  let next = 0;
  const worker = async () => {
    while (next < targets.length) {
      const target = targets[next++];
      const seed = fixedSeed ?? (Math.random() * 2 ** 31) | 0;
      const r = jobs === 1 ? await runOne(target, seed) : await runChild(target.name, seed);
      console.log(row(r));
      results.push(r);
    }
  };
  await Promise.all(Array.from({ length: jobs }, worker));
  results.sort(
    (a, b) =>
      targets.findIndex((t) => t.name === a.name) - targets.findIndex((t) => t.name === b.name),
  );
  const header = `${'target'.padEnd(20)} ${pad('seed', 11)} ${pad('cases', 8)} ${pad('accepted', 8)} ${pad('rejected', 8)} ${pad('escaped', 7)} ${pad('violations', 10)} ${pad('time s', 7)}`;
  console.log(`\n${header}\n${results.map(row).join('\n')}`);
  console.log(`total ${((performance.now() - t0) / 1000).toFixed(1)} s (wall)`);
  const failures = results.map((r) => r.failure).filter((f) => f !== null);
  if (failures.length > 0) {
    console.log(`\nFAILURES\n\n${failures.join('\n\n')}`);
    process.exitCode = 1;
  }
}

await main();
