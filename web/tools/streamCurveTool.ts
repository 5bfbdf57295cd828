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
import { type PendingStroke, StrokeTool } from './strokeTool';
import type { ToolPointer } from './tool';

/** The cosine of the largest angle between the view and the curve's viewpoint from which a
 *  press beside the selected curve is a hint (60°; "Set viewpoint" moves the viewpoint). */
const HINT_VIEW_COS = 0.5;

export interface StrokeContext {
  sample(x: number, y: number): StrokeSample;
  /** The press's sample: as sample, but a press just off the scalp starts on its nearest point
   *  (absent: sample). */
  sampleStart?(x: number, y: number): StrokeSample;
  eye(): Vec3;
  forward(): Vec3;
  step(): number; // grid step d
  showDraft(points: readonly Vec3[] | null): void;
  commit(points: Vec3[]): void;
  /** Live preview of the stroke so far (resampled), or null when the stroke ends. */
  preview(points: Vec3[] | null): void;
  notify(message: string): void;
  /** The selected stream curve and its supporting surface, when hint strokes may edit it;
   *  viewDir: the unit direction of the view the surface faces (the curve's viewpoint). */
  hintTarget?(): { points: readonly Vec3[]; surface: SupportingSurface; viewDir?: Vec3 } | null;
  /** Deselects the selected curve (a press that draws nothing). */
  deselect?(): void;
  /** A hint stroke was recognised (or not: op.kind 'none'); apply the edited points. */
  applyHint?(result: HintResult): void;
  /**
   * Optional: client coordinates (the pointer's frame) of a world point in the current view, or
   * null when it is not on screen. Used to measure how far a stroke pressed on the scalp is from
   * the selected curve's image; without it the tool measures the angle between the pointer's ray
   * and the curve instead (RADIANS_PER_PIXEL).
   */
  toScreen?(p: Vec3): { x: number; y: number } | null;
  /** What the stroke draws, for the status line ('A stream curve' when absent; the Braid tool
   *  draws its stroke with this tool and no hint target). */
  noun?: string;
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

/** One stroke of the tool, from press to release: everything the stroke gathers lives here and
 *  goes when it ends (end()), so no field outlives its stroke. */
interface Stroke extends PendingStroke {
  mode: 'drawing' | 'hinting';
  samples: StrokeSample[];
  /** The pointer position of each sample (for screen distances). */
  pointers: Array<{ x: number; y: number }>;
  /** The camera when the stroke began (the depth rule lifts it from there). */
  eye: Vec3;
  forward: Vec3;
  /** Hinting: the selected curve the stroke edits. Drawing from the scalp on the selected
   *  curve's surface: the curve the stroke may be a hint for (null: it is a new curve). */
  target: Target | null;
  /** The candidate curve's image (with toScreen), and each sample's distance from it (px). */
  curveImage: Array<{ x: number; y: number } | null> | null;
  screenDistances: number[];
}

export class StreamCurveTool extends StrokeTool<Stroke> {
  readonly name = 'stream';

  constructor(private readonly ctx: StrokeContext) {
    super();
  }

  get state(): 'idle' | 'drawing' | 'hinting' {
    return this.stroke?.mode ?? 'idle';
  }

  protected begin(p: ToolPointer): Stroke | null {
    let first = this.ctx.sample(p.x, p.y);
    let target = this.ctx.hintTarget?.() ?? null;
    // hints are drawn from about the view the curve's surface faces: from another view (the
    // camera turned past HINT_VIEW_COS) a press beside the curve starts a new curve, not an edit
    // of the selected one (fresh eyes: a stroke in the left view after one in the top view
    // extended that one)
    const f = this.ctx.forward();
    const v = target?.viewDir;
    if (v && f[0] * v[0] + f[1] * v[1] + f[2] * v[2] < HINT_VIEW_COS) target = null;
    let onSurface = false;
    if (target) {
      const hit = intersectSupportingSurface(target.surface, first.origin, first.direction);
      const head = first.headDistance ?? Number.POSITIVE_INFINITY;
      // on the surface, and not behind the head (a step of slack: curves lie on the scalp)
      onSurface = !!hit && (!first.scalpHit || hit.rayT <= head + this.ctx.step());
    }
    const hinting = !!target && onSurface && !first.scalpHit;
    // not a hint: a press just off the scalp starts on it
    if (!hinting && !first.scalpHit && this.ctx.sampleStart) first = this.ctx.sampleStart(p.x, p.y);
    if (!hinting && !first.scalpHit) {
      // a press on nothing deselects, as a click on the background does: the panel of a curve
      // selected before must not take the next click for it (fresh eyes changed an old curve)
      this.ctx.deselect?.();
      this.ctx.notify(
        `${this.ctx.noun ?? 'A stream curve'} must start on the scalp: nothing was created.`,
      );
      return null; // the press is still the tool's: it must not orbit the camera
    }
    const candidate = target && onSurface ? target : null;
    const toScreen = this.ctx.toScreen?.bind(this.ctx);
    return {
      mode: hinting ? 'hinting' : 'drawing',
      raw: [],
      samples: [first],
      pointers: [{ x: p.x, y: p.y }],
      eye: this.ctx.eye(),
      forward: this.ctx.forward(),
      target: candidate,
      curveImage:
        !hinting && candidate && toScreen ? candidate.points.map((q) => toScreen(q)) : null,
      screenDistances: [],
    };
  }

