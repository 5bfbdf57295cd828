// The `hairsketch` command line. Runs the same wasm module as the app, under Node.
//   hairsketch solve PROBLEM.json --out DIR [--solver exact|fast|auto|cg]
//   hairsketch grow SESSION --out FILE [--format …] [--grid …] [--solver …] [--strands N] (grow.ts)
// Exit codes: 0 done, 2 bad input (a one-line message on stderr), 1 internal error.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadRawSolver } from '../solver/wasmEngine';
import { CliError } from './errors';
import { runGrow } from './grow';
import { constraintStates, decodeProblem } from './problem';

const SOLVE_USAGE = 'usage: hairsketch solve PROBLEM.json --out DIR [--solver exact|fast|auto|cg]';
const SOLVERS = ['exact', 'fast', 'auto', 'cg'];

function parseArgs(argv: string[]): {
  command: string;
  problem: string;
  out: string;
  solver: string;
} {
  const [command, ...rest] = argv;
  if (command !== 'solve')
    throw new CliError(
      command
        ? `unknown command "${command}" (solve or grow); ${SOLVE_USAGE}`
        : `no command (solve or grow); ${SOLVE_USAGE}`,
    );
  let problem = '';
  let out = '';
  let solver = 'auto';
  for (let i = 0; i < rest.length; i++) {
    const a = rest[i];
    if (a === '--out' || a === '--solver') {
      const v = rest[++i];
      if (v === undefined) throw new CliError(`${a} needs a value; ${SOLVE_USAGE}`);
      if (a === '--out') out = v;
      else solver = v;
    } else if (a.startsWith('--')) {
      throw new CliError(`unknown option "${a}"; ${SOLVE_USAGE}`);
    } else if (!problem) {
      problem = a;
    } else {
      throw new CliError(`unexpected argument "${a}"; ${SOLVE_USAGE}`);
    }
  }
  if (!problem || !out) throw new CliError(SOLVE_USAGE);
  if (!SOLVERS.includes(solver))
    throw new CliError(`unknown solver "${solver}" (one of ${SOLVERS.join(', ')})`);
  return { command, problem, out, solver };
}

/** The wasm module's bytes (built by wasm-build/build.sh into web/generated/). */
function wasmBinary(): Uint8Array {
  const here = dirname(fileURLToPath(import.meta.url));
  return readFileSync(resolve(here, '../generated/hairsolver.wasm'));
}

export async function main(argv: string[]): Promise<number> {
  try {
    if (argv[0] === 'grow') {
      await runGrow(argv.slice(1), { wasmBinary: wasmBinary() }, (line) =>
        process.stdout.write(`${line}\n`),
      );
      return 0;
    }
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
    const solver = await loadRawSolver(args.solver, { wasmBinary: wasmBinary() });
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
    return e instanceof CliError ? e.exitCode : 1;
  }
}
