// The "Bun" tool: one loop drawn on the head where the bun sits (solver-cpp/src/braid_bun.hpp
// takes the loop's mean as the bun's centre, its plane's normal as its axis and its size as its
// radius). Idle -> Drawing -> Idle. Every point of the stroke must lie on the head: a stroke that
// leaves it, or a loop too small to be one, makes nothing and says why.
import { resamplePolyline } from '../model/resample';
import { add, distance, scale, type Vec3 } from '../model/vec3';
import type { StrokeSample } from './depthRule';
import { type PendingStroke, StrokeTool } from './strokeTool';
import type { ToolPointer } from './tool';

export interface BunContext {
  sample(x: number, y: number): StrokeSample;
  step(): number; // grid step d
  showDraft(points: readonly Vec3[] | null): void;
  commit(points: Vec3[]): void;
  notify(message: string): void;
}

/** The fewest points (at the grid step) of a bun's loop. */
export const BUN_MIN_POINTS = 6;

/** The point where a sample's ray meets the head, or null when it misses the head. */
function headPoint(s: StrokeSample): Vec3 | null {
  if (s.headDistance == null) return s.scalpHit;
  return s.scalpHit ?? add(s.origin, scale(s.direction, s.headDistance));
}

/** Why a loop (at the grid step) cannot be a bun, or null when it can. */
export function bunLoopProblem(points: readonly Vec3[], step: number): string | null {
  if (points.length < BUN_MIN_POINTS)
    return 'The loop was too short for a bun: nothing was created.';
  const c: Vec3 = [0, 0, 0];
  for (const p of points) for (let a = 0; a < 3; a++) c[a] += p[a] / points.length;
  let size = 0;
  for (const p of points) size += distance(p, c) / points.length;
  if (size < step) return 'The loop was too small for a bun: nothing was created.';
  return null;
}

interface BunStroke extends PendingStroke {
  points: Vec3[];
  offHead: boolean;
}

export class BunTool extends StrokeTool<BunStroke> {
  readonly name = 'bun';

  constructor(private readonly ctx: BunContext) {
    super();
  }

  get state(): 'idle' | 'drawing' {
    return this.stroke ? 'drawing' : 'idle';
  }

  protected begin(p: ToolPointer): BunStroke | null {
    const first = headPoint(this.ctx.sample(p.x, p.y));
    if (!first) {
      // fresh eyes began a loop on its far side, just past the head's outline, and could not
      // tell which point was off the head
      this.ctx.notify(
        'A bun is a loop drawn on the head: this press is off it (beyond the outline). Start the loop inside the outline; nothing was created.',
      );
      return null;
    }
    return { raw: [], points: [first], offHead: false };
  }

  protected finish(k: BunStroke): void {
    if (k.offHead) {
      this.ctx.notify(
        "The bun's loop left the head (it went past the outline): draw it a little further inside; nothing was created.",
      );
      return;
    }
    const points = resamplePolyline(k.points, this.ctx.step());
    const problem = bunLoopProblem(points, this.ctx.step());
    if (problem) {
      this.ctx.notify(problem);
      return;
    }
    this.ctx.commit(points);
  }

  protected clearShown(): void {
    this.ctx.showDraft(null);
  }

  protected sample(k: BunStroke): void {
    for (const r of k.raw) {
      const q = headPoint(this.ctx.sample(r.x, r.y));
      if (q) k.points.push(q);
      else k.offHead = true;
    }
    k.raw = [];
    this.ctx.showDraft(k.points);
  }
}
