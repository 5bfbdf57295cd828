// The `hairsketch` command line. Runs the same wasm module as the app, under Node.
//   hairsketch solve PROBLEM.json --out DIR [--solver exact|fast|auto|cg]
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadRawSolver } from '../solver/wasmEngine';
import { constraintStates, decodeProblem } from './problem';

const USAGE = 'usage: hairsketch solve PROBLEM.json --out DIR [--solver exact|fast|auto|cg]';
const SOLVERS = ['exact', 'fast', 'auto', 'cg'];

class CliError extends Error {}

function parseArgs(argv: string[]): {
  command: string;
  problem: string;
  out: string;
  solver: string;
} {
  const [command, ...rest] = argv;
  if (command !== 'solve')
    throw new CliError(command ? `unknown command "${command}"; ${USAGE}` : USAGE);
  let problem = '';
  let out = '';
  let solver = 'auto';
  for (let i = 0; i < rest.length; i++) {
    const a = rest[i];
    if (a === '--out' || a === '--solver') {
      const v = rest[++i];
      if (v === undefined) throw new CliError(`${a} needs a value; ${USAGE}`);
      if (a === '--out') out = v;
      else solver = v;
    } else if (a.startsWith('--')) {
      throw new CliError(`unknown option "${a}"; ${USAGE}`);
    } else if (!problem) {
      problem = a;
    } else {
      throw new CliError(`unexpected argument "${a}"; ${USAGE}`);
    }
  }
  if (!problem || !out) throw new CliError(USAGE);
  if (!SOLVERS.includes(solver))
    throw new CliError(`unknown solver "${solver}" (one of ${SOLVERS.join(', ')})`);
  return { command, problem, out, solver };
}

export async function main(argv: string[]): Promise<number> {
  try {
    const args = parseArgs(argv);
    let text: string;
    try {
      text = readFileSync(args.problem, 'utf8');
    } catch (e) {
      throw new CliError(`cannot read ${args.problem}: ${(e as NodeJS.ErrnoException).code ?? e}`);
    }
    const decoded = decodeProblem(text);
    if (!decoded.ok) throw new CliError(`${args.problem}: ${decoded.error}`);
    const p = decoded.value;
    mkdirSync(args.out, { recursive: true });
    const here = dirname(fileURLToPath(import.meta.url));
    const wasmBinary = readFileSync(resolve(here, '../generated/hairsolver.wasm'));
    const solver = await loadRawSolver(args.solver, { wasmBinary });
    try {
      solver.setGrid(p.grid, p.omega);
      let step = 0;
      for (const state of constraintStates(p)) {
        const index = new Int32Array(state.size);
        const target = new Float64Array(3 * state.size);
        let e = 0;
        for (const [idx, t] of [...state.entries()].sort((a, b) => a[0] - b[0])) {
          index[e] = idx;
          target.set(t, 3 * e);
          e++;
        }
        const t0 = performance.now();
        solver.setConstraints(index, target);
        solver.solve();
        const ms = performance.now() - t0;
        const field = solver.field();
        writeFileSync(
          join(args.out, `field-${step}.f64`),
          new Uint8Array(field.buffer, field.byteOffset, field.byteLength),
        );
        const st = solver.stats();
        process.stdout.write(
          `${JSON.stringify({
            step,
            constraints: state.size,
            added: st.added,
            removed: st.removed,
            changed: st.changed,
            method: st.method,
            iterations: st.iterations,
            milliseconds: Number(ms.toFixed(2)),
          })}\n`,
        );
        step++;
      }
    } finally {
      solver.dispose();
    }
    return 0;
  } catch (e) {
    const msg = e instanceof Error ? e.message : String(e);
    process.stderr.write(`hairsketch: ${msg.split('\n')[0]}\n`);
    return e instanceof CliError ? 2 : 1;
  }
}
