// Frames that cost only what changed. The scene is drawn in three layers, back to front:
//   static  — the head (everything that is neither hair nor an overlay);
//   hair    — the strands, opaque, depth-tested against the head;
//   overlay — curves, the stroke being drawn, guides and display glyphs (transparent, cheap),
//             depth-tested against head and hair (overlayStyle.ts).
// After drawing the static layer, and again after the hair, the frame's colour and depth are
// copied (blitFramebuffer) into a cache slot. A later frame whose view (camera, drawing-buffer
// size) and static part are unchanged starts from a copy of a slot instead of drawing it again:
// from the hair slot when the hair is unchanged too (only overlays are drawn: a stroke's draft
// between previews, a selection, a display toggle), else from the static slot (a preview's hair
// and the overlays are drawn: the head is not). The frame is drawn into the canvas itself and
// copied both ways with its own depth, so what a cached frame shows is what a full redraw shows.
// A blit cannot write into a multisampled canvas (a GPU with antialiasing): there the cache is
// off, and frames are cheap anyway.
import type * as THREE from 'three';

/** Where a frame starts: 'hair' = a copy of head and hair (draw only the overlays); 'static' =
 *  a copy of the head (draw hair and overlays); 'none' = draw everything. */
export type FrameSource = 'hair' | 'static' | 'none';

export type FrameMode = 'interactive' | 'settled' | 'full';

/** Hair index count a frame of `mode` draws, given all of the hair and the interactive prefix,
 *  and whether a full-detail frame must follow: a settled view is drawn whole only when an
 *  interactive frame could draw it all, else at interactive detail first. */
export function frameDetail(
  mode: FrameMode,
  all: number,
  interactive: number,
): { count: number; fullDetailNext: boolean } {
  if (mode === 'interactive') return { count: interactive, fullDetailNext: false };
  if (mode === 'settled' && interactive < all) return { count: interactive, fullDetailNext: true };
  return { count: all, fullDetailNext: false };
}

export interface FramePlan {
  source: FrameSource;
  /** Hair index count on screen after the frame (drawn now, or as cached). */
  count: number;
  /** A full-detail frame must follow (the settled view shows a sample of the hair). */
  fullDetailNext: boolean;
}

/** How to draw a frame of `mode`. `staticValid`: the static slot holds this view's head;
 *  `cachedHair`: the hair count the hair slot holds of this view, this hair and static part
 *  (null when it holds none). A cached hair layer is used whenever it has at least the detail
 *  the frame wants: more detail costs nothing there. */
export function planFrame(
  mode: FrameMode,
  all: number,
  interactive: number,
  staticValid: boolean,
  cachedHair: number | null,
): FramePlan {
  const want = frameDetail(mode, all, interactive);
  if (cachedHair !== null && cachedHair >= want.count)
    return {
      source: 'hair',
      count: cachedHair,
      fullDetailNext: want.fullDetailNext && cachedHair < all,
    };
  return { source: staticValid ? 'static' : 'none', ...want };
}

/** Overlay-only frames waiting for hair on its way (a stroke's preview). On a software
 *  rasteriser each frame holds the page's main thread until its pixels are read back, and an
 *  answer that arrives meanwhile waits behind it; the answer's frame draws the overlays too. The
 *  wait lasts at most `ms` from the first expect() that found none running, so the overlays
 *  (the stroke line) still move when answers are slow. Times in ms on one clock. */
export class OverlayWait {
  private until = 0;
  constructor(private readonly ms: number) {}

  /** Hair is on its way (again). */
  expect(now: number): void {
    if (now >= this.until) this.until = now + this.ms;
  }

  /** Nothing is on its way any more. */
  cancel(): void {
    this.until = 0;
  }

  /** Whether a frame planned as `plan` in `mode` waits: only interactive frames that would draw
   *  the overlays alone, while a wait runs. */
  waits(plan: FramePlan, mode: FrameMode, now: number): boolean {
    return plan.source === 'hair' && mode === 'interactive' && now < this.until;
  }

