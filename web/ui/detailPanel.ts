// The "Hair" panel: strand count and maximum length (growth settings), which rule sets the
// length, Volume (with the shape rules), the colour
// (ui/hairLookEditor.ts: melanin, redness, grey, dye, tips…), and the detail (curl,
// clump, frizz, flyaway, length jitter) of the whole head and, with a curve selected, below it that
// curve's own (of the strands it governs). Lengths in centimetres. Built from model/detail.ts DETAIL_PARAMS; every change is one undoable edit
// (the app runs it as an editor command).

import { CURL_TYPES, curlTypeOf } from '../model/curlTypes';
import {
  DETAIL_BLOCKS,
  DETAIL_PARAMS,
  type DetailBlock,
  type DetailParamSpec,
  defaultBlock,
  type HairDetail,
  LENGTH_JITTER,
} from '../model/detail';
import { MAX_HAIR_LENGTH } from '../model/grid';
import type { GrowthParams } from '../model/growthParams';
import { DEFAULT_BAND_COLOR, type HairLook } from '../model/hairLook';
import { defOf } from '../model/kinds';
import { DEFAULT_GROWTH, type SessionState, type StyleCurve } from '../model/session';
import { SESSION_SETTINGS } from '../model/sessionSchema';
import { hairLookEditors } from './hairLookEditor';
import { numberInput, type Say } from './numberInput';

/** Roots the built-in head's scalp gives at 1° × 1° sampling (S5.1): the strand count scales
 *  with 1 / (θ step · φ step). */
export const ROOTS_AT_ONE_DEGREE = 29_948;
export const STRANDS_RANGE = { min: 1_000, max: 100_000, step: 1_000 };
/** What "Longer" and "Shorter" move the style by (world units: 5 cm). */
export const LENGTHEN_STEP = 0.5;

/** Maximum strand length in the panel, centimetres (world units × 10). */
export const LENGTH_RANGE_CM = { min: 2, max: MAX_HAIR_LENGTH * 10, step: 1 };

/** Volume in the panel, centimetres (the session's volume setting × 10). */
export const VOLUME_RANGE_CM = {
  min: SESSION_SETTINGS.volume.min * 10,
  max: SESSION_SETTINGS.volume.max * 10,
  step: SESSION_SETTINGS.volume.quantum * 10,
};

/** Which rule sets the length of hair no stroke ends (shown under Max length); with ties from
 *  any hand, also that a ponytail's or braid's hair reaches its stroke's end. */
export function lengthRule(s: Pick<SessionState, 'shape' | 'fall' | 'curves' | 'ties'>): string {
  // a tie along a spine (it has a supporting surface: ponytails, braids; a bun lies on the head)
  const spineTie = (c: SessionState['curves'][number]) =>
    defOf(c).role === 'tie' && defOf(c).surface(c) !== null;
  const ties =
    s.ties && s.fall && s.curves.some(spineTie)
      ? ' Ponytails and braids reach their strokes’ ends.'
      : '';
  if (!s.fall) return 'Length: the strokes alone (the paper’s method).';
  if (!s.shape || !s.curves.some((c) => defOf(c).role === 'flow'))
    return `Length: hair no stroke ends grows to Max length.${ties}`;
  return `Length: hair no stroke ends is as long as the strokes near it, up to Max length.${ties}`;
}

/** The strand count the panel shows for a session's growth (before its cap). */
export function strandsOf(g: GrowthParams): number {
  const n = Math.round(ROOTS_AT_ONE_DEGREE / (g.thetaStepDeg * g.phiStepDeg));
  return g.maxStrands > 0 ? Math.min(g.maxStrands, n) : n;
}

/** Sampling steps (equal in θ and φ, on a 1e-4° grid) that give at least `n` strands. */
export function stepsForStrands(n: number): Pick<GrowthParams, 'thetaStepDeg' | 'phiStepDeg'> {
  const step = Math.floor(Math.sqrt(ROOTS_AT_ONE_DEGREE / n) * 1e4) / 1e4;
  return { thetaStepDeg: step, phiStepDeg: step };
}

/** The growth for `n` strands: sampling steps that give at least n, and the cap at n when they
 *  give more (the engine keeps an even subsample), so the panel shows the number typed. */
export function growthForStrands(
  n: number,
): Pick<GrowthParams, 'thetaStepDeg' | 'phiStepDeg' | 'maxStrands'> {
  const steps = stepsForStrands(n);
  const count = strandsOf({ ...DEFAULT_GROWTH, ...steps, maxStrands: 0 });
  return { ...steps, maxStrands: count > n ? n : 0 };
}

