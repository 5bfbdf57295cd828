// Every change a user makes to the session, as one typed command, and what each does: a pure
// function from (session, command) to the next session, the selection after it and a sentence
// for the status line. The Editor (editor.ts) runs them through one path: history, then notify.

import { detailForCurlType, rootLiftOf } from '../model/curlTypes';
import { CURVE_PARAMS, type CurveParamSpec, defaultParams } from '../model/curveParams';
import { blockIsOn, detailIsOn, type HairDetail } from '../model/detail';
import type { GrowthParams } from '../model/growthParams';
import { DEFAULT_BAND_COLOR, type HairLook } from '../model/hairLook';
import { shadeOf } from '../model/hairShades';
import { defOf } from '../model/kinds';
import { lengthenSession } from '../model/lengthen';
import {
  isSelfMirror,
  type MirrorPlane,
  mirrorCurve,
  reflectPoint,
  syncMirrorTwins,
  X_PLANE,
} from '../model/mirror';
import { bandIndex, PONYTAIL_WIDTH, widenPonytail } from '../model/ponytailFromSpine';
import { keepBand, type PonytailCircle } from '../model/ponytailGeometry';
import { quantizeSession } from '../model/quantize';
import type { ReferenceImage } from '../model/referenceImage';
import {
  addCurve,
  type BraidCurve,
  deleteCurve,
  findCurve,
  type HeadRef,
  nextCurveId,
  type PonytailCurve,
  type ScalpStroke,
  type SessionState,
  type StyleCurve,
  updateCurve,
  type Viewpoint,
} from '../model/session';
import { parseSession } from '../model/sessionFile';
import { SESSION_SETTINGS } from '../model/sessionSchema';
import type { SurfaceMode } from '../model/supportingSurface';
import type { Vec3 } from '../model/vec3';

/** A new curve as a tool makes it: everything but its id (the editor assigns it). */
export type NewCurve = StyleCurve extends infer C
  ? C extends StyleCurve
    ? Omit<C, 'id'>
    : never
  : never;

/** Scalar parameters the curve panel edits: those of protocol.ts CURVE_PARAMS for the curve's
 *  kind (within their ranges), and "extend" (stream curves and ponytails). */
export type CurveParamPatch = Readonly<Record<string, number | boolean>>;

export type HintKind = 'cut' | 'concatenate' | 'insert';

