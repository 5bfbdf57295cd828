// Pointer and keyboard input. A press goes to the active tool (which may take it from the
// camera); keys run the action whose shortcut they spell (the actions table), except while
// typing into a text field.
import type { Tool } from '../tools/tool';
import type { Action } from '../ui/action';
import { typesText } from '../ui/displayToggles';
import type { Viewer } from '../viewer/viewer';
import { actionForShortcut, shortcutOf } from './actions';

export interface InputDeps {
  viewer: Viewer;
  tool(): Tool;
  actions: readonly Action[];
  /** A key was pressed while an overlay (help) is open: it may close it. */
  overlayKey?(key: string): boolean;
  /** Benchmark probe: when the last pointer-up happened (performance.now()). */
  pointerUp?(time: number): void;
}

export function bindInput(d: InputDeps): void {
  const canvas = d.viewer.canvas;
  let captured: number | null = null;
  const ptr = (e: PointerEvent) => ({
    x: e.clientX,
    y: e.clientY,
    button: e.button,
    shiftKey: e.shiftKey,
  });
  canvas.addEventListener('pointerdown', (e) => {
    if (captured !== null) return;
    // a text selection left on the page (Ctrl+A) would turn this drag into the browser's drag
    // of the selection: strokes did nothing and said nothing
    window.getSelection()?.removeAllRanges();
    if (d.tool().onPointerDown(ptr(e))) {
      captured = e.pointerId;
      canvas.setPointerCapture(e.pointerId);
      d.viewer.hold('stroke', true);
    } else if (e.button === 0) {
      captured = e.pointerId;
    }
  });
  canvas.addEventListener('dragstart', (e) => e.preventDefault());
  // Pointer samples as they come (pointerrawupdate, where the browser has it: not held until
  // the next animation frame as pointermove is), so a preview can go out between frames.
  const moves = 'onpointerrawupdate' in canvas ? 'pointerrawupdate' : 'pointermove';
  canvas.addEventListener(moves, (e) => {
    if (e instanceof PointerEvent && e.pointerId === captured) d.tool().onPointerMove(ptr(e));
  });
  // hovering (no press): a tool may show where it would act (the scalp brush's ring)
  let hover: ReturnType<typeof ptr> | null = null;
  canvas.addEventListener('pointermove', (e) => {
    hover = ptr(e);
    if (captured === null) d.tool().onHover?.(hover);
  });
  canvas.addEventListener('pointerleave', () => {
    hover = null;
    if (captured === null) d.tool().onHover?.(null);
  });
  // Shift pressed or let go over the view without moving: the hover shows it (the scalp brush's
  // ring turns red while Shift is held)
  const shift = (e: KeyboardEvent) => {
    if (e.key !== 'Shift' || captured !== null || !hover) return;
    hover = { ...hover, shiftKey: e.type === 'keydown' };
    d.tool().onHover?.(hover);
  };
  window.addEventListener('keydown', shift);
  window.addEventListener('keyup', shift);
  const end = (e: PointerEvent, cancel: boolean) => {
    if (e.pointerId !== captured) return;
    captured = null;
    // the tool first: its edit holds the view while the hair settles, so the view does not
    // settle (a full-resolution, full-detail frame) in between
    if (cancel) d.tool().onCancel();
    else d.tool().onPointerUp(ptr(e));
    d.viewer.hold('stroke', false);
  };
  canvas.addEventListener('pointerup', (e) => {
    d.pointerUp?.(performance.now());
    end(e, false);
  });
  canvas.addEventListener('pointercancel', (e) => end(e, true));
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  // a tool may take the wheel (the scalp brush's radius): caught before the camera controls
  (canvas.parentElement ?? canvas).addEventListener(
    'wheel',
    (e) => {
      if (e.target !== canvas || !d.tool().onWheel?.(e.deltaY)) return;
      e.preventDefault();
      e.stopPropagation();
    },
    { capture: true, passive: false },
  );

  window.addEventListener('keydown', (e) => {
    if (typesText(e.target)) return;
    // a modal dialog (Styles) has the keyboard: Escape closes it, Tab and Enter choose in it
    if (e.target instanceof Element && e.target.closest('dialog[open]')) return;
    const s = shortcutOf(e);
    if (s === null) return;
    if (d.overlayKey?.(s)) {
      e.preventDefault();
      return;
    }
    const a = actionForShortcut(d.actions, s);
    if (!a || (a.enabled && !a.enabled())) return;
    e.preventDefault();
    a.run();
  });
}