export interface DetailPanelEvents {
  setGrowth(patch: Partial<GrowthParams>): void;
  /** Volume: the lift at the roots, world units. */
  setVolume(volume: number): void;
  /** "Longer" / "Shorter": the whole style by `by` world units. */
  lengthen(by: number): void;
  /** A sentence for the status line (an entry clamped or rounded). */
  say: Say;
  /** curveId null: the session's detail. */
  setDetail(curveId: string | null, detail: HairDetail | undefined): void;
  /** Curl type `type` (curlTypes.ts) for the whole head (null) or one curve. */
  setCurlType(curveId: string | null, type: string): void;
  /** The colour model (null: the colour box's direct colour). */
  setHairLook(look: HairLook | null): void;
  /** The ties' band colour, #rrggbb. */
  setBandColor(color: string): void;
}

export interface DetailPanel {
  readonly open: boolean;
  toggle(): void;
  show(session: SessionState, selected: StyleCurve | null): void;
}

export function buildDetailPanel(root: HTMLElement, events: DetailPanelEvents): DetailPanel {
  const panel = document.createElement('section');
  panel.id = 'detail-panel';
  panel.setAttribute('aria-label', 'Hair detail');
  panel.hidden = true;
  root.append(panel);
  let shownKey = '';
  let last: { session: SessionState; selected: StyleCurve | null } | null = null;

  const row = (text: string, input: HTMLElement): HTMLLabelElement => {
    const label = document.createElement('label');
    label.className = 'detail-row';
    label.append(text, input);
    return label;
  };

  function render(s: SessionState, selected: StyleCurve | null): void {
    panel.replaceChildren();
    const title = document.createElement('h2');
    title.textContent = 'Hair';
    panel.append(title);
    panel.append(
      row(
        'Strands',
        numberInput(
          STRANDS_RANGE,
          strandsOf(s.growth),
          { label: 'Strands', decimals: 0 },
          (n) => events.setGrowth(growthForStrands(n)),
          events.say,
        ),
      ),
      row(
        'Max length (cm)',
        numberInput(
          LENGTH_RANGE_CM,
          s.growth.maxLength * 10,
          { label: 'Max length', unit: 'cm', decimals: 3 },
          // the whole style follows: stroke ends move with the maximum length (model/lengthen.ts)
          (cm) => events.lengthen(Math.round(cm * 1e3) / 1e4 - s.growth.maxLength),
          events.say,
        ),
      ),
    );
    // the whole style longer or shorter: stroke ends and the maximum length move together
    const longer = document.createElement('button');
    longer.textContent = `+${LENGTHEN_STEP * 10} cm`;
    // the accessible name starts with the visible text (fresh eyes looked the button up by it)
    longer.setAttribute('aria-label', `+${LENGTHEN_STEP * 10} cm: longer`);
    longer.title = 'Every stroke that ends hair goes on, and Max length rises, by this much';
    longer.addEventListener('click', () => events.lengthen(LENGTHEN_STEP));
    const shorter = document.createElement('button');
    shorter.textContent = `−${LENGTHEN_STEP * 10} cm`;
    shorter.setAttribute('aria-label', `−${LENGTHEN_STEP * 10} cm: shorter`);
    shorter.title = 'Every stroke that ends hair is cut back, and Max length falls, by this much';
    shorter.addEventListener('click', () => events.lengthen(-LENGTHEN_STEP));
    // a div, not a label: a label would pass a click on its text to the first button
    const lengthRow = document.createElement('div');
    lengthRow.className = 'detail-row';
    const buttons = document.createElement('span');
    buttons.append(shorter, ' ', longer);
    lengthRow.append('Length', buttons);
    panel.append(lengthRow);
    const rule = document.createElement('p');
    rule.dataset.testid = 'length-rule';
    rule.className = 'length-rule';
    rule.textContent = lengthRule(s);
    rule.title =
      'A stroke extended off the head counts as Max length, one that ends on the scalp as its own length; a ponytail’s or braid’s hair reaches the end of its stroke whatever Max length says.';
    panel.append(rule);
    if (s.shape)
      panel.append(
        row(
          'Volume (cm)',
          numberInput(
            VOLUME_RANGE_CM,
            (s.volume ?? SESSION_SETTINGS.volume.default) * 10,
            { label: 'Volume', unit: 'cm', decimals: 1 },
            (cm) => events.setVolume(cm / 10),
            events.say,
          ),
        ),
      );
    panel.append(heading('Colour'));
    // the band's colour only where there are bands to colour (sessions with ties)
    const band = s.ties
      ? { colour: s.bandColor ?? DEFAULT_BAND_COLOR, set: events.setBandColor }
      : undefined;
    panel.append(
      hairLookEditors(s.hairLook ?? null, events.setHairLook, events.say, band, s.growth.maxLength),
    );
    // the whole head's detail is always here; a selected curve's own detail follows it
    panel.append(heading('Detail: whole head'));
    detailEditors(s.detail ?? {}, (d) => events.setDetail(null, d), '', null);
    if (!selected) return;
    const own = selected.detail !== undefined;
    panel.append(heading(`Detail: curve ${selected.id} only`));
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.checked = own;
    box.addEventListener('change', () =>
      events.setDetail(selected.id, box.checked ? (s.detail ?? {}) : undefined),
    );
    const label = document.createElement('label');
    label.className = 'detail-row';
    label.append(box, ` Own detail for ${selected.id}`);
    panel.append(label);
    if (!own) {
      const note = document.createElement('p');
      note.textContent = `Curve ${selected.id} uses the whole head’s detail.`;
      panel.append(note);
      return;
    }
    detailEditors(
      selected.detail ?? {},
      (d) => events.setDetail(selected.id, d),
      `${selected.id} `,
      selected.id,
    );
  }

  function heading(text: string): HTMLElement {
    const h = document.createElement('h2');
    h.textContent = text;
    return h;
  }

  /** The curl, clump, frizz and flyaway editors and length jitter of one detail; `prefix` starts every
   *  accessible name (empty for the whole head's, so its names stay "Curl", "Curl radius"…). */
  function detailEditors(
    detail: HairDetail,
    set: (d: HairDetail) => void,
    prefix: string,
    curveId: string | null,
  ): void {
    panel.append(row('Curl type', curlTypeSelect(detail, curveId, prefix)));
    for (const b of DETAIL_BLOCKS) panel.append(blockEditor(b, detail, set, prefix));
    const jitter = numberInput(
      LENGTH_JITTER,
      detail.lengthJitter ?? 0,
      { label: `${prefix}${LENGTH_JITTER.label}` },
      (v) => {
        const { lengthJitter: _, ...rest } = detail;
        set(v > 0 ? { ...rest, lengthJitter: v } : rest);
      },
      events.say,
    );
    // its own name, as every other number here has: a curve's is "c3 Length jitter", not a
    // second "Length jitter" beside the whole head's (a new user could not tell them apart)
    jitter.setAttribute('aria-label', `${prefix}${LENGTH_JITTER.label}`);
    panel.append(row(LENGTH_JITTER.label, jitter));
  }

  /** "Curl type": straight, the wavy, curly and coily types (model/curlTypes.ts), or "Own curl"
   *  when the curl matches none; choosing one sets curl and clump and takes frizz off (and, for
   *  the whole head, a curly or coily type's root lift as the Volume: editor setCurlType). */
  function curlTypeSelect(
    detail: HairDetail,
    curveId: string | null,
    prefix: string,
  ): HTMLSelectElement {
    const select = document.createElement('select');
    select.setAttribute('aria-label', `${prefix}Curl type`);
    const current = curlTypeOf(detail);
    const options: [string, string][] = [
      ['1', '1 straight'],
      ...CURL_TYPES.map((t): [string, string] => [t.id, t.label]),
    ];
    if (current === null) options.push(['', 'Own curl (set below)']);
    for (const [value, text] of options) {
      const o = document.createElement('option');
      o.value = value;
      o.textContent = text;
      select.append(o);
    }
    select.value = current ?? '';
    select.addEventListener('change', () => {
      if (select.value) events.setCurlType(curveId, select.value);
    });
    return select;
  }

  function blockEditor(
    b: DetailBlock,
    detail: HairDetail,
    set: (d: HairDetail) => void,
    prefix: string,
  ): HTMLElement {
    const group = document.createElement('fieldset');
    const legend = document.createElement('legend');
    const box = document.createElement('input');
    box.type = 'checkbox';
    const block = detail[b] as Record<string, number> | undefined;
    box.checked = block !== undefined;
    const name = b[0].toUpperCase() + b.slice(1);
    box.setAttribute('aria-label', `${prefix}${name}`);
    box.addEventListener('change', () => {
      const { [b]: _, ...rest } = detail;
      set(box.checked ? { ...rest, [b]: defaultBlock(b) } : rest);
    });
    legend.append(box, ` ${name}`);
    group.append(legend);
    if (block)
      for (const p of DETAIL_PARAMS[b] as readonly DetailParamSpec[]) {
        const label = `${prefix}${name} ${p.label.toLowerCase()}`;
        // lengths in centimetres (world units × 10)
        const k = p.unit === 'cm' ? 10 : 1;
        const input = numberInput(
          { min: p.min * k, max: p.max * k, step: p.step * k },
          block[p.key] * k,
          { label, unit: p.unit === 'cm' ? 'cm' : undefined },
          (v) => set({ ...detail, [b]: { ...block, [p.key]: v / k } }),
          events.say,
        );
        input.setAttribute('aria-label', label);
        group.append(row(p.unit ? `${p.label} (${p.unit})` : p.label, input));
      }
    return group;
  }

  return {
    get open() {
      return !panel.hidden;
    },
    toggle() {
      panel.hidden = !panel.hidden;
      shownKey = '';
      if (last) this.show(last.session, last.selected);
    },
    show(session, selected) {
      last = { session, selected };
      if (panel.hidden) return;
      const key = JSON.stringify([
        session.growth,
        session.shape,
        session.volume,
        lengthRule(session),
        session.detail,
        session.hairLook,
        session.ties,
        session.bandColor,
        selected?.id,
        selected?.detail,
      ]);
      if (key === shownKey) return; // keep focus while the user types
      shownKey = key;
      render(session, selected);
    },
  };
}
