// A number input for the panels: its range and step, the value shown rounded, and `onValue`
// called with the value clamped to the range when the user commits a finite number (an empty or
// non-numeric entry changes nothing).
export interface NumberRange {
  min: number;
  max: number;
  step: number;
}

export function numberInput(
  range: NumberRange,
  value: number,
  onValue: (v: number) => void,
  decimals = 4,
): HTMLInputElement {
  const input = document.createElement('input');
  input.type = 'number';
  input.min = String(range.min);
  input.max = String(range.max);
  input.step = String(range.step);
  const f = 10 ** decimals;
  input.value = String(Math.round(value * f) / f);
  input.addEventListener('change', () => {
    const v = Number(input.value);
    if (input.value.trim() === '' || !Number.isFinite(v)) return;
    onValue(Math.min(range.max, Math.max(range.min, v)));
  });
  return input;
}
