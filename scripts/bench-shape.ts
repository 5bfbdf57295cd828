// npm run bench:shape [SESSION.json ...]: the shape figures of docs/natural-fall.md section 5 (tests/support/
// shapeMetrics.ts) for hairstyles drawn with real pointer strokes (tests/fixtures/shape/*.json,
// written by shape.spec.ts with SHOT_DIR), each grown from scratch as `hairsketch grow` grows it
// (25k grid, fast solver, every strand). With SHAPE_COMPARE=1 each session is grown twice: with
// the shape rules off (`shape` removed: the hair a session saved before them has) and on, so one
// run gives before and after. Writes bench-results/shape.{json,md}.
import { readdirSync, readFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import {
  earCoverShare,
  faceShare,
  fallOfUngoverned,
  napeLength,
  standOff,
  widthAtEars,
} from '../tests/support/shapeMetrics';
import { headForGrow } from '../web/cli/head';
import { growSessionHair } from '../web/export/growSession';
import { gridForSession } from '../web/model/grid';
import { hangLength, type SessionState } from '../web/model/session';
import { parseSession } from '../web/model/sessionFile';
import { singleNodeOptions } from '../web/solver/nodeThreads';
import { loadSolverEngine } from '../web/solver/wasmEngine';
import { writeBenchResults } from './benchResults.mjs';

const dir = 'tests/fixtures/shape';
const files = process.argv.slice(2).length
  ? process.argv.slice(2)
  : readdirSync(dir)
      .filter((f) => f.endsWith('.json'))
      .map((f) => join(dir, f));
const compare = process.env.SHAPE_COMPARE === '1';

async function figures(session: SessionState) {
  const { scalp } = await headForGrow(session, undefined, null);
  const engine = await loadSolverEngine(singleNodeOptions());
  try {
    const hair = growSessionHair(engine, session, scalp, {
      grid: gridForSession(session.grid, session.curves, undefined, hangLength(session)),
      solver: 'fast',
    });
    const s = hair.strands;
    const fall = fallOfUngoverned(s, session.curves);
    const ears = widthAtEars(s);
    const nape = napeLength(s, session.curves);
    return {
      strands: s.strandStart.length - 1,
      standOffCm: +(10 * standOff(s, session.curves, 0.3, 0.4)).toFixed(2),
      ungovernedAngle: +fall.medianAngle.toFixed(1),
      ungovernedAbove: +(100 * fall.aboveShare).toFixed(1),
      facePct: +(100 * faceShare(s)).toFixed(2),
      earCoverPct: +(100 * earCoverShare(s)).toFixed(2),
      widthAtEarsCm: +(10 * ears.hair).toFixed(1),
      headWidthCm: +(10 * ears.head).toFixed(1),
      napeCm: +(10 * nape.nape).toFixed(1),
      strokeHairCm: +(10 * nape.strokes).toFixed(1),
      solveMs: Math.round(hair.solveMs),
      growMs: Math.round(hair.growMs),
    };
  } finally {
    engine.dispose();
  }
}

const rows: Record<string, unknown>[] = [];
for (const f of files) {
  const r = parseSession(JSON.parse(readFileSync(f, 'utf8')));
  if (!r.ok) throw new Error(`${f}: ${r.error}`);
  const name = basename(f, '.json');
  const { shape: _shape, ...off } = r.value;
  const variants: [string, SessionState][] = compare
    ? [
        ['rules off', off],
        ['rules on', { ...r.value, shape: true }],
      ]
    : [['as drawn', r.value]];
  for (const [label, s] of variants) {
    const row = { style: name, label, ...(await figures(s)) };
    rows.push(row);
    console.log(JSON.stringify(row));
  }
}

const keys = Object.keys(rows[0] ?? {});
const md = [
  `| ${keys.join(' | ')} |`,
  `| ${keys.map(() => '---').join(' | ')} |`,
  ...rows.map((r) => `| ${keys.map((k) => String(r[k])).join(' | ')} |`),
];
writeBenchResults('shape', {
  title: 'Shape of hand-drawn hairstyles (the shape rules off and on)',
  script: 'scripts/bench-shape.ts',
  command: 'npm run bench:shape (SHAPE_COMPARE=1: also with the shape rules off)',
  measures:
    'Per style drawn with real pointer strokes (tests/fixtures/shape): the median distance from the head ' +
    'over the first 3 cm of hair rooted 4 cm or more from every stroke (standOffCm); of that hair, the median ' +
    'root-to-tip angle from straight down and the share ending above its root; the share of strands crossing the ' +
    'face and hiding an ear from the front; the hair width at ear level against the head; the median length of ' +
    'nape hair and of hair rooted at the strokes. Grown as `hairsketch grow` grows it (25k grid, fast solver).',
  config: { files, compare },
  results: rows,
  table: md.join('\n'),
});
