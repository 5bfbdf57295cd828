// The grid every number of a session lives on. A session is quantised when it is made (the
// editor quantises every curve it receives, presets are quantised when built), so a share link,
// which stores these integers exactly (sessionLink.ts), reopens the very same numbers and so the
// very same hair. Each kind of number has its own step:
//
//   positions (curve points, cross-sections, profiles, circle centres and radii,
//   viewpoint positions and targets): 1e-4 world units (10 µm)
//   directions (dividing-curve normals, ponytail circle axes, scalp-avoidance targets): 1e-4
//   curve parameters: each its row's quantum in curveParams.ts CURVE_PARAMS (angles alpha0,
//   alpha1 1e-5 rad; sigma, h in grid steps, tightness 1e-4)
//   the session's number settings: their quantum in sessionSchema.ts SESSION_SETTINGS
//   indices (circle spineIndex: rounded; avoid grid index: truncated, as Int32Array does)
//   growth settings and the hair colour: exact (the colour as lowercase #rrggbb)
//   scalp brush strokes (points, radius): positions
//   the mirror plane (symmetry): its offset a position; its normal exact, as a unit vector
//   (unitNormal: divided by its length unless that is already 1 within 1e-12, so doing it twice
//   changes nothing), written in full by a link
//
// A quantised number is Math.round(x * scale) / scale (never -0; |x| clamped to 1e6, far
// outside any head), so it prints as a short decimal, and quantising twice changes nothing.
// Every function returns its argument itself when it is already on the grid: quantising an
// unchanged curve keeps its identity (the solver bridge compares curves by identity).
import { CURVE_KINDS, curveParamSpecs, quantumScale } from './curveParams';
import { DIRECTION_SCALE, PARAM_SCALE, POSITION_SCALE, quantize } from './gridNumbers';
import { defOf } from './kinds';
import type { QuantizeKit } from './kinds/curveKind';
import type { MirrorPlane } from './mirror';
import { quantizeHairLook } from './readHairLook';
import { REFERENCE_RANGES, type ReferenceImage } from './referenceImage';
import type { ScalpStroke, SessionState, StyleCurve, Viewpoint } from './session';
import { SETTING_NAMES, type SessionSettings, settingSpec } from './sessionSchema';
import type { Vec3 } from './vec3';

/** The grid of curve parameter `name` (its row's quantum in CURVE_PARAMS), as integers per unit. */
export function paramScale(name: string): number {
  for (const k of CURVE_KINDS)
    for (const spec of curveParamSpecs(k)) if (spec.name === name) return quantumScale(spec);
  return PARAM_SCALE;
}

function qv(v: Vec3, scale: number): Vec3 {
  const a = quantize(v[0], scale);
  const b = quantize(v[1], scale);
  const c = quantize(v[2], scale);
  return Object.is(a, v[0]) && Object.is(b, v[1]) && Object.is(c, v[2]) ? v : [a, b, c];
}

/** Maps `list` by `f`, returning `list` itself when every element maps to itself. */
function mapSame<T>(list: readonly T[], f: (t: T) => T): T[] {
  let out: T[] | null = null;
  for (let i = 0; i < list.length; i++) {
    const t = f(list[i]);
    if (out) out.push(t);
    else if (t !== list[i]) {
      out = list.slice(0, i);
      out.push(t);
    }
  }
  return out ?? (list as T[]);
}

const positions = (p: Vec3[]) => mapSame(p, (v) => qv(v, POSITION_SCALE));
const directions = (p: Vec3[]) => mapSame(p, (v) => qv(v, DIRECTION_SCALE));

export function quantizeViewpoint(vp: Viewpoint): Viewpoint {
  const position = qv(vp.position, POSITION_SCALE);
  const target = qv(vp.target, POSITION_SCALE);
  return position === vp.position && target === vp.target ? vp : { ...vp, position, target };
}

// what a kind's own fields are quantised with (kinds/curveKind.ts)
const KIT: QuantizeKit = { positions, directions, mapSame, qv, quantize };

/** A curve with every number on the grid and each scalar parameter of its kind present (its
 *  default when missing); the curve itself when already so. */
export function quantizeCurve<C extends StyleCurve>(c: C): C {
  const patch: Record<string, unknown> = {};
  const set = (key: string, was: unknown, now: unknown) => {
    if (!Object.is(was, now)) patch[key] = now;
  };
  set('points', c.points, positions(c.points));
  set('viewpoint', c.viewpoint, quantizeViewpoint(c.viewpoint));
  const rec = c as unknown as Record<string, number>;
  // every scalar parameter of its kind spelled out, as the reader spells it out: a curve made
  // in code before a parameter existed (a preset, a tool) is the curve a file or link reopens
  for (const spec of curveParamSpecs(c.type)) {
    const v = rec[spec.name];
    set(spec.name, v, typeof v === 'number' ? quantize(v, quantumScale(spec)) : spec.default);
  }
  defOf(c).quantize(c, set, KIT);
  return Object.keys(patch).length === 0 ? c : ({ ...c, ...patch } as C);
}

