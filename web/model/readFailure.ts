// How the session reader refuses: it throws a ParseError (`<path>: <what>`) that only its own
// code can make, so an exception a hostile input throws (a Proxy trap, a getter) is never taken
// for one of its messages.

export class ParseError extends Error {}

/** ParseErrors the reader threw (a WeakSet: asking it runs no trap of a thrown Proxy). */
const OURS = new WeakSet<object>();
export const isOurs = (e: unknown): e is ParseError =>
  typeof e === 'object' && e !== null && OURS.has(e);

/** Refuses with `message` as it is. */
export function refuse(message: string): never {
  const e = new ParseError(message);
  OURS.add(e);
  throw e;
}

/** Refuses the value at `path`: `<path>: <what>`. */
export function fail(path: string, what: string): never {
  refuse(`${path}: ${what}`);
}

/** The answer for what a read threw: its message when it is ours, else a sentence saying the
 *  input threw. */
export function failed(e: unknown): { ok: false; error: string } {
  if (isOurs(e)) return { ok: false, error: e.message };
  return { ok: false, error: 'session: could not be read (reading it threw)' };
}

/** A key as a path step: `.name` for an identifier, else `["…"]` (JSON, cut to 40 characters). */
export const keyStep = (k: string) =>
  /^[A-Za-z_$][\w$]*$/.test(k) && k.length <= 40
    ? `.${k}`
    : `[${JSON.stringify(k.length > 40 ? `${k.slice(0, 40)}…` : k)}]`;
