// Errors of the command line: a CliError is the user's input (exit code 2), anything else is
// internal (exit code 1).

export class CliError extends Error {
  constructor(
    message: string,
    /** The exit code (2: bad input; 130: interrupted). */
    readonly exitCode = 2,
  ) {
    super(message);
    this.name = 'CliError';
  }
}

/** A `--max-seconds` / `--progress-seconds` value: a number of seconds > 0. */
export function parseSeconds(option: string, value: string): number {
  const x = Number(value);
  if (!(value.trim() !== '' && Number.isFinite(x) && x > 0))
    throw new CliError(`${option} must be a number of seconds > 0, not "${value.slice(0, 40)}"`);
  return x;
}
