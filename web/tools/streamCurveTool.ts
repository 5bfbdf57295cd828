// The "Stream curve" tool (method S4.1–S4.4): Idle -> Drawing | Hinting -> Idle.
//
// Which strokes draw and which edit (hintStroke.ts has the thresholds):
//  - A press off the scalp on the selected stream curve's supporting surface (in front of the
//    head) is a hint stroke: it cuts, extends or re-routes that curve, or changes nothing and
//    says why ('Hint: no operation (reason)').
//  - A press off the scalp and off that surface draws nothing and says why.
//  - A press on the scalp draws a new stream curve, unless the stroke is clearly a hint for the
//    selected curve (scalpHintEdit): it starts on that curve's supporting surface and not behind
//    the head, it is recognised as an operation, and concatenate / insert start on the curve
//    itself (within 8 px of its image); an insert must also leave the curve between its ends
//    (a stroke along the curve, however close, is a new curve); a cut must start and end clear
//    of the curve and really cross it. Whether it is a hint is decided when the stroke ends (the
//    draft shows which way it currently reads); anything else is a new curve, so drawing curve
//    after curve from the scalp gives a curve every time, wherever the last one lies.
// "Distance from the curve's image" uses ctx.toScreen when the app supplies it, else the angle
// between the pointer's ray and the curve, at RADIANS_PER_PIXEL.
import { resamplePolyline } from '../model/resample';
import { intersectSupportingSurface, type SupportingSurface } from '../model/supportingSurface';
import { add, distance, dot, length, scale, sub, type Vec3 } from '../model/vec3';
import { liftStroke, type StrokeSample } from './depthRule';
import {
  editWithHintStroke,
  type HintResult,
  type HintSample,
  liftHintStroke,
  type StrokeRay,
  scalpHintEdit,
} from './hintStroke';
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
  /**
   * Optional: client coordinates (the pointer's frame) of a world point in the current view, or
   * null when it is not on screen. Used to measure how far a stroke pressed on the scalp is from
   * the selected curve's image; without it the tool measures the angle between the pointer's ray
   * and the curve instead (RADIANS_PER_PIXEL).
   */
  toScreen?(p: Vec3): { x: number; y: number } | null;
}

/** Without ctx.toScreen, an angle of this many radians counts as one pixel (a 35° field of view
 *  over a canvas about 610 px high). */
export const RADIANS_PER_PIXEL = 0.001;

type Target = { points: readonly Vec3[]; surface: SupportingSurface };

/** Smallest angle (radians) between the ray and a point of the segment a-b. */
function rayAngleToSegment(o: Vec3, u: Vec3, a: Vec3, b: Vec3): number {
  const angle = (q: Vec3) => {
    const w = sub(q, o);
    const along = dot(w, u);
    return Math.atan2(length(sub(w, scale(u, along))), along);
  };
  // the segment's point nearest the ray's line, then the better of it and the two ends
  const e = sub(b, a);
  const w0 = sub(a, o);
  const ee = dot(e, e);
  const eu = dot(e, u);
  const den = ee - eu * eu;
  let best = Math.min(angle(a), angle(b));
  if (den > 1e-18 * ee) {
    const t = (eu * dot(w0, u) - dot(w0, e)) / den;
    if (t > 0 && t < 1) best = Math.min(best, angle(add(a, scale(e, t))));
  }
  return best;
}

/** Distance (pixels) of a point to a screen polyline with gaps (null: not on screen). */
function screenDistanceToPolyline(
  q: { x: number; y: number },
  line: ReadonlyArray<{ x: number; y: number } | null>,
): number {
  let best = Number.POSITIVE_INFINITY;
  for (let i = 0; i < line.length; i++) {
    const a = line[i];
    if (!a) continue;
    best = Math.min(best, Math.hypot(q.x - a.x, q.y - a.y));
    const b = line[i + 1];
    if (!b) continue;
    const ex = b.x - a.x;
    const ey = b.y - a.y;
    const ee = ex * ex + ey * ey;
    if (ee <= 0) continue;
    const t = ((q.x - a.x) * ex + (q.y - a.y) * ey) / ee;
    if (t > 0 && t < 1) best = Math.min(best, Math.hypot(q.x - a.x - t * ex, q.y - a.y - t * ey));
  }
  return best;
}

export class StreamCurveTool implements Tool {
  readonly name = 'stream';
  state: 'idle' | 'drawing' | 'hinting' = 'idle';
  private raw: Array<{ x: number; y: number }> = [];
  private samples: StrokeSample[] = [];
  /** The pointer position of each sample (for screen distances). */
  private pointers: Array<{ x: number; y: number }> = [];
  private target: Target | null = null;
  /** Drawing from the scalp on the selected curve's surface: the stroke may be a hint for it. */
  private candidate: Target | null = null;
  /** The candidate curve's image (with toScreen), and each sample's distance from it (px). */
  private curveImage: Array<{ x: number; y: number } | null> | null = null;
  private screenDistances: number[] = [];
  private eye: Vec3 = [0, 0, 0];
  private forward: Vec3 = [0, 0, -1];

  constructor(private readonly ctx: StrokeContext) {}

