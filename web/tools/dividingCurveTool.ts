// The "Dividing curve" tool (SPEC S4.5): Idle -> Drawing -> Idle.
// A stroke on the scalp (every sample projected onto the head where the pointer is over the
// scalp) makes a dividing curve. A stroke that starts within HINT_RADIUS grid steps of the
// selected dividing curve is a hint instead: it sets the tilt of that side (tiltFromHint).
import { tiltFromHint } from '../model/dividingFrames';
import { resamplePolyline } from '../model/resample';
import { distance, type Vec3 } from '../model/vec3';
import type { StrokeSample } from './depthRule';
import type { Tool, ToolPointer } from './tool';

/** A press this near the selected dividing curve (grid steps) is a tilt hint. */
export const HINT_RADIUS = 2;

export interface DividingContext {
  sample(x: number, y: number): StrokeSample;
  step(): number;
  /** The selected dividing curve, if any. */
  selected(): { points: readonly Vec3[]; normals: readonly Vec3[] } | null;
  normalsAt(points: readonly Vec3[]): Vec3[];
  showDraft(points: readonly Vec3[] | null): void;
  commit(points: Vec3[], normals: Vec3[]): void;
  setTilt(end: 'alpha0' | 'alpha1', alpha: number, side: 1 | -1): void;
  notify(message: string): void;
}

export class DividingCurveTool implements Tool {
  readonly name = 'dividing';
  state: 'idle' | 'drawing' | 'hinting' = 'idle';
  private raw: Array<{ x: number; y: number }> = [];
  private points: Vec3[] = [];

  constructor(private readonly ctx: DividingContext) {}

  onPointerDown(p: ToolPointer): boolean {
    if (p.button !== 0) return false;
    const first = this.ctx.sample(p.x, p.y);
    if (!first.scalpHit) {
      this.ctx.notify('A dividing curve is drawn on the scalp: nothing was created.');
      return true;
    }
    const sel = this.ctx.selected();
    const hit = first.scalpHit;
    const reach = HINT_RADIUS * this.ctx.step();
    const near = sel?.points.some((q) => distance(q, hit) <= reach) ?? false;
    this.state = near ? 'hinting' : 'drawing';
    this.points = [first.scalpHit];
    this.raw = [];
    return true;
  }

  onPointerMove(p: ToolPointer): void {
    if (this.state !== 'idle') this.raw.push({ x: p.x, y: p.y });
  }

  onPointerUp(p: ToolPointer): void {
    if (this.state === 'idle') return;
    this.raw.push({ x: p.x, y: p.y });
    this.update();
    const hinting = this.state === 'hinting';
    this.state = 'idle';
    this.ctx.showDraft(null);
    const stroke = this.points;
    this.points = [];
    if (hinting) {
      const sel = this.ctx.selected();
      const t = sel && tiltFromHint(sel.points, sel.normals, stroke);
      if (!t) {
        this.ctx.notify('The tilt hint was too short: nothing changed.');
        return;
      }
      this.ctx.setTilt(t.end, t.alpha, t.side);
      return;
    }
    const points = resamplePolyline(stroke, this.ctx.step());
    if (points.length < 3) {
      this.ctx.notify('A dividing curve needs at least two grid steps on the scalp: ignored.');
      return;
    }
    this.ctx.commit(points, this.ctx.normalsAt(points));
  }

  onCancel(): void {
    this.state = 'idle';
    this.raw = [];
    this.points = [];
    this.ctx.showDraft(null);
  }

  update(): void {
    if (this.state === 'idle' || this.raw.length === 0) return;
    // only samples over the scalp: the curve lies on the head
    for (const r of this.raw) {
      const hit = this.ctx.sample(r.x, r.y).scalpHit;
      if (hit) this.points.push(hit);
    }
    this.raw = [];
    this.ctx.showDraft(this.points);
  }
}
