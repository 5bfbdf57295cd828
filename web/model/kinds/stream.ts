// The stream curve (S4.1–S4.4): a stroke the hair flows along; no scalar parameters yet.
import { MODES } from '../linkFormat';
import { fail } from '../readFailure';
import { bool } from '../readValues';
import type { StrokeKindDef } from './curveKind';

export const STREAM: StrokeKindDef<'stream'> = {
  name: 'stream',
  fields: ['extend', 'surfaceMode'],
  role: 'flow',
  surface: (c) => c.surfaceMode ?? 'ruled',
  extends: true,
  fromStroke: (points, viewpoint, extend) => ({ type: 'stream', points, extend, viewpoint }),
  read({ o, path, id, points, viewpoint, scalars, common }) {
    const extend = bool(o.extend, `${path}.extend`);
    const vp = viewpoint();
    const mode = o.surfaceMode;
    if (mode !== undefined && mode !== 'ruled' && mode !== 'strip')
      fail(`${path}.surfaceMode`, 'must be "ruled" or "strip"');
    return {
      id,
      type: 'stream',
      points,
      extend,
      viewpoint: vp,
      ...(mode === undefined ? {} : { surfaceMode: mode }),
      ...scalars,
      ...common,
    };
  },
  quantize() {},
  mirror: () => ({}),
  solverParams: (_c, scalars) => scalars,
  // the supporting surface's mode: absent (ruled, as before the option), ruled or strip
  linkMode: (c) => MODES.indexOf(c.surfaceMode),
  writeLink(_w, c, extra) {
    if (MODES.indexOf(c.surfaceMode) < 0) extra.surfaceMode = c.surfaceMode;
  },
  readLink(_r, c, mode) {
    if (mode) c.surfaceMode = MODES[mode];
  },
};
