// `hairsketch grow`: a saved session (or a share link, or an export that carries one) to a hair
// file, through the same pipeline as the app's export (export/growSession.ts, then
// export/writeExport.ts), so the same session gives the same file.
//   hairsketch grow SESSION --out FILE [--format FORMAT (export/formats.ts)] [--grid 25k|50k|100k|250k]
//                   [--solver fast|exact] [--strands N] [--cards N] [--with-head|--no-head] [--head FILE]
//                   [--motion settle|head-turn|nod|wind [--frames N]] (a .usda with time samples)
// The head is the session's (cli/head.ts): the built-in one, or a loaded head's file embedded in
// the session file or given with --head FILE (OBJ, glTF/GLB, PLY, STL).
// The file is written to a temporary name beside FILE and renamed into place only when complete.
import {
  closeSync,
  fsyncSync,
  openSync,
  readFileSync,
  renameSync,
  statSync,
  unlinkSync,
  writeSync,
} from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
import { cardCountProblem } from '../export/cardCount';
import { exportHeadWithBody } from '../export/exportHead';
import {
  EXPORT_FORMAT_IDS,
  EXPORT_FORMATS,
  type ExportFormat,
  exportFormatsWith,
  extensionsInWords,
  formatFromFileName,
  isExportFormat,
  MOTION_EXPORT,
} from '../export/formats';
import { growSessionHair } from '../export/growSession';
import { motionFramesProblem, motionNameProblem, simulateMotion } from '../export/motionExport';
import { readExportedSession } from '../export/readExport';
import { exportedCounts } from '../export/strandsForExport';
import type { ExportHead } from '../export/types';
import { writeExport } from '../export/writeExport';
import { builtinBody } from '../head/buildBody';
import { contentKey } from '../model/curveSet';
import { GRID_PRESETS, type GridPreset, isGridPreset } from '../model/grid';
import { MOTION_DEFAULT_FRAMES, MOTIONS, type MotionName } from '../model/motion';
import type { SessionState } from '../model/session';
import { sessionGrid } from '../model/session';
import { type HeadFileData, readSessionFile } from '../model/sessionFile';
import { decodeSessionLink } from '../model/sessionLink';
import { SolverError } from '../solver/engine';
import { type LoadOptions, loadSolverEngine } from '../solver/wasmEngine';
import { CliError, parseSeconds } from './errors';
import { headForGrow } from './head';

const formatList = EXPORT_FORMAT_IDS.join('|');

export const GROW_USAGE = `usage: hairsketch grow SESSION --out FILE [--format ${formatList}] [--grid 25k|50k|100k|250k] [--solver fast|exact] [--strands N] [--cards N] [--with-head|--no-head] [--head FILE] [--motion ${MOTIONS.join('|')} [--frames N]] [--max-seconds N] [--progress-seconds N]`;

const GROW_SOLVERS = ['fast', 'exact'] as const;
type GrowSolver = (typeof GROW_SOLVERS)[number];
export const MAX_STRANDS_OPTION = 1_000_000;
/** Largest session file read (a saved session, which may embed its head file; an export
 *  carrying one may be larger). */
const MAX_SESSION_BYTES = 500 << 20;
const MAX_EXPORT_BYTES = 1 << 30;

export interface GrowArgs {
  session: string;
  out: string;
  format: ExportFormat;
  grid: GridPreset | null; // null: the session's grid
  solver: GrowSolver;
  strands: number | null; // null: the session's growth.maxStrands
  /** --cards N: hair cards to cut the hair into (null: the default). */
  cards: number | null;
  /** Write the head mesh into the file (--with-head / --no-head). */
  head: boolean;
  /** --head FILE: the head file to grow on (null: the session's own). */
  headFile: string | null;
  /** --motion NAME [--frames N]: the motion written as time samples (USD only; null: none). */
  motion: { name: MotionName; frames: number } | null;
  /** Stop (exit 3) when the solve and growth take longer than this. */
  maxSeconds: number;
  /** A JSON progress line on stderr at most this often during the solve. */
  progressSeconds: number;
}

/** The one line `grow` prints on success. */
export interface GrowReport {
  strands: number;
  points: number;
  bytes: number;
  solveMs: number;
  growMs: number;
  format: ExportFormat;
  file: string;
  /** The grown strands' content key (model/curveSet.ts contentKey of points and strandStart):
   *  the app's `window.hairsketch.hairHash()` for the same session and strand count. */
  hairHash: string;
}