export type Command =
  /** `mirror`: also add the curve's mirrored twin (unless it is its own mirror image). */
  | { kind: 'addCurve'; curve: NewCurve; what: string; mirror?: boolean }
  | { kind: 'deleteCurve'; id: string }
  /** A hint stroke's edit of a stream curve or ponytail spine (S4.4): its new points. */
  | { kind: 'hintEdit'; id: string; op: HintKind; points: Vec3[] }
  /** A dividing curve's tilt from a tilt hint (S4.5). */
  | { kind: 'setTilt'; id: string; end: 'alpha0' | 'alpha1'; alpha: number; side: 1 | -1 }
  | { kind: 'patchCurve'; id: string; patch: CurveParamPatch }
  /** "Braid the tail": the ponytail `id` becomes a braid on its spine (same id, extend, viewpoint,
   *  detail and twin), as wide as twice its circles' mean radius. */
  | { kind: 'braidTail'; id: string }
  /** A ponytail's cross-section and two profiles drawn after its spine (method S4.6's strokes
   *  2-4): they replace those its one stroke made, and its circles follow. */
  /** The curve panel's width of a ponytail: at least `width` (world units) across at its band
   *  (the hair it holds may make it wider), the circles and strokes widened about the spine. */
  | { kind: 'setPonytailWidth'; id: string; width: number }
  | {
      kind: 'shapePonytail';
      id: string;
      crossSection: Vec3[];
      profiles: [Vec3[], Vec3[]];
      circles: PonytailCircle[];
    }
  | { kind: 'setViewpoint'; id: string; viewpoint: Viewpoint }
  | { kind: 'setSurfaceMode'; id: string; mode: SurfaceMode }
  /** "Avoid scalp" (S4.7) on or off: a setting the solver applies whenever it solves. */
  | { kind: 'setAvoidScalp'; on: boolean }
  | { kind: 'setBust'; on: boolean }
  /** Volume (the shape rules' lift at the roots, world units 0 to 0.3). */
  | { kind: 'setVolume'; volume: number }
  /** The session's detail (curveId null) or one curve's own (undefined: none / the session's). */
  | { kind: 'setDetail'; curveId: string | null; detail: HairDetail | undefined }
  /** The Hair panel's Curl type: the type's detail (curlTypes.ts), and for the whole head of a
   *  session with the shape rules whose Volume is the default, the type's root lift, one edit. */
  | { kind: 'setCurlType'; curveId: string | null; type: string }
  /** Growth settings (strand density, cap, maximum length). */
  | { kind: 'setGrowth'; patch: Partial<GrowthParams> }
  /** "Longer" / "Shorter": every stroke that ends hair moved on by `by` world units (cut back
   *  when negative), and the maximum length with it (model/lengthen.ts). */
  | { kind: 'lengthen'; by: number }
  | { kind: 'setHairColor'; color: string }
  /** The colour model (model/hairLook.ts); null: the colour box's direct colour. */
  | { kind: 'setHairLook'; look: HairLook | null }
  /** The ties' band colour (#rrggbb; the default band's colour is stored as absent). */
  | { kind: 'setBandColor'; color: string }
  /** The head the hair grows on (Open head, Rotate, the built-in head). The scalp painting of
   *  the previous head is dropped (it belongs to that mesh); `symmetry`: the new head's mirror
   *  plane (absent: x = 0). */
  | { kind: 'setHead'; head: 'builtin' | HeadRef; symmetry?: MirrorPlane; what: string }
  /** A scalp brush stroke (painting or erasing scalp), applied over the strokes before it. */
  // mirror: the stroke and its reflection in the symmetry plane, as one edit (Mirror on)
  | { kind: 'paintScalp'; stroke: ScalpStroke; mirror?: boolean }
  /** The mirror plane (Mirror editing); absent = x = 0. */
  | { kind: 'setSymmetry'; plane: MirrorPlane | undefined }
  /** The reference pictures (added, placed, adjusted, hidden or removed); `what` says which. */
  | { kind: 'setReferences'; references: ReferenceImage[]; what: string }
  /** Replaces the whole session (a file, a link, a test hook). The page's grid is kept: curves
   *  are in world units. `camera`: the view the session was saved with, if any. */
  | {
      kind: 'loadSession';
      session: SessionState;
      what: string;
      camera?: Viewpoint;
      /** Start a new history (a link opened with the page) instead of an undoable edit. */
      resetHistory?: boolean;
    };

export type CommandKind = Command['kind'];

export interface CommandResult {
  session: SessionState;
  /** The selection after the command (undefined: unchanged). */
  selectedId?: string | null;
  message: string;
}

/** The braid that replaces ponytail `c` ("Braid the tail"): its spine, width twice the mean
 *  circle radius (within the table's range), the other parameters the table's defaults. */
export function braidOfPonytail(c: PonytailCurve): BraidCurve {
  const spec = CURVE_PARAMS.braid[0];
  const mean = c.circles.reduce((a, q) => a + q.radius, 0) / Math.max(1, c.circles.length);
  const width = Math.min(spec.max, Math.max(spec.min, 2 * mean));
  return {
    id: c.id,
    type: 'braid',
    points: c.points,
    extend: c.extend,
    viewpoint: c.viewpoint,
    ...defaultParams('braid'),
    width,
    ...(c.detail ? { detail: c.detail } : {}),
    ...(c.mirror ? { mirror: c.mirror } : {}),
  };
}

const deg = (rad: number) => Math.round((rad * 180) / Math.PI);
const HEX_COLOR = /^#[0-9a-fA-F]{6}$/;

