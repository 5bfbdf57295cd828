// The scalp brush: drag on the head to paint scalp, Shift+drag to erase it; the wheel
// sets the brush radius (5 % a notch). A ring on the head under the pointer shows the brush's
// size and whether it paints or erases (Shift held). A drag that starts off the head paints from
// where it comes onto the head. The stroke is shown painted while it is drawn (a preview of the mask,
// no solve) and becomes one undoable edit on release: the session keeps the stroke, and the
// roots redistribute over the painted area when the solver gets the new mask.
import type { ScalpPaintStroke } from '../head/scalpPaint';
import type { Vec3 } from '../model/vec3';
import type { Tool, ToolPointer } from './tool';

export const BRUSH_RADIUS = { min: 0.05, max: 1.0, initial: 0.2 } as const;

export interface ScalpBrushDeps {
  /** The head surface under the pointer (any part), or null. */
  hit(x: number, y: number): Vec3 | null;
  /** Shows the stroke painted (null: the preview ends). */
  preview(stroke: ScalpPaintStroke | null): void;
  commit(stroke: ScalpPaintStroke): void;
  /** The radius changed (status line). */
  radiusChanged?(radius: number): void;
  /** Shows the brush's ring at a head point (null: hides it). */
  ring?(at: { point: Vec3; radius: number; erase: boolean } | null): void;
  notify(message: string): void;
}

/** One brush stroke, from press to release; it goes when the stroke ends (end()). */
interface Stroke {
  erase: boolean;
  points: Vec3[];
  /** Points came since the preview was last shown. */
  dirty: boolean;
}

export class ScalpBrushTool implements Tool {
  readonly name = 'scalp';
  private stroke: Stroke | null = null;
  private r: number = BRUSH_RADIUS.initial;
  /** Where the ring is shown (the last head point under the pointer), and its mode. */
  private ringAt: { point: Vec3; erase: boolean } | null = null;

  constructor(private readonly d: ScalpBrushDeps) {}

  get state(): string {
    return this.stroke ? 'painting' : 'idle';
  }

  get radius(): number {
    return this.r;
  }

  setRadius(r: number): void {
    const next = Math.min(BRUSH_RADIUS.max, Math.max(BRUSH_RADIUS.min, r));
    if (!Number.isFinite(next) || next === this.r) return;
    this.r = next;
    this.d.radiusChanged?.(next);
    this.showRing();
  }

  /** The wheel scales the radius (5 % a notch) instead of zooming. */
  onWheel(deltaY: number): boolean {
    this.setRadius(this.r * (deltaY < 0 ? 1.05 : 1 / 1.05));
    return true;
  }

  onHover(p: ToolPointer | null): void {
    const hit = p ? this.d.hit(p.x, p.y) : null;
    this.ringAt = hit && p ? { point: hit, erase: !!p.shiftKey } : null;
    this.showRing();
  }

  /** The tool is put down: the ring goes. */
  hideRing(): void {
    this.ringAt = null;
    this.showRing();
  }

  private showRing(): void {
    const a = this.ringAt;
    this.d.ring?.(a ? { point: a.point, radius: this.r, erase: a.erase } : null);
  }

  onPointerDown(p: ToolPointer): boolean {
    if (p.button !== 0) return false;
    const hit = this.d.hit(p.x, p.y);
    // off the head the stroke starts empty and paints once the drag comes onto the head
    this.stroke = { erase: !!p.shiftKey, points: hit ? [hit] : [], dirty: !!hit };
    this.ringAt = hit ? { point: hit, erase: !!p.shiftKey } : null;
    this.showRing();
    return true;
  }

  onPointerMove(p: ToolPointer): void {
    const k = this.stroke;
    if (!k) return;
    const hit = this.d.hit(p.x, p.y);
    if (!hit) return;
    this.ringAt = { point: hit, erase: k.erase };
    this.showRing();
    const last = k.points[k.points.length - 1];
    if (last && Math.hypot(hit[0] - last[0], hit[1] - last[1], hit[2] - last[2]) < this.r / 3)
      return;
    k.points.push(hit);
    k.dirty = true;
  }

  onPointerUp(p: ToolPointer): void {
    const k = this.stroke;
    if (!k) return;
    this.onPointerMove(p);
    this.end();
    if (k.points.length === 0) {
      this.d.notify('Scalp brush: the drag never came onto the head, so nothing was painted.');
      return;
    }
    this.d.commit(this.painted(k));
  }

  onCancel(): void {
    if (this.stroke) this.end();
  }

  /** Leaving the stroke: its data and its preview go. */
  private end(): void {
    this.stroke = null;
    this.d.preview(null);
  }

  update(): void {
    const k = this.stroke;
    if (!k?.dirty) return;
    k.dirty = false;
    this.d.preview(this.painted(k));
  }

  private painted(k: Stroke): ScalpPaintStroke {
    return { erase: k.erase, radius: this.r, points: [...k.points] };
  }
}