const gridList = Object.keys(GRID_PRESETS).join('|');

export function parseGrowArgs(argv: readonly string[]): GrowArgs {
  let session = '';
  let out = '';
  let format: string | null = null;
  let grid: string | null = null;
  let solver = 'fast';
  let strands: string | null = null;
  let cards: string | null = null;
  let motion: string | null = null;
  let frames: string | null = null;
  let head: boolean | null = null;
  let headFile: string | null = null;
  let maxSeconds = 600;
  let progressSeconds = 5;
  const valued = [
    '--out',
    '--format',
    '--grid',
    '--solver',
    '--strands',
    '--max-seconds',
    '--progress-seconds',
    '--head',
    '--cards',
    '--motion',
    '--frames',
  ];
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (valued.includes(a)) {
      const v = argv[++i];
      if (v === undefined || v === '') throw new CliError(`${a} needs a value; ${GROW_USAGE}`);
      if (a === '--out') out = v;
      else if (a === '--format') format = v;
      else if (a === '--grid') grid = v;
      else if (a === '--solver') solver = v;
      else if (a === '--max-seconds') maxSeconds = parseSeconds(a, v);
      else if (a === '--progress-seconds') progressSeconds = parseSeconds(a, v);
      else if (a === '--head') headFile = v;
      else if (a === '--cards') cards = v;
      else if (a === '--motion') motion = v;
      else if (a === '--frames') frames = v;
      else strands = v;
    } else if (a === '--with-head' || a === '--no-head') {
      head = a === '--with-head';
    } else if (a.startsWith('--')) {
      throw new CliError(`unknown option "${a}"; ${GROW_USAGE}`);
    } else if (!session) {
      session = a;
    } else {
      throw new CliError(`unexpected argument "${a}"; ${GROW_USAGE}`);
    }
  }
  if (!session) throw new CliError(`no SESSION given; ${GROW_USAGE}`);
  if (!out) throw new CliError(`no --out FILE given; ${GROW_USAGE}`);
  let fmt: ExportFormat | null;
  if (format !== null) {
    fmt = isExportFormat(format) ? format : null;
    if (!fmt) throw new CliError(`unknown format "${format}" (--format ${formatList})`);
  } else {
    fmt = formatFromFileName(out);
    if (!fmt)
      throw new CliError(
        `cannot tell the format from the extension of "${basename(out)}": name it ${extensionsInWords(exportFormatsWith('byExtension'))}, or give --format ${formatList}`,
      );
  }
  if (grid !== null && !isGridPreset(grid))
    throw new CliError(`unknown grid "${grid}" (--grid ${gridList})`);
  if (!(GROW_SOLVERS as readonly string[]).includes(solver))
    throw new CliError(`unknown solver "${solver}" (--solver ${GROW_SOLVERS.join('|')})`);
  let n: number | null = null;
  if (strands !== null) {
    n = /^[0-9]{1,7}$/.test(strands) ? Number(strands) : Number.NaN;
    if (!(n >= 1 && n <= MAX_STRANDS_OPTION))
      throw new CliError(
        `--strands must be an integer from 1 to ${MAX_STRANDS_OPTION.toLocaleString('en-US')}, got "${strands}"`,
      );
  }
  let cardCount: number | null = null;
  if (cards !== null) {
    cardCount = /^[0-9]{1,7}$/.test(cards) ? Number(cards) : Number.NaN;
    const problem = cardCountProblem(cardCount);
    if (problem) throw new CliError(`--cards: ${problem.replace(/got .*$/, `got "${cards}"`)}`);
    if (!EXPORT_FORMATS[fmt].takesCardCount)
      throw new CliError(`--cards needs --format ${exportFormatsWith('takesCardCount').join('|')}`);
  }
  let motionArg: GrowArgs['motion'] = null;
  if (frames !== null && motion === null) throw new CliError('--frames needs --motion');
  if (motion !== null) {
    const bad = motionNameProblem(motion);
    if (bad) throw new CliError(`--motion: ${bad}`);
    const n =
      frames === null
        ? MOTION_DEFAULT_FRAMES
        : /^[0-9]{1,9}$/.test(frames)
          ? Number(frames)
          : Number.NaN;
    const problem = motionFramesProblem(n);
    if (problem) throw new CliError(`--frames: ${problem.replace(/got .*$/, `got "${frames}"`)}`);
    if (fmt !== MOTION_EXPORT.format)
      throw new CliError(`--motion needs --format ${MOTION_EXPORT.format} (a .usda file)`);
    motionArg = { name: motion as MotionName, frames: n };
  }
  return {
    session,
    out,
    format: fmt,
    motion: motionArg,
    cards: cardCount,
    grid: grid as GridPreset | null,
    solver: solver as GrowSolver,
    strands: n,
    head: head ?? EXPORT_FORMATS[fmt].headByDefault,
    headFile,
    maxSeconds,
    progressSeconds,
  };
}

