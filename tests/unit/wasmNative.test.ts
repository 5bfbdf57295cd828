// The wasm module gives the same fields as the native build (<= 1e-12 relative) on shared
// fixtures. The native fields come from tests/native/solve_problem.cpp, which ctest runs (npm test
// runs ctest before vitest) into build/native/native-fields/<fixture>/; the wasm fields come from
// `hairsketch solve` (the bundled command line, the real wasm under Node) on the same PROBLEM.json.
import { existsSync, mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { bundledCli } from './cliBundle';

// The bundled command line (what `npx hairsketch` runs), built from web/cli/.
const { main } = await bundledCli();

const NATIVE_DIR = 'build/native/native-fields';
const FIXTURES = ['problem-small', 'problem-edits'];
const TOLERANCE = 1e-12;

const HOW =
  'run `cmake -S solver-cpp -B build/native -G Ninja && cmake --build build/native && ' +
  'ctest --test-dir build/native -R native_fields` first (npm test does this before vitest)';

const readF64 = (file: string): Float64Array => {
  const buf = readFileSync(file);
  return new Float64Array(buf.buffer.slice(buf.byteOffset, buf.byteOffset + buf.byteLength));
};

interface StepLine {
  step: number;
  constraints: number;
  added: number;
  removed: number;
  changed: number;
  method: string;
}
const parseLines = (text: string): StepLine[] =>
  text
    .trim()
    .split('\n')
    .map((l) => JSON.parse(l) as StepLine);

/** ‖a − b‖ / ‖b‖ (‖a − b‖ itself when b = 0, e.g. a step with no constraints). */
function relDiff(a: Float64Array, b: Float64Array): number {
  let num = 0;
  let den = 0;
  for (let i = 0; i < a.length; i++) {
    num += (a[i] - b[i]) ** 2;
    den += b[i] ** 2;
  }
  return den === 0 ? Math.sqrt(num) : Math.sqrt(num / den);
}

describe('wasm and native exact solver agree', () => {
  let out: string[] = [];
  beforeEach(() => {
    out = [];
    vi.spyOn(process.stdout, 'write').mockImplementation((s) => {
      out.push(String(s));
      return true;
    });
  });
  afterEach(() => vi.restoreAllMocks());

  for (const name of FIXTURES) {
    it(`gives the same fields step by step (${name}, --solver exact, <= ${TOLERANCE} relative)`, async () => {
      const fixture = `tests/fixtures/${name}.json`;
      const native = join(NATIVE_DIR, name);
      const nativeSteps = join(native, 'steps.jsonl');
      if (!existsSync(nativeSteps))
        throw new Error(`native fields missing (${nativeSteps} not found): ${HOW}`);
      if (readFileSync(join(native, 'problem.json'), 'utf8') !== readFileSync(fixture, 'utf8'))
        throw new Error(`native fields in ${native} are stale (${fixture} changed since): ${HOW}`);

      const dir = mkdtempSync(join(tmpdir(), 'hs-wasm-native-'));
      expect(await main(['solve', fixture, '--out', dir, '--solver', 'exact'])).toBe(0);
      const wasmLines = parseLines(out.join(''));
      const nativeLines = parseLines(readFileSync(nativeSteps, 'utf8'));
      // The same edits, step by step (the methods may differ: the cost model's rates are set
      // per target, and both methods are exact).
      const edits = (ls: StepLine[]) =>
        ls.map((l) => [l.constraints, l.added, l.removed, l.changed]);
      expect(edits(wasmLines)).toEqual(edits(nativeLines));
      expect(wasmLines.length).toBeGreaterThan(0);

      for (let step = 0; step < nativeLines.length; step++) {
        const got = readF64(join(dir, `field-${step}.f64`));
        const ref = readF64(join(native, `field-${step}.f64`));
        expect(got.length).toBe(ref.length);
        // A step with constraints has a non-zero field (else the comparison would be empty).
        if (nativeLines[step].constraints > 0) expect(ref.some((v) => v !== 0)).toBe(true);
        expect(
          relDiff(got, ref),
          `step ${step} (wasm ${wasmLines[step].method}, native ${nativeLines[step].method})`,
        ).toBeLessThanOrEqual(TOLERANCE);
      }
      // problem-edits goes through every path of the exact solver in wasm.
      if (name === 'problem-edits')
        expect(new Set(wasmLines.map((l) => l.method))).toEqual(
          new Set(['factor', 'update', 'rhs', 'refactor', 'zero']),
        );
    });
  }
});
