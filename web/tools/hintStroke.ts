// Hint strokes on a stream curve's supporting surface (method S4.4, paper Fig. 3c–h): lifting the
// stroke's rays onto the surface, recognising the operation, and applying it to the curve.
//
// Thresholds, in grid steps d (HintThresholds):
//   near = 1.5  an on-surface sample is "near" the curve when |offset| <= near
//   minLength = 1  shorter strokes are ignored ('too-short')
//   endWindow = 2  "near the curve's end": start parameter >= last index - endWindow
//   minSpan = 1  insert needs its two ends >= minSpan points apart along the curve
//   leave = 1  margin past `near` an insert pressed on the scalp must reach (see below)
// Rules, in order (the first that applies):
//   1. the first sample is not on the surface -> none 'not-on-surface';
//   2. stroke length < minLength -> none 'too-short';
//   3. starts near and ends near (the last sample on the surface and near) -> insert between
//      the start and end parameters (the stroke is reversed when it runs backwards), or none
//      'insert-too-short' when they are < minSpan apart;
//   4. starts near, ends far or off the surface -> concatenate when the start parameter is within
//      endWindow of the curve's end, else none 'concatenate-not-at-end';
//   5. starts far: when two consecutive on-surface samples have offsets of opposite signs with
//      the crossing parameter interpolated between them, the stroke reaches at least `near` on
//      both sides, and it ends far -> cut at the crossing; else none 'no-operation'.
// Operations (the result is resampled at step d from the curve's first point):
//   cut: keep the curve from its root to the crossing parameter;
//   concatenate: the curve up to the start parameter, then the stroke;
//   insert: the curve up to the start parameter, the stroke, the curve from the end parameter.
//
// Strokes pressed on the scalp (scalpHintEdit). A press on the scalp is also how a new stream
// curve starts, and a new curve is usually drawn right beside the last one (which is selected),
// so such a stroke is a hint only when it clearly is one; otherwise the tool draws a new curve.
// "Screen distance" is a sample's distance from the curve's image, in pixels (SCALP_HINT_PIXELS);
// a sample is "hidden" when its surface point lies behind the head. It is a hint when the rules
// above give an operation and:
//   concatenate: the press is on the curve (screen distance <= pressPixels, 8);
//   insert: the press is on the curve, the end is not hidden, and the stroke leaves the curve
//     between its ends: its largest |offset| exceeds (near + leave) d and its largest screen
//     distance clearPixels (16) (a stroke running along the curve, however close, is a new curve);
//   cut: the stroke really crosses the curve: it starts and ends clear of the curve's image
//     (screen distance >= clearPixels), and the crossing, interpolated between its two samples,
//     lies within near d of the curve and is not hidden behind the head;
//   anything else ('none' included) is not a hint: a new curve.
// Strokes pressed off the scalp keep the rules above unchanged ('none' says why).
import { resamplePolyline } from '../model/resample';
import { intersectSupportingSurface, type SupportingSurface } from '../model/supportingSurface';
import { add, distance, dot, length, lerp, scale, sub, type Vec3 } from '../model/vec3';

/** One stroke point lifted onto the supporting surface. */
export interface HintSample {
  point: Vec3; // world position (on the surface, or extrapolated when off it)
  onSurface: boolean;
  param: number; // curve parameter (point-index units); NaN when off the surface
  offset: number; // signed offset from the curve in the surface, world units; NaN when off it
  ray?: number; // index of the stroke ray it was lifted from (liftHintStroke skips a few)
  hidden?: boolean; // on the surface but behind the head (set by the tool; see scalpHintEdit)
}

export interface HintThresholds {
  near: number;
  minLength: number;
  endWindow: number;
  minSpan: number;
  /** Margin past `near` (grid steps) an insert pressed on the scalp must reach. */
  leave: number;
}

export const DEFAULT_HINT_THRESHOLDS: HintThresholds = {
  near: 1.5,
  minLength: 1,
  endWindow: 2,
  minSpan: 1,
  leave: 1,
};

/** Screen tolerances for strokes pressed on the scalp (pixels; see the header). */
export interface ScalpHintPixels {
  /** The press is "on the curve" within this distance of its image. */
  pressPixels: number;
  /** A stroke is "clear of the curve" beyond this distance of its image. */
  clearPixels: number;
}

export const SCALP_HINT_PIXELS: ScalpHintPixels = { pressPixels: 8, clearPixels: 16 };

export type HintReason =
  | 'empty'
  | 'not-on-surface'
  | 'too-short'
  | 'insert-too-short'
  | 'concatenate-not-at-end'
  | 'no-operation'
  | 'cut-leaves-nothing';

export type HintOperation =
  | { kind: 'cut'; at: number }
  | { kind: 'concatenate'; from: number }
  | { kind: 'insert'; from: number; to: number; reversed: boolean }
  | { kind: 'none'; reason: HintReason };

export interface StrokeRay {
  origin: Vec3;
  direction: Vec3; // unit
}

