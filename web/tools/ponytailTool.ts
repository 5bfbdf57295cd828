// The "Ponytail" tool. One stroke makes a ponytail; three more may shape it (method S4.6):
//   stage 'spine':    a stroke from the scalp where the tie sits along the tail, lifted like a
//                     stream curve (S4.2) and previewed as the ponytail it makes; on release the
//                     ponytail is made (model/ponytailFromSpine.ts: its cross-section, profiles
//                     and circles made for it);
//   (the user may orbit the view: the right button orbits with any drawing tool)
//   stage 'cross':    a stroke across the spine: the cross-section curve;
//   stage 'profileA', 'profileB': two strokes along the spine on either side: the profiles;
//                     after the second, the circles are computed from the drawn strokes
//                     (ponytailCircles) and replace the made ones (one undoable edit).
// A press on the scalp away from the spine starts the next ponytail instead. The last three
// strokes are lifted onto the spine's supporting surface rebuilt from the view of the moment
// (the 'strip' mode, which faces that view), with hintStroke.ts's depth rule off it. Each stroke
// is its own state machine Idle -> Drawing -> Idle; `stage` says which stroke comes next.

import { bandIndex } from '../model/ponytailFromSpine';
import { type PonytailCircle, ponytailCircles } from '../model/ponytailGeometry';
import { resamplePolyline } from '../model/resample';
import { buildSupportingSurface, type SupportingSurface } from '../model/supportingSurface';
import type { Vec3 } from '../model/vec3';
import { liftStroke, type StrokeSample } from './depthRule';
import { liftHintStroke } from './hintStroke';
import { type PendingStroke, StrokeTool } from './strokeTool';
import type { ToolPointer } from './tool';

export type PonytailStage = 'spine' | 'cross' | 'profileA' | 'profileB';

/** Half width of the rebuilt supporting surface, in grid steps. */
export const PONYTAIL_SURFACE_HALF_WIDTH = 12;

/** The strokes that shape a ponytail after its spine, and the circles computed from them. */
export interface PonytailShape {
  crossSection: Vec3[];
  profiles: [Vec3[], Vec3[]];
  circles: PonytailCircle[];
}

export interface PonytailContext {
  sample(x: number, y: number): StrokeSample;
  /** The press's sample: as sample, but a press just off the scalp starts on its nearest point
   *  (absent: sample). */
  sampleStart?(x: number, y: number): StrokeSample;
  eye(): Vec3;
  forward(): Vec3;
  step(): number;
  showDraft(points: readonly Vec3[] | null): void;
  /** Strokes of the ponytail made so far (shown until it is complete). */
  showGuides(lines: readonly (readonly Vec3[])[]): void;
  /** The spine drawn so far (null: none): the hair previews the ponytail it will make. */
  preview(points: Vec3[] | null): void;
  /** Makes the ponytail of one spine: its id and its spine as made (on the head's symmetry
   *  plane when drawn near it), or null when nothing was made. */
  commitSpine(spine: Vec3[]): { id: string; spine: Vec3[] } | null;
  /** The cross-section and profiles drawn for ponytail `id`. */
  shape(id: string, shape: PonytailShape): void;
  /** Whether the screen point is near the spine's image (a shaping stroke starts there). */
  nearSpine(x: number, y: number, spine: readonly Vec3[]): boolean;
  notify(message: string): void;
  /** The stage changed: the app tells the user which stroke is next. */
  stageChanged(stage: PonytailStage): void;
}

export const PONYTAIL_STAGE_HINT: Record<PonytailStage, string> = {
  spine:
    'Ponytail: drag its spine from the scalp where the tie sits, along the tail (one stroke makes it)',
  cross:
    'Ponytail made. To shape it (2/4): orbit if you like (right-drag), then draw the cross-section across the spine; or drag from the scalp for another',
  profileA: 'Ponytail 3/4: draw the first profile along one side of the spine',
  profileB: 'Ponytail 4/4: draw the second profile along the other side of the spine',
};

/** One stroke, from press to release; it goes when the stroke ends (end()). */
interface Stroke extends PendingStroke {
  samples: StrokeSample[];
  /** The camera when the stroke began. */
  eye: Vec3;
  forward: Vec3;
  /** The spine's supporting surface from that camera (null while drawing the spine). */
  surface: SupportingSurface | null;
}

export class PonytailTool extends StrokeTool<Stroke> {
  readonly name = 'ponytail';
  stage: PonytailStage = 'spine';
  /** The ponytail's strokes so far (kept between strokes, dropped by reset()). */
  private spine: Vec3[] = [];
  private cross: Vec3[] = [];
  private profileA: Vec3[] = [];
  /** The ponytail the shaping strokes are for. */
  private made: string | null = null;

  constructor(private readonly ctx: PonytailContext) {
    super();
  }

  get state(): 'idle' | 'drawing' {
    return this.stroke ? 'drawing' : 'idle';
  }

  /** The spine drawn so far (empty at stage 'spine'). */
  get spinePoints(): readonly Vec3[] {
    return this.spine;
  }

