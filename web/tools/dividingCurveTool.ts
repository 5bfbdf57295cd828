// The "Dividing curve" tool (method S4.5): Idle -> Drawing -> Idle.
// A stroke on the scalp (every sample projected onto the head where the pointer is over the
// scalp) makes a dividing curve. A stroke that starts within HINT_RADIUS grid steps of the
// selected dividing curve may instead be a tilt hint, which sets the tilt of that side
// (tiltFromHint). It is one only when it clearly is (isTiltHint): it leaves the curve, its end
// being farther from the curve than its start by at least max(1 grid step, TILT_LEAVE x the
// start-to-end distance) (so it heads away within about 70° of the curve's normal), and the tilt
// it asks for is under 90°. Anything else, e.g. a parting drawn alongside the selected one,
// however close, is a new dividing curve. Decided when the stroke ends.
import { tiltFromHint } from '../model/dividingFrames';
import { resamplePolyline } from '../model/resample';
import { add, distance, dot, scale, sub, type Vec3 } from '../model/vec3';
import type { StrokeSample } from './depthRule';
import { type PendingStroke, StrokeTool } from './strokeTool';
import type { ToolPointer } from './tool';

/** A press this near the selected dividing curve (grid steps) may be a tilt hint (isTiltHint). */
export const HINT_RADIUS = 2;
/** A tilt hint's end is farther from the curve than its start by this fraction of its span. */
export const TILT_LEAVE = 0.3;

/** Distance from p to the polyline. */
export function distanceToPolyline(p: Vec3, line: readonly Vec3[]): number {
  let best = Number.POSITIVE_INFINITY;
  for (let i = 0; i < line.length; i++) {
    best = Math.min(best, distance(p, line[i]));
    if (i + 1 >= line.length) continue;
    const e = sub(line[i + 1], line[i]);
    const ee = dot(e, e);
    const t = ee > 0 ? dot(sub(p, line[i]), e) / ee : 0;
    if (t > 0 && t < 1) best = Math.min(best, distance(p, add(line[i], scale(e, t))));
  }
  return best;
}

/** Whether a stroke (on the scalp) pressed near the dividing curve is clearly a tilt hint. */
export function isTiltHint(
  curve: readonly Vec3[],
  stroke: readonly Vec3[],
  step: number,
  alpha: number,
): boolean {
  if (stroke.length < 2 || !(Math.abs(alpha) < Math.PI / 2)) return false;
  const a = stroke[0];
  const b = stroke[stroke.length - 1];
  const gain = distanceToPolyline(b, curve) - distanceToPolyline(a, curve);
  return gain >= Math.max(step, TILT_LEAVE * distance(a, b));
}

export interface DividingContext {
  sample(x: number, y: number): StrokeSample;
  /** The press's sample: as sample, but a press just off the scalp starts on its nearest point
   *  (absent: sample). */
  sampleStart?(x: number, y: number): StrokeSample;
  step(): number;
  /** The selected dividing curve, if any. */
  selected(): { points: readonly Vec3[]; normals: readonly Vec3[] } | null;
  normalsAt(points: readonly Vec3[]): Vec3[];
  showDraft(points: readonly Vec3[] | null): void;
  commit(points: Vec3[], normals: Vec3[]): void;
  setTilt(end: 'alpha0' | 'alpha1', alpha: number, side: 1 | -1): void;
  notify(message: string): void;
}

/** One stroke, from press to release; it goes when the stroke ends (end()). */
interface Stroke extends PendingStroke {
  /** 'hinting': pressed near the selected dividing curve, so it may be a tilt hint. */
  mode: 'drawing' | 'hinting';
  /** The stroke's samples over the scalp. */
  points: Vec3[];
}

export class DividingCurveTool extends StrokeTool<Stroke> {
  readonly name = 'dividing';

  constructor(private readonly ctx: DividingContext) {
    super();
  }

  get state(): 'idle' | 'drawing' | 'hinting' {
    return this.stroke?.mode ?? 'idle';
  }

  protected begin(p: ToolPointer): Stroke | null {
    const hit = (this.ctx.sampleStart ?? this.ctx.sample).call(this.ctx, p.x, p.y).scalpHit;
    if (!hit) {
      this.ctx.notify(
        'A parting must start on the scalp (or within 2 cm of it): nothing was created.',
      );
      return null;
    }
    const sel = this.ctx.selected();
    const reach = HINT_RADIUS * this.ctx.step();
    const near = !!sel && distanceToPolyline(hit, sel.points) <= reach;
    return { mode: near ? 'hinting' : 'drawing', raw: [], points: [hit] };
  }

  protected clearShown(): void {
    this.ctx.showDraft(null);
  }

  /** What a released stroke does: a tilt, a new dividing curve, or a sentence saying why not. */
  protected finish(k: Stroke): void {
    if (k.mode === 'hinting') {
      const sel = this.ctx.selected();
      const t = sel && tiltFromHint(sel.points, sel.normals, k.points);
      if (sel && t && isTiltHint(sel.points, k.points, this.ctx.step(), t.alpha)) {
        this.ctx.setTilt(t.end, t.alpha, t.side);
        return;
      }
      // not clearly a tilt hint: a new dividing curve
    }
    const points = resamplePolyline(k.points, this.ctx.step());
    if (points.length < 3) {
      this.ctx.notify('A dividing curve needs at least two grid steps on the scalp: ignored.');
      return;
    }
    this.ctx.commit(points, this.ctx.normalsAt(points));
  }

  protected sample(k: Stroke): void {
    // only samples over the scalp: the curve lies on the head
    for (const r of k.raw) {
      const hit = this.ctx.sample(r.x, r.y).scalpHit;
      if (hit) k.points.push(hit);
    }
    k.raw = [];
    this.ctx.showDraft(k.points);
  }
}
