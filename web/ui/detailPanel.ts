// The "Hair" panel: strand count and maximum length (growth settings), and the detail (curl,
// clump, frizz, length jitter) of the whole head or, with a curve selected, of the strands that
// curve governs. Built from model/detail.ts DETAIL_PARAMS; every change is one undoable edit
// (the app runs it as an editor command).
import {
  DETAIL_BLOCKS,
  DETAIL_PARAMS,
  type DetailBlock,
  type DetailParamSpec,
  defaultBlock,
  type HairDetail,
  LENGTH_JITTER,
} from '../model/detail';
import type { SessionState, StyleCurve } from '../model/session';
import type { GrowthParams } from '../solver/protocol';
import { numberInput } from './numberInput';

/** Roots the built-in head's scalp gives at 1° × 1° sampling (S5.1): the strand count scales
 *  with 1 / (θ step · φ step). */
export const ROOTS_AT_ONE_DEGREE = 29_948;
export const STRANDS_RANGE = { min: 1_000, max: 100_000, step: 1_000 };
/** Maximum strand length in the panel, centimetres (world units × 10). */
export const LENGTH_RANGE_CM = { min: 2, max: 36, step: 1 };

/** The strand count the panel shows for a session's growth (before its cap). */
export function strandsOf(g: GrowthParams): number {
  const n = Math.round(ROOTS_AT_ONE_DEGREE / (g.thetaStepDeg * g.phiStepDeg));
  return g.maxStrands > 0 ? Math.min(g.maxStrands, n) : n;
}

/** Sampling steps (equal in θ and φ, on a 1e-4° grid) that give about `n` strands. */
export function stepsForStrands(n: number): Pick<GrowthParams, 'thetaStepDeg' | 'phiStepDeg'> {
  const step = Math.round(Math.sqrt(ROOTS_AT_ONE_DEGREE / n) * 1e4) / 1e4;
  return { thetaStepDeg: step, phiStepDeg: step };
}

export interface DetailPanelEvents {
  setGrowth(patch: Partial<GrowthParams>): void;
  /** curveId null: the session's detail. */
  setDetail(curveId: string | null, detail: HairDetail | undefined): void;
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
        numberInput(STRANDS_RANGE, strandsOf(s.growth), (n) =>
          events.setGrowth({ ...stepsForStrands(n), maxStrands: 0 }),
        ),
      ),
      row(
        'Max length (cm)',
        numberInput(LENGTH_RANGE_CM, s.growth.maxLength * 10, (cm) =>
          events.setGrowth({ maxLength: Math.round(cm * 1e3) / 1e4 }),
        ),
      ),
    );
    const own = selected?.detail !== undefined;
    const scope = document.createElement('h2');
    scope.textContent = selected ? `Detail: ${selected.id}` : 'Detail: whole head';
    panel.append(scope);
    if (selected) {
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
        note.textContent = 'Uses the whole head’s detail.';
        panel.append(note);
        return;
      }
    }
    const curveId = selected ? selected.id : null;
    const detail: HairDetail = (selected ? selected.detail : s.detail) ?? {};
    const set = (d: HairDetail) => events.setDetail(curveId, d);
    for (const b of DETAIL_BLOCKS) panel.append(blockEditor(b, detail, set));
    panel.append(
      row(
        LENGTH_JITTER.label,
        numberInput(LENGTH_JITTER, detail.lengthJitter ?? 0, (v) => {
          const { lengthJitter: _, ...rest } = detail;
          set(v > 0 ? { ...rest, lengthJitter: v } : rest);
        }),
      ),
    );
  }

  function blockEditor(
    b: DetailBlock,
    detail: HairDetail,
    set: (d: HairDetail) => void,
  ): HTMLElement {
    const group = document.createElement('fieldset');
    const legend = document.createElement('legend');
    const box = document.createElement('input');
    box.type = 'checkbox';
    const block = detail[b] as Record<string, number> | undefined;
    box.checked = block !== undefined;
    const name = b[0].toUpperCase() + b.slice(1);
    box.setAttribute('aria-label', name);
    box.addEventListener('change', () => {
      const { [b]: _, ...rest } = detail;
      set(box.checked ? { ...rest, [b]: defaultBlock(b) } : rest);
    });
    legend.append(box, ` ${name}`);
    group.append(legend);
    if (block)
      for (const p of DETAIL_PARAMS[b] as readonly DetailParamSpec[]) {
        const input = numberInput(p, block[p.key], (v) =>
          set({ ...detail, [b]: { ...block, [p.key]: v } }),
        );
        input.setAttribute('aria-label', `${name} ${p.label.toLowerCase()}`);
        group.append(row(p.label, input));
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
      const key = JSON.stringify([session.growth, session.detail, selected?.id, selected?.detail]);
      if (key === shownKey) return; // keep focus while the user types
      shownKey = key;
      render(session, selected);
    },
  };
}