  protected begin(p: ToolPointer): Stroke | null {
    let first = this.ctx.sample(p.x, p.y);
    // a spine's press just off the scalp starts on it
    if (this.stage === 'spine' && !first.scalpHit && this.ctx.sampleStart)
      first = this.ctx.sampleStart(p.x, p.y);
    // a press on the scalp away from the spine starts the next ponytail
    if (this.stage !== 'spine' && first.scalpHit && !this.ctx.nearSpine(p.x, p.y, this.spine))
      this.reset();
    if (this.stage === 'spine' && !first.scalpHit) {
      this.ctx.notify('A ponytail spine must start on the scalp: nothing was created.');
      return null;
    }
    const eye = this.ctx.eye();
    const surface =
      this.stage === 'spine'
        ? null
        : buildSupportingSurface(
            this.spine,
            eye,
            'strip',
            PONYTAIL_SURFACE_HALF_WIDTH * this.ctx.step(),
          );
    return { raw: [], samples: [first], eye, forward: this.ctx.forward(), surface };
  }

  protected clearShown(): void {
    this.ctx.showDraft(null);
    this.ctx.preview(null);
  }

  protected finish(k: Stroke): void {
    this.finishLifted(this.lifted(k));
  }

  /** A released stroke, lifted: the ponytail's next part, or a sentence saying why not. */
  private finishLifted(pts: Vec3[] | null): void {
    const step = this.ctx.step();
    const line = pts ? resamplePolyline(pts, step / 2) : [];
    if (line.length < 2) {
      this.ctx.notify('The stroke was shorter than one grid step: ignored.');
      return;
    }
    switch (this.stage) {
      case 'spine': {
        const spine = resamplePolyline(pts ?? [], step);
        if (spine.length < 3) {
          this.ctx.notify('A ponytail spine needs at least two grid steps: ignored.');
          return;
        }
        const made = this.ctx.commitSpine(spine);
        if (!made) return;
        this.spine = made.spine;
        this.made = made.id;
        this.setStage('cross');
        break;
      }
      case 'cross':
        this.cross = line;
        this.setStage('profileA');
        break;
      case 'profileA':
        this.profileA = line;
        this.setStage('profileB');
        break;
      case 'profileB': {
        const g = ponytailCircles(this.spine, this.cross, this.profileA, line, {
          every: 2,
          from: bandIndex(this.spine),
        });
        if (g.circles.length === 0) {
          this.ctx.notify(
            'The profiles do not run beside the spine on both sides: draw the two profiles again.',
          );
          this.setStage('profileA');
          return;
        }
        const shape: PonytailShape = {
          crossSection: this.cross,
          profiles: [this.profileA, line],
          circles: g.circles,
        };
        const id = this.made;
        this.reset();
        if (id) this.ctx.shape(id, shape);
        break;
      }
    }
  }

  /** The session changed (an edit, Undo, Redo, a loaded file): shaping strokes wait for a
   *  ponytail only while it is still the one made. Fresh eyes undid a new ponytail, drew the next
   *  spine beside where it had been, and got the cross-section of the ponytail undone. */
  sessionChanged(curves: readonly { id: string; points: readonly Vec3[] }[]): void {
    if (this.stage === 'spine' || this.stroke || this.made === null) return;
    const c = curves.find((k) => k.id === this.made);
    if (!c || c.points.length !== this.spine.length) this.reset();
  }

  private setStage(stage: PonytailStage): void {
    this.stage = stage;
    const guides = [this.spine, this.cross, this.profileA].filter((l) => l.length >= 2);
    this.ctx.showGuides(stage === 'spine' ? [] : guides);
    this.ctx.stageChanged(stage);
  }

  /** Abandons the ponytail: its strokes so far go. */
  private reset(): void {
    this.spine = [];
    this.cross = [];
    this.profileA = [];
    this.made = null;
    this.setStage('spine');
  }

  private lifted(k: Stroke): Vec3[] | null {
    if (this.stage === 'spine') {
      const l = liftStroke(k.samples, k.eye, k.forward, true);
      return l.ok ? l.points : null;
    }
    if (!k.surface) return null;
    const rays = k.samples.map((s) => ({ origin: s.origin, direction: s.direction }));
    return liftHintStroke(rays, k.surface, k.eye, k.forward).map((h) => h.point);
  }

  onCancel(): void {
    const drawing = this.stroke !== null;
    super.onCancel();
    // cancelling a stroke keeps the ponytail's earlier strokes; cancelling between strokes
    // (Escape, another tool) abandons the ponytail
    if (!drawing && this.stage !== 'spine') this.reset();
  }

  /** Samples the pointer positions taken since the last call, shows the stroke and (unless
   *  `preview` is false) previews the spine's ponytail. */
  protected sample(k: Stroke, preview: boolean): void {
    for (const r of k.raw) k.samples.push(this.ctx.sample(r.x, r.y));
    k.raw = [];
    const pts = this.lifted(k);
    if (!pts) return;
    this.ctx.showDraft(pts);
    if (preview && this.stage === 'spine') {
      const spine = resamplePolyline(pts, this.ctx.step());
      if (spine.length >= 3) this.ctx.preview(spine);
    }
  }
}