  /** A stroke's previews are on their way: each replaces the hair drawn before it, so the hair
   *  drawn is not copied into the cache (on a software rasteriser the copy costs as much as the
   *  preview's hair). */
  previewing = false;
  /** The hair the last frame drew (its drawable stamp). */
  private drawnHair = '';

  /** As waits, and a frame that would draw again the preview just drawn (not kept in the cache)
   *  only to move the overlays waits as an overlay-only frame does. `hair`: the hair's stamp. */
  holds(plan: FramePlan, mode: FrameMode, now: number, hair: string): boolean {
    const redraw = this.previewing && plan.source === 'static' && hair === this.drawnHair;
    return this.waits(redraw ? { ...plan, source: 'hair' } : plan, mode, now);
  }

  /** A frame was drawn from `source` with the hair `hair` (its stamp). */
  drew(source: FrameSource, hair: string): void {
    if (source !== 'hair') this.drawnHair = hair;
  }
}

/** What a slot was drawn from; a slot is used only while its key equals the frame's. */
export interface LayerKey {
  /** Camera matrices and drawing-buffer size (viewKey). */
  view: string;
  /** The static part's state (the head's geometry and material versions, invalidations). */
  scene: string;
}

/** Key of the hair slot: the layer key plus what hair it holds. */
export interface HairKey extends LayerKey {
  hair: string;
  count: number;
}

export const sameLayer = (a: LayerKey | null, b: LayerKey): boolean =>
  a !== null && a.view === b.view && a.scene === b.scene;

/** The view a frame is drawn from: camera (world and projection matrices) and drawing-buffer
 *  size. Any change (orbit, zoom, resize, the interactive half resolution) invalidates every
 *  slot. */
export function viewKey(
  matrixWorld: ArrayLike<number>,
  projection: ArrayLike<number>,
  width: number,
  height: number,
): string {
  return `${Array.from(matrixWorld).join(',')}|${Array.from(projection).join(',')}|${width}x${height}`;
}

/** Version stamp of objects' drawable state: ids, visibility, geometry and attribute versions,
 *  material versions (an attribute or material flagged needsUpdate bumps it). Not draw ranges:
 *  the viewer sets the hair's per frame and keys the hair slot by its count. Uniform changes are
 *  not seen here: their owners call Viewer.invalidateFrameCache. */
export function drawableStamp(objects: readonly THREE.Object3D[]): string {
  const parts: string[] = [];
  for (const root of objects)
    root.traverse((o) => {
      parts.push(`${o.id}${o.visible ? '' : 'h'}`);
      const m = o as THREE.Mesh;
      if (m.geometry) {
        const g = m.geometry;
        parts.push(`g${g.id}`);
        for (const name in g.attributes) {
          const a = g.attributes[name] as THREE.BufferAttribute;
          parts.push(`${a.version}`);
        }
        if (g.index) parts.push(`i${g.index.version}`);
      }
      const mats = m.material ? (Array.isArray(m.material) ? m.material : [m.material]) : [];
      for (const mat of mats) parts.push(`m${mat.id}.${mat.version}`);
    });
  return parts.join(' ');
}

interface Slot {
  framebuffer: WebGLFramebuffer;
  colour: WebGLRenderbuffer;
  depth: WebGLRenderbuffer;
}

/** Depth formats a slot may use: the first whose blit to and from the canvas raises no error
 *  (the formats must match the canvas's; Chromium's canvas depth is packed depth-stencil). */
const DEPTH_FORMATS = ['DEPTH24_STENCIL8', 'DEPTH_COMPONENT24', 'DEPTH_COMPONENT32F'] as const;

/** The two cache slots (colour + depth renderbuffers) and the copies between them and the
 *  canvas. `available` is false when the canvas cannot be copied to (multisampled) or no depth
 *  format matches: then every frame is drawn whole. */
export class FrameSlots {
  private readonly gl: WebGL2RenderingContext;
  private slots: { static: Slot; hair: Slot } | null = null;
  private width = 0;
  private height = 0;
  private depthFormat: number | null = null;
  private probed = false;
  available = true;

