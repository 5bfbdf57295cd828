// The sketching tools as state machines, fed pointer events without a browser: a flat "scalp"
// (the plane z = 0 for x < 1, seen by rays straight down -z from z = 10).
import { describe, expect, it } from 'vitest';
import { buildSupportingSurface } from '../../web/model/supportingSurface';
import type { Vec3 } from '../../web/model/vec3';
import type { StrokeSample } from '../../web/tools/depthRule';
import { DividingCurveTool } from '../../web/tools/dividingCurveTool';
import type { HintResult } from '../../web/tools/hintStroke';
import { type PonytailShape, PonytailTool } from '../../web/tools/ponytailTool';
import { StreamCurveTool } from '../../web/tools/streamCurveTool';
import type { Tool } from '../../web/tools/tool';

const EYE: Vec3 = [0, 0, 10];
const FORWARD: Vec3 = [0, 0, -1];
const STEP = 0.25;

/** Rays parallel to -z through (x, y); the scalp is z = 0 where `scalp(x, y)`. */
const sampler =
  (scalp: (x: number, y: number) => boolean) =>
  (x: number, y: number): StrokeSample => ({
    origin: [x, y, 10],
    direction: [0, 0, -1],
    scalpHit: scalp(x, y) ? [x, y, 0] : null,
    headDistance: scalp(x, y) ? 10 : null,
  });

function drag(tool: Tool, pts: Array<[number, number]>): void {
  tool.onPointerDown({ x: pts[0][0], y: pts[0][1], button: 0 });
  for (const [x, y] of pts.slice(1)) tool.onPointerMove({ x, y, button: 0 });
  tool.update();
  const [x, y] = pts[pts.length - 1];
  tool.onPointerUp({ x, y, button: 0 });
}

const line = (a: [number, number], b: [number, number], n = 40): Array<[number, number]> =>
  Array.from({ length: n + 1 }, (_, i) => [
    a[0] + ((b[0] - a[0]) * i) / n,
    a[1] + ((b[1] - a[1]) * i) / n,
  ]);