/** What `cmd` does to `s`. The session is returned unchanged (same object) when nothing
 *  changes; the message then says why. Every number the command brings in is put on the grid
 *  of model/quantize.ts (curves, viewpoints, avoid targets), so the session a share link
 *  reopens is this very session; unchanged curves keep their identity. */
export function applyCommand(s: SessionState, cmd: Command): CommandResult {
  const r = applyExact(s, cmd);
  if (r.session === s) return r;
  // Mirrored twins follow: one deleted takes the other, one edited remakes the other.
  const synced =
    cmd.kind === 'loadSession'
      ? null
      : syncMirrorTwins(s.curves, r.session.curves, r.session.symmetry ?? X_PLANE);
  if (synced) r.session = { ...r.session, curves: synced };
  const next = quantizeSession(r.session);
  // A curve a tool made (or edited) must be one the session reader accepts, so the editor never
  // holds a session that a link, a file or an export would refuse (e.g. a stroke drawn far off
  // the head, past the working volume). Only the curves this command made are read.
  const made = next.curves.filter((c) => !s.curves.includes(c));
  if (made.length > 0 && cmd.kind !== 'loadSession') {
    const check = parseSession({ ...next, curves: made });
    if (!check.ok)
      return {
        session: s,
        message: `Nothing changed: the curve is not one a session can hold (${check.error.replace(/^session\.curves\[\d+\]/, 'curve')}).`,
      };
  }
  return { ...r, session: next };
}

/** One handler per command kind: the session after it, and what the status line says. */
/** Turns a session flag on or off (written only when on, as the schema says), with the status
 *  line's words for each outcome. */
function setFlag(
  s: SessionState,
  key: 'avoidScalp' | 'bust',
  on: boolean,
  words: { already: string; on: string; off: string },
): { session: SessionState; message: string } {
  if (!!s[key] === on) return { session: s, message: `${words.already} ${on ? 'on' : 'off'}.` };
  const { [key]: _, ...rest } = s;
  return { session: on ? { ...rest, [key]: true } : rest, message: on ? words.on : words.off };
}

