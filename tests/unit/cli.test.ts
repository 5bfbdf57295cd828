// `hairsketch solve` against an independent dense solve of method S2.3 written here from S2.2.
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { beforeEach, describe, expect, it } from 'vitest';
import { constraintStates, decodeProblem, type Problem } from '../../web/cli/problem';
import { captureOutput } from './captureOutput';
import { bundledCli } from './cliBundle';

// The bundled command line (what `npx hairsketch` runs), built from web/cli/.
const { main } = await bundledCli();

const FIXTURE = 'tests/fixtures/problem-small.json';

/** Dense (DᵀD + ω²S) T = ω² S C, built point by point from the definition, solved by Cholesky. */
function denseSolve(p: Problem, state: Map<number, [number, number, number]>): Float64Array {
  const [nx, ny, nz] = p.grid;
  const n = nx * ny * nz;
  const D = Array.from({ length: n }, () => new Float64Array(n));
  for (let k = 0; k < nz; k++)
    for (let j = 0; j < ny; j++)
      for (let i = 0; i < nx; i++) {
        const row = i + nx * (j + ny * k);
        const nb: number[] = [];
        for (const [a, b, c] of [
          [i - 1, j, k],
          [i + 1, j, k],
          [i, j - 1, k],
          [i, j + 1, k],
          [i, j, k - 1],
          [i, j, k + 1],
        ])
          if (a >= 0 && b >= 0 && c >= 0 && a < nx && b < ny && c < nz)
            nb.push(a + nx * (b + ny * c));
        D[row][row] = -1;
        for (const q of nb) D[row][q] = 1 / nb.length;
      }
  const w2 = p.omega * p.omega;
  const M = Array.from({ length: n }, () => new Float64Array(n));
  for (let a = 0; a < n; a++)
    for (let b = 0; b < n; b++) {
      let s = 0;
      for (let r = 0; r < n; r++) s += D[r][a] * D[r][b];
      M[a][b] = s;
    }
  const B = new Float64Array(3 * n);
  for (const [idx, t] of state) {
    M[idx][idx] += w2;
    for (let c = 0; c < 3; c++) B[3 * idx + c] = w2 * t[c];
  }
  if (state.size === 0) return new Float64Array(3 * n);
  // Cholesky M = L Lᵀ.
  const L = Array.from({ length: n }, () => new Float64Array(n));
  for (let j = 0; j < n; j++) {
    let d = M[j][j];
    for (let k = 0; k < j; k++) d -= L[j][k] * L[j][k];
    L[j][j] = Math.sqrt(d);
    for (let i = j + 1; i < n; i++) {
      let s = M[i][j];
      for (let k = 0; k < j; k++) s -= L[i][k] * L[j][k];
      L[i][j] = s / L[j][j];
    }
  }
  const T = new Float64Array(3 * n);
  for (let c = 0; c < 3; c++) {
    const y = new Float64Array(n);
    for (let i = 0; i < n; i++) {
      let s = B[3 * i + c];
      for (let k = 0; k < i; k++) s -= L[i][k] * y[k];
      y[i] = s / L[i][i];
    }
    for (let i = n - 1; i >= 0; i--) {
      let s = y[i];
      for (let k = i + 1; k < n; k++) s -= L[k][i] * T[3 * k + c];
      T[3 * i + c] = s / L[i][i];
    }
  }
  return T;
}

const relErr = (a: Float64Array, b: Float64Array) => {
  let num = 0;
  let den = 0;
  for (let i = 0; i < a.length; i++) {
    num += (a[i] - b[i]) ** 2;
    den += b[i] ** 2;
  }
  return den === 0 ? Math.sqrt(num) : Math.sqrt(num / den);
};

describe('hairsketch solve', () => {
  let out: string[] = [];
  let err: string[] = [];
  beforeEach(() => {
    out = [];
    err = [];
  });
  captureOutput(
    (s) => out.push(s),
    (s) => err.push(s),
  );

  // Exact factorisation: rounding only. Iterative paths: their stopping bound (1e-6 or tighter).
  const tolerance: Record<string, number> = { cg: 1e-6, exact: 1e-10, fast: 1e-6, auto: 1e-6 };
  for (const solver of Object.keys(tolerance)) {
    it(`writes fields equal to a dense solve, step by step (--solver ${solver})`, async () => {
      const dir = mkdtempSync(join(tmpdir(), 'hs-cli-'));
      const code = await main(['solve', FIXTURE, '--out', dir, '--solver', solver]);
      expect(err.join('')).toBe('');
      expect(code).toBe(0);
      const decoded = decodeProblem(readFileSync(FIXTURE, 'utf8'));
      if (!decoded.ok) throw new Error(decoded.error);
      const lines = out
        .join('')
        .trim()
        .split('\n')
        .map((l) => JSON.parse(l));
      expect(lines).toHaveLength(4);
      expect(lines.map((l) => [l.constraints, l.added, l.removed, l.changed])).toEqual([
        [4, 4, 0, 0],
        [4, 1, 1, 1],
        [0, 0, 4, 0],
        [1, 1, 0, 0],
      ]);
      let step = 0;
      for (const state of constraintStates(decoded.value)) {
        const buf = readFileSync(join(dir, `field-${step}.f64`));
        const got = new Float64Array(
          buf.buffer.slice(buf.byteOffset, buf.byteOffset + buf.byteLength),
        );
        expect(got.length).toBe(3 * 120);
        const ref = denseSolve(decoded.value, state);
        expect(relErr(got, ref)).toBeLessThan(tolerance[solver]);
        step++;
      }
    });
  }

  it('rejects bad input with a one-line error and a non-zero exit', async () => {
    const cases: Array<[string, RegExp]> = [
      ['{"grid":[4,5,6],"steps":[],"extra":1}', /unknown key "extra"/],
      ['{"grid":[4,5,6],"steps":[{"set":[[4,0,0,1,0,0]]}]}', /outside the grid/],
      ['{"grid":[4,5,6],"steps":[{"set":[[1,0,0,1e999,0,0]]}]}', /not finite/],
      ['{"grid":[400,400,400],"steps":[]}', /memory cap/],
      ['{"grid":[4,5],"steps":[]}', /"grid" must be/],
      ['not json', /not valid JSON/],
    ];
    for (const [text, re] of cases) {
      const d = decodeProblem(text);
      expect(d.ok).toBe(false);
      if (!d.ok) expect(d.error).toMatch(re);
    }
    expect(await main(['solve', 'tests/fixtures/does-not-exist.json', '--out', tmpdir()])).not.toBe(
      0,
    );
    expect(await main(['solve', FIXTURE])).not.toBe(0);
    expect(await main(['frobnicate'])).not.toBe(0);
    expect(err.every((l) => l.trim().split('\n').length === 1)).toBe(true);
  });
});