describe('StreamCurveTool', () => {
  const curve: Vec3[] = Array.from({ length: 17 }, (_, i) => [i * STEP, 0, 0] as Vec3);
  const eyeAbove: Vec3 = [2, 0.3, 10];
  function setup(
    selected: boolean,
    scalp: (x: number, y: number) => boolean = (x) => x < 1,
    viewDir?: Vec3,
  ) {
    const log: { commits: Vec3[][]; hints: HintResult[]; notes: string[]; deselected: number } = {
      commits: [],
      hints: [],
      notes: [],
      deselected: 0,
    };
    const surface = buildSupportingSurface(curve, eyeAbove, 'strip', 6 * STEP);
    const tool = new StreamCurveTool({
      sample: sampler(scalp),
      eye: () => EYE,
      forward: () => FORWARD,
      step: () => STEP,
      showDraft: () => {},
      commit: (p) => log.commits.push(p),
      preview: () => {},
      notify: (m) => log.notes.push(m),
      hintTarget: () => (selected ? { points: curve, surface, viewDir } : null),
      applyHint: (r) => log.hints.push(r),
      deselect: () => {
        log.deselected++;
      },
    });
    return { tool, log };
  }

  it('draws a new curve from the scalp when no curve is selected', () => {
    const { tool, log } = setup(false);
    drag(tool, line([0.2, 0.5], [2, 0.5]));
    expect(log.commits).toHaveLength(1);
    expect(log.commits[0].length).toBeGreaterThan(5);
    expect(log.hints).toHaveLength(0);
  });

  it('recognises cut, concatenate and insert on the selected curve’s surface', () => {
    const { tool, log } = setup(true);
    drag(tool, line([3, -1], [3, 1])); // across the curve, far on both sides
    drag(tool, line([3.9, 0.02], [6, 0.5])); // from the end, away from it
    drag(
      tool,
      line([1.5, 0.02], [3.5, 0.02]).map(([x, y]) => [x, y + 0.2 * Math.sin(x)]),
    ); // near -> near
    drag(tool, line([2, 1], [2.5, 1.2])); // far and never crossing
    expect(log.hints.map((h) => h.op.kind)).toEqual(['cut', 'concatenate', 'insert', 'none']);
    expect(log.hints[0].points.length).toBeLessThan(curve.length); // cut at x = 3 -> 13 points
    expect(log.hints[0].points.length).toBe(13);
    expect(log.hints[1].points.length).toBeGreaterThan(curve.length);
    expect(log.hints[3].points).toEqual(curve); // nothing changed
    expect(log.commits).toHaveLength(0);
  });

  // The whole plane is scalp here: the selected curve lies on it, and every stroke starts on it.
  // Without ctx.toScreen the tool measures the angle to the curve: 0.001 rad a pixel, so at the
  // rays' 10 units 1 px = 0.01 (8 px = 0.08, 16 px = 0.16; a grid step is 0.25).
  it('from the scalp, a stroke is a hint only when it clearly is one (Fig. 3 cases)', () => {
    const { tool, log } = setup(true, () => true);
    drag(tool, line([3, -1], [3, 1])); // across the curve, far on both sides
    drag(tool, line([3.95, 0.0], [6, 0.5])); // from the end (on it), away from it
    drag(
      tool,
      line([1.5, 0], [3.5, 0]).map(([x, y]) => [x, y + 0.8 * Math.sin((Math.PI * (x - 1.5)) / 2)]),
    ); // from the curve, out 3.2 steps, back onto the curve
    expect(log.hints.map((h) => h.op.kind)).toEqual(['cut', 'concatenate', 'insert']);
    expect(log.hints[0].points.length).toBe(13);
    expect(log.hints[1].points.length).toBeGreaterThan(curve.length);
    expect(log.hints[2].points.length).toBeGreaterThan(curve.length);
    expect(log.commits).toHaveLength(0);
  });

  it('from the scalp, a stroke that is not clearly a hint is a new curve, never an edit', () => {
    const { tool, log } = setup(true, () => true);
    const strokes: Array<Array<[number, number]>> = [
      line([1.5, 0.03], [3.5, 0.03]), // alongside, 0.12 steps off: was an insert
      line([1.5, 0.02], [3.5, 0.02]).map(([x, y]) => [x, y + 0.3 * Math.sin(x)]), // was insert
      line([0.05, 0.05], [3, 0.1]), // from beside the root, along it: was an insert
      line([2, 0.02], [2.5, 1.5]), // from the middle, leaving it: was 'concatenate-not-at-end'
      line([3, -0.1], [3, 1]), // across, but from on the curve: was 'concatenate-not-at-end'
      line([2, 1], [2.5, 1.2]), // beside it, never crossing: was 'no operation'
      line([3.95, 0.12], [6, 0.5]), // 12 px from the end: not on it (was concatenate)
    ];
    for (const s of strokes) drag(tool, s);
    expect(log.hints).toEqual([]);
    expect(log.commits).toHaveLength(strokes.length);
    for (const c of log.commits) expect(c.length).toBeGreaterThan(1);
  });

  it('starts a press just off the scalp where sampleStart puts it, on the scalp', () => {
    const log: Vec3[][] = [];
    const plain = sampler((x) => x < 1);
    const tool = new StreamCurveTool({
      sample: plain,
      // the press lands at x 1.1, off the scalp: its start is the scalp's edge at x 0.95
      sampleStart: (x, y) => (x < 1.2 ? { ...plain(x, y), scalpHit: [0.95, y, 0] } : plain(x, y)),
      eye: () => EYE,
      forward: () => FORWARD,
      step: () => STEP,
      showDraft: () => {},
      commit: (p) => log.push(p),
      preview: () => {},
      notify: () => {},
    });
    drag(tool, line([1.1, 0.5], [3, 0.5]));
    expect(log).toHaveLength(1);
    expect(log[0][0]).toEqual([0.95, 0.5, 0]);
    // without it, the same press draws nothing
    const { tool: bare, log: l2 } = setup(false);
    drag(bare, line([1.1, 0.5], [3, 0.5]));
    expect(l2.commits).toHaveLength(0);
  });

  it('takes no hint from a view turned more than 60 degrees from the curve’s viewpoint', () => {
    const run = (viewDir: Vec3) => {
      const { tool, log } = setup(true, (x) => x < 1, viewDir);
      drag(tool, line([3, -1], [3, 1])); // across the curve, far on both sides: a cut
      return log;
    };
    // drawn from this view (the view looks along -z): a hint
    expect(run([0, 0, -1]).hints).toHaveLength(1);
    // drawn from a view at 90 degrees (looking along -x): no hint; the press is off the scalp,
    // so nothing is drawn either
    const turned = run([-1, 0, 0]);
    expect(turned.hints).toHaveLength(0);
    expect(turned.commits).toHaveLength(0);
  });

  it('says why a press off the scalp and off the surface draws nothing, and deselects', () => {
    const { tool, log } = setup(true);
    drag(tool, line([3, 5], [4, 6]));
    expect(log.notes[0]).toMatch(/must start on the scalp/);
    expect(log.deselected).toBe(1);
    expect(log.hints).toHaveLength(0);
    expect(log.commits).toHaveLength(0);
  });
});

