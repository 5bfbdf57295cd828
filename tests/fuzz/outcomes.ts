// What a fuzz target is (tests/fuzz/targets/), how its case ends (accepted or rejected by the
// code under test; an escaped throw or a property violated), and the checks targets share.
// (It imports nothing of the app's, so that the targets' modules load the app's in their order.)
import type fc from 'fast-check';
import { show } from './mutate';

// ---- outcomes ----------------------------------------------------------------------------------

export type Outcome = 'accepted' | 'rejected';

/** The code under test threw (none may escape). */
export class EscapedThrow extends Error {}
/** The code under test answered, wrongly (a round trip changed the data, an error names
 *  nothing, an output invariant broke). */
export class Violation extends Error {}

export function escaped(what: string, e: unknown): EscapedThrow {
  const msg = e instanceof Error ? `${e.name}: ${e.message}` : show(e);
  return new EscapedThrow(`${what} threw ${msg}`);
}

export function guard<T>(what: string, f: () => T): T {
  try {
    return f();
  } catch (e) {
    throw escaped(what, e);
  }
}

export async function guardAsync<T>(what: string, f: () => Promise<T>): Promise<T> {
  try {
    return await f();
  } catch (e) {
    throw escaped(what, e);
  }
}

export function check(ok: boolean, what: () => string): asserts ok {
  if (!ok) throw new Violation(what());
}

/** The first place where a and b differ (numbers by Object.is, so -0 ≠ 0; holes ≠ values;
 *  own enumerable keys), or null when deep-equal. */
export function firstDifference(a: unknown, b: unknown, at = ''): string | null {
  if (typeof a === 'number' && typeof b === 'number')
    return Object.is(a, b) ? null : `${at || '(root)'}: ${show(a)} vs ${show(b)}`;
  if (typeof a !== 'object' || typeof b !== 'object' || a === null || b === null)
    return a === b ? null : `${at || '(root)'}: ${show(a)} vs ${show(b)}`;
  if (Array.isArray(a) !== Array.isArray(b)) return `${at}: array vs not`;
  if (Array.isArray(a) && Array.isArray(b)) {
    if (a.length !== b.length) return `${at}.length: ${a.length} vs ${b.length}`;
    for (let i = 0; i < a.length; i++) {
      if (i in a !== i in b) return `${at}[${i}]: a hole on one side`;
      const d = firstDifference(a[i], b[i], `${at}[${i}]`);
      if (d) return d;
    }
    return null;
  }
  const ka = Object.keys(a);
  const kb = Object.keys(b);
  const ra = a as Record<string, unknown>;
  const rb = b as Record<string, unknown>;
  for (const k of ka) if (!Object.hasOwn(rb, k)) return `${at}.${k}: missing on one side`;
  for (const k of kb) if (!Object.hasOwn(ra, k)) return `${at}.${k}: missing on one side`;
  for (const k of ka) {
    const d = firstDifference(ra[k], rb[k], `${at}.${k}`);
    if (d) return d;
  }
  return null;
}

/** A rejection message: present, on one line, short (a CLI prints it as its one line). */
export function checkMessage(error: unknown, where: string): asserts error is string {
  check(
    typeof error === 'string' && error.length > 0,
    () => `${where}: the error is not a message (${show(error)})`,
  );
  check(!/[\r\n]/.test(error), () => `${where}: the error is not one line: ${show(error)}`);
  check(
    error.length <= 500,
    () => `${where}: the error is ${error.length} characters: ${show(error)}`,
  );
}

// ---- a target ----------------------------------------------------------------------------------

export interface FuzzTarget<T> {
  name: string;
  arbitrary: fc.Arbitrary<T>;
  /** Checks one case: 'accepted' / 'rejected' by the code under test; throws EscapedThrow or
   *  Violation. */
  run(input: T): Outcome | Promise<Outcome>;
  /** What the case is, for a report (the input it makes, the mutations applied). */
  explain(input: T): string;
}