const isLink = (s: string) => /^https?:\/\//i.test(s) || s.startsWith('#s=');

/** The session SESSION names: a share link (http…#s=… or #s=…), a saved session file (JSON, with
 *  the head file it may embed), or an exported .usda/.glb that carries one. Every path ends in
 *  the app's strict reader. */
export async function readSessionArg(
  arg: string,
): Promise<{ session: SessionState; headFile?: HeadFileData }> {
  if (isLink(arg)) {
    let fragment = arg;
    if (!arg.startsWith('#')) {
      try {
        fragment = new URL(arg).hash;
      } catch {
        throw new CliError('the session link is not a valid URL');
      }
    }
    const r = await decodeSessionLink(fragment);
    if (!r.ok) throw new CliError(r.error);
    return { session: r.value };
  }
  let size: number;
  try {
    const st = statSync(arg);
    if (st.isDirectory()) throw new CliError(`cannot read session ${arg}: it is a directory`);
    size = st.size;
  } catch (e) {
    if (e instanceof CliError) throw e;
    throw new CliError(`cannot read session ${arg}: ${(e as NodeJS.ErrnoException).code ?? e}`);
  }
  if (size > MAX_EXPORT_BYTES) throw new CliError(`session ${arg} is larger than 1 GB`);
  let bytes: Uint8Array;
  try {
    bytes = readFileSync(arg);
  } catch (e) {
    throw new CliError(`cannot read session ${arg}: ${(e as NodeJS.ErrnoException).code ?? e}`);
  }
  let data: unknown;
  const exported = readExportedSession(bytes);
  if (exported) {
    if (!exported.ok) throw new CliError(`session ${arg}: ${exported.error}`);
    data = exported.session;
  } else {
    if (size > MAX_SESSION_BYTES)
      throw new CliError(`session ${arg} is larger than ${MAX_SESSION_BYTES >> 20} MB`);
    try {
      data = JSON.parse(new TextDecoder().decode(bytes));
    } catch {
      throw new CliError(
        `session ${arg} is not JSON (nor an exported ${extensionsInWords(exportFormatsWith('carriesSession'))})`,
      );
    }
  }
  const parsed = await readSessionFile(data);
  if (!parsed.ok) throw new CliError(`session ${arg}: ${parsed.error}`);
  return parsed.value;
}

/** Checks now, before the solve, that a file can be created beside `out` (a probe, removed). */
function checkWritable(out: string): void {
  const target = resolve(out);
  try {
    if (statSync(target).isDirectory())
      throw new CliError(`cannot write ${out}: it is a directory`);
  } catch (e) {
    if (e instanceof CliError) throw e;
    // absent: fine
  }
  const probe = openTemp(out);
  closeSync(probe.fd);
  unlinkSync(probe.path);
}

/** A new temporary file beside `out`. */
function openTemp(out: string): { path: string; fd: number } {
  const target = resolve(out);
  const dir = dirname(target);
  const path = join(dir, `.${basename(target)}.${process.pid}.${Date.now().toString(36)}.tmp`);
  try {
    return { path, fd: openSync(path, 'wx', 0o644) };
  } catch (e) {
    const code = (e as NodeJS.ErrnoException).code;
    const why = code === 'ENOENT' ? `no directory ${dir}` : (code ?? String(e));
    throw new CliError(`cannot write ${out}: ${why}`);
  }
}

function writeAll(fd: number, chunk: Uint8Array): void {
  let off = 0;
  while (off < chunk.byteLength) off += writeSync(fd, chunk, off, chunk.byteLength - off);
}

