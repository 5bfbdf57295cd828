// The Hair panel's colour editors (model/hairLook.ts): "Shade" picks a named colour
// (model/hairShades.ts: Black … Platinum blonde, Copper, Auburn, Silver…); "Natural colour" on
// gives the colour model — "Melanin", "Redness", "Grey (%)", "Dye" (off by default) with its colour, "Tips"
// (lighter tips, a balayage: "Tip melanin", "Lighter tips over (cm)" from each strand's tip, "Tip
// dye"), "Variation" and "Roughness"; off, the hair shows the colour box's direct colour. A
// session saved before lengths in cm keeps its fraction of the strand until a length is set.
// "Band colour" (the ties' bands, model/tieBands.ts) is there either way: a new session shows the
// direct colour and has bands. Every change is one call of `set` or `band.set` (one undoable edit).
import { DEFAULT_HAIR_LOOK, type HairLook, hasTips } from '../model/hairLook';
import { HAIR_SHADES, shadeById, shadeOf, withLighterTips, withShade } from '../model/hairShades';
import { HAIR_LOOK_NUMBERS } from '../model/readHairLook';
import { numberInput, type Say } from './numberInput';

/** The numbers edited as they are (tipStart, an older session's, is only shown). */
type NumberKey = Exclude<keyof typeof HAIR_LOOK_NUMBERS, 'tipStart'>;

/** The number inputs: key, accessible name, shown × scale, step shown. */
const NUMBERS: readonly { key: NumberKey; label: string; scale: number; step: number }[] = [
  { key: 'melanin', label: 'Melanin', scale: 1, step: 0.01 },
  { key: 'redness', label: 'Redness', scale: 1, step: 0.01 },
  { key: 'grey', label: 'Grey (%)', scale: 1, step: 1 },
  { key: 'variation', label: 'Variation', scale: 1, step: 0.01 },
  { key: 'roughness', label: 'Roughness', scale: 1, step: 0.01 },
];

const TIP_MELANIN = { key: 'tipMelanin', label: 'Tip melanin', scale: 1, step: 0.01 } as const;

/** The lighter tips' length when Tips is switched on: 8 cm (world units). */
const TIPS_LENGTH = 0.8;
/** "Lighter tips over (cm)": whole centimetres (as a stylist says it), 1 … 100 (the longest
 *  hair a session grows). */
const TIP_LENGTH_CM = { min: 1, max: 100, step: 1 };

/** The look without an older session's tip fraction (a length replaces it). */
function withoutTipStart(look: HairLook): HairLook {
  const { tipStart: _, ...rest } = look;
  return rest;
}

/** The band colour shown and where a new one goes (the editor's setBandColor). */
export interface BandColourEditor {
  colour: string;
  set(colour: string): void;
}

/** `longest`: the session's Max length (world units), to show an older session's fraction of
 *  the strand as the length it gives the longest hair. */
export function hairLookEditors(
  look: HairLook | null,
  set: (look: HairLook | null) => void,
  say: Say,
  band?: BandColourEditor,
  longest = 1,
): HTMLElement {
  const group = document.createElement('fieldset');
  const legend = document.createElement('legend');
  const natural = checkbox('Natural colour', look !== null, (on) =>
    set(on ? { ...DEFAULT_HAIR_LOOK } : null),
  );
  legend.append(natural, ' Natural colour');
  group.append(legend, shadeRow(look, set));
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
  const tips = hasTips(look);
  group.append(
    row(
      'Tips',
      checkbox('Tips', tips, (on) =>
        set(
          on
            ? withLighterTips({ ...withoutTipStart(look), tipLength: TIPS_LENGTH })
            : { ...withoutTipStart(look), tipLength: 0 },
        ),
      ),
    ),
  );
  if (tips) {
    group.append(numberRow(TIP_MELANIN));
    group.append(tipLengthRow(look, longest, set, say));
    group.append(dyeRow('Tip dye', look.tipDye, (tipDye) => set({ ...look, tipDye })));
  }
  for (const n of NUMBERS.slice(3)) group.append(numberRow(n));
  if (band) group.append(bandRow(band));
  return group;
}

/** "Lighter tips over (cm)": the length from each strand's tip over which the tip colour fades
 *  in. An older session's fraction of the strand shows as the length it gives the longest hair,
 *  with a line saying so; a length set here replaces the fraction. */
function tipLengthRow(
  look: HairLook,
  longest: number,
  set: (look: HairLook | null) => void,
  say: Say,
): HTMLElement {
  const label = 'Lighter tips over (cm)';
  const older = look.tipStart;
  const cm = older === undefined ? look.tipLength * 10 : (1 - older) * longest * 10;
  const input = numberInput(
    TIP_LENGTH_CM,
    Math.min(TIP_LENGTH_CM.max, Math.max(TIP_LENGTH_CM.min, cm)),
    { label: 'Lighter tips over', unit: 'cm', decimals: 0 },
    (v) => set({ ...withoutTipStart(look), tipLength: v / 10 }),
    say,
  );
  input.setAttribute('aria-label', label);
  const r = row(label, input);
  if (older === undefined) return r;
  // short, as the panel's other notes are (the panel is as wide as its widest line); the whole
  // story in the tooltip
  const share = Math.round((1 - older) * 100);
  const note = document.createElement('p');
  note.textContent = `Saved as the last ${share} % of each strand`;
  note.title = `Saved before tips were a length: the last ${share} % of each strand, which is ${Math.round(cm)} cm of the longest hair. A length set here replaces it.`;
  input.title = note.title;
  const both = document.createElement('div');
  both.append(r, note);
  return both;
}

/** "Shade": the named colours (model/hairShades.ts); choosing one sets the pigment and grey
 *  share in one edit (and turns the colour model on); a look that is no shade shows "Custom". */
function shadeRow(look: HairLook | null, set: (look: HairLook | null) => void): HTMLElement {
  const select = document.createElement('select');
  select.setAttribute('aria-label', 'Shade');
  const current = shadeOf(look);
  const custom = new Option(look ? 'Custom' : 'Colour box', '');
  custom.disabled = true;
  select.append(custom);
  for (const shade of HAIR_SHADES) {
    const option = new Option(shade.name, shade.id);
    select.append(option);
  }
  select.value = current?.id ?? '';
  select.addEventListener('change', () => {
    const shade = shadeById(select.value);
    if (shade) set(withShade(look, shade));
  });
  return row('Shade', select);
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
