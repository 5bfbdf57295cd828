// The motion controls on the toolbar's display row: a labelled "Motion" select (Settle, Head turn, Nod, Wind)
// and a "Play" button that reads "Stop" while a motion plays (app/motionPlayer.ts plays it).
import { MOTION_LABELS, MOTIONS, type MotionName } from '../model/motion';

export interface MotionControlsActions {
  play(motion: MotionName): void;
  stop(): void;
  playing(): MotionName | null;
}

export interface MotionControls {
  /** Shows the button's state again (after a motion started or stopped). */
  refresh(): void;
  /** The motion chosen in the select. */
  selected(): MotionName;
}

export function buildMotionControls(
  row: HTMLElement,
  actions: MotionControlsActions,
): MotionControls {
  const group = document.createElement('span');
  group.className = 'motion-controls';
  const label = document.createElement('label');
  label.textContent = 'Motion ';
  label.title = 'What the head does while the hair plays';
  const select = document.createElement('select');
  select.id = 'motion-select';
  for (const m of MOTIONS) {
    const o = document.createElement('option');
    o.value = m;
    o.textContent = MOTION_LABELS[m];
    select.append(o);
  }
  select.value = 'head-turn';
  label.append(select);
  const button = document.createElement('button');
  button.type = 'button';
  button.id = 'motion-play';
  const refresh = (): void => {
    const on = actions.playing() !== null;
    button.textContent = on ? 'Stop' : 'Play';
    button.title = on
      ? 'Stop the motion: the hair is the groom again'
      : 'Play the chosen motion: the head moves and the hair follows';
    button.setAttribute('aria-pressed', String(on));
  };
  button.addEventListener('click', () => {
    if (actions.playing()) actions.stop();
    else actions.play(select.value as MotionName);
    refresh();
  });
  select.addEventListener('change', () => {
    // a new choice while playing plays it instead
    if (actions.playing()) {
      actions.stop();
      actions.play(select.value as MotionName);
    }
    refresh();
  });
  group.append(label, button);
  // on the display toggles' row, before them, at their height: the toolbar gains no row (the 3D
  // view keeps its size)
  row.insertBefore(group, row.querySelector(':scope > .display-toggles'));
  refresh();
  return { refresh, selected: () => select.value as MotionName };
}
