// Wind moves hair (issue 51): the simulation works in world units (1 unit = 10 cm) and the wind's
// gusts are given in m/s, so they are scaled to world units (hair_sim.hpp kUnitsPerMetre); used
// as units/s they were a tenth of their speed and the tips of long hair moved 0.03-0.6 cm. On the
// `long` preset (300 strands, the export's pipeline: growSessionHair then simulateMotion), the tips
// must move more than 2 cm on average, the figure, over the second and third second.
// The Motion controls' wind: from the head's left the tips go right (-x), from its right left; with
// no speed they stay where the groom has them (as far as Settle moves them); a speed out of range
// is refused with the reason.
import { beforeAll, describe, expect, it } from 'vitest';
import { headForGrow } from '../../web/cli/head';
import { presetSession } from '../../web/cli/presetSession';
import { growSessionHair } from '../../web/export/growSession';
import { simulateMotion } from '../../web/export/motionExport';
import { Head } from '../../web/head/head';
import { gridForSession } from '../../web/model/grid';
import type { StrandArrays } from '../../web/model/hairArrays';
import type { MotionName, WindSettings } from '../../web/model/motion';
import { hangLength, type SessionState } from '../../web/model/session';
import type { SolverEngine } from '../../web/solver/engine';
import { singleNodeOptions } from '../../web/solver/nodeThreads';
import { loadSolverEngine } from '../../web/solver/wasmEngine';

let engine: SolverEngine;
let session: SessionState;
let s: StrandArrays;

beforeAll(async () => {
  session = presetSession('long', Head.builtin(), '25k', 300);
  const { scalp } = await headForGrow(session, undefined, null);
  engine = await loadSolverEngine(singleNodeOptions());
  const grid = gridForSession(session.grid, session.curves, undefined, hangLength(session));
  s = growSessionHair(engine, session, scalp, { grid, solver: 'fast' }).strands;
  return () => engine.dispose();
});

/** The tips' mean displacement (cm, and its mean x and z parts) over frames 48-72. */
function tipMotion(motion: MotionName, wind?: WindSettings) {
  const frames = simulateMotion(engine, s, session, motion, 73, wind).frames;
  const n = s.strandStart.length - 1;
  let sum = 0;
  let sx = 0;
  let sz = 0;
  let count = 0;
  for (let f = 48; f <= 72; f += 4) {
    const P = frames[f];
    for (let i = 0; i < n; i++) {
      const tip = s.strandStart[i + 1] - 1;
      if (tip <= s.strandStart[i]) continue;
      const d = [0, 1, 2].map((k) => P[3 * tip + k] - s.points[3 * tip + k]);
      sum += Math.hypot(d[0], d[1], d[2]);
      sx += d[0];
      sz += d[2];
      count++;
    }
  }
  return { mean: (10 * sum) / count, x: (10 * sx) / count, z: (10 * sz) / count };
}

describe('wind', () => {
  it('moves long hair several centimetres, along the wind', () => {
    const m = tipMotion('wind');
    console.log(
      `wind from the front: mean tip displacement ${m.mean.toFixed(2)} cm (frames 48-72), along z ${m.z.toFixed(2)} cm`,
    );
    expect(m.mean).toBeGreaterThan(2);
    expect(m.z).toBeLessThan(-1); // blown back, away from the face
  });

  it('from the left blows the tips right, from the right left; with no speed they stay as Settle leaves them', () => {
    const left = tipMotion('wind', { fromDeg: 90, speed: 3 });
    const right = tipMotion('wind', { fromDeg: 270, speed: 3 });
    const still = tipMotion('wind', { fromDeg: 90, speed: 0 });
    const settle = tipMotion('settle');
    console.log(
      `wind from the left: tips x ${left.x.toFixed(2)} cm (mean ${left.mean.toFixed(2)}); from the right: x ${right.x.toFixed(2)} cm; speed 0: ${still.mean.toFixed(2)} cm; Settle ${settle.mean.toFixed(2)} cm`,
    );
    expect(left.x).toBeLessThan(-1);
    expect(right.x).toBeGreaterThan(1);
    expect(still.mean).toBeCloseTo(settle.mean, 5);
  });

  it('refuses a speed out of range with the reason', () => {
    expect(() => tipMotion('wind', { fromDeg: 0, speed: 31 })).toThrow(
      /wind speed must be 0 to 30/,
    );
    expect(() => tipMotion('wind', { fromDeg: Number.NaN, speed: 3 })).toThrow(/wind direction/);
  });
});
