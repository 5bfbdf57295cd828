// The dividing curve (S4.5): a parting drawn on the scalp, with the scalp normal at each point;
// its parameters are the parting's Gaussian profile and the tilt at both ends.

import { DIRECTION_SCALE as DIR } from '../gridNumbers';
import { readPolyline, writePolyline } from '../linkBytes';
import { fail } from '../readFailure';
import { array, unit, unitFast } from '../readValues';
import type { CurveKindDef } from './curveKind';

export const DIVIDING: CurveKindDef<'dividing'> = {
  name: 'dividing',
  fields: ['normals'],
  role: 'parting',
  surface: () => null,
  extends: false,
  read({ o, path, id, points, viewpoint, scalars, common }) {
    const n = array(o.normals, `${path}.normals`, 'normals');
    if (n.length !== points.length)
      fail(`${path}.normals`, `must have one normal per point (${points.length}), has ${n.length}`);
    const normals = n.map((x, i) => unitFast(x) ?? unit(x, `${path}.normals[${i}]`));
    const vp = viewpoint();
    return {
      id,
      type: 'dividing',
      points,
      normals,
      viewpoint: vp,
      ...(scalars as { sigma: number; h: number; alpha0: number; alpha1: number }),
      ...common,
    };
  },
  quantize(c, set, kit) {
    set('normals', c.normals, kit.directions(c.normals));
  },
  // the reflection turns the parting's handedness: its tilts change sign
  mirror: (c, _flip, flipDir) => ({
    normals: c.normals.map(flipDir),
    alpha0: -c.alpha0 + 0,
    alpha1: -c.alpha1 + 0,
  }),
  solverParams: (c, scalars) => [...scalars, ...c.normals.flatMap((n) => [n[0], n[1], n[2]])],
  linkMode: () => 0,
  writeLink(w, c) {
    writePolyline(w, c.normals, DIR);
  },
  readLink(r, c) {
    c.normals = readPolyline(r, DIR);
  },
};
