// The "Stream curve" tool (SPEC S4.1–S4.4): Idle -> Drawing | Hinting -> Idle.
// A press on the scalp draws a new stream curve; a press on the selected stream curve's
// supporting surface (in front of the head, or off it) is a hint stroke that cuts, extends or
// re-routes that curve (hintStroke.ts). A press that is neither draws nothing and says why.
import { resamplePolyline } from '../model/resample';
import { intersectSupportingSurface, type SupportingSurface } from '../model/supportingSurface';
import type { Vec3 } from '../model/vec3';
import { liftStroke, type StrokeSample } from './depthRule';
import { editWithHintStroke, type HintResult, liftHintStroke, type StrokeRay } from './hintStroke';
import type { Tool, ToolPointer } from './tool';

export interface StrokeContext {
  sample(x: number, y: number): StrokeSample;
  eye(): Vec3;
  forward(): Vec3;
  step(): number; // grid step d
  showDraft(points: readonly Vec3[] | null): void;
  commit(points: Vec3[]): void;
  /** Live preview of the stroke so far (resampled), or null when the stroke ends. */
  preview(points: Vec3[] | null): void;
  notify(message: string): void;
  /** The selected stream curve and its supporting surface, when hint strokes may edit it. */
  hintTarget?(): { points: readonly Vec3[]; surface: SupportingSurface } | null;
  /** A hint stroke was recognised (or not: op.kind 'none'); apply the edited points. */
  applyHint?(result: HintResult): void;
}

export class StreamCurveTool implements Tool {
  readonly name = 'stream';
  state: 'idle' | 'drawing' | 'hinting' = 'idle';
  private raw: Array<{ x: number; y: number }> = [];
  private samples: StrokeSample[] = [];
  private target: { points: readonly Vec3[]; surface: SupportingSurface } | null = null;
  private eye: Vec3 = [0, 0, 0];
  private forward: Vec3 = [0, 0, -1];

  constructor(private readonly ctx: StrokeContext) {}

  onPointerDown(p: ToolPointer): boolean {
    if (p.button !== 0) return false;
    const first = this.ctx.sample(p.x, p.y);
    this.eye = this.ctx.eye();
    this.forward = this.ctx.forward();
    this.samples = [first];
    this.raw = [];
    const target = this.ctx.hintTarget?.() ?? null;
    if (target) {
      const hit = intersectSupportingSurface(target.surface, first.origin, first.direction);
      const head = first.headDistance ?? Number.POSITIVE_INFINITY;
      // on the surface, and not behind the head (a step of slack: curves lie on the scalp)
      if (hit && (!first.scalpHit || hit.rayT <= head + this.ctx.step())) {
        this.state = 'hinting';
        this.target = target;
        return true;
      }
    }
    if (!first.scalpHit) {
      this.samples = [];
      this.ctx.notify('A stream curve must start on the scalp: nothing was created.');
      return true; // the press is still the tool's: it must not orbit the camera
    }
    this.state = 'drawing';
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
    this.ctx.preview(null);
    const samples = this.samples;
    this.samples = [];
    if (hinting) {
      const target = this.target;
      this.target = null;
      if (target) this.finishHint(samples, target);
      return;
    }
    const lifted = liftStroke(samples, this.eye, this.forward);
    if (!lifted.ok) return;
    const points = resamplePolyline(lifted.points, this.ctx.step());
    if (points.length < 2) {
      this.ctx.notify('The stroke was shorter than one grid step: ignored.');
      return;
    }
    this.ctx.commit(points);
  }

  private finishHint(
    samples: readonly StrokeSample[],
    target: { points: readonly Vec3[]; surface: SupportingSurface },
  ): void {
    const rays: StrokeRay[] = samples.map((s) => ({ origin: s.origin, direction: s.direction }));
    const lifted = liftHintStroke(rays, target.surface, this.eye, this.forward);
    const result = editWithHintStroke(target.points, lifted, this.ctx.step());
    this.ctx.applyHint?.(result);
  }

  onCancel(): void {
    this.state = 'idle';
    this.raw = [];
    this.samples = [];
    this.target = null;
    this.ctx.showDraft(null);
    this.ctx.preview(null);
  }

  update(): void {
    if (this.state === 'idle' || this.raw.length === 0) return;
    for (const r of this.raw) this.samples.push(this.ctx.sample(r.x, r.y));
    this.raw = [];
    if (this.state === 'hinting') {
      const t = this.target;
      if (!t) return;
      const rays = this.samples.map((s) => ({ origin: s.origin, direction: s.direction }));
      this.ctx.showDraft(
        liftHintStroke(rays, t.surface, this.eye, this.forward).map((h) => h.point),
      );
      return;
    }
    const lifted = liftStroke(this.samples, this.eye, this.forward);
    if (!lifted.ok) return;
    this.ctx.showDraft(lifted.points);
    this.ctx.preview(resamplePolyline(lifted.points, this.ctx.step()));
  }
}