describe('DividingCurveTool', () => {
  it('draws a curve on the scalp, then a stroke beside it sets that side’s tilt', () => {
    let selected: { points: Vec3[]; normals: Vec3[] } | null = null;
    const tilts: Array<[string, number, number]> = [];
    const tool = new DividingCurveTool({
      sample: sampler(() => true),
      step: () => STEP,
      selected: () => selected,
      normalsAt: (pts) => pts.map(() => [0, 0, 1] as Vec3),
      showDraft: () => {},
      commit: (points, normals) => {
        selected = { points, normals };
      },
      setTilt: (end, alpha, side) => tilts.push([end, alpha, side]),
      notify: () => {},
    });
    drag(tool, line([0, 0], [0, 3]));
    expect(selected).not.toBeNull();
    const sel = selected as unknown as { points: Vec3[]; normals: Vec3[] };
    expect(sel.points.length).toBe(13);
    expect(sel.normals.length).toBe(13);
    // beside the first half, pointing away from the curve: side known, tilt about 0
    drag(tool, line([0.3, 0.5], [1.3, 0.5]));
    expect(tilts).toHaveLength(1);
    expect(tilts[0][0]).toBe('alpha0');
    expect(Math.abs(tilts[0][1])).toBeLessThan(1e-9);
    // beside the second half on the other side, slanted 45° toward the curve's end
    drag(tool, line([-0.3, 2.5], [-1.3, 3.5]));
    expect(tilts[1][0]).toBe('alpha1');
    expect(tilts[1][2]).toBe(-tilts[0][2]);
    expect(Math.abs(Math.abs(tilts[1][1]) - Math.PI / 4)).toBeLessThan(1e-6);
    // a parting drawn alongside the selected one, within HINT_RADIUS of it: a new parting
    const first = sel;
    drag(tool, line([0.2, 0.2], [0.25, 3]));
    expect(tilts).toHaveLength(2);
    expect(selected).not.toBe(first);
    const second = selected as unknown as { points: Vec3[] };
    expect(second.points[0][0]).toBeCloseTo(0.2, 9);
    // a stroke from beside it across to the other side is no tilt either
    drag(tool, line([0.3, 1], [-0.5, 1.2]));
    expect(tilts).toHaveLength(2);
  });
});

