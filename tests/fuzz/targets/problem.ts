// Fuzz target 3: the CLI problem reader (decodeProblem, `hairsketch solve`).
import fc from 'fast-check';
import { decodeProblem, MAX_GRID_POINTS } from '../../../web/cli/problem';
import { binaryText, type FuzzContext } from '../context';
import { applyMutations, type Mutation, mutation, show } from '../mutate';
import { check, checkMessage, type FuzzTarget, guard } from '../outcomes';
import { PLAIN_MUTATIONS } from './session';

// ---- 3. the CLI problem reader ----------------------------------------------------------------

export type ProblemCase =
  | { kind: 'text'; text: string }
  | { kind: 'json'; value: unknown }
  | { kind: 'made'; value: unknown; numbers: { at: number; token: string }[]; cut: number | null }
  | { kind: 'mutated'; base: number; mutations: Mutation[]; cut: number | null };

/** Number spellings JSON.parse reads as values a JSON writer never writes. */
const NUMBER_TOKENS = ['1e999', '-1e999', '-0', '1.5', '1e-400', '4294967297', '9007199254740993'];

/** A grid size: mostly valid (2..6), now and then not. */
const gridSize = fc.oneof(
  { weight: 9, arbitrary: fc.integer({ min: 2, max: 6 }) },
  { weight: 1, arbitrary: fc.constantFrom(0, 1, 7) },
);
/** A grid index: mostly inside every valid grid (0, 1), now and then anywhere. */
const gridIndex = fc.oneof(
  { weight: 9, arbitrary: fc.integer({ min: 0, max: 1 }) },
  { weight: 1, arbitrary: fc.integer({ min: -1, max: 7 }) },
);

function made(): fc.Arbitrary<unknown> {
  return fc
    .record({
      grid: fc.tuple(gridSize, gridSize, gridSize),
      omega: fc.option(fc.oneof(fc.double(), fc.constantFrom(100, 1, 0, -1))),
      steps: fc.array(
        fc.record(
          {
            set: fc.array(
              fc.tuple(
                gridIndex,
                gridIndex,
                gridIndex,
                fc.oneof(fc.double({ min: -2, max: 2 }), fc.double()),
                fc.double({ min: -2, max: 2, noNaN: true }),
                fc.double({ min: -2, max: 2, noNaN: true }),
              ),
              { maxLength: 6 },
            ),
            unset: fc.array(
              fc.tuple(gridIndex, gridIndex, gridIndex).map((t) => [...t]),
              { maxLength: 3 },
            ),
          },
          { requiredKeys: [] },
        ),
        { maxLength: 4 },
      ),
    })
    .map((p) => ({ ...p, omega: p.omega ?? undefined }));
}

const cut = fc.option(fc.nat(), { freq: 6 });

function problemText(ctx: FuzzContext, c: ProblemCase): { text: string; log: string } {
  switch (c.kind) {
    case 'text':
      return { text: c.text, log: 'text' };
    case 'json':
      return { text: JSON.stringify(c.value) ?? '', log: 'json' };
    case 'made': {
      let text = JSON.stringify(c.value) ?? '';
      const log = [`made ${show(c.value, 300)}`];
      for (const { at, token } of c.numbers) {
        const all = [...text.matchAll(/-?\d+(\.\d+)?([eE][-+]?\d+)?/g)];
        if (all.length === 0) break;
        const m = all[at % all.length];
        const i = m.index ?? 0;
        text = text.slice(0, i) + token + text.slice(i + m[0].length);
        log.push(`number #${at % all.length} → ${token}`);
      }
      if (c.cut !== null) {
        text = text.slice(0, c.cut % (text.length + 1));
        log.push(`cut at ${c.cut % (text.length + 1)}`);
      }
      return { text, log: log.join('; ') };
    }
    case 'mutated': {
      const base = ctx.problems[c.base % ctx.problems.length];
      const r = applyMutations(base.json, base.places, c.mutations, PLAIN_MUTATIONS, 'problem');
      let text = JSON.stringify(r.input) ?? '';
      if (c.cut !== null) text = text.slice(0, c.cut % (text.length + 1));
      return { text, log: [...r.log, c.cut === null ? '' : `cut at ${c.cut}`].join('; ') };
    }
  }
}

export function problemTarget(ctx: FuzzContext): FuzzTarget<ProblemCase> {
  const arbitrary: fc.Arbitrary<ProblemCase> = fc.oneof(
    {
      weight: 1,
      arbitrary: fc.record({
        kind: fc.constant('text' as const),
        text: fc.oneof(fc.string(), binaryText, fc.json()),
      }),
    },
    {
      weight: 1,
      arbitrary: fc.record({ kind: fc.constant('json' as const), value: fc.jsonValue() }),
    },
    {
      weight: 4,
      arbitrary: fc.record({
        kind: fc.constant('made' as const),
        value: made(),
        numbers: fc.array(fc.record({ at: fc.nat(), token: fc.constantFrom(...NUMBER_TOKENS) }), {
          maxLength: 2,
        }),
        cut,
      }),
    },
    {
      weight: 4,
      arbitrary: fc.record({
        kind: fc.constant('mutated' as const),
        base: fc.nat(),
        mutations: fc.array(mutation(PLAIN_MUTATIONS), { maxLength: 3 }),
        cut,
      }),
    },
  );
  return {
    name: 'CLI problem reader',
    arbitrary,
    explain: (c) => {
      const { text, log } = problemText(ctx, c);
      return `${log}; text ${show(text, 400)}`;
    },
    run(c) {
      const { text } = problemText(ctx, c);
      const r = guard('decodeProblem', () => decodeProblem(text));
      if (!r.ok) {
        checkMessage(r.error, 'decodeProblem');
        check(
          /\b(JSON|problem|grid|omega|steps?|set|unset|key)\b/.test(r.error),
          () => `the error says nothing of what is wrong: ${show(r.error)}`,
        );
        return 'rejected';
      }
      const { grid, omega, steps } = r.value;
      check(
        Array.isArray(grid) &&
          grid.length === 3 &&
          grid.every((n) => Number.isInteger(n) && n >= 2),
        () => `accepted grid ${show(grid)}`,
      );
      const points = grid[0] * grid[1] * grid[2];
      check(points <= MAX_GRID_POINTS, () => `accepted a grid of ${points} points`);
      check(Number.isFinite(omega) && omega > 0, () => `accepted omega ${show(omega)}`);
      const inGrid = (e: readonly unknown[]) =>
        [0, 1, 2].every((a) => Number.isInteger(e[a]) && (e[a] as number) >= 0) &&
        (e[0] as number) < grid[0] &&
        (e[1] as number) < grid[1] &&
        (e[2] as number) < grid[2];
      steps.forEach((st, s) => {
        st.set.forEach((e, i) => {
          check(
            Array.isArray(e) && e.length === 6 && inGrid(e),
            () => `accepted step ${s} set[${i}] = ${show(e)}`,
          );
          check(
            e.slice(3).every((x) => typeof x === 'number' && Number.isFinite(x)),
            () => `accepted a target that is not finite: step ${s} set[${i}] = ${show(e)}`,
          );
        });
        st.unset.forEach((e, i) => {
          check(
            Array.isArray(e) && e.length === 3 && inGrid(e),
            () => `accepted step ${s} unset[${i}] = ${show(e)}`,
          );
        });
      });
      return 'accepted';
    },
  };
}
