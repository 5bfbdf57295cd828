// A small panel with the selected curve's parameters, built from protocol.ts CURVE_PARAMS (label,
// unit, range; angles in degrees in the panel, radians in the session; lengths in centimetres in
// the panel, world units in the session), plus "Extend past the
// end" for every curve but dividing ones, and "Braid the tail" for a ponytail. Every change is reported as one edit (the app records it
// in History).

import { CURVE_PARAMS, type CurveParamSpec } from '../model/curveParams';
import { defOf, extendsPastEnd } from '../model/kinds';
import { PONYTAIL_WIDTH } from '../model/ponytailFromSpine';
import type { StyleCurve } from '../model/session';
import { numberInput, type Say } from './numberInput';

/** The fields a panel edit changes: scalar parameters by name (session units), or `extend`. */
export type CurvePatch = Readonly<Record<string, number | boolean>>;

export interface CurvePanel {
  show(curve: StyleCurve | null): void;
}

const DEG = 180 / Math.PI;

/** Session value -> panel value, and back (degrees for angles, centimetres for lengths). */
const VIEW_SCALE: Partial<Record<CurveParamSpec['unit'], number>> = { rad: DEG, cm: 10 };
const toView = (s: CurveParamSpec, v: number) => v * (VIEW_SCALE[s.unit] ?? 1);
const fromView = (s: CurveParamSpec, v: number) => v / (VIEW_SCALE[s.unit] ?? 1);

/** The panel label: the table's label and its unit as shown. */
export function paramLabel(s: CurveParamSpec): string {
  if (s.unit === 'rad') return `${s.label} (°)`;
  if (s.unit === 'choice') return s.label;
  return s.unit ? `${s.label} (${s.unit})` : s.label;
}

const specsOf = (c: StyleCurve): readonly CurveParamSpec[] => CURVE_PARAMS[c.type];

function paramValue(c: StyleCurve, s: CurveParamSpec): number {
  const v = (c as unknown as Record<string, unknown>)[s.name];
  return typeof v === 'number' ? v : s.default;
}

export function buildCurvePanel(
  root: HTMLElement,
  onChange: (id: string, patch: CurvePatch) => void,
  /** A sentence for the status line (an entry clamped or rounded). */
  say: Say,
  /** "Braid the tail" of a ponytail (absent: no button). */
  braidTail?: (id: string) => void,
  /** A ponytail's width at its band, world units (absent: no input). */
  ponytailWidth?: (id: string, width: number) => void,
): CurvePanel {
  const panel = document.createElement('section');
  panel.id = 'curve-panel';
  panel.setAttribute('aria-label', 'Curve parameters');
  panel.hidden = true;
  root.append(panel);
  let shownKey = '';
  return {
    show(curve) {
      const key = curve ? JSON.stringify([curve.id, curve.type, paramsOf(curve)]) : '';
      if (key === shownKey) return; // keep focus while the user types
      shownKey = key;
      panel.replaceChildren();
      panel.hidden = curve === null;
      if (!curve) return;
      const title = document.createElement('h2');
      title.textContent = `${curve.type} curve ${curve.id}`;
      panel.append(title);
      if (defOf(curve).extends) {
        const label = document.createElement('label');
        const box = document.createElement('input');
        box.type = 'checkbox';
        box.checked = extendsPastEnd(curve);
        box.addEventListener('change', () => onChange(curve.id, { extend: box.checked }));
        label.append(box, ' Extend past the end');
        panel.append(label);
      }
      if (curve.type === 'ponytail' && braidTail) {
        const button = document.createElement('button');
        button.type = 'button';
        button.textContent = 'Braid the tail';
        button.title = 'Replace this ponytail by a braid on its spine';
        button.addEventListener('click', () => braidTail(curve.id));
        panel.append(button);
      }
      if (curve.type === 'ponytail' && ponytailWidth && curve.circles.length > 0) {
        // the profile's scale: the tail at least this wide at its band (the hair it holds may
        // make it wider)
        const label = document.createElement('label');
        label.textContent = 'Width at the band, at least (cm)';
        label.append(
          numberInput(
            { min: 10 * PONYTAIL_WIDTH.min, max: 10 * PONYTAIL_WIDTH.max, step: 0.5 },
            20 * curve.circles[0].radius,
            { label: 'Width at the band', unit: 'cm', decimals: 2 },
            (v) => ponytailWidth(curve.id, v / 10),
            say,
          ),
        );
        panel.append(label);
      }
      for (const s of specsOf(curve)) {
        const label = document.createElement('label');
        label.textContent = paramLabel(s);
        if (s.unit === 'choice') {
          const select = document.createElement('select');
          (s.choices ?? []).forEach((name, i) => {
            select.append(new Option(name, String(i), false, paramValue(curve, s) === i));
          });
          select.addEventListener('change', () =>
            onChange(curve.id, { [s.name]: Number(select.value) }),
          );
          label.append(' ', select);
          panel.append(label);
          continue;
        }
        const input = numberInput(
          s.view,
          toView(s, paramValue(curve, s)),
          { label: s.label, unit: s.unit === 'rad' ? '°' : s.unit || undefined, decimals: 3 },
          (v) => onChange(curve.id, { [s.name]: fromView(s, v) }),
          say,
        );
        label.append(input);
        panel.append(label);
      }
    },
  };
}

/** What the panel shows of a curve: it is rebuilt when this changes. */
function paramsOf(c: StyleCurve): unknown {
  return [
    extendsPastEnd(c),
    ...specsOf(c).map((s) => paramValue(c, s)),
    defOf(c).guides?.(c)[0]?.radius ?? null,
  ];
}
