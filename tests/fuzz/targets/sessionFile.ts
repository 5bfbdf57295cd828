// Fuzz target 1b: session files with embedded picture files (readSessionFile).
import { createHash } from 'node:crypto';
import fc from 'fast-check';
import { readSessionFile } from '../../../web/model/sessionFile';
import type { FuzzContext } from '../context';
import { applyMutations, type Mutation, mutation, show } from '../mutate';
import { check, checkMessage, type FuzzTarget, guardAsync } from '../outcomes';
import { checkReadsBack, SESSION_FIELD, SESSION_MUTATIONS } from './session';

// ---- 1b. session files (embedded picture files) ----------------------------------------------

export type SessionFileCase = { base: number; mutations: Mutation[] };

export function sessionFileTarget(ctx: FuzzContext): FuzzTarget<SessionFileCase> {
  const make = (c: SessionFileCase) => {
    const base = ctx.sessionFiles[c.base];
    return applyMutations(base.json, base.places, c.mutations, SESSION_MUTATIONS, 'session');
  };
  return {
    name: 'session file reader',
    arbitrary: fc.record({
      base: fc.nat(ctx.sessionFiles.length - 1),
      mutations: fc.array(mutation(SESSION_MUTATIONS), { maxLength: 4 }),
    }),
    explain: (c) => make(c).log.join('; '),
    async run(c) {
      const { input } = make(c);
      const r = await guardAsync('readSessionFile', () => readSessionFile(input));
      if (!r.ok) {
        checkMessage(r.error, 'readSessionFile');
        check(SESSION_FIELD.test(r.error), () => `the error names no field: ${show(r.error)}`);
        return 'rejected';
      }
      checkReadsBack(r.value.session, 'readSessionFile');
      // every embedded file is one the session names, with the bytes its hash says
      const named = new Set((r.value.session.references ?? []).map((p) => p.hash));
      for (const f of r.value.pictureFiles ?? []) {
        check(named.has(f.hash), () => `picture file ${f.hash} is no picture of the session`);
        const h = createHash('sha256').update(new Uint8Array(f.bytes)).digest('hex');
        check(h === f.hash, () => `picture file ${f.name}: its bytes hash to ${h}, not ${f.hash}`);
      }
      return 'accepted';
    },
  };
}
