// Fuzz target 1: the session reader (parseSession) on mutated preset sessions, JSON and anything.
import fc from 'fast-check';
import type { SessionState } from '../../../web/model/session';
import { parseSession } from '../../../web/model/sessionFile';
import type { FuzzContext } from '../context';
import { applyMutations, type Mutation, type MutationOptions, mutation, show } from '../mutate';
import {
  check,
  checkMessage,
  type FuzzTarget,
  firstDifference,
  guard,
  Violation,
} from '../outcomes';

// ---- 1. the session reader ------------------------------------------------------------------

/** The session reader's messages start with the path of the field: `session.curves[2].points[4]
 *  [1]: must be a finite number`; a key that is not an identifier would be quoted as JSON
 *  (`session["a b"]: …`), so that the path stays unambiguous. */
export const SESSION_FIELD = /^session(\.[A-Za-z_$][\w$]*|\[\d+\]|\["(?:[^"\\]|\\.)*"\])*: \S/;

/** A session the reader accepted reads back, after JSON, as the same session. */
export function checkReadsBack(value: SessionState, where: string): void {
  let json: unknown;
  try {
    json = JSON.parse(JSON.stringify(value));
  } catch (e) {
    throw new Violation(`${where}: the accepted session is not JSON (${show(e)})`);
  }
  const again = guard('parseSession (reading back)', () => parseSession(json));
  check(again.ok, () => `${where}: the accepted session reads back rejected: ${show(again)}`);
  const d = firstDifference(value, again.ok ? again.value : null, 'session');
  check(d === null, () => `${where}: the accepted session reads back changed at ${d}`);
}

export const SESSION_MUTATIONS: MutationOptions = {
  exotic: true,
  longLengths: [3, 201, 5001, 200_001],
};
export const PLAIN_MUTATIONS: MutationOptions = { exotic: false, longLengths: [3, 201, 5001] };

export type SessionCase =
  | { kind: 'mutated'; base: number; mutations: Mutation[] }
  | { kind: 'json'; value: unknown }
  | { kind: 'anything'; value: unknown };

export function sessionCase(ctx: FuzzContext, opts: MutationOptions): fc.Arbitrary<SessionCase> {
  const mutated = fc.record({
    kind: fc.constant('mutated' as const),
    base: fc.nat(ctx.sessions.length - 1),
    mutations: fc.array(mutation(opts), { maxLength: 4 }),
  });
  const arbs: fc.WeightedArbitrary<SessionCase>[] = [
    { weight: 12, arbitrary: mutated },
    {
      weight: 1,
      arbitrary: fc.record({ kind: fc.constant('json' as const), value: fc.jsonValue() }),
    },
  ];
  if (opts.exotic)
    arbs.push({
      weight: 1,
      arbitrary: fc.record({
        kind: fc.constant('anything' as const),
        value: fc.anything({
          withBigInt: true,
          withBoxedValues: true,
          withDate: true,
          withMap: true,
          withNullPrototype: true,
          withSparseArray: true,
          withTypedArray: true,
        }),
      }),
    });
  return fc.oneof(...arbs);
}

export function makeSession(
  ctx: FuzzContext,
  c: SessionCase,
  opts: MutationOptions,
): { input: unknown; log: string[] } {
  if (c.kind !== 'mutated') return { input: c.value, log: [`${c.kind}: ${show(c.value)}`] };
  const base = ctx.sessions[c.base];
  const r = applyMutations(base.json, base.places, c.mutations, opts, 'session');
  return { input: r.input, log: [`preset ${base.name}`, ...r.log] };
}

/** A session the reader accepts, from a case: the mutated preset when the reader accepts it
 *  (-0, 1e308, missing optional fields, …), else the preset itself; as the reader returns it. */
export function acceptedSession(ctx: FuzzContext, c: SessionCase): SessionState {
  const r = parseSession(makeSession(ctx, c, PLAIN_MUTATIONS).input);
  if (r.ok) return r.value;
  const base = parseSession(ctx.sessions[c.kind === 'mutated' ? c.base : 0].json);
  if (!base.ok) throw new Error(`a preset session is refused: ${base.error}`);
  return base.value;
}

export function sessionTarget(ctx: FuzzContext): FuzzTarget<SessionCase> {
  return {
    name: 'session reader',
    arbitrary: sessionCase(ctx, SESSION_MUTATIONS),
    explain: (c) => makeSession(ctx, c, SESSION_MUTATIONS).log.join('; '),
    run(c) {
      const { input } = makeSession(ctx, c, SESSION_MUTATIONS);
      const r = guard('parseSession', () => parseSession(input));
      if (!r.ok) {
        checkMessage(r.error, 'parseSession');
        check(SESSION_FIELD.test(r.error), () => `the error names no field: ${show(r.error)}`);
        return 'rejected';
      }
      checkReadsBack(r.value, 'parseSession');
      return 'accepted';
    },
  };
}
