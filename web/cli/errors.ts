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
