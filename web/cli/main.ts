// The `hairsketch` command line. Runs the same wasm module as the app, under Node.
//   hairsketch solve PROBLEM.json --out DIR [--solver exact|fast|auto|cg] [--max-seconds N]
//                    [--progress-seconds N]
//   hairsketch grow SESSION --out FILE [--format …] [--grid …] [--solver …] [--strands N] (grow.ts)
//   hairsketch render SESSION|LINK --out FILE.png [--view …] [--size WxH] (render.ts)
// Exit codes: 0 done, 2 bad input (a one-line message on stderr; a grid over the memory cap is
// refused by the solver's estimate before it allocates), 3 stopped at the --max-seconds time cap,
// 1 internal error. Iterative solves print a JSON progress line to stderr every
// --progress-seconds (default 5).
import { mkdirSync, readFileSync, writeFileSync, writeSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { SolverError } from '../solver/engine';
import { loadRawSolver, type RawSolveProgress } from '../solver/wasmEngine';
import { CliError, parseSeconds } from './errors';
import { constraintStates, decodeProblem } from './problem';

const SOLVE_USAGE =
  'usage: hairsketch solve PROBLEM.json --out DIR [--solver exact|fast|auto|cg] [--max-seconds N] [--progress-seconds N]';
/** Default time cap of a `solve` run (seconds). */
export const DEFAULT_MAX_SECONDS = 600;
/** Exit code of a run stopped at its time cap. */
export const EXIT_TIME_CAP = 3;
const SOLVERS = ['exact', 'fast', 'auto', 'cg'];

function parseArgs(argv: string[]): {
  command: string;
  problem: string;
  out: string;
  solver: string;
  maxSeconds: number;
  progressSeconds: number;
} {
  const [command, ...rest] = argv;
  if (command !== 'solve')
    throw new CliError(
      command
        ? `unknown command "${command}" (solve, grow or render); ${SOLVE_USAGE}`
        : `no command (solve, grow or render); ${SOLVE_USAGE}`,
    );
  let problem = '';
  let out = '';
  let solver = 'auto';
  let maxSeconds = DEFAULT_MAX_SECONDS;
  let progressSeconds = 5;
  for (let i = 0; i < rest.length; i++) {
    const a = rest[i];
    if (a === '--out' || a === '--solver' || a === '--max-seconds' || a === '--progress-seconds') {
      const v = rest[++i];
      if (v === undefined) throw new CliError(`${a} needs a value; ${SOLVE_USAGE}`);
      if (a === '--out') out = v;
      else if (a === '--solver') solver = v;
      else if (a === '--max-seconds') maxSeconds = parseSeconds(a, v);
      else progressSeconds = parseSeconds(a, v);
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
  return { command, problem, out, solver, maxSeconds, progressSeconds };
}

// Set by the bundle's build (vite.cli.config.ts), which puts the wasm module beside the bundle.
declare const __CLI_WASM_BESIDE__: string | undefined;

/** The wasm module's bytes (built by wasm-build/build.sh into web/generated/; the bundled
 *  command line carries a copy beside itself). */
function wasmBinary(): Uint8Array {
  const here = dirname(fileURLToPath(import.meta.url));
  const beside = typeof __CLI_WASM_BESIDE__ === 'string' ? __CLI_WASM_BESIDE__ : null;
  return readFileSync(resolve(here, beside ?? '../generated/hairsolver.wasm'));
}

export async function main(argv: string[]): Promise<number> {
  try {
    if (argv[0] === 'grow') {
      // Loaded only for `grow`: it brings the head code (three.js and its loaders), which `solve`
      // does not need and would otherwise pay for at every start.
      const { runGrow } = await import('./grow');
      await runGrow(argv.slice(1), { wasmBinary: wasmBinary() }, (line) =>
        process.stdout.write(`${line}\n`),
      );
      return 0;
    }
    if (argv[0] === 'render') {
      // Loaded only for `render`: it brings the browser launcher.
      const { runRender } = await import('./render');
      await runRender(argv.slice(1), (line) => process.stdout.write(`${line}\n`));
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
      // The solver's memory estimate refuses a grid over the cap here, before allocating.
      try {
        solver.setGrid(p.grid, p.omega);
      } catch (e) {
        if (
          e instanceof SolverError &&
          (e.kind === 'over_memory_cap' || e.kind === 'invalid_input')
        )
          throw new CliError(`${p.grid.join('x')} grid: ${e.message}`);
        throw e;
      }
      const start = performance.now();
      const elapsed = () => (performance.now() - start) / 1000;
      let step = 0;
      let stopped: RawSolveProgress | null = null;
      let lastPrint = 0;
      // Iterative solvers report every 250 ms of iterations; a line goes out every
      // --progress-seconds, and past --max-seconds the solve is told to stop.
      solver.onProgress(Math.min(250, 1000 * args.progressSeconds), (pr) => {
        const t = elapsed();
        if (t > args.maxSeconds) {
          stopped = pr;
          return false;
        }
        if (t - lastPrint >= args.progressSeconds) {
          lastPrint = t;
          writeSync(
            2,
            `${JSON.stringify({
              progress: {
                step,
                iterations: pr.iterations,
                errorEstimate: Number.isFinite(pr.errorEstimate) ? pr.errorEstimate : null,
                relResidual: pr.relResidual,
                seconds: Number(t.toFixed(1)),
              },
            })}\n`,
          );
        }
        return true;
      });
      const timeCap = (pr: RawSolveProgress | null) =>
        new CliError(
          `stopped at the time cap of ${args.maxSeconds} s (--max-seconds) in step ${step}` +
            (pr
              ? ` after ${pr.iterations} iterations (relative residual ${pr.relResidual.toExponential(2)}` +
                (Number.isFinite(pr.errorEstimate)
                  ? `, error estimate ${pr.errorEstimate.toExponential(2)})`
                  : ')')
              : '') +
            `; fields of steps before ${step} are written`,
          EXIT_TIME_CAP,
        );
      for (const state of constraintStates(p)) {
        if (elapsed() > args.maxSeconds) throw timeCap(null);
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
        try {
          solver.solve();
        } catch (err) {
          if (stopped) throw timeCap(stopped);
          throw err;
        }
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
