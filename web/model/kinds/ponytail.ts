// The ponytail (S4.6): `points` is the spine (edited like a stream curve); the cross-section and
// the two profile strokes are kept as drawn, the circles computed from them (C1 first).

import { defaultParams } from '../curveParams';
import { DIRECTION_SCALE as DIR, POSITION_SCALE as POS, toGridInt } from '../gridNumbers';
import { readPolyline, writePolyline } from '../linkBytes';
import { bandIndex, ponytailFromSpine } from '../ponytailFromSpine';
import { type PonytailCircle, ponytailCircles } from '../ponytailGeometry';
import { fail } from '../readFailure';
import {
  array,
  bool,
  CURVE_HI,
  CURVE_LO,
  int,
  num,
  polyline,
  position,
  record,
  unit,
} from '../readValues';
import { SESSION_LIMITS as L } from '../sessionLimits';
import type { Vec3 } from '../vec3';
import type { QuantizeKit, StrokeKindDef } from './curveKind';

function readCircles(o: { circles?: unknown }, path: string, spine: number): PonytailCircle[] {
  const cs = array(o.circles as never, `${path}.circles`, 'circles');
  if (cs.length < 1) fail(`${path}.circles`, 'needs at least 1 circle');
  if (cs.length > spine)
    fail(
      `${path}.circles`,
      `has ${cs.length} circles, more than its ${spine} spine points (the cap)`,
    );
  const circles: PonytailCircle[] = [];
  for (let i = 0; i < cs.length; i++) {
    const at = `${path}.circles[${i}]`;
    const q = record(cs[i], at, ['centre', 'axis', 'radius', 'spineIndex']);
    const centre = position(q.centre, `${at}.centre`, CURVE_LO, CURVE_HI, L.curveMargin);
    const axis = unit(q.axis, `${at}.axis`);
    const radius = num(q.radius, `${at}.radius`, 0, L.maxRadius);
    if (toGridInt(radius, POS) === 0)
      fail(
        `${at}.radius`,
        `must be greater than 0 (at least ${L.positionStep / 2}, at most ${L.maxRadius})`,
      );
    const spineIndex = int(q.spineIndex, `${at}.spineIndex`, 0, spine - 1);
    if (i > 0 && spineIndex <= circles[i - 1].spineIndex)
      fail(
        `${at}.spineIndex`,
        "must be greater than the previous circle's (C1 first, in spine order)",
      );
    circles.push({ centre, axis, radius, spineIndex });
  }
  return circles;
}

function quantizeCircle(c: PonytailCircle, kit: QuantizeKit): PonytailCircle {
  const centre = kit.qv(c.centre, POS);
  const axis = kit.qv(c.axis, DIR);
  const radius = kit.quantize(c.radius, POS);
  const spineIndex = kit.quantize(c.spineIndex, 1);
  return centre === c.centre &&
    axis === c.axis &&
    Object.is(radius, c.radius) &&
    Object.is(spineIndex, c.spineIndex)
    ? c
    : { ...c, centre, axis, radius, spineIndex };
}