const HANDLERS: {
  readonly [K in Command['kind']]: (
    s: SessionState,
    cmd: Extract<Command, { kind: K }>,
  ) => CommandResult;
} = {
  addCurve(s, cmd) {
    const id = nextCurveId(s);
    const curve = { ...cmd.curve, id } as StyleCurve;
    const plane = s.symmetry ?? X_PLANE;
    if (cmd.mirror && !isSelfMirror(curve, plane)) {
      const twinId = `c${Number(id.slice(1)) + 1}`;
      const first = { ...curve, mirror: twinId } as StyleCurve;
      const twin = mirrorCurve(first, twinId, id, plane);
      return {
        session: addCurve(addCurve(s, first), twin),
        selectedId: id,
        message: `Added ${cmd.what.replace('{id}', id)} and its mirror ${twinId}.`,
      };
    }
    return {
      session: addCurve(s, curve),
      selectedId: id,
      message: `Added ${cmd.what.replace('{id}', id)}.`,
    };
  },
  deleteCurve(s, cmd) {
    const next = deleteCurve(s, cmd.id);
    if (next === s) return { session: s, message: `No curve ${cmd.id} to delete.` };
    // the selection drops only if it was this curve (the editor drops missing selections)
    const twin = findCurve(s, cmd.id)?.mirror;
    return {
      session: next,
      message: twin
        ? `Deleted curve ${cmd.id} and its mirror ${twin}.`
        : `Deleted curve ${cmd.id}.`,
    };
  },
  hintEdit(s, cmd) {
    const c = findCurve(s, cmd.id);
    if (!c || !defOf(c).surface(c)) return { session: s, message: `No curve ${cmd.id} to edit.` };
    const def = defOf(c);
    const next = def.respine ? def.respine(c, cmd.points) : { ...c, points: cmd.points };
    if (!next)
      return {
        session: s,
        message: `Hint: ${cmd.op} would leave the ${c.type} without circles — nothing changed.`,
      };
    return {
      session: updateCurve(s, c.id, () => next),
      message: `Hint: ${cmd.op} — ${c.id} now has ${cmd.points.length} points.`,
    };
  },
  setTilt(s, cmd) {
    const c = findCurve(s, cmd.id);
    if (c?.type !== 'dividing') return { session: s, message: `No dividing curve ${cmd.id}.` };
    return {
      session: updateCurve(s, c.id, () => ({ ...c, [cmd.end]: cmd.alpha })),
      message: `Tilt: ${cmd.end} of ${c.id} = ${deg(cmd.alpha)}° (stroke on the ${cmd.side > 0 ? '+x' : '−x'} side).`,
    };
  },
  braidTail(s, cmd) {
    const c = findCurve(s, cmd.id);
    if (c?.type !== 'ponytail') return { session: s, message: `No ponytail ${cmd.id}.` };
    const braid = braidOfPonytail(c);
    return {
      session: updateCurve(s, c.id, () => braid),
      selectedId: c.id,
      message: `Braided the tail of ${c.id}: a braid ${Math.round(braid.width * 100) / 10} cm wide.`,
    };
  },
  setPonytailWidth(s, cmd) {
    const c = findCurve(s, cmd.id);
    if (c?.type !== 'ponytail' || c.circles.length === 0)
      return { session: s, message: `No ponytail ${cmd.id}.` };
    if (
      !Number.isFinite(cmd.width) ||
      cmd.width < PONYTAIL_WIDTH.min ||
      cmd.width > PONYTAIL_WIDTH.max
    )
      return {
        session: s,
        message: `Width must be a number from ${10 * PONYTAIL_WIDTH.min} to ${10 * PONYTAIL_WIDTH.max} cm: nothing changed.`,
      };
    const wide = widenPonytail(c.points, c, cmd.width / (2 * c.circles[0].radius));
    return {
      session: updateCurve(s, c.id, () => ({ ...c, ...wide })),
      selectedId: c.id,
      message: `Ponytail ${c.id} at least ${Math.round(100 * cmd.width) / 10} cm wide at its band.`,
    };
  },
  shapePonytail(s, cmd) {
    const c = findCurve(s, cmd.id);
    if (c?.type !== 'ponytail') return { session: s, message: `No ponytail ${cmd.id}.` };
    if (cmd.circles.length === 0)
      return { session: s, message: 'The profiles do not run beside the spine: nothing changed.' };
    const { crossSection, profiles } = cmd;
    // the band keeps its radius: the profiles shape the tail below it (the tool's circles are
    // every other spine point from the band)
    const circles = keepBand(cmd.circles, c.circles[0]?.radius, bandIndex(c.points), 2);
    return {
      session: updateCurve(s, c.id, () => ({ ...c, crossSection, profiles, circles })),
      selectedId: c.id,
      message: `Shaped ponytail ${c.id} (${circles.length} circles).`,
    };
  },
  patchCurve(s, cmd) {
    const c = findCurve(s, cmd.id);
    if (!c) return { session: s, message: `No curve ${cmd.id}.` };
    const patch: Record<string, number | boolean> = {};
    for (const [k, v] of Object.entries(cmd.patch)) {
      const spec = (CURVE_PARAMS[c.type] as readonly CurveParamSpec[]).find((p) => p.name === k);
      if (spec) {
        if (typeof v !== 'number' || !Number.isFinite(v) || v < spec.min || v > spec.max)
          return {
            session: s,
            message: `${spec.label} must be a number from ${spec.min} to ${spec.max}: nothing changed.`,
          };
        patch[k] = v;
      } else if (k === 'extend' && defOf(c).extends && typeof v === 'boolean') {
        patch[k] = v;
      }
    }
    const keys = Object.keys(patch);
    if (keys.length === 0) return { session: s, message: `Nothing to change on ${c.id}.` };
    return {
      session: updateCurve(s, c.id, () => ({ ...c, ...patch }) as StyleCurve),
      message: `Changed ${keys.join(', ')} of ${c.id}.`,
    };
  },
  setViewpoint(s, cmd) {
    const c = findCurve(s, cmd.id);
    if (!c) return { session: s, message: `No curve ${cmd.id}.` };
    return {
      session: updateCurve(s, c.id, () => ({ ...c, viewpoint: cmd.viewpoint })),
      message: `Viewpoint of ${c.id} set to the current view.`,
    };
  },
  setSurfaceMode(s, cmd) {
    const c = findCurve(s, cmd.id);
    if (c?.type !== 'stream')
      return { session: s, message: 'Surface mode applies to a selected stream curve.' };
    if ((c.surfaceMode ?? 'ruled') === cmd.mode)
      return { session: s, message: `Supporting surface of ${c.id}: ${cmd.mode}.` };
    return {
      session: updateCurve(s, c.id, () => ({ ...c, surfaceMode: cmd.mode })),
      message: `Supporting surface of ${c.id}: ${cmd.mode}.`,
    };
  },
  setAvoidScalp: (s, cmd) =>
    setFlag(s, 'avoidScalp', cmd.on, {
      already: 'Avoid scalp is already',
      on: 'Avoid scalp on: hair near the head is turned along it.',
      off: 'Avoid scalp off.',
    }),
  setBust: (s, cmd) =>
    setFlag(s, 'bust', cmd.on, {
      already: 'The bust is already',
      on: 'Bust on: neck, shoulders and chest under the head; long hair rests on them.',
      off: 'Bust off: the head alone.',
    }),
  setVolume(s, cmd) {
    const spec = SESSION_SETTINGS.volume;
    if (!Number.isFinite(cmd.volume) || cmd.volume < spec.min || cmd.volume > spec.max)
      return {
        session: s,
        message: `Volume must be from ${spec.min * 10} to ${spec.max * 10} cm: nothing changed.`,
      };
    const volume = Math.round(cmd.volume / spec.quantum) / Math.round(1 / spec.quantum);
    if (!s.shape)
      return { session: s, message: 'Volume applies to sessions with the shape rules.' };
    if ((s.volume ?? spec.default) === volume)
      return { session: s, message: `Volume is already ${(volume * 10).toFixed(1)} cm.` };
    const { volume: _old, ...rest } = s;
    return {
      session: volume === spec.default ? rest : { ...rest, volume },
      message: `Volume ${(volume * 10).toFixed(1)} cm: the hair stands off the head by that much at its roots.`,
    };
  },
  setDetail(s, cmd) {
    const d = cmd.detail && (detailIsOn(cmd.detail) || cmd.curveId) ? cmd.detail : undefined;
    if (cmd.curveId === null) {
      if (JSON.stringify(d) === JSON.stringify(s.detail))
        return { session: s, message: 'Detail unchanged.' };
      const { detail: _, ...rest } = s;
      const next = d ? { ...rest, detail: d } : rest;
      const check = parseSession({ ...next, curves: [] });
      if (!check.ok) return { session: s, message: `Nothing changed: ${check.error}.` };
      return {
        session: next,
        message: d ? `Detail: ${describeDetail(d)}.` : 'Detail off.',
      };
    }
    const c = findCurve(s, cmd.curveId);
    if (!c) return { session: s, message: `No curve ${cmd.curveId}.` };
    if (JSON.stringify(d) === JSON.stringify(c.detail))
      return { session: s, message: 'Detail unchanged.' };
    return {
      session: updateCurve(s, c.id, () => {
        const { detail: _, ...rest } = c;
        return (d ? { ...rest, detail: d } : rest) as StyleCurve;
      }),
      message: d
        ? `Detail of ${c.id}: ${describeDetail(d)}.`
        : `${c.id} uses the session's detail.`,
    };
  },
  setCurlType(s, cmd) {
    const c = cmd.curveId === null ? null : findCurve(s, cmd.curveId);
    if (cmd.curveId !== null && !c) return { session: s, message: `No curve ${cmd.curveId}.` };
    const detail = detailForCurlType(cmd.type, c ? c.detail : s.detail);
    const r = HANDLERS.setDetail(s, { kind: 'setDetail', curveId: cmd.curveId, detail });
    const lift = rootLiftOf(cmd.type);
    const spec = SESSION_SETTINGS.volume;
    if (c || lift === undefined || !s.shape || s.volume !== undefined) return r;
    const lifted = { ...r.session, volume: Math.min(spec.max, lift) };
    return {
      session: lifted,
      message: `${r.session === s ? `Curl type ${cmd.type}` : r.message.replace(/\.$/, '')}; Volume ${(lifted.volume * 10).toFixed(1)} cm: its roots stand off the head.`,
    };
  },
  lengthen(s, cmd) {
    const r = lengthenSession(s, cmd.by);
    if (r.session === s || !Number.isFinite(cmd.by))
      return { session: s, message: 'Length unchanged.' };
    const check = parseSession(r.session);
    if (!check.ok) return { session: s, message: `Nothing changed: ${check.error}.` };
    const cm = Math.round(Math.abs(cmd.by) * 100) / 10;
    const ml = (g: SessionState['growth']) => Math.round(g.maxLength * 100) / 10;
    // no stroke's end moved: only the cap changed, which the hair no stroke ends grows to
    const message =
      r.strokes === 0
        ? `Max length ${ml(r.session.growth)} cm (was ${ml(s.growth)} cm): hair no stroke ends grows to at most that; no stroke's end moved.`
        : `Hair ${cmd.by > 0 ? 'lengthened' : 'shortened'} by ${cm} cm: ${r.strokes} stroke end${r.strokes === 1 ? '' : 's'} moved, Max length ${ml(r.session.growth)} cm.`;
    return { session: r.session, message };
  },
  setGrowth(s, cmd) {
    const g = { ...s.growth };
    let changed = false;
    for (const [k, v] of Object.entries(cmd.patch) as [keyof GrowthParams, number][]) {
      if (!(k in g) || typeof v !== 'number' || !Number.isFinite(v))
        return { session: s, message: `Growth setting ${String(k)} is not a finite number.` };
      if (g[k] !== v) {
        g[k] = v;
        changed = true;
      }
    }
    if (!changed) return { session: s, message: 'Growth unchanged.' };
    const check = parseSession({ ...s, curves: [], growth: g });
    if (!check.ok) return { session: s, message: `Nothing changed: ${check.error}.` };
    return { session: { ...s, growth: g }, message: 'Growth settings changed.' };
  },
  setHairColor(s, cmd) {
    if (!HEX_COLOR.test(cmd.color))
      return { session: s, message: `Hair colour "${cmd.color.slice(0, 20)}" is not #rrggbb.` };
    // the colour box is the direct colour: picking one leaves the colour model
    const { hairLook: _, ...rest } = s;
    if (cmd.color === s.hairColor && !s.hairLook)
      return { session: s, message: `Hair colour ${cmd.color}.` };
    return { session: { ...rest, hairColor: cmd.color }, message: `Hair colour ${cmd.color}.` };
  },
  setHairLook(s, cmd) {
    const { hairLook: _, ...rest } = s;
    const next: SessionState = cmd.look ? { ...rest, hairLook: cmd.look } : rest;
    if (JSON.stringify(next.hairLook) === JSON.stringify(s.hairLook))
      return { session: s, message: 'Hair colour unchanged.' };
    const check = parseSession({ ...next, curves: [] });
    if (!check.ok) return { session: s, message: `Nothing changed: ${check.error}.` };
    const l = cmd.look;
    const shade = shadeOf(l);
    return {
      session: next,
      message: !l
        ? 'Hair colour: the colour box’s colour.'
        : shade
          ? `Hair colour: ${shade.name} (melanin ${l.melanin}, redness ${l.redness}, grey ${l.grey} %).`
          : `Hair colour: melanin ${l.melanin}, redness ${l.redness}, grey ${l.grey} %.`,
    };
  },
  setBandColor(s, cmd) {
    if (!HEX_COLOR.test(cmd.color))
      return { session: s, message: `Band colour "${cmd.color.slice(0, 20)}" is not #rrggbb.` };
    const color = cmd.color.toLowerCase();
    const { bandColor: _, ...rest } = s;
    if (color === (s.bandColor ?? DEFAULT_BAND_COLOR))
      return { session: s, message: `Band colour ${color}.` };
    // the default is not written, so sessions that never change it keep their bytes
    const next: SessionState = color === DEFAULT_BAND_COLOR ? rest : { ...rest, bandColor: color };
    return { session: next, message: `Band colour ${color}.` };
  },
  setHead(s, cmd) {
    const { scalpPaint: _p, symmetry: _s, ...rest } = s;
    const next: SessionState = { ...rest, head: cmd.head };
    if (cmd.symmetry) next.symmetry = cmd.symmetry;
    if (JSON.stringify(next.head) === JSON.stringify(s.head) && !s.scalpPaint)
      if (JSON.stringify(next.symmetry) === JSON.stringify(s.symmetry))
        return { session: s, message: `${cmd.what} (unchanged).` };
    return { session: next, message: `${cmd.what}.` };
  },
  paintScalp(s, cmd) {
    const k = cmd.stroke;
    if (!(k.radius > 0) || k.points.length === 0)
      return { session: s, message: 'Scalp brush: the stroke missed the head.' };
    const plane = s.symmetry ?? X_PLANE;
    const strokes = cmd.mirror
      ? [k, { ...k, points: k.points.map((p) => reflectPoint(p, plane)) }]
      : [k];
    const next = { ...s, scalpPaint: [...(s.scalpPaint ?? []), ...strokes] };
    const check = parseSession({ ...next, curves: [] });
    if (!check.ok) return { session: s, message: `Nothing changed: ${check.error}.` };
    return {
      session: next,
      message: `${k.erase ? 'Erased' : 'Painted'} scalp (brush ${Math.round(k.radius * 100)} mm${cmd.mirror ? ', both sides' : ''}).`,
    };
  },
  setSymmetry(s, cmd) {
    if (JSON.stringify(cmd.plane) === JSON.stringify(s.symmetry))
      return { session: s, message: 'Mirror plane unchanged.' };
    const { symmetry: _, ...rest } = s;
    return {
      session: cmd.plane ? { ...rest, symmetry: cmd.plane } : rest,
      message: 'Mirror plane moved (new mirrored curves use it).',
    };
  },
  setReferences(s, cmd) {
    if (JSON.stringify(cmd.references) === JSON.stringify(s.references ?? []))
      return { session: s, message: `${cmd.what} (unchanged).` };
    const { references: _, ...rest } = s;
    return {
      session: cmd.references.length > 0 ? { ...rest, references: cmd.references } : rest,
      message: `${cmd.what}.`,
    };
  },
  loadSession(s, cmd) {
    return {
      session: { ...cmd.session, grid: s.grid },
      selectedId: null,
      message: `${cmd.what} (${cmd.session.curves.length} curves).`,
    };
  },
};

function applyExact(s: SessionState, cmd: Command): CommandResult {
  return (HANDLERS[cmd.kind] as (s: SessionState, cmd: Command) => CommandResult)(s, cmd);
}

function describeDetail(d: HairDetail): string {
  // a block set to 0 in the Detail panel (Flyaway share 0) is off, though present
  const on = (['curl', 'clump', 'frizz', 'flyaway'] as const).filter((b) => blockIsOn(d, b));
  if ((d.lengthJitter ?? 0) > 0) on.push('length jitter' as never);
  return on.length ? on.join(', ') : 'none';
}
