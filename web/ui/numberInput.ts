// A number input for the panels: its range and step, the value shown rounded. When the user
// commits a finite number it is clamped to the range and rounded to the places shown, the input
// shows that value, `onValue` gets it, and when it is not what was typed `say` gets one sentence
// saying why (for the status line), e.g. "Max length: 120 cm is above the maximum 100 cm; set to
// 100 cm." An empty or non-numeric entry changes nothing: the input shows its value again and
// `say` says so.
export interface NumberRange {
  min: number;
  max: number;
  step: number;
}

/** How the status line names the input and its values. */
export interface NumberField {
  /** The input's name in a sentence ("Max length"). */
  label: string;
  /** The unit after a value ("cm", "mm", "°"); none when absent. */
  unit?: string;
  /** Decimal places shown, and the value is rounded to (default 4). */
  decimals?: number;
}

/** Where a committed entry's sentence goes (StatusPresenter.note). */
export type Say = (message: string) => void;

const round = (v: number, decimals: number) => {
  const f = 10 ** decimals;
  const r = Math.round(v * f) / f;
  return r === 0 ? 0 : r; // never -0
};

/** A value as the status line writes it: grouped thousands, at most `decimals` places, unit. */
export function formatValue(v: number, field: NumberField): string {
  const text = v.toLocaleString('en-US', { maximumFractionDigits: field.decimals ?? 4 });
  if (!field.unit) return text;
  return field.unit === '°' ? `${text}°` : `${text} ${field.unit}`;
}

/** What committing `text` gives: null when it is not a finite number (nothing changes); else the
 *  value in the range, rounded to the places shown, and the sentence when that is not the number
 *  typed ('' when it is). */
export function commitNumber(
  range: NumberRange,
  text: string,
  field: NumberField,
): { value: number; message: string } | null {
  const typed = Number(text);
  if (text.trim() === '' || !Number.isFinite(typed)) return null;
  const decimals = field.decimals ?? 4;
  const value = round(Math.min(range.max, Math.max(range.min, typed)), decimals);
  if (value === typed) return { value, message: '' };
  const f = (v: number) => formatValue(v, field);
  // the typed number in full (toLocaleString would round it the way being reported)
  const shown = field.unit
    ? field.unit === '°'
      ? `${text.trim()}°`
      : `${text.trim()} ${field.unit}`
    : text.trim();
  const why =
    typed > range.max
      ? `${shown} is above the maximum ${f(range.max)}`
      : typed < range.min
        ? `${shown} is below the minimum ${f(range.min)}`
        : decimals === 0
          ? `${shown} is not a whole number`
          : `${shown} has more than ${decimals} decimal place${decimals === 1 ? '' : 's'}`;
  return { value, message: `${field.label}: ${why}; set to ${f(value)}.` };
}

export function numberInput(
  range: NumberRange,
  value: number,
  field: NumberField,
  onValue: (v: number) => void,
  say: Say,
): HTMLInputElement {
  const input = document.createElement('input');
  input.type = 'number';
  input.min = String(range.min);
  input.max = String(range.max);
  input.step = String(range.step);
  const decimals = field.decimals ?? 4;
  let shown = round(value, decimals);
  input.value = String(shown);
  input.addEventListener('change', () => {
    const c = commitNumber(range, input.value, field);
    if (!c) {
      input.value = String(shown);
      say(`${field.label}: not a number; kept ${formatValue(shown, field)}.`);
      return;
    }
    shown = c.value;
    input.value = String(c.value);
    onValue(c.value);
    if (c.message) say(c.message);
  });
  // Enter commits and Escape puts the value back; either leaves the field, as design tools do,
  // so the next key is a shortcut again (a field that kept the focus swallowed H, X, L… and the
  // next stroke went on in the view before)
  input.addEventListener('keydown', (e) => {
    if (e.key === 'Escape') input.value = String(shown);
    if (e.key === 'Enter' || e.key === 'Escape') {
      e.stopPropagation();
      input.blur();
    }
  });
  return input;
}
