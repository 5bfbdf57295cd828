// The "Select" tool: a click picks the nearest style curve on screen; a drag orbits the camera.
import type { Vec3 } from '../model/vec3';
import type { Tool, ToolPointer } from './tool';

export interface SelectContext {
  curves(): ReadonlyArray<{ id: string; points: readonly Vec3[] }>;
  toScreen(p: Vec3): { x: number; y: number } | null;
  /** The curve clicked, or null; on a miss, how far (px) the nearest curve's line was. */
  select(id: string | null, missedBy?: number): void;
}

const CLICK_SLOP = 5; // px a click may move
const PICK_RADIUS = 12; // px

export class SelectTool implements Tool {
  readonly name = 'select';
  state: 'idle' | 'pressed' = 'idle';
  private down = { x: 0, y: 0 };

  constructor(private readonly ctx: SelectContext) {}

  onPointerDown(p: ToolPointer): boolean {
    if (p.button !== 0) return false;
    this.state = 'pressed';
    this.down = { x: p.x, y: p.y };
    return false; // a drag still orbits
  }

  onPointerMove(p: ToolPointer): void {
    if (this.state === 'pressed' && Math.hypot(p.x - this.down.x, p.y - this.down.y) > CLICK_SLOP)
      this.state = 'idle';
  }

  onPointerUp(p: ToolPointer): void {
    if (this.state !== 'pressed') return;
    this.state = 'idle';
    const { id, distance } = nearestCurve(this.ctx, p.x, p.y);
    if (id !== null && distance < PICK_RADIUS) this.ctx.select(id);
    else this.ctx.select(null, id === null ? undefined : distance);
  }

  onCancel(): void {
    this.state = 'idle';
  }

  update(): void {}
}

/** The curve nearest (x, y) and its distance in pixels, measured to its screen-space segments
 *  (a click picks it within PICK_RADIUS). */
export function nearestCurve(
  ctx: SelectContext,
  x: number,
  y: number,
): { id: string | null; distance: number } {
  let best: string | null = null;
  let bestD = Number.POSITIVE_INFINITY;
  for (const c of ctx.curves()) {
    const s = c.points.map((p) => ctx.toScreen(p));
    for (let i = 1; i < s.length; i++) {
      const a = s[i - 1];
      const b = s[i];
      if (!a || !b) continue;
      const d = segmentDistance(x, y, a, b);
      if (d < bestD) {
        bestD = d;
        best = c.id;
      }
    }
  }
  return { id: best, distance: bestD };
}

function segmentDistance(
  x: number,
  y: number,
  a: { x: number; y: number },
  b: { x: number; y: number },
): number {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const l2 = dx * dx + dy * dy;
  const t = l2 > 0 ? Math.max(0, Math.min(1, ((x - a.x) * dx + (y - a.y) * dy) / l2)) : 0;
  return Math.hypot(x - (a.x + t * dx), y - (a.y + t * dy));
}