/**
 * Lifts a stroke's rays onto the surface. On-surface samples take the hit. Once the stroke has
 * left the surface, depth is extrapolated from the last on-surface segment (a -> b): with depth
 * D(x) = (x - eye) . forward and lateral distance L(v) = |v - (v . forward) forward|, the depth
 * keeps changing at the segment's rate k = (D(b) - D(a)) / L(b - a) per unit of lateral travel:
 * the point is the ray's point at depth D(b) + k L(x0 - b), x0 being the ray's point at depth
 * D(b). With a single on-surface sample before, k = 0 (constant depth, as in S4.2). Samples
 * before the first on-surface one are kept as off-surface placeholders at the depth of the
 * curve's centroid: they only make the classifier answer 'not-on-surface'.
 */
export function liftHintStroke(
  rays: readonly StrokeRay[],
  surface: SupportingSurface,
  eye: Vec3,
  forward: Vec3,
): HintSample[] {
  const out: HintSample[] = [];
  const depth = (x: Vec3) => dot(sub(x, eye), forward);
  const lateral = (v: Vec3) => length(sub(v, scale(forward, dot(v, forward))));
  const atDepth = (r: StrokeRay, D: number): Vec3 | null => {
    const rate = dot(r.direction, forward);
    if (!(rate > 1e-9)) return null;
    return add(r.origin, scale(r.direction, (D - depth(r.origin)) / rate));
  };
  let lastOn: Vec3 | null = null;
  let prevOn: Vec3 | null = null;
  for (let ray = 0; ray < rays.length; ray++) {
    const r = rays[ray];
    const hit = intersectSupportingSurface(surface, r.origin, r.direction);
    if (hit) {
      prevOn = lastOn;
      lastOn = hit.point;
      out.push({ point: hit.point, onSurface: true, param: hit.param, offset: hit.offset, ray });
      continue;
    }
    if (!lastOn) {
      let c: Vec3 = [0, 0, 0];
      for (const p of surface.curve) c = add(c, p);
      const x = atDepth(r, depth(scale(c, 1 / Math.max(1, surface.curve.length))));
      if (x) out.push({ point: x, onSurface: false, param: Number.NaN, offset: Number.NaN, ray });
      continue;
    }
    let k = 0;
    if (prevOn) {
      const L = lateral(sub(lastOn, prevOn));
      if (L > 1e-12) k = (depth(lastOn) - depth(prevOn)) / L;
    }
    const x0 = atDepth(r, depth(lastOn));
    if (!x0) continue;
    const x = atDepth(r, depth(lastOn) + k * lateral(sub(x0, lastOn))) ?? x0;
    out.push({ point: x, onSurface: false, param: Number.NaN, offset: Number.NaN, ray });
  }
  return out;
}

const strokeLength = (s: readonly HintSample[]) => {
  let l = 0;
  for (let i = 1; i < s.length; i++) l += distance(s[i - 1].point, s[i].point);
  return l;
};

/** Recognises the operation (see the header). `curvePoints` is the curve's point count. */
export function classifyHintStroke(
  samples: readonly HintSample[],
  curvePoints: number,
  step: number,
  thresholds: HintThresholds = DEFAULT_HINT_THRESHOLDS,
): HintOperation {
  if (samples.length === 0 || curvePoints < 2) return { kind: 'none', reason: 'empty' };
  const first = samples[0];
  const lastS = samples[samples.length - 1];
  if (!first.onSurface) return { kind: 'none', reason: 'not-on-surface' };
  if (strokeLength(samples) < thresholds.minLength * step)
    return { kind: 'none', reason: 'too-short' };
  const near = thresholds.near * step;
  const isNear = (s: HintSample) => s.onSurface && Math.abs(s.offset) <= near;
  const lastIndex = curvePoints - 1;
  if (isNear(first) && isNear(lastS)) {
    const a = first.param;
    const b = lastS.param;
    if (Math.abs(b - a) < thresholds.minSpan) return { kind: 'none', reason: 'insert-too-short' };
    return { kind: 'insert', from: Math.min(a, b), to: Math.max(a, b), reversed: b < a };
  }
  if (isNear(first)) {
    if (first.param >= lastIndex - thresholds.endWindow)
      return { kind: 'concatenate', from: first.param };
    return { kind: 'none', reason: 'concatenate-not-at-end' };
  }
  // Starts far: look for a crossing.
  const c = findCrossing(samples);
  if (c && c.maxPos >= near && c.maxNeg >= near && !isNear(lastS)) return { kind: 'cut', at: c.at };
  return { kind: 'none', reason: 'no-operation' };
}

/**
 * The stroke's first crossing of the curve within the surface: two consecutive on-surface
 * samples i - 1, i whose offsets change sign (a sample exactly on the curve, offset 0, counts),
 * the parameter interpolated between them at fraction f; with the largest offsets reached on
 * either side over the whole stroke. Null when the stroke never crosses.
 */
