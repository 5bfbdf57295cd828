// The motion controls on the toolbar's display row: a labelled "Motion" select (Settle, Head turn, Nod, Wind),
// a "Play" button that reads "Stop" while a motion plays (app/motionPlayer.ts plays it), and the
// wind's direction and speed (enabled when Wind is chosen; always there, so the toolbar does not
// move when the choice changes).
import {
  DEFAULT_WIND,
  MOTION_LABELS,
  MOTIONS,
  type MotionName,
  WIND_FROM,
  WIND_SPEED_RANGE,
  type WindSettings,
} from '../model/motion';

export interface MotionControlsActions {
  play(motion: MotionName, wind: WindSettings): void;
  stop(): void;
  playing(): MotionName | null;
}

export interface MotionControls {
  /** Shows the button's state again (after a motion started or stopped). */
  refresh(): void;
  /** The motion chosen in the select. */
  selected(): MotionName;
  /** The wind chosen (direction and speed; the speed field's last valid number). */
  wind(): WindSettings;
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
  // the wind: where it comes from and how strong, for the Wind motion
  const windLabel = document.createElement('label');
  windLabel.textContent = 'Wind ';
  windLabel.title =
    'The Wind motion: where the wind comes from, and its mean speed (gusts vary it by half)';
  const from = document.createElement('select');
  from.id = 'wind-from';
  from.setAttribute('aria-label', 'Wind direction');
  for (const w of WIND_FROM) {
    const o = document.createElement('option');
    o.value = String(w.deg);
    o.textContent = w.label;
    from.append(o);
  }
  from.value = String(DEFAULT_WIND.fromDeg);
  const speed = document.createElement('input');
  speed.type = 'number';
  speed.id = 'wind-speed';
  speed.setAttribute('aria-label', 'Wind speed (m/s)');
  speed.min = String(WIND_SPEED_RANGE.min);
  speed.max = String(WIND_SPEED_RANGE.max);
  speed.step = String(WIND_SPEED_RANGE.step);
  speed.value = String(DEFAULT_WIND.speed);
  speed.style.width = '4em';
  const unit = document.createElement('span');
  unit.textContent = ' m/s';
  windLabel.append(from, ' ', speed, unit);
  let lastSpeed = DEFAULT_WIND.speed;
  const wind = (): WindSettings => {
    const v = speed.valueAsNumber;
    if (Number.isFinite(v) && v >= WIND_SPEED_RANGE.min && v <= WIND_SPEED_RANGE.max) lastSpeed = v;
    return { fromDeg: Number(from.value), speed: lastSpeed };
  };
  const syncWind = (): void => {
    const on = select.value === 'wind';
    from.disabled = !on;
    speed.disabled = !on;
    const v = speed.valueAsNumber;
    speed.setCustomValidity(
      Number.isFinite(v) && v >= WIND_SPEED_RANGE.min && v <= WIND_SPEED_RANGE.max
        ? ''
        : `The wind speed is ${WIND_SPEED_RANGE.min} to ${WIND_SPEED_RANGE.max} m/s (keeping ${lastSpeed})`,
    );
  };
  const playChosen = (): void => actions.play(select.value as MotionName, wind());
  button.addEventListener('click', () => {
    if (actions.playing()) actions.stop();
    else playChosen();
    refresh();
  });
  // a new choice while playing plays it instead
  const replay = (): void => {
    syncWind();
    if (actions.playing()) {
      actions.stop();
      playChosen();
    }
    refresh();
  };
  select.addEventListener('change', replay);
  from.addEventListener('change', replay);
  speed.addEventListener('change', replay);
  speed.addEventListener('input', syncWind);
  syncWind();
  group.append(label, button, ' ', windLabel);
  // on the display toggles' row, before them, at their height: the toolbar gains no row (the 3D
  // view keeps its size)
  row.insertBefore(group, row.querySelector(':scope > .display-toggles'));
  refresh();
  return { refresh, selected: () => select.value as MotionName, wind };
}