  constructor(private readonly renderer: THREE.WebGLRenderer) {
    this.gl = renderer.getContext() as WebGL2RenderingContext;
    const gl = this.gl;
    if (typeof gl.blitFramebuffer !== 'function') this.available = false;
    else if (Number(gl.getParameter(gl.SAMPLES)) > 0) this.available = false;
  }

  /** Copies the canvas into `slot` (`save`) or `slot` into the canvas (`restore`); the canvas
   *  is `width` × `height`. Returns false when the cache cannot be used. */
  copy(slot: 'static' | 'hair', direction: 'save' | 'restore', width: number, height: number) {
    if (!this.available || !this.ensure(width, height) || !this.slots) return false;
    const fb = this.slots[slot].framebuffer;
    this.blit(direction === 'save' ? null : fb, direction === 'save' ? fb : null);
    return true;
  }

  private blit(from: WebGLFramebuffer | null, to: WebGLFramebuffer | null): void {
    const gl = this.gl;
    const state = this.renderer.state;
    state.setScissorTest(false);
    state.buffers.color.setMask(true);
    state.buffers.depth.setMask(true);
    state.bindFramebuffer(gl.READ_FRAMEBUFFER, from);
    state.bindFramebuffer(gl.DRAW_FRAMEBUFFER, to);
    const w = this.width;
    const h = this.height;
    gl.blitFramebuffer(
      0,
      0,
      w,
      h,
      0,
      0,
      w,
      h,
      gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT,
      gl.NEAREST,
    );
    state.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    state.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
  }

  /** Slots of the canvas's size (made, or remade on a resize). */
  private ensure(width: number, height: number): boolean {
    if (this.slots && width === this.width && height === this.height) return true;
    this.release();
    this.width = width;
    this.height = height;
    const gl = this.gl;
    const formats = this.probed
      ? this.depthFormat === null
        ? []
        : [this.depthFormat]
      : DEPTH_FORMATS.map((f) => gl[f]);
    for (const format of formats) {
      const s = { static: this.makeSlot(format), hair: this.makeSlot(format) };
      if (!this.probed) {
        // errors from before are not the probe's
        for (let k = 0; k < 16 && gl.getError() !== gl.NO_ERROR; k++);
        this.blit(null, s.static.framebuffer);
        this.blit(s.static.framebuffer, null);
        if (gl.getError() !== gl.NO_ERROR) {
          this.freeSlot(s.static);
          this.freeSlot(s.hair);
          continue;
        }
        this.probed = true;
        this.depthFormat = format;
      }
      this.slots = s;
      return true;
    }
    this.probed = true;
    this.available = false;
    return false;
  }

  private makeSlot(depthFormat: number): Slot {
    const gl = this.gl;
    const framebuffer = gl.createFramebuffer();
    const colour = gl.createRenderbuffer();
    const depth = gl.createRenderbuffer();
    if (!framebuffer || !colour || !depth)
      throw new Error('WebGL: no framebuffer for the frame cache');
    gl.bindRenderbuffer(gl.RENDERBUFFER, colour);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.RGBA8, this.width, this.height);
    gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
    gl.renderbufferStorage(gl.RENDERBUFFER, depthFormat, this.width, this.height);
    gl.bindRenderbuffer(gl.RENDERBUFFER, null);
    const state = this.renderer.state;
    state.bindFramebuffer(gl.DRAW_FRAMEBUFFER, framebuffer);
    gl.framebufferRenderbuffer(gl.DRAW_FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, colour);
    const attachment =
      depthFormat === gl.DEPTH24_STENCIL8 ? gl.DEPTH_STENCIL_ATTACHMENT : gl.DEPTH_ATTACHMENT;
    gl.framebufferRenderbuffer(gl.DRAW_FRAMEBUFFER, attachment, gl.RENDERBUFFER, depth);
    state.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
    return { framebuffer, colour, depth };
  }

  private freeSlot(s: Slot): void {
    this.gl.deleteFramebuffer(s.framebuffer);
    this.gl.deleteRenderbuffer(s.colour);
    this.gl.deleteRenderbuffer(s.depth);
  }

  private release(): void {
    if (!this.slots) return;
    this.freeSlot(this.slots.static);
    this.freeSlot(this.slots.hair);
    this.slots = null;
  }
}