  protected clearShown(): void {
    this.ctx.showDraft(null);
    this.ctx.preview(null);
  }

  /** What a released stroke does: a hint's edit, a new curve, or a sentence saying why not. */
  protected finish(k: Stroke): void {
    if (k.mode === 'hinting') {
      if (k.target) this.finishHint(k, k.target);
      return;
    }
    const hint = k.target ? this.scalpHint(k, k.target) : null;
    if (hint) {
      this.ctx.applyHint?.(hint);
      return;
    }
    const lifted = liftStroke(k.samples, k.eye, k.forward);
    if (!lifted.ok) return;
    const points = resamplePolyline(lifted.points, this.ctx.step());
    if (points.length < 2) {
      this.ctx.notify('The stroke was shorter than one grid step: ignored.');
      return;
    }
    this.ctx.commit(points);
  }

  private finishHint(k: Stroke, target: Target): void {
    const result = editWithHintStroke(target.points, this.liftOnto(k, target), this.ctx.step());
    this.ctx.applyHint?.(result);
  }

  private liftOnto(k: Stroke, target: Target): HintSample[] {
    const rays: StrokeRay[] = k.samples.map((s) => ({ origin: s.origin, direction: s.direction }));
    return liftHintStroke(rays, target.surface, k.eye, k.forward);
  }

  /** Distance (pixels) of a sample, taken at `pointer`, from the candidate curve's image. */
  private screenDistance(
    k: Stroke,
    s: StrokeSample,
    pointer: { x: number; y: number } | undefined,
    target: Target,
  ): number {
    if (k.curveImage && pointer) return screenDistanceToPolyline(pointer, k.curveImage);
    const c = target.points;
    let best = Number.POSITIVE_INFINITY;
    for (let i = 0; i + 1 < c.length; i++)
      best = Math.min(best, rayAngleToSegment(s.origin, s.direction, c[i], c[i + 1]));
    if (c.length === 1) best = rayAngleToSegment(s.origin, s.direction, c[0], c[0]);
    return best / RADIANS_PER_PIXEL;
  }

  /** A stroke pressed on the scalp: the hint it clearly is (scalpHintEdit), or null. */
  private scalpHint(k: Stroke, target: Target): HintResult | null {
    const samples = k.samples;
    for (let i = k.screenDistances.length; i < samples.length; i++)
      k.screenDistances.push(this.screenDistance(k, samples[i], k.pointers[i], target));
    const step = this.ctx.step();
    // samples whose surface point is behind the head (a step of slack) are marked hidden
    const lifted = this.liftOnto(k, target).map((h): HintSample => {
      const s = samples[h.ray ?? 0];
      if (!h.onSurface || s.headDistance == null) return h;
      return { ...h, hidden: distance(h.point, s.origin) > s.headDistance + step };
    });
    const screen = lifted.map((h, i) => k.screenDistances[h.ray ?? i]);
    return scalpHintEdit(target.points, lifted, screen, step);
  }

  /** Samples the pointer positions that came since the last call, shows the stroke so far and
   *  (unless `preview` is false) asks for a preview of it. */
  protected sample(k: Stroke, preview: boolean): void {
    for (const r of k.raw) {
      k.samples.push(this.ctx.sample(r.x, r.y));
      k.pointers.push(r);
    }
    k.raw = [];
    if (k.mode === 'hinting') {
      if (k.target) this.ctx.showDraft(this.liftOnto(k, k.target).map((h) => h.point));
      return;
    }
    // a stroke from the scalp that reads as a hint so far shows the edit's stroke
    if (k.target && this.scalpHint(k, k.target)) {
      this.ctx.preview(null);
      this.ctx.showDraft(this.liftOnto(k, k.target).map((h) => h.point));
      return;
    }
    const lifted = liftStroke(k.samples, k.eye, k.forward);
    if (!lifted.ok) return;
    this.ctx.showDraft(lifted.points);
    if (preview) this.ctx.preview(resamplePolyline(lifted.points, this.ctx.step()));
  }
}