  onPointerDown(p: ToolPointer): boolean {
    if (p.button !== 0) return false;
    const first = this.ctx.sample(p.x, p.y);
    this.eye = this.ctx.eye();
    this.forward = this.ctx.forward();
    this.samples = [first];
    this.pointers = [{ x: p.x, y: p.y }];
    this.raw = [];
    this.candidate = null;
    this.curveImage = null;
    this.screenDistances = [];
    const target = this.ctx.hintTarget?.() ?? null;
    let onSurface = false;
    if (target) {
      const hit = intersectSupportingSurface(target.surface, first.origin, first.direction);
      const head = first.headDistance ?? Number.POSITIVE_INFINITY;
      // on the surface, and not behind the head (a step of slack: curves lie on the scalp)
      onSurface = !!hit && (!first.scalpHit || hit.rayT <= head + this.ctx.step());
    }
    if (target && onSurface && !first.scalpHit) {
      this.state = 'hinting';
      this.target = target;
      return true;
    }
    if (!first.scalpHit) {
      this.samples = [];
      this.pointers = [];
      this.ctx.notify('A stream curve must start on the scalp: nothing was created.');
      return true; // the press is still the tool's: it must not orbit the camera
    }
    this.state = 'drawing';
    if (target && onSurface) {
      this.candidate = target;
      if (this.ctx.toScreen) {
        const toScreen = this.ctx.toScreen.bind(this.ctx);
        this.curveImage = target.points.map((q) => toScreen(q));
      }
    }
    return true;
  }

  onPointerMove(p: ToolPointer): void {
    if (this.state !== 'idle') this.raw.push({ x: p.x, y: p.y });
  }

  onPointerUp(p: ToolPointer): void {
    if (this.state === 'idle') return;
    this.raw.push({ x: p.x, y: p.y });
    this.update(false); // the stroke is final: its solve follows, no preview of it
    const hinting = this.state === 'hinting';
    this.state = 'idle';
    this.ctx.showDraft(null);
    this.ctx.preview(null);
    const samples = this.samples;
    const candidate = this.candidate;
    const hint = candidate && !hinting ? this.scalpHint(samples, candidate) : null;
    this.samples = [];
    this.pointers = [];
    this.candidate = null;
    this.curveImage = null;
    this.screenDistances = [];
    if (hinting) {
      const target = this.target;
      this.target = null;
      if (target) this.finishHint(samples, target);
      return;
    }
    if (hint) {
      this.ctx.applyHint?.(hint);
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

  private finishHint(samples: readonly StrokeSample[], target: Target): void {
    const rays: StrokeRay[] = samples.map((s) => ({ origin: s.origin, direction: s.direction }));
    const lifted = liftHintStroke(rays, target.surface, this.eye, this.forward);
    const result = editWithHintStroke(target.points, lifted, this.ctx.step());
    this.ctx.applyHint?.(result);
  }

  /** Distance (pixels) of a sample, taken at `pointer`, from the candidate curve's image. */
  private screenDistance(
    s: StrokeSample,
    pointer: { x: number; y: number } | undefined,
    target: Target,
  ): number {
    if (this.curveImage && pointer) return screenDistanceToPolyline(pointer, this.curveImage);
    const c = target.points;
    let best = Number.POSITIVE_INFINITY;
    for (let k = 0; k + 1 < c.length; k++)
      best = Math.min(best, rayAngleToSegment(s.origin, s.direction, c[k], c[k + 1]));
    if (c.length === 1) best = rayAngleToSegment(s.origin, s.direction, c[0], c[0]);
    return best / RADIANS_PER_PIXEL;
  }

  /** A stroke pressed on the scalp: the hint it clearly is (scalpHintEdit), or null. */
  private scalpHint(samples: readonly StrokeSample[], target: Target): HintResult | null {
    for (let i = this.screenDistances.length; i < samples.length; i++)
      this.screenDistances.push(this.screenDistance(samples[i], this.pointers[i], target));
    const rays: StrokeRay[] = samples.map((s) => ({ origin: s.origin, direction: s.direction }));
    const step = this.ctx.step();
    // samples whose surface point is behind the head (a step of slack) are marked hidden
    const lifted = liftHintStroke(rays, target.surface, this.eye, this.forward).map(
      (h): HintSample => {
        const s = samples[h.ray ?? 0];
        if (!h.onSurface || s.headDistance == null) return h;
        return { ...h, hidden: distance(h.point, s.origin) > s.headDistance + step };
      },
    );
    const screen = lifted.map((h, i) => this.screenDistances[h.ray ?? i]);
    return scalpHintEdit(target.points, lifted, screen, step);
  }

  onCancel(): void {
    this.state = 'idle';
    this.raw = [];
    this.samples = [];
    this.pointers = [];
    this.target = null;
    this.candidate = null;
    this.curveImage = null;
    this.screenDistances = [];
    this.ctx.showDraft(null);
    this.ctx.preview(null);
  }

  /** Samples the pointer positions that came since the last call, shows the stroke so far and
   *  (unless `preview` is false) asks for a preview of it. */
  update(preview = true): void {
    if (this.state === 'idle' || this.raw.length === 0) return;
    for (const r of this.raw) {
      this.samples.push(this.ctx.sample(r.x, r.y));
      this.pointers.push(r);
    }
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
    // a stroke from the scalp that reads as a hint so far shows the edit's stroke
    const hint = this.candidate && this.scalpHint(this.samples, this.candidate);
    if (hint) {
      const rays = this.samples.map((s) => ({ origin: s.origin, direction: s.direction }));
      const t = this.candidate as Target;
      this.ctx.preview(null);
      this.ctx.showDraft(
        liftHintStroke(rays, t.surface, this.eye, this.forward).map((h) => h.point),
      );
      return;
    }
    const lifted = liftStroke(this.samples, this.eye, this.forward);
    if (!lifted.ok) return;
    this.ctx.showDraft(lifted.points);
    if (preview) this.ctx.preview(resamplePolyline(lifted.points, this.ctx.step()));
  }
}
