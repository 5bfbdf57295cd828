// The "Head" panel (G): which head the hair grows on (Open head, Built-in head), Rotate by quarter
// turns for a loaded head that came in another convention, the scalp brush's radius, and the
// mirror plane (offset, yaw, roll; "Fit" finds the head's best symmetry plane again). Every
// change to the session is one undoable edit (the app runs it as an editor command).
import { planeAngles, planeNormal } from '../head/symmetryPlane';
import type { MirrorPlane } from '../model/mirror';
import type { SessionState } from '../model/session';
import { BRUSH_RADIUS } from '../tools/scalpBrushTool';
import type { Say } from './numberInput';
import { panelButton as button, numberRow } from './panelControls';

type Axis = 'x' | 'y' | 'z';

export interface HeadPanelEvents {
  openHead(): void;
  useBuiltin(): void;
  rotate(axis: Axis): void;
  setBrushRadius(radius: number): void;
  setPlane(plane: MirrorPlane | undefined): void;
  fitPlane(): void;
  /** A sentence for the status line (an entry clamped or rounded). */
  say: Say;
}

export interface HeadPanelState {
  session: SessionState;
  /** One line about the head shown ("Built-in mannequin", "bust.obj · 120,000 triangles"). */
  label: string;
  /** The session's head when its file is missing from this browser. */
  missing: string | null;
  brushRadius: number;
}

export interface HeadPanel {
  readonly open: boolean;
  toggle(): void;
  show(state: HeadPanelState): void;
}

const DEG = 180 / Math.PI;

export function buildHeadPanel(root: HTMLElement, events: HeadPanelEvents): HeadPanel {
  const panel = document.createElement('section');
  panel.id = 'head-panel';
  panel.setAttribute('aria-label', 'Head');
  panel.hidden = true;
  root.append(panel);
  let shownKey = '';
  let last: HeadPanelState | null = null;

  function render(st: HeadPanelState): void {
    const s = st.session;
    panel.replaceChildren();
    const title = document.createElement('h2');
    title.textContent = 'Head';
    const label = document.createElement('p');
    label.className = 'head-label';
    label.textContent = st.missing ? `Needs “${st.missing}” (not stored here)` : st.label;
    const files = document.createElement('div');
    files.className = 'head-buttons';
    files.append(
      button('Open head…', 'Load a head mesh: OBJ, glTF/GLB, PLY or STL', events.openHead),
      button('Built-in head', 'Grow the hair on the built-in mannequin', events.useBuiltin),
    );
    panel.append(title, label, files);
    if (s.head !== 'builtin') {
      const turns = document.createElement('div');
      turns.className = 'head-buttons';
      turns.append('Rotate 90°:');
      for (const axis of ['x', 'y', 'z'] as const)
        turns.append(
          button(axis.toUpperCase(), `Rotate the head 90° about ${axis.toUpperCase()}`, () =>
            events.rotate(axis),
          ),
        );
      for (const b of turns.querySelectorAll('button'))
        b.setAttribute('aria-label', `Rotate about ${b.textContent}`);
      panel.append(turns);
    }
    const brush = document.createElement('h2');
    brush.textContent = 'Scalp brush (B)';
    const hint = document.createElement('p');
    hint.textContent = 'Drag paints scalp, Shift+drag erases, the wheel sets the radius.';
    panel.append(
      brush,
      hint,
      numberRow(
        'Brush radius',
        'cm',
        2,
        { min: BRUSH_RADIUS.min * 10, max: BRUSH_RADIUS.max * 10, step: 0.1 },
        st.brushRadius * 10,
        (cm) => events.setBrushRadius(cm / 10),
        events.say,
      ),
    );
    const mirror = document.createElement('h2');
    mirror.textContent = 'Mirror plane';
    const plane = s.symmetry ?? { normal: [1, 0, 0], offset: 0 };
    const { yaw, roll } = planeAngles(plane.normal);
    const set = (y: number, r: number, offset: number) =>
      events.setPlane({ normal: planeNormal(y, r), offset });
    panel.append(
      mirror,
      numberRow(
        'Offset',
        'mm',
        2,
        { min: -200, max: 200, step: 1 },
        plane.offset * 100,
        (mm) => set(yaw, roll, mm / 100),
        events.say,
      ),
      numberRow(
        'Yaw',
        '°',
        2,
        { min: -30, max: 30, step: 0.5 },
        yaw * DEG,
        (d) => set(d / DEG, roll, plane.offset),
        events.say,
      ),
      numberRow(
        'Roll',
        '°',
        2,
        { min: -30, max: 30, step: 0.5 },
        roll * DEG,
        (d) => set(yaw, d / DEG, plane.offset),
        events.say,
      ),
    );
    const fit = document.createElement('div');
    fit.className = 'head-buttons';
    fit.append(
      button('Fit', 'Find the head’s best left–right symmetry plane', events.fitPlane),
      button('x = 0', 'The plane x = 0', () => events.setPlane(undefined)),
    );
    panel.append(fit);
  }

  return {
    get open() {
      return !panel.hidden;
    },
    toggle() {
      panel.hidden = !panel.hidden;
      shownKey = '';
      if (last) this.show(last);
    },
    show(st) {
      last = st;
      if (panel.hidden) return;
      const key = JSON.stringify([
        st.session.head,
        st.session.symmetry,
        st.label,
        st.missing,
        st.brushRadius,
      ]);
      if (key === shownKey) return; // keep focus while the user types
      shownKey = key;
      render(st);
    },
  };
}