export const PONYTAIL: StrokeKindDef<'ponytail'> = {
  name: 'ponytail',
  fields: ['extend', 'crossSection', 'profiles', 'circles'],
  role: 'tie',
  surface: () => 'ruled',
  extends: true,
  tieNear: (c) => c.points.slice(0, 1),
  // the circles follow the edited spine, between the profiles as drawn, from the band on
  respine(c, points) {
    const { circles } = ponytailCircles(points, c.crossSection, c.profiles[0], c.profiles[1], {
      every: 2,
      from: bandIndex(points),
      bandRadius: c.circles[0]?.radius,
    });
    return circles.length === 0 ? null : { ...c, points, circles };
  },
  guides: (c) => c.circles,
  // one stroke (ponytailFromSpine.ts): the spine; the cross-section, profiles and circles made
  // for it (a later cross-section and two profiles replace them)
  fromStroke: (points, viewpoint, extend) => ({
    type: 'ponytail',
    points,
    extend,
    viewpoint,
    ...ponytailFromSpine(points, viewpoint),
    ...defaultParams('ponytail'),
  }),
  read({ o, path, id, points, viewpoint, scalars, common }) {
    const extend = bool(o.extend, `${path}.extend`);
    const vp = viewpoint();
    const crossSection = polyline(o.crossSection, `${path}.crossSection`);
    const pr = array(o.profiles, `${path}.profiles`, 'profile strokes');
    if (pr.length !== 2)
      fail(`${path}.profiles`, `must hold two profile strokes, has ${pr.length}`);
    const profiles: [Vec3[], Vec3[]] = [
      polyline(pr[0], `${path}.profiles[0]`),
      polyline(pr[1], `${path}.profiles[1]`),
    ];
    const circles = readCircles(o, path, points.length);
    return {
      id,
      type: 'ponytail',
      points,
      extend,
      viewpoint: vp,
      crossSection,
      profiles,
      circles,
      ...(scalars as { tightness: number; section: number }),
      ...common,
    };
  },
  quantize(c, set, kit) {
    set('crossSection', c.crossSection, kit.positions(c.crossSection));
    const p0 = kit.positions(c.profiles[0]);
    const p1 = kit.positions(c.profiles[1]);
    if (p0 !== c.profiles[0] || p1 !== c.profiles[1]) set('profiles', c.profiles, [p0, p1]);
    set(
      'circles',
      c.circles,
      kit.mapSame(c.circles, (q) => quantizeCircle(q, kit)),
    );
  },
  mirror: (c, flip, flipDir) => ({
    crossSection: c.crossSection.map(flip),
    profiles: [c.profiles[0].map(flip), c.profiles[1].map(flip)],
    circles: c.circles.map(
      (q): PonytailCircle => ({ ...q, centre: flip(q.centre), axis: flipDir(q.axis) }),
    ),
  }),
  // solver-cpp/src/curve_params.hpp PonytailParam: [tightness] (the paper's) or [tightness,
  // gather = 1, section] (gathered: natural fall, the tail a solid of revolution fed by a
  // funnel, solver-cpp/src/ponytail_constraints.hpp); then its circles
  solverParams(c, [tightness, section], gather) {
    return [
      ...(gather ? [tightness, 1, section] : [tightness]),
      c.circles.length,
      ...c.circles.flatMap((q) => [...q.centre, ...q.axis, q.radius]),
    ];
  },
  linkMode: () => 0,
  writeLink(w, c) {
    writePolyline(w, c.crossSection, POS);
    writePolyline(w, c.profiles[0], POS);
    writePolyline(w, c.profiles[1], POS);
    w.varint(c.circles.length);
    const prev = [0, 0, 0, 0, 0, 0, 0, 0];
    for (const q of c.circles) {
      const now = [
        toGridInt(q.spineIndex, 1),
        ...q.centre.map((x) => toGridInt(x, POS)),
        ...q.axis.map((x) => toGridInt(x, DIR)),
        toGridInt(q.radius, POS),
      ];
      now.forEach((k, i) => {
        w.zigzag(k - prev[i]);
        prev[i] = k;
      });
    }
  },
  readLink(r, c) {
    c.crossSection = readPolyline(r, POS);
    c.profiles = [readPolyline(r, POS), readPolyline(r, POS)];
    const m = r.count(8);
    const prev = [0, 0, 0, 0, 0, 0, 0, 0];
    const circles = [];
    for (let i = 0; i < m; i++) {
      for (let j = 0; j < 8; j++) prev[j] += r.zigzag();
      circles.push({
        centre: [prev[1] / POS + 0, prev[2] / POS + 0, prev[3] / POS + 0],
        axis: [prev[4] / DIR + 0, prev[5] / DIR + 0, prev[6] / DIR + 0],
        radius: prev[7] / POS + 0,
        spineIndex: prev[0],
      });
    }
    c.circles = circles;
  },
};