/** A scalp brush stroke with its points and radius on the position grid (itself when so). */
export function quantizeStroke(st: ScalpStroke): ScalpStroke {
  const points = positions(st.points);
  const radius = quantize(st.radius, POSITION_SCALE);
  return points === st.points && Object.is(radius, st.radius) ? st : { ...st, points, radius };
}

/** `n` as a unit vector: n / |n|, or `n` itself when |n| is 1 within 1e-12 (so a unit normal
 *  stays bit for bit what it is, and normalising twice changes nothing); never -0. A zero or non-finite
 *  vector is returned as it is (the reader refuses it). */
export function unitNormal(n: Vec3): Vec3 {
  const len = Math.hypot(n[0], n[1], n[2]);
  if (!(len > 0) || !Number.isFinite(len)) return n;
  if (Math.abs(len - 1) <= 1e-12)
    return n.some((x) => Object.is(x, -0)) ? [n[0] + 0, n[1] + 0, n[2] + 0] : n;
  return [n[0] / len + 0, n[1] / len + 0, n[2] / len + 0];
}

/** The mirror plane with a unit normal and its offset on the position grid (itself when so). */
export function quantizePlane(p: MirrorPlane): MirrorPlane {
  const normal = unitNormal(p.normal);
  const offset = quantize(p.offset, POSITION_SCALE);
  return normal === p.normal && Object.is(offset, p.offset) ? p : { ...p, normal, offset };
}

/** A session with every number on the grid and the hair colour in lowercase: exactly what its
 *  share link reopens. The same
 *  object when nothing changes; unchanged curves keep their identity. */
export function quantizeSession(s: SessionState): SessionState {
  const curves = mapSame(s.curves, quantizeCurve);
  const hairColor = s.hairColor.toLowerCase();
  const scalpPaint = s.scalpPaint && mapSame(s.scalpPaint, quantizeStroke);
  const symmetry = s.symmetry && quantizePlane(s.symmetry);
  const settings = quantizeSettings(s);
  const references = s.references && mapSame(s.references, quantizeReference);
  const hairLook = s.hairLook && quantizeHairLook(s.hairLook);
  if (
    curves === s.curves &&
    hairColor === s.hairColor &&
    scalpPaint === s.scalpPaint &&
    symmetry === s.symmetry &&
    references === s.references &&
    hairLook === s.hairLook &&
    settings === null
  )
    return s;
  return {
    ...s,
    curves,
    hairColor,
    ...(scalpPaint ? { scalpPaint } : {}),
    ...(symmetry ? { symmetry } : {}),
    ...(references ? { references } : {}),
    ...(hairLook ? { hairLook } : {}),
    ...settings,
  };
}

/** A reference picture's numbers on their grids (referenceImage.ts REFERENCE_RANGES); the same
 *  object when they already are. */
export function quantizeReference(r: ReferenceImage): ReferenceImage {
  const q = (x: number, k: keyof typeof REFERENCE_RANGES) =>
    quantize(x, Math.round(1 / REFERENCE_RANGES[k].quantum));
  const opacity = q(r.opacity, 'opacity');
  const scale = q(r.scale, 'scale');
  const ox = q(r.offset[0], 'offset');
  const oy = q(r.offset[1], 'offset');
  if (
    Object.is(opacity, r.opacity) &&
    Object.is(scale, r.scale) &&
    Object.is(ox, r.offset[0]) &&
    Object.is(oy, r.offset[1])
  )
    return r;
  return { ...r, opacity, scale, offset: [ox, oy] };
}

/** The number settings (sessionSchema.ts) that are off their quantum's grid, put on it; null
 *  when every one is on it. */
function quantizeSettings(s: SessionSettings): Record<string, number> | null {
  let out: Record<string, number> | null = null;
  const values = s as Record<string, unknown>;
  for (const k of SETTING_NAMES) {
    const spec = settingSpec(k);
    const v = values[k];
    if (spec.type !== 'number' || typeof v !== 'number') continue;
    const q = quantize(v, Math.round(1 / spec.quantum));
    if (!Object.is(q, v)) {
      out ??= {};
      out[k] = q;
    }
  }
  return out;
}
