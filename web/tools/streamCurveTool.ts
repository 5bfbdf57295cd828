// The "Stream curve" tool (SPEC S4.1, S4.2): Idle -> Drawing -> Idle.
// A press that does not start on the scalp draws nothing and says why.
import { resamplePolyline } from '../model/resample';
import type { Vec3 } from '../model/vec3';
import { liftStroke, type StrokeSample } from './depthRule';
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
}

export class StreamCurveTool implements Tool {
  readonly name = 'stream';
  state: 'idle' | 'drawing' = 'idle';
  private raw: Array<{ x: number; y: number }> = [];
  private samples: StrokeSample[] = [];
  private eye: Vec3 = [0, 0, 0];
  private forward: Vec3 = [0, 0, -1];

  constructor(private readonly ctx: StrokeContext) {}

  onPointerDown(p: ToolPointer): boolean {
    if (p.button !== 0) return false;
    const first = this.ctx.sample(p.x, p.y);
    if (!first.scalpHit) {
      this.ctx.notify('A stream curve must start on the scalp: nothing was created.');
      return true; // the press is still the tool's: it must not orbit the camera
    }
    this.state = 'drawing';
    this.eye = this.ctx.eye();
    this.forward = this.ctx.forward();
    this.samples = [first];
    this.raw = [];
    return true;
  }

  onPointerMove(p: ToolPointer): void {
    if (this.state === 'drawing') this.raw.push({ x: p.x, y: p.y });
  }

  onPointerUp(p: ToolPointer): void {
    if (this.state !== 'drawing') return;
    this.raw.push({ x: p.x, y: p.y });
    this.update();
    this.state = 'idle';
    this.ctx.showDraft(null);
    this.ctx.preview(null);
    const lifted = liftStroke(this.samples, this.eye, this.forward);
    this.samples = [];
    if (!lifted.ok) return;
    const points = resamplePolyline(lifted.points, this.ctx.step());
    if (points.length < 2) {
      this.ctx.notify('The stroke was shorter than one grid step: ignored.');
      return;
    }
    this.ctx.commit(points);
  }

  onCancel(): void {
    this.state = 'idle';
    this.raw = [];
    this.samples = [];
    this.ctx.showDraft(null);
    this.ctx.preview(null);
  }

  update(): void {
    if (this.state !== 'drawing' || this.raw.length === 0) return;
    for (const r of this.raw) this.samples.push(this.ctx.sample(r.x, r.y));
    this.raw = [];
    const lifted = liftStroke(this.samples, this.eye, this.forward);
    if (!lifted.ok) return;
    this.ctx.showDraft(lifted.points);
    this.ctx.preview(resamplePolyline(lifted.points, this.ctx.step()));
  }
}
