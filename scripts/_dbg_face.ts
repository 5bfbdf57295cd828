import { readFileSync } from 'node:fs';
import { headForGrow } from '../web/cli/head';
import { growSessionHair } from '../web/export/growSession';
import { gridForSession } from '../web/model/grid';
import { hangLength } from '../web/model/session';
import { parseSession } from '../web/model/sessionFile';
import { singleNodeOptions } from '../web/solver/nodeThreads';
import { loadSolverEngine } from '../web/solver/wasmEngine';
import { eachStrand, faceShare } from '../tests/support/shapeMetrics';
for (const f of process.argv.slice(2)) {
  const r = parseSession(JSON.parse(readFileSync(f, 'utf8')));
  if (!r.ok) throw new Error(r.error);
  const session = r.value;
  const { scalp } = await headForGrow(session, undefined, null);
  const engine = await loadSolverEngine(singleNodeOptions());
  const hair = growSessionHair(engine, session, scalp, { grid: gridForSession(session.grid, session.curves, undefined, hangLength(session)), solver: 'fast' });
  let n = 0, bad = 0;
  eachStrand(hair.strands, (pts) => {
    n++;
    if (pts.some(([x, y, z]) => y < 0.15 && y > -0.6 && z > 0.45 && Math.abs(x) < 0.75)) bad++;
  });
  console.log(f.split('/').pop(), `${bad} of ${n} strands in front of the eyes/temples; face share ${(100 * faceShare(hair.strands)).toFixed(2)} %`);
}