export function findCrossing(
  samples: readonly HintSample[],
): { at: number; index: number; f: number; maxPos: number; maxNeg: number } | null {
  let found: { at: number; index: number; f: number } | null = null;
  let maxPos = 0;
  let maxNeg = 0;
  for (let i = 0; i < samples.length; i++) {
    const s = samples[i];
    if (!s.onSurface) continue;
    maxPos = Math.max(maxPos, s.offset);
    maxNeg = Math.max(maxNeg, -s.offset);
    const p = samples[i - 1];
    if (found || i === 0 || !p.onSurface) continue;
    if ((p.offset < 0 && s.offset >= 0) || (p.offset > 0 && s.offset <= 0)) {
      const f = p.offset / (p.offset - s.offset);
      found = { at: p.param + (s.param - p.param) * f, index: i, f };
    }
  }
  return found ? { ...found, maxPos, maxNeg } : null;
}

/** The curve's point at a fractional parameter (clamped). */
export function curveAt(curve: readonly Vec3[], param: number): Vec3 {
  const last = curve.length - 1;
  const t = Math.min(last, Math.max(0, param));
  const i = Math.min(last - 1, Math.floor(t));
  return i < 0 ? curve[0] : lerp(curve[i], curve[i + 1], t - i);
}

/** The curve from its first point to `param` (inclusive, interpolated). */
function head(curve: readonly Vec3[], param: number): Vec3[] {
  const out: Vec3[] = [];
  for (let i = 0; i < curve.length && i < param; i++) out.push(curve[i]);
  out.push(curveAt(curve, param));
  return out;
}

/** The curve from `param` (interpolated) to its last point. */
function tail(curve: readonly Vec3[], param: number): Vec3[] {
  const out: Vec3[] = [curveAt(curve, param)];
  for (let i = Math.floor(param) + 1; i < curve.length; i++) if (i > param) out.push(curve[i]);
  return out;
}

/** Applies a recognised operation; `none` returns the curve unchanged (a copy). */
export function applyHintStroke(
  curve: readonly Vec3[],
  samples: readonly HintSample[],
  op: HintOperation,
  step: number,
): Vec3[] {
  const stroke = samples.map((s) => s.point);
  let poly: Vec3[];
  switch (op.kind) {
    case 'none':
      return curve.slice();
    case 'cut':
      poly = head(curve, op.at);
      break;
    case 'concatenate':
      poly = [...head(curve, op.from), ...stroke];
      break;
    case 'insert': {
      const s = op.reversed ? stroke.slice().reverse() : stroke;
      poly = [...head(curve, op.from), ...s, ...tail(curve, op.to)];
      break;
    }
  }
  return resamplePolyline(poly, step);
}

export interface HintResult {
  op: HintOperation;
  points: Vec3[]; // the edited curve (unchanged when op is none)
}

/** Classify and apply in one go; an operation that would leave < 2 points becomes none. */
export function editWithHintStroke(
  curve: readonly Vec3[],
  samples: readonly HintSample[],
  step: number,
  thresholds: HintThresholds = DEFAULT_HINT_THRESHOLDS,
): HintResult {
  const op = classifyHintStroke(samples, curve.length, step, thresholds);
  const points = applyHintStroke(curve, samples, op, step);
  if (op.kind !== 'none' && points.length < 2)
    return { op: { kind: 'none', reason: 'cut-leaves-nothing' }, points: curve.slice() };
  return { op, points };
}

/**
 * A stroke pressed on the scalp (see the header): the edit when it is clearly a hint, else null
 * (the tool then draws a new curve). `screenDistance[i]` is sample i's distance from the curve's
 * image in pixels; samples whose surface point is behind the head are marked `hidden`.
 */
export function scalpHintEdit(
  curve: readonly Vec3[],
  samples: readonly HintSample[],
  screenDistance: readonly number[],
  step: number,
  thresholds: HintThresholds = DEFAULT_HINT_THRESHOLDS,
  pixels: ScalpHintPixels = SCALP_HINT_PIXELS,
): HintResult | null {
  const result = editWithHintStroke(curve, samples, step, thresholds);
  const op = result.op;
  if (op.kind === 'none' || samples.length === 0) return null;
  const far = (thresholds.near + thresholds.leave) * step;
  const pressed = screenDistance[0] ?? Number.POSITIVE_INFINITY;
  const released = screenDistance[samples.length - 1] ?? Number.POSITIVE_INFINITY;
  if (op.kind === 'concatenate') return pressed <= pixels.pressPixels ? result : null;
  const last = samples[samples.length - 1];
  if (op.kind === 'insert') {
    if (!(pressed <= pixels.pressPixels) || last.hidden) return null;
    let offset = 0;
    let screen = 0;
    samples.forEach((s, i) => {
      if (!s.onSurface) return;
      offset = Math.max(offset, Math.abs(s.offset));
      screen = Math.max(screen, screenDistance[i] ?? 0);
    });
    return offset > far && screen >= pixels.clearPixels ? result : null;
  }
  // cut
  if (!(pressed >= pixels.clearPixels && released >= pixels.clearPixels)) return null;
  const c = findCrossing(samples);
  if (!c) return null;
  const [a, b] = [samples[c.index - 1], samples[c.index]];
  if (a.hidden || b.hidden) return null;
  const at = lerp(a.point, b.point, c.f);
  return distance(at, curveAt(curve, c.at)) <= thresholds.near * step ? result : null;
}
