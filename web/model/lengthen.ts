// Lengthen (or shorten) a session's hair: "Longer" and "Shorter" in the Hair panel. With natural
// fall a stroke's hair ends where the stroke ends, so raising the maximum length alone leaves a
// sketched style where it was; lengthening moves every such end (a stream curve without "Extend
// past the end") on by the same amount, falling as hair past a cut falls, and the maximum length
// with it, so the whole style grows (or is cut back) and every rule still holds: the hair ends
// where its (longer) stroke ends. A fringe (a stroke that ends in front of the face, above the
// nose) keeps its end: a stylist asked for longer hair does not cut the fringe to the chin.

import { gridForPreset, MAX_HAIR_LENGTH } from './grid';
import { defOf, extendsPastEnd } from './kinds';
import { quantizeSession } from './quantize';
import { DEFAULT_GROWTH, type SessionState, type StyleCurve } from './session';
import { SESSION_LIMITS } from './sessionFile';
import type { Vec3 } from './vec3';

/** growth.maxSegments for strands of `maxLength` (world units) on a grid of step `step`: its
 *  length in growth steps (stepFraction × step) twice over, since a step is that times the
 *  field's magnitude, which falls below 1 where hair turns or a curve's end fades; never below
 *  the default's nor above the session limit. The engine checks that every strand at this many
 *  segments fits in memory, so it is not raised further. */
export function segmentsForLength(maxLength: number, stepFraction: number, step: number): number {
  const need = Math.ceil((2 * maxLength) / (stepFraction * step) - 1e-9);
  return Math.min(SESSION_LIMITS.maxSegments, Math.max(DEFAULT_GROWTH.maxSegments, need));
}

// Spacing of the points added past a stroke's end (world units: 1 cm), the shortest a stroke is
// cut back to (2 cm), and the shortest maximum length (2 cm, the panel's minimum).
const STEP = 0.1;
const SHORTEST_STROKE = 0.2;
const SHORTEST_HAIR = 0.2;

// Where a fringe ends, in the frame every head is placed in (the built-in head's: cranium top at
// y = 1, face towards +z, centred on x = z = 0): in front of the face (z above FRINGE.front,
// within FRINGE.halfAngle of straight ahead) and between the nose (FRINGE.low) and the top of
// the forehead (FRINGE.high).
const FRINGE = { front: 0.3, halfAngle: 0.8, low: -0.6, high: 0.6 } as const;

/** Whether a stroke ending at `p` is a fringe (see FRINGE). */
export function endsAsFringe(p: Vec3): boolean {
  return (
    p[2] > FRINGE.front &&
    Math.abs(Math.atan2(p[0], p[2])) < FRINGE.halfAngle &&
    p[1] > FRINGE.low &&
    p[1] < FRINGE.high
  );
}

function arcLength(p: readonly Vec3[]): number {
  let L = 0;
  for (let i = 1; i < p.length; i++)
    L += Math.hypot(p[i][0] - p[i - 1][0], p[i][1] - p[i - 1][1], p[i][2] - p[i - 1][2]);
  return L;
}

/** The stroke `p` carried on by `by` (> 0) past its end: a step at a time, turning from its last
 *  direction towards straight down (hair past a cut falls). */
function carryOn(p: readonly Vec3[], by: number): Vec3[] {
  const out = p.map((q) => [...q] as Vec3);
  const a = p[p.length - 2];
  const b = p[p.length - 1];
  const len = Math.hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]) || 1;
  let dir: Vec3 = [(b[0] - a[0]) / len, (b[1] - a[1]) / len, (b[2] - a[2]) / len];
  let left = by;
  while (left > 1e-9) {
    const step = Math.min(STEP, left);
    // half-way to straight down at every step
    const d: Vec3 = [dir[0] / 2, (dir[1] - 1) / 2, dir[2] / 2];
    const n = Math.hypot(d[0], d[1], d[2]) || 1;
    dir = [d[0] / n, d[1] / n, d[2] / n];
    const last = out[out.length - 1];
    out.push([last[0] + step * dir[0], last[1] + step * dir[1], last[2] + step * dir[2]]);
    left -= step;
  }
  return out;
}

/** The stroke `p` cut back by `by` (> 0) from its end, or null when that would leave it shorter
 *  than SHORTEST_STROKE. */
function cutBack(p: readonly Vec3[], by: number): Vec3[] | null {
  const keep = arcLength(p) - by;
  if (keep < SHORTEST_STROKE) return null;
  const out: Vec3[] = [p[0]];
  let s = 0;
  for (let i = 1; i < p.length; i++) {
    const a = p[i - 1];
    const b = p[i];
    const seg = Math.hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    if (s + seg >= keep) {
      const u = seg > 0 ? (keep - s) / seg : 0;
      out.push([a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]), a[2] + u * (b[2] - a[2])]);
      return out;
    }
    out.push(b);
    s += seg;
  }
  return out;
}

export interface Lengthened {
  session: SessionState;
  /** Strokes whose end moved. */
  strokes: number;
}

/** The session with its hair `by` world units longer (shorter when negative): every stream
 *  curve that ends its hair moved on (or cut back; a stroke that would be shorter than 2 cm is
 *  left; a fringe keeps its end), and the maximum length moved by as much, within
 *  2 cm .. MAX_HAIR_LENGTH. */
export function lengthenSession(s: SessionState, by: number): Lengthened {
  if (!Number.isFinite(by) || by === 0) return { session: s, strokes: 0 };
  let strokes = 0;
  const curves = s.curves.map((c): StyleCurve => {
    if (defOf(c).role !== 'flow' || extendsPastEnd(c) || c.points.length < 2) return c;
    if (endsAsFringe(c.points[c.points.length - 1])) return c;
    const points = by > 0 ? carryOn(c.points, by) : cutBack(c.points, -by);
    if (!points) return c;
    strokes++;
    return { ...c, points };
  });
  // to 0.01 mm, as the Hair panel shows it
  const maxLength =
    Math.round(Math.min(MAX_HAIR_LENGTH, Math.max(SHORTEST_HAIR, s.growth.maxLength + by)) * 1e4) /
    1e4;
  const growth = {
    ...s.growth,
    maxLength,
    maxSegments: segmentsForLength(maxLength, s.growth.stepFraction, gridForPreset(s.grid).step),
  };
  return { session: quantizeSession({ ...s, curves, growth }), strokes };
}
