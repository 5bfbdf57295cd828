// Controls the side panels (Head, Reference pictures) share: a plain button and a labelled
// number input.
import { type NumberRange, numberInput, type Say } from './numberInput';

/** A button with a tooltip that runs `run` on click. */
export function panelButton(label: string, title: string, run: () => void): HTMLButtonElement {
  const b = document.createElement('button');
  b.type = 'button';
  b.textContent = label;
  b.title = title;
  b.addEventListener('click', run);
  return b;
}

/** A number input in a row labelled "Label (unit)", which is also its accessible name; values
 *  are shown and rounded to `decimals` places. */
export function numberRow(
  label: string,
  unit: string,
  decimals: number,
  range: NumberRange,
  value: number,
  onValue: (v: number) => void,
  say: Say,
): HTMLLabelElement {
  const input = numberInput(range, value, { label, unit, decimals }, onValue, say);
  input.setAttribute('aria-label', `${label} (${unit})`);
  const row = document.createElement('label');
  row.className = 'detail-row';
  row.append(`${label} (${unit})`, input);
  return row;
}
