// Drawing stream curve after stream curve from the scalp, each new stroke starting a few pixels
// from the last curve (which the app selects as soon as it is drawn), after orbiting the camera:
// every stroke must make a new curve and never edit the selected one. A perspective camera
// (35° field of view, 1000 x 665 px) around a spherical head whose upper part is the scalp; the
// selected curve's supporting surface is the real one (buildSupportingSurface, 6 grid steps wide,
// from the viewpoint the curve was drawn from), at the 25K and 50K grid steps.
import { describe, expect, it } from 'vitest';
import { gridForPreset } from '../../web/model/grid';
import { buildSupportingSurface, type SurfaceMode } from '../../web/model/supportingSurface';
import { add, dot, normalize, scale, sub, type Vec3 } from '../../web/model/vec3';
import type { StrokeSample } from '../../web/tools/depthRule';
import type { HintResult } from '../../web/tools/hintStroke';
import { StreamCurveTool, type StrokeContext } from '../../web/tools/streamCurveTool';

const W = 1000;
const H = 665;
const FOCAL = H / 2 / Math.tan((35 * Math.PI) / 360);
const TARGET: Vec3 = [0, -0.3, 0];
const RADIUS = 1; // the head: a unit sphere at the origin; the scalp is where y > -0.3

const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];

class Camera {
  eye: Vec3 = [0, 0, 7.7];
  fwd: Vec3 = [0, 0, -1];
  right: Vec3 = [1, 0, 0];
  up: Vec3 = [0, 1, 0];
  orbit(yawDeg: number, pitchDeg: number): void {
    const y = (yawDeg * Math.PI) / 180;
    const p = (pitchDeg * Math.PI) / 180;
    this.eye = add(
      TARGET,
      scale([Math.sin(y) * Math.cos(p), Math.sin(p), Math.cos(y) * Math.cos(p)], 7.7),
    );
    this.fwd = normalize(sub(TARGET, this.eye));
    this.right = normalize(cross(this.fwd, [0, 1, 0]));
    this.up = cross(this.right, this.fwd);
  }
  toScreen(p: Vec3): { x: number; y: number } | null {
    const v = sub(p, this.eye);
    const z = dot(v, this.fwd);
    if (z <= 0) return null;
    return {
      x: W / 2 + (FOCAL * dot(v, this.right)) / z,
      y: H / 2 - (FOCAL * dot(v, this.up)) / z,
    };
  }
  sample(x: number, y: number): StrokeSample {
    const d = normalize(
      add(
        this.fwd,
        add(scale(this.right, (x - W / 2) / FOCAL), scale(this.up, -(y - H / 2) / FOCAL)),
      ),
    );
    const o = this.eye;
    const b = dot(o, d);
    const disc = b * b - (dot(o, o) - RADIUS * RADIUS);
    let hit: Vec3 | null = null;
    let t: number | null = null;
    if (disc >= 0) {
      t = -b - Math.sqrt(disc);
      hit = add(o, scale(d, t));
    }
    return {
      origin: o,
      direction: d,
      scalpHit: hit && hit[1] > -0.3 ? hit : null,
      headDistance: t,
    };
  }
}

type P = { x: number; y: number };

/** The app as the tool sees it: a new curve is selected and keeps the camera as viewpoint. */
function sketcher(step: number, mode: SurfaceMode, withScreen: boolean) {
  const cam = new Camera();
  cam.orbit(20, 8);
  const log = { commits: 0, hints: [] as HintResult[] };
  let selected: { points: Vec3[]; viewpoint: Vec3 } | null = null;
  const ctx: StrokeContext = {
    sample: (x, y) => cam.sample(x, y),
    eye: () => cam.eye,
    forward: () => cam.fwd,
    step: () => step,
    showDraft: () => {},
    preview: () => {},
    notify: () => {},
    commit: (points) => {
      log.commits++;
      selected = { points, viewpoint: cam.eye };
    },
    hintTarget: () =>
      selected && {
        points: selected.points,
        surface: buildSupportingSurface(selected.points, selected.viewpoint, mode, 6 * step),
      },
    applyHint: (r) => {
      log.hints.push(r);
      if (selected && r.op.kind !== 'none') selected = { ...selected, points: r.points };
    },
  };
  if (withScreen) ctx.toScreen = (p) => cam.toScreen(p);
  const tool = new StreamCurveTool(ctx);
  const drag = (pts: P[]) => {
    tool.onPointerDown({ ...pts[0], button: 0 });
    for (const p of pts.slice(1)) tool.onPointerMove({ ...p, button: 0 });
    tool.update();
    tool.onPointerUp({ ...pts[pts.length - 1], button: 0 });
  };
  return { cam, log, drag, selected: () => selected };
}