const yieldToEvents = () => new Promise<void>((r) => setImmediate(r));

/** Runs `grow`: returns the report it printed. */
export async function runGrow(
  argv: readonly string[],
  load: LoadOptions,
  print: (line: string) => void,
): Promise<GrowReport> {
  const args = parseGrowArgs(argv);
  const read = await readSessionArg(args.session);
  const { mesh, scalp, bounds, session } = await headForGrow(
    read.session,
    read.headFile,
    args.headFile,
  );
  const preset = args.grid ?? session.grid;
  const exportHead: ExportHead | null = args.head
    ? exportHeadWithBody(
        { positions: mesh.positions, indices: mesh.indices, normals: mesh.normals },
        session.bust && session.head === 'builtin' ? builtinBody() : null,
      )
    : null;

  checkWritable(args.out);

  const engine = await loadSolverEngine(load);
  let hair: ReturnType<typeof growSessionHair>;
  let motion: ReturnType<typeof simulateMotion> | null = null;
  try {
    const t0 = performance.now();
    let lastLine = t0;
    hair = growSessionHair(engine, session, scalp, {
      grid: sessionGrid(session, bounds, preset),
      solver: args.solver,
      ...(args.strands !== null ? { maxStrands: args.strands } : {}),
      // between solver slices: progress on stderr now and then, and the time cap
      onProgress: (phase, fraction) => {
        const now = performance.now();
        const s = (now - t0) / 1000;
        if (now - lastLine >= 1000 * args.progressSeconds) {
          lastLine = now;
          process.stderr.write(
            `${JSON.stringify({ phase, fraction: Number(fraction.toFixed(3)), seconds: Number(s.toFixed(1)) })}\n`,
          );
        }
        if (s > args.maxSeconds)
          throw new CliError(
            `stopped at the time cap of ${args.maxSeconds} s (--max-seconds) while ${phase === 'solve' ? 'solving' : 'growing'} (${Math.round(100 * fraction)} %)`,
            3,
          );
      },
    });
    if (args.motion)
      motion = simulateMotion(engine, hair.strands, session, args.motion.name, args.motion.frames);
  } catch (e) {
    // a solver refusing the input (an exact factor over the memory cap, …) is the user's choice
    if (e instanceof SolverError && (e.kind === 'over_memory_cap' || e.kind === 'invalid_input'))
      throw new CliError(`the solver cannot grow this session: ${e.message}`);
    throw e;
  } finally {
    engine.dispose();
  }

  // Only now a temporary file exists: a signal while writing removes it (the write yields to
  // the event loop now and then so that the handler runs).
  const temp = openTemp(args.out);
  let fd: number | null = temp.fd;
  let interrupted: NodeJS.Signals | null = null;
  const onSignal = (sig: NodeJS.Signals) => {
    interrupted = sig;
  };
  process.on('SIGINT', onSignal);
  process.on('SIGTERM', onSignal);
  try {
    let bytes = 0;
    let chunks = 0;
    for (const chunk of writeExport(args.format, {
      strands: hair.strands,
      session,
      head: exportHead,
      headUv: mesh.cornerUvs
        ? { positions: mesh.positions, indices: mesh.indices, cornerUvs: mesh.cornerUvs }
        : null,
      ...(args.cards !== null ? { cards: args.cards } : {}),
      ...(motion ? { motion } : {}),
    })) {
      writeAll(fd, chunk);
      bytes += chunk.byteLength;
      if (++chunks % 16 === 0) await yieldToEvents();
      if (interrupted) throw new CliError(`interrupted (${interrupted})`, 130);
    }
    fsyncSync(fd);
    closeSync(fd);
    fd = null;
    renameSync(temp.path, args.out);
    const report: GrowReport = {
      ...exportedCounts(hair.strands),
      bytes,
      solveMs: Math.round(hair.solveMs),
      growMs: Math.round(hair.growMs),
      format: args.format,
      file: resolve(args.out),
      hairHash: contentKey(hair.strands.points, hair.strands.strandStart),
    };
    print(JSON.stringify(report));
    return report;
  } catch (e) {
    if (fd !== null) closeSync(fd);
    try {
      unlinkSync(temp.path);
    } catch {
      // already gone
    }
    throw e;
  } finally {
    process.off('SIGINT', onSignal);
    process.off('SIGTERM', onSignal);
  }
}