describe('PonytailTool', () => {
  function ponytailTool(near = true) {
    const spines: Vec3[][] = [];
    const shaped: { id: string; shape: PonytailShape }[] = [];
    const stages: string[] = [];
    const previews: (Vec3[] | null)[] = [];
    const tool = new PonytailTool({
      sample: sampler((_x, y) => y > -0.05),
      eye: () => EYE,
      forward: () => FORWARD,
      step: () => STEP,
      showDraft: () => {},
      showGuides: () => {},
      preview: (p) => previews.push(p),
      commitSpine: (spine) => {
        spines.push(spine);
        return { id: `c${spines.length}`, spine };
      },
      shape: (id, shape) => shaped.push({ id, shape }),
      nearSpine: () => near,
      notify: () => {},
      stageChanged: (s) => stages.push(s),
    });
    return { tool, spines, shaped, stages, previews };
  }

  it('makes the ponytail from its spine, then takes a cross-section and two profiles that shape it', () => {
    const { tool, spines, shaped, stages, previews } = ponytailTool();
    expect(tool.stage).toBe('spine');
    drag(tool, line([0, 0], [0, -4])); // spine down from the scalp edge, at depth z = 0
    expect(spines).toHaveLength(1);
    expect(spines[0].length).toBe(17);
    // the spine was previewed while drawn, and the preview ended with the stroke
    expect(previews.some((p) => p !== null && p.length >= 3)).toBe(true);
    expect(previews[previews.length - 1]).toBeNull();
    expect(tool.stage).toBe('cross');
    drag(tool, line([-0.25, -1], [0.25, -1]));
    drag(tool, line([-0.2, -0.5], [-0.1, -3.5]));
    expect(shaped).toHaveLength(0);
    drag(tool, line([0.2, -0.5], [0.1, -3.5]));
    expect(stages).toEqual(['cross', 'profileA', 'profileB', 'spine']);
    expect(shaped).toHaveLength(1);
    expect(shaped[0].id).toBe('c1');
    const p = shaped[0].shape;
    expect(p.circles.length).toBeGreaterThan(3);
    // C1 first (nearest the root), radius from the cross-section: 0.25 at y = -1
    expect(p.circles[0].centre[1]).toBeGreaterThan(p.circles[1].centre[1]);
    const atCross = p.circles.reduce((a, c) =>
      Math.abs(c.centre[1] + 1) < Math.abs(a.centre[1] + 1) ? c : a,
    );
    expect(atCross.radius).toBeCloseTo(0.25, 2);
    // the circles narrow toward the tip, as the profiles do
    expect(p.circles[p.circles.length - 1].radius).toBeLessThan(p.circles[0].radius);
  });

  it('a press on the scalp away from the spine starts the next ponytail', () => {
    const { tool, spines, shaped, stages } = ponytailTool(false);
    drag(tool, line([0, 0], [0, -4]));
    drag(tool, line([0.4, 0.5], [0.4, -3]));
    expect(spines).toHaveLength(2);
    expect(shaped).toHaveLength(0);
    expect(stages).toEqual(['cross', 'spine', 'cross']);
  });

  it('an Undo that takes the ponytail away ends its shaping: the next stroke is a spine', () => {
    const { tool, spines, shaped, stages } = ponytailTool(true);
    drag(tool, line([0, 0], [0, -4]));
    const made = { id: 'c1', type: 'ponytail', points: spines[0] };
    // an edit that keeps it (another curve added) keeps the shaping
    tool.sessionChanged([made, { id: 'c2', type: 'stream', points: [] }]);
    expect(tool.stage).toBe('cross');
    tool.sessionChanged([]); // Undo
    expect(tool.stage).toBe('spine');
    // a stroke near where the spine was is a new ponytail, not a cross-section
    drag(tool, line([0, 0], [0, -4]));
    expect(spines).toHaveLength(2);
    expect(shaped).toHaveLength(0);
    expect(stages).toEqual(['cross', 'spine', 'cross']);
  });
});
