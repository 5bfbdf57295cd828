// The scalp brush's effect on the hair: painting adds roots only inside the painted
// area, erasing removes every root there, and undo gives back the default scalp's roots. The
// real wasm solver grows the default preset on the built-in head with each mask; roots are the
// strands' first points, and which triangle a root is on comes from the head's BVH (closest
// point), independently of the solver's own sampling.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Editor } from '../../web/editor/editor';
import { growSessionHair } from '../../web/export/growSession';
import { Head } from '../../web/head/head';
import { applyScalpPaint, forEachCovered, type ScalpPaintStroke } from '../../web/head/scalpPaint';
import { gridForPreset } from '../../web/model/grid';
import type { Vec3 } from '../../web/model/vec3';
import { loadSolverEngine } from '../../web/solver/wasmEngine';

const wasmPath = fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url));
let wasmBinary: Uint8Array;
beforeAll(() => {
  wasmBinary = new Uint8Array(readFileSync(wasmPath));
});

const head = Head.builtin();
const grid = gridForPreset('25k');
const session = {
  ...presetSession('default', head, '25k', 0),
  growth: { ...presetSession('default', head, '25k', 0).growth, thetaStepDeg: 2, phiStepDeg: 2 },
};
const defaultMask = head.mesh.scalp.slice();

async function roots(mask: Uint8Array): Promise<Vec3[]> {
  const engine = await loadSolverEngine({ wasmBinary });
  try {
    const scalp = { ...head.scalpMesh(), scalp: mask };
    const { strands } = growSessionHair(engine, session, scalp, { grid, solver: 'fast' });
    const out: Vec3[] = [];
    for (let i = 0; i + 1 < strands.strandStart.length; i++) {
      const k = 3 * strands.strandStart[i];
      out.push([strands.points[k], strands.points[k + 1], strands.points[k + 2]]);
    }
    return out;
  } finally {
    engine.dispose();
  }
}

const key = (p: Vec3) => p.map((v) => v.toFixed(4)).join(',');
const triangleOf = (p: Vec3) => head.closest(p).triangle;

/** A stroke over the forehead (not scalp by default) and a dab on the crown. */
const forehead: ScalpPaintStroke = {
  erase: false,
  radius: 0.25,
  points: [
    [-0.35, 0.55, 0.85],
    [0.35, 0.55, 0.85],
  ],
};
const crown: ScalpPaintStroke = { erase: true, radius: 0.3, points: [[0, 1, 0]] };

describe('scalp brush → roots', () => {
  it('painting adds roots only inside the painted area; erasing removes them', async () => {
    const base = await roots(defaultMask);
    const paintedMask = applyScalpPaint(head.mesh, defaultMask, [forehead]);
    const painted = await roots(paintedMask);
    const covered = new Set<number>();
    forEachCovered(head.mesh, forehead, (t) => covered.add(t));
    // the painted area is new scalp
    let added = 0;
    for (const t of covered) if (!defaultMask[t]) added++;
    expect(added).toBeGreaterThan(30);

    const before = new Set(base.map(key));
    const fresh = painted.filter((p) => !before.has(key(p)));
    expect(fresh.length).toBeGreaterThan(20);
    for (const p of fresh) expect(covered.has(triangleOf(p)), `root ${p}`).toBe(true);
    // every root is on a scalp triangle of its mask
    for (const p of painted) expect(paintedMask[triangleOf(p)]).toBe(1);

    const erasedMask = applyScalpPaint(head.mesh, defaultMask, [forehead, crown]);
    const erased = await roots(erasedMask);
    const gone = new Set<number>();
    forEachCovered(head.mesh, crown, (t) => gone.add(t));
    expect(base.some((p) => gone.has(triangleOf(p)))).toBe(true); // there were roots there
    for (const p of erased) expect(gone.has(triangleOf(p))).toBe(false);
    expect(erased.length).toBeLessThan(painted.length);
  }, 120_000);

  it('undo restores the default scalp', () => {
    const e = new Editor(session, 'scalp');
    e.run({ kind: 'paintScalp', stroke: { ...forehead, points: [...forehead.points] } });
    expect(e.session.scalpPaint).toHaveLength(1);
    const painted = applyScalpPaint(head.mesh, defaultMask, e.session.scalpPaint ?? []);
    expect(painted).not.toEqual(defaultMask);
    e.undo();
    expect(applyScalpPaint(head.mesh, defaultMask, e.session.scalpPaint ?? [])).toEqual(
      defaultMask,
    );
  });

  it('with Mirror, one stroke paints both sides as one edit', () => {
    // a dab on the left cheek (off the default scalp), on the head
    const at = head.closest([0.8, -0.4, 0.3]).point;
    const dab: ScalpPaintStroke = { erase: false, radius: 0.08, points: [at] };
    const e = new Editor(session, 'scalp');
    e.run({ kind: 'paintScalp', stroke: { ...dab, points: [...dab.points] }, mirror: true });
    const strokes = e.session.scalpPaint ?? [];
    expect(strokes).toHaveLength(2);
    // its reflection (the session keeps points to 1e-4)
    for (const [k, v] of [-at[0], at[1], at[2]].entries())
      expect(strokes[1].points[0][k]).toBeCloseTo(v, 3);
    // the mask gains triangles on both sides of the head, about as many on each
    const mask = applyScalpPaint(head.mesh, defaultMask, strokes);
    const gained = { left: 0, right: 0 };
    const I = head.mesh.indices;
    const P = head.mesh.positions;
    for (let t = 0; t < mask.length; t++) {
      if (mask[t] === defaultMask[t]) continue;
      const x = (P[3 * I[3 * t]] + P[3 * I[3 * t + 1]] + P[3 * I[3 * t + 2]]) / 3;
      gained[x > 0 ? 'left' : 'right']++;
    }
    expect(gained.left).toBeGreaterThan(5);
    expect(gained.right).toBeGreaterThan(0.7 * gained.left);
    expect(gained.right).toBeLessThan(1.4 * gained.left);
    e.undo();
    expect(e.session.scalpPaint ?? []).toHaveLength(0);
  });
});
