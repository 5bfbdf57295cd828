// The "Ponytail" tool (method S4.6): four strokes make one ponytail.
//   stage 'spine':    a stroke from the scalp, lifted like a stream curve (S4.2);
//   (the user may orbit the view: the right button orbits with any drawing tool)
//   stage 'cross':    a stroke across the spine: the cross-section curve;
//   stage 'profileA', 'profileB': two strokes along the spine on either side: the profiles.
// The last three are lifted onto the spine's supporting surface rebuilt from the view of the
// moment (the 'strip' mode, which faces that view), with hintStroke.ts's depth rule off it.
// After the second profile the circles are computed (ponytailCircles) and the ponytail is
// committed; the tool is then ready for the next spine. Each stroke is its own state machine
// Idle -> Drawing -> Idle; `stage` says which stroke comes next.
import { type PonytailCircle, ponytailCircles } from '../model/ponytailGeometry';
import { resamplePolyline } from '../model/resample';
import { buildSupportingSurface, type SupportingSurface } from '../model/supportingSurface';
import type { Vec3 } from '../model/vec3';
import { liftStroke, type StrokeSample } from './depthRule';
import { liftHintStroke } from './hintStroke';
import type { Tool, ToolPointer } from './tool';

export type PonytailStage = 'spine' | 'cross' | 'profileA' | 'profileB';

/** Half width of the rebuilt supporting surface, in grid steps. */
export const PONYTAIL_SURFACE_HALF_WIDTH = 12;

export interface PonytailDraft {
  spine: Vec3[];
  crossSection: Vec3[];
  profiles: [Vec3[], Vec3[]];
  circles: PonytailCircle[];
}

export interface PonytailContext {
  sample(x: number, y: number): StrokeSample;
  eye(): Vec3;
  forward(): Vec3;
  step(): number;
  showDraft(points: readonly Vec3[] | null): void;
  /** Strokes of the ponytail made so far (shown until it is complete). */
  showGuides(lines: readonly (readonly Vec3[])[]): void;
  commit(p: PonytailDraft): void;
  notify(message: string): void;
  /** The stage changed: the app tells the user which stroke is next. */
  stageChanged(stage: PonytailStage): void;
}

export const PONYTAIL_STAGE_HINT: Record<PonytailStage, string> = {
  spine: 'Ponytail 1/4: drag from the scalp to draw the spine',
  cross:
    'Ponytail 2/4: orbit if you like (right-drag), then draw the cross-section across the spine',
  profileA: 'Ponytail 3/4: draw the first profile along one side of the spine',
  profileB: 'Ponytail 4/4: draw the second profile along the other side of the spine',
};

export class PonytailTool implements Tool {
  readonly name = 'ponytail';
  state: 'idle' | 'drawing' = 'idle';
  stage: PonytailStage = 'spine';
  private raw: Array<{ x: number; y: number }> = [];
  private samples: StrokeSample[] = [];
  private eye: Vec3 = [0, 0, 0];
  private forward: Vec3 = [0, 0, -1];
  private surface: SupportingSurface | null = null;
  private spine: Vec3[] = [];
  private cross: Vec3[] = [];
  private profileA: Vec3[] = [];

  constructor(private readonly ctx: PonytailContext) {}

  /** The spine drawn so far (empty at stage 'spine'). */
  get spinePoints(): readonly Vec3[] {
    return this.spine;
  }

  onPointerDown(p: ToolPointer): boolean {
    if (p.button !== 0) return false;
    const first = this.ctx.sample(p.x, p.y);
    if (this.stage === 'spine' && !first.scalpHit) {
      this.ctx.notify('A ponytail spine must start on the scalp: nothing was created.');
      return true;
    }
    this.eye = this.ctx.eye();
    this.forward = this.ctx.forward();
    this.surface =
      this.stage === 'spine'
        ? null
        : buildSupportingSurface(
            this.spine,
            this.eye,
            'strip',
            PONYTAIL_SURFACE_HALF_WIDTH * this.ctx.step(),
          );
    this.samples = [first];
    this.raw = [];
    this.state = 'drawing';
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
    const pts = this.lifted();
    this.samples = [];
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
        this.spine = spine;
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
        const g = ponytailCircles(this.spine, this.cross, this.profileA, line, { every: 2 });
        if (g.circles.length === 0) {
          this.ctx.notify(
            'The profiles do not run beside the spine on both sides: draw the two profiles again.',
          );
          this.setStage('profileA');
          return;
        }
        const draft: PonytailDraft = {
          spine: this.spine,
          crossSection: this.cross,
          profiles: [this.profileA, line],
          circles: g.circles,
        };
        this.reset();
        this.ctx.commit(draft);
        break;
      }
    }
  }

  private setStage(stage: PonytailStage): void {
    this.stage = stage;
    const guides = [this.spine, this.cross, this.profileA].filter((l) => l.length >= 2);
    this.ctx.showGuides(stage === 'spine' ? [] : guides);
    this.ctx.stageChanged(stage);
  }

  private reset(): void {
    this.spine = [];
    this.cross = [];
    this.profileA = [];
    this.setStage('spine');
  }

  private lifted(): Vec3[] | null {
    if (this.stage === 'spine') {
      const l = liftStroke(this.samples, this.eye, this.forward);
      return l.ok ? l.points : null;
    }
    if (!this.surface) return null;
    const rays = this.samples.map((s) => ({ origin: s.origin, direction: s.direction }));
    return liftHintStroke(rays, this.surface, this.eye, this.forward).map((h) => h.point);
  }

  onCancel(): void {
    const drawing = this.state === 'drawing';
    this.state = 'idle';
    this.raw = [];
    this.samples = [];
    this.ctx.showDraft(null);
    // cancelling a stroke keeps the ponytail's earlier strokes; cancelling between strokes
    // (Escape, another tool) abandons the ponytail
    if (!drawing && this.stage !== 'spine') this.reset();
  }

  update(): void {
    if (this.state !== 'drawing' || this.raw.length === 0) return;
    for (const r of this.raw) this.samples.push(this.ctx.sample(r.x, r.y));
    this.raw = [];
    const pts = this.lifted();
    if (pts) this.ctx.showDraft(pts);
  }
}
