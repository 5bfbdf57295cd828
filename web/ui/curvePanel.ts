// A small panel with the selected curve's parameters: dividing σ, h, α0, α1 (degrees in the
// panel, radians in the session); ponytail tightness; stream/ponytail "extend". Every change is
// reported as one edit (the app records it in History).
import type { StyleCurve } from '../model/session';

export type CurvePatch =
  | { sigma?: number; h?: number; alpha0?: number; alpha1?: number }
  | { tightness?: number }
  | { extend?: boolean };

export interface CurvePanel {
  show(curve: StyleCurve | null): void;
}

interface Field {
  key: string;
  label: string;
  min: number;
  max: number;
  step: number;
  toView?: (v: number) => number;
  fromView?: (v: number) => number;
}

const DEG = 180 / Math.PI;
const angle = { toView: (v: number) => v * DEG, fromView: (v: number) => v / DEG };

const FIELDS: Record<'dividing' | 'ponytail', Field[]> = {
  dividing: [
    { key: 'sigma', label: 'σ (grid steps)', min: 0.25, max: 4, step: 0.05 },
    { key: 'h', label: 'h (grid steps)', min: 0, max: 3, step: 0.05 },
    { key: 'alpha0', label: 'α0 (°)', min: -80, max: 80, step: 1, ...angle },
    { key: 'alpha1', label: 'α1 (°)', min: -80, max: 80, step: 1, ...angle },
  ],
  ponytail: [{ key: 'tightness', label: 'Tightness', min: 0, max: 1, step: 0.05 }],
};

export function buildCurvePanel(
  root: HTMLElement,
  onChange: (id: string, patch: CurvePatch) => void,
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
      if (curve.type !== 'dividing') {
        const label = document.createElement('label');
        const box = document.createElement('input');
        box.type = 'checkbox';
        box.checked = curve.extend;
        box.addEventListener('change', () => onChange(curve.id, { extend: box.checked }));
        label.append(box, ' Extend past the end');
        panel.append(label);
      }
      if (curve.type === 'stream') return;
      for (const f of FIELDS[curve.type]) {
        const label = document.createElement('label');
        label.textContent = f.label;
        const input = document.createElement('input');
        input.type = 'number';
        input.min = String(f.min);
        input.max = String(f.max);
        input.step = String(f.step);
        const raw = (curve as unknown as Record<string, number>)[f.key];
        input.value = String(Math.round((f.toView ? f.toView(raw) : raw) * 1000) / 1000);
        input.addEventListener('change', () => {
          const v = Number(input.value);
          if (!Number.isFinite(v)) return;
          const clamped = Math.min(f.max, Math.max(f.min, v));
          onChange(curve.id, { [f.key]: f.fromView ? f.fromView(clamped) : clamped } as CurvePatch);
        });
        label.append(input);
        panel.append(label);
      }
    },
  };
}

function paramsOf(c: StyleCurve): unknown {
  switch (c.type) {
    case 'stream':
      return [c.extend];
    case 'dividing':
      return [c.sigma, c.h, c.alpha0, c.alpha1];
    case 'ponytail':
      return [c.extend, c.tightness];
  }
}
