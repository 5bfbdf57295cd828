// The pointer handling every stroke tool shares (stream curve, dividing curve, ponytail, bun): a
// primary press starts a stroke (or is taken and starts nothing, having said why), moves queue
// their pointer positions, update() samples them once a frame, and the release samples the last,
// finishes the stroke and ends it (its draft and preview go). A subclass says what a press
// starts, how queued positions are sampled and what a released stroke does.
import type { Tool, ToolPointer } from './tool';

/** What every stroke keeps: pointer positions not sampled yet. */
export interface PendingStroke {
  raw: Array<{ x: number; y: number }>;
}

export abstract class StrokeTool<K extends PendingStroke> implements Tool {
  abstract readonly name: string;
  abstract readonly state: string;
  protected stroke: K | null = null;

  /** A primary press: the stroke it starts, or null when it starts none (the press is still the
   *  tool's, so the camera does not orbit; the tool has said why). */
  protected abstract begin(p: ToolPointer): K | null;
  /** Samples k.raw (and empties it); shows the stroke so far, and a preview unless `preview`
   *  is false (the release: the stroke's solve follows). */
  protected abstract sample(k: K, preview: boolean): void;
  /** What a released stroke does (its commit comes before the stroke ends, so a commit ends the
   *  stroke's preview with it). */
  protected abstract finish(k: K): void;
  /** What goes when a stroke ends, beside its data: its draft, its preview. */
  protected abstract clearShown(): void;

  onPointerDown(p: ToolPointer): boolean {
    if (p.button !== 0) return false;
    this.stroke = this.begin(p);
    return true;
  }

  onPointerMove(p: ToolPointer): void {
    this.stroke?.raw.push({ x: p.x, y: p.y });
  }

  onPointerUp(p: ToolPointer): void {
    const k = this.stroke;
    if (!k) return;
    k.raw.push({ x: p.x, y: p.y });
    this.sample(k, false);
    this.finish(k);
    this.end();
  }

  onCancel(): void {
    this.end();
  }

  /** Samples the pointer positions that came since the last call (once a frame). */
  update(): void {
    const k = this.stroke;
    if (k && k.raw.length > 0) this.sample(k, true);
  }

  /** Leaving the stroke: its data goes, and what it showed. */
  protected end(): void {
    this.stroke = null;
    this.clearShown();
  }
}
