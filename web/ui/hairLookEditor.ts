// The Hair panel's colour editors (model/hairLook.ts): "Natural colour" on gives the colour
// model — "Melanin", "Redness", "Grey (%)", "Dye" (off by default) with its colour, "Tips" (an
// ombré: "Tip melanin", "Tips start (%)" along the strand, "Tip dye"), "Variation" and
// "Roughness"; off, the hair shows the colour box's direct colour. "Band colour" (the ties'
// bands, model/tieBands.ts) is there either way: a new session shows the direct colour and has
// bands. Every change is one call of `set` or `band.set` (one undoable edit).
import { DEFAULT_HAIR_LOOK, type HairLook } from '../model/hairLook';
import { HAIR_LOOK_NUMBERS } from '../model/readHairLook';
import { numberInput, type Say } from './numberInput';

type NumberKey = keyof typeof HAIR_LOOK_NUMBERS;

/** The number inputs: key, accessible name, shown × scale, step shown. */
const NUMBERS: readonly { key: NumberKey; label: string; scale: number; step: number }[] = [
  { key: 'melanin', label: 'Melanin', scale: 1, step: 0.01 },
  { key: 'redness', label: 'Redness', scale: 1, step: 0.01 },
  { key: 'grey', label: 'Grey (%)', scale: 1, step: 1 },
  { key: 'variation', label: 'Variation', scale: 1, step: 0.01 },
  { key: 'roughness', label: 'Roughness', scale: 1, step: 0.01 },
];

const TIP_NUMBERS: readonly { key: NumberKey; label: string; scale: number; step: number }[] = [
  { key: 'tipMelanin', label: 'Tip melanin', scale: 1, step: 0.01 },
  { key: 'tipStart', label: 'Tips start (%)', scale: 100, step: 1 },
];

/** Where the ombré starts when Tips is switched on. */
const TIPS_START = 0.6;

/** The band colour shown and where a new one goes (the editor's setBandColor). */
export interface BandColourEditor {
  colour: string;
  set(colour: string): void;
}

export function hairLookEditors(
  look: HairLook | null,
  set: (look: HairLook | null) => void,
  say: Say,
  band?: BandColourEditor,
): HTMLElement {
  const group = document.createElement('fieldset');
  const legend = document.createElement('legend');
  const natural = checkbox('Natural colour', look !== null, (on) =>
    set(on ? { ...DEFAULT_HAIR_LOOK } : null),
  );
  legend.append(natural, ' Natural colour');
  group.append(legend);
  if (!look) {
    const note = document.createElement('p');
    note.textContent = 'The colour box’s colour, as it is.';
    group.append(note);
    if (band) group.append(bandRow(band));
    return group;
  }
  const numberRow = (n: (typeof NUMBERS)[number]) => {
    const spec = HAIR_LOOK_NUMBERS[n.key];
    const input = numberInput(
      { min: spec.min * n.scale, max: spec.max * n.scale, step: n.step },
      look[n.key] * n.scale,
      { label: n.label, decimals: n.step < 1 ? 2 : 0 },
      (v) => set({ ...look, [n.key]: v / n.scale }),
      say,
    );
    input.setAttribute('aria-label', n.label);
    return row(n.label, input);
  };
  for (const n of NUMBERS.slice(0, 3)) group.append(numberRow(n));
  group.append(dyeRow('Dye', look.dye, (dye) => set({ ...look, dye })));
  const tips = look.tipStart < 1;
  group.append(
    row(
      'Tips',
      checkbox('Tips', tips, (on) =>
        set({ ...look, tipStart: on ? TIPS_START : 1, tipMelanin: look.tipMelanin }),
      ),
    ),
  );
  if (tips) {
    for (const n of TIP_NUMBERS) group.append(numberRow(n));
    group.append(dyeRow('Tip dye', look.tipDye, (tipDye) => set({ ...look, tipDye })));
  }
  for (const n of NUMBERS.slice(3)) group.append(numberRow(n));
  if (band) group.append(bandRow(band));
  return group;
}

/** "Band colour": a colour input, one edit when a colour is picked. */
function bandRow(band: BandColourEditor): HTMLElement {
  const colour = document.createElement('input');
  colour.type = 'color';
  colour.value = band.colour;
  colour.setAttribute('aria-label', 'Band colour');
  colour.addEventListener('change', () => band.set(colour.value));
  return row('Band colour', colour);
}

/** A checkbox `name` and, while it is on, a colour input "`name` colour". */
function dyeRow(name: string, value: string | null, set: (v: string | null) => void): HTMLElement {
  const span = document.createElement('span');
  const colour = document.createElement('input');
  colour.type = 'color';
  colour.value = value ?? '#b03a2e';
  colour.setAttribute('aria-label', `${name} colour`);
  colour.hidden = value === null;
  colour.addEventListener('change', () => set(colour.value));
  span.append(
    checkbox(name, value !== null, (on) => set(on ? colour.value : null)),
    ' ',
    colour,
  );
  return row(name, span);
}

function checkbox(name: string, checked: boolean, onChange: (on: boolean) => void): HTMLElement {
  const box = document.createElement('input');
  box.type = 'checkbox';
  box.checked = checked;
  box.setAttribute('aria-label', name);
  box.addEventListener('change', () => onChange(box.checked));
  return box;
}

function row(text: string, input: HTMLElement): HTMLElement {
  const label = document.createElement('div');
  label.className = 'detail-row';
  label.append(text, input);
  return label;
}