/** The curve's image from point j on, `gap` px to its side, then 40 px on past its end. */
function alongside(cam: Camera, curve: readonly Vec3[], j: number, gap: number): P[] | null {
  const img = curve.map((p) => cam.toScreen(p));
  if (img.some((p) => !p)) return null;
  const q = img as P[];
  const out: P[] = [];
  for (let i = j; i < q.length; i++) {
    const a = q[Math.max(0, i - 1)];
    const b = q[Math.min(q.length - 1, i + 1)];
    const l = Math.hypot(b.x - a.x, b.y - a.y) || 1;
    const n = { x: -(b.y - a.y) / l, y: (b.x - a.x) / l };
    const p = { x: q[i].x + gap * n.x, y: q[i].y + gap * n.y };
    if (out.length) {
      const prev = out[out.length - 1];
      for (let k = 1; k < 4; k++)
        out.push({ x: prev.x + ((p.x - prev.x) * k) / 4, y: prev.y + ((p.y - prev.y) * k) / 4 });
    }
    out.push(p);
  }
  const a = q[q.length - 2];
  const b = q[q.length - 1];
  const l = Math.hypot(b.x - a.x, b.y - a.y) || 1;
  const last = out[out.length - 1];
  for (let k = 1; k <= 10; k++)
    out.push({ x: last.x + (4 * k * (b.x - a.x)) / l, y: last.y + (4 * k * (b.y - a.y)) / l });
  return out;
}

/** From point j of the curve's image, `gap` px to its side, 200 px away at `turn` radians. */
function diverging(cam: Camera, curve: readonly Vec3[], j: number, gap: number, turn: number) {
  const a = cam.toScreen(curve[j]);
  const b = cam.toScreen(curve[Math.min(curve.length - 1, j + 2)]);
  if (!a || !b) return null;
  const l = Math.hypot(b.x - a.x, b.y - a.y) || 1;
  const t = { x: (b.x - a.x) / l, y: (b.y - a.y) / l };
  const n = { x: -t.y, y: t.x };
  const s = { x: a.x + gap * n.x, y: a.y + gap * n.y };
  const dir = {
    x: Math.cos(turn) * t.x + Math.sin(turn) * n.x,
    y: Math.cos(turn) * t.y + Math.sin(turn) * n.y,
  };
  return Array.from({ length: 41 }, (_, k) => ({ x: s.x + 5 * k * dir.x, y: s.y + 5 * k * dir.y }));
}

// Orbits between strokes (yaw, pitch in degrees), where each stroke starts, how far beside the
// last curve (px), and whether it runs along it or turns away from it.
const PLAN: Array<{ yaw: number; pitch: number; j: number; gap: number; turn?: number }> = [
  { yaw: 20, pitch: 8, j: 0, gap: 3 }, // no orbit: right beside the last curve
  { yaw: 20, pitch: 8, j: 1, gap: -4 },
  { yaw: 35, pitch: 15, j: 0, gap: 2 },
  { yaw: 5, pitch: 0, j: 2, gap: 4, turn: 0.5 },
  { yaw: 50, pitch: 20, j: 1, gap: -3 },
  { yaw: 30, pitch: 5, j: 3, gap: 2, turn: -0.6 },
  { yaw: 0, pitch: 25, j: 0, gap: 4 },
  { yaw: 25, pitch: 10, j: 2, gap: -2 },
  { yaw: 45, pitch: 0, j: 1, gap: 5, turn: 0.8 },
  { yaw: 15, pitch: 30, j: 0, gap: -3 },
  { yaw: 40, pitch: 12, j: 4, gap: 3, turn: 0.3 },
  { yaw: 10, pitch: 5, j: 1, gap: 2 },
];

describe('stream curves drawn one after another from the scalp', () => {
  for (const preset of ['25k', '50k'] as const)
    for (const mode of ['ruled', 'strip'] as const)
      for (const withScreen of [true, false])
        it(`each stroke makes a new curve (${preset}, ${mode}, ${withScreen ? 'toScreen' : 'ray angle'})`, () => {
          const step = gridForPreset(preset).step;
          const s = sketcher(step, mode, withScreen);
          // the first curve: from the scalp down over the side of the head
          const root = s.cam.toScreen(normalize([0.35, 0.85, 0.4]) as Vec3) as P;
          s.drag(
            Array.from({ length: 41 }, (_, k) => ({ x: root.x + 1.5 * k, y: root.y + 6 * k })),
          );
          expect(s.log.commits).toBe(1);
          let drawn = 1;
          for (const move of PLAN) {
            s.cam.orbit(move.yaw, move.pitch);
            const c = s.selected()?.points ?? [];
            const j = Math.min(move.j, c.length - 2);
            const pts =
              move.turn === undefined
                ? alongside(s.cam, c, j, move.gap)
                : diverging(s.cam, c, j, move.gap, move.turn);
            if (!pts || !s.cam.sample(pts[0].x, pts[0].y).scalpHit) continue;
            s.drag(pts);
            drawn++;
            expect(s.log.hints.map((h) => h.op)).toEqual([]);
            expect(s.log.commits).toBe(drawn);
          }
          expect(drawn).toBeGreaterThanOrEqual(9);
        });
});
