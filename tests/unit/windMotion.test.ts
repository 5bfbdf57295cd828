// Wind moves hair (issue 51): the simulation works in world units (1 unit = 10 cm) and the wind's
// gusts are given in m/s, so they are scaled to world units (hair_sim.hpp kUnitsPerMetre); used
// as units/s they were a tenth of their speed and the tips of long hair moved 0.03-0.6 cm. On the
// `long` preset (300 strands, the export's pipeline: growSessionHair then simulateMotion), the tips
// must move more than 2 cm on average, the figure, over the second and third second.
import { expect, it } from 'vitest';
import { headForGrow } from '../../web/cli/head';
import { presetSession } from '../../web/cli/presetSession';
import { growSessionHair } from '../../web/export/growSession';
import { simulateMotion } from '../../web/export/motionExport';
import { Head } from '../../web/head/head';
import { gridForSession } from '../../web/model/grid';
import { hangLength } from '../../web/model/session';
import { singleNodeOptions } from '../../web/solver/nodeThreads';
import { loadSolverEngine } from '../../web/solver/wasmEngine';

it('wind moves long hair several centimetres', async () => {
  const session = presetSession('long', Head.builtin(), '25k', 300);
  const { scalp } = await headForGrow(session, undefined, null);
  const engine = await loadSolverEngine(singleNodeOptions());
  try {
    const grid = gridForSession(session.grid, session.curves, undefined, hangLength(session));
    const s = growSessionHair(engine, session, scalp, { grid, solver: 'fast' }).strands;
    const frames = simulateMotion(engine, s, session, 'wind', 73).frames;
    const n = s.strandStart.length - 1;
    const means: number[] = [];
    for (let f = 48; f <= 72; f += 4) {
      const P = frames[f];
      let sum = 0;
      let count = 0;
      for (let i = 0; i < n; i++) {
        const tip = s.strandStart[i + 1] - 1;
        if (tip <= s.strandStart[i]) continue;
        const d = [0, 1, 2].map((k) => P[3 * tip + k] - s.points[3 * tip + k]);
        sum += Math.hypot(d[0], d[1], d[2]);
        count++;
      }
      means.push((10 * sum) / count); // cm
    }
    const mean = means.reduce((a, b) => a + b, 0) / means.length;
    console.log(`wind: mean tip displacement ${mean.toFixed(2)} cm (frames 48-72)`);
    expect(mean).toBeGreaterThan(2);
  } finally {
    engine.dispose();
  }
});
