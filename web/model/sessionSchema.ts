// The session schema: every field a session holds, declared once with what it does to the hair
// and where a share link keeps it. The reader (sessionRead.ts), the quantiser (quantize.ts), the
// file writer (sessionFile.ts), the link codec (linkPack.ts, linkUnpack.ts), the solve options
// (curveSet.ts packHairOptions), "does this change need a solve" (needsSolve) and the hair
// cache key (curveSet.ts hairRequestKey) all follow it.
//
// Settings (SESSION_SETTINGS) are the simple fields, a flag or a number: adding a row here is
// all the session side needs: SessionState and the solver's HairOptions gain the field, the
// reader checks it (a number within [min, max], absent = the default), files and links carry it
// (a link in its JSON tail), the editor and links keep a number on its quantum's grid, and a
// setting with hair: 'request' reaches every solve, is compared by needsSolve and is part of the
// cache key. The curves' scalar parameters have their own table (curveParams.ts), the growth
// settings theirs (growthParams.ts), hair detail its own (detail.ts).

/** What a field does to the hair:
 *  'request': it is part of what every solve is asked (curves, growth, options): a change needs
 *    a solve, and the result cache tells results apart by it;
 *  'setup': it changes what the solver is set up on (head, scalp, bounding volume): the head
 *    controller and the solver bridge set it up again, then solve;
 *  false: the hair does not depend on it (the colour is drawn, the mirror plane aids editing). */
export type HairEffect = 'request' | 'setup' | false;

/** Where a share link keeps a field: a place in its binary layout, or the JSON tail that carries
 *  every field the layout has no place for (linkFormat.ts). */
export type LinkPlace = 'layout' | 'tail';

export interface FieldSpec {
  readonly hair: HairEffect;
  readonly link: LinkPlace;
}

/** A simple setting of the session. A flag: absent = false, written only when true. A number:
 *  absent = `default`, written only when it differs; accepted within [min, max] (whole numbers
 *  when `integer`), kept on a grid of `quantum` (a power of ten, or 1 for whole numbers). */
export type SettingSpec =
  | { readonly type: 'flag'; readonly hair: HairEffect }
  | {
      readonly type: 'number';
      readonly hair: HairEffect;
      readonly default: number;
      readonly min: number;
      readonly max: number;
      readonly quantum: number;
      readonly integer?: boolean;
    };

/** The session's settings, in the order a file writes them. */
export const SESSION_SETTINGS = {
  /** "Avoid scalp" (S4.7): the solver derives the avoidance constraints from the curves' field
   *  each time it solves them. */
  avoidScalp: { type: 'flag', hair: 'request' },
  /** Natural fall (hairArrays.ts HairOptions): on in every new session; off, the hair of
   *  sessions made before it (version 3 and older) exactly. */
  fall: { type: 'flag', hair: 'request' },
  /** Sections (solver-cpp/src/scalp_sections.hpp): partings split the scalp and a tie whose
   *  `section` parameter is on gathers every strand rooted in its section; on in every new
   *  session; off, every tie takes the hair that reaches it, as in sessions made before. */
  sections: { type: 'flag', hair: 'request' },
  /** Finished edges: the built-in head's natural hairline (round the ears, down to the nape), no
   *  lone hair left by an erase (head/scalpPaint.ts sessionScalpMask), and ends spread a little
   *  near a cut line (solver-cpp/src/strand_growth.hpp); on in every new session; off, the scalp
   *  and ends of sessions made before. */
  finish: { type: 'flag', hair: 'request' },
  /** A bust under the built-in head (head/bodySdf.ts: neck, shoulders, the top of the chest and
   *  back) that hair rests on and slides over; with a loaded head, the head's own mesh below the
   *  chin counts as body (solver-cpp/src/strand_growth.cpp). On in every new session; off, the
   *  head alone, as in sessions made before it. */
  bust: { type: 'flag', hair: 'request' },
  /** The shape rules (docs/natural-fall.md "Shape", solver-cpp/src/hair_fall.hpp ShapeRules): a
   *  stroke's reach of a few centimetres, hair laid on the head, length from the strokes around.
   *  On in every new session; off, the hair of sessions made before them. */
  shape: { type: 'flag', hair: 'request' },
  /** Volume (Hair panel): how far the hair stands off the head at its roots, world units (0 to
   *  3 cm), with the shape rules. */
  volume: { type: 'number', hair: 'request', default: 0.05, min: 0, max: 0.3, quantum: 0.01 },
  /** Ties from any hand (docs/braids-buns.md "Ties"): a parting that stops within 4 cm of the
   *  scalp's edge or of another parting is carried on to it; a tie's hair grows as long as its
   *  tail needs; tails taper to uneven ends under a band; a bun coils. On in every new session;
   *  off, the ties of sessions made before. */
  ties: { type: 'flag', hair: 'request' },
  /** A soft hairline (solver-cpp/src/soft_hairline.hpp): over the scalp's last centimetre the
   *  roots thin out and some grow short hairs, instead of a hard, comb-tooth edge. On in every
   *  new session; off, the roots of sessions made before. */
  hairline: { type: 'flag', hair: 'request' },
  /** Curl volume (solver-cpp/src/strand_detail.hpp "Curl volume"): curly and coily hair spreads
   *  out towards its ends, as curls stand out from the hair under them, instead of hanging as a
   *  straight curtain with a curl texture. On in every new session; off, the curls of sessions
   *  made before. */
  curlVolume: { type: 'flag', hair: 'request' },
  /** A low nape (head/scalpRegion.ts, with finished edges): the built-in head's hairline goes on
   *  down the upper neck behind the ears, as on a person, so up-styles and short backs are not
   *  cut off where the head meets the neck. On in every new session; off, the scalp of sessions
   *  made before. */
  nape: { type: 'flag', hair: 'request' },
  /** Coil volume (solver-cpp/src/strand_detail.hpp "Coil volume", with curl volume): coily hair
   *  (4A–4C) stands out from the head and up from its top, as a spring of coils does, where looser
   *  curls hang. On in every new session; off, the coils of sessions made before. */
  coilVolume: { type: 'flag', hair: 'request' },
  /** Round plaits (solver-cpp/src/gathered_tail_shapes.cpp plaitStretch): a braid's three
   *  sections stay round across their own path where they cross aslant, so its lobes read as
   *  plaited hair, not flat fins. On in every new session; off, the braids of sessions made
   *  before. */
  roundPlaits: { type: 'flag', hair: 'request' },
  /** Tie volume (solver-cpp/src/gathered_tail.hpp kTieVolume, with ties from any hand): a
   *  ponytail or bun that gathers a whole section holds its hair half as wide again, as a
   *  stylist's tails and buns do, where they were too thin for the hair they gathered. On in every
   *  new session; off, the ties of sessions made before. */
  tieVolume: { type: 'flag', hair: 'request' },
  /** Compact bun (solver-cpp/src/gathered_tail.hpp knotShape, with ties from any hand): a bun's
   *  rope wraps its own base in a round knot, each wrap a little lower and further out, every
   *  strand as long as the rope, where it spiralled out over a flat dome (a loop with a loose end
   *  round a hole, to the judges). On in every new session; off, the buns of sessions made
   *  before. */
  compactBun: { type: 'flag', hair: 'request' },
  /** Clump all (solver-cpp/src/strand_detail.hpp applyDetail's clumpAll): a strand whose path
   *  parts from its nearest clump guide's is clumped to the next nearest whose path stays with
   *  it, where it was not clumped (with curls each such strand curled on its own: a wiry halo of
   *  lone loops round long curly hair). On in every new session; off, sessions made before. */
  clumpAll: { type: 'flag', hair: 'request' },
  /** Face clear (solver-cpp/src/hair_fall.hpp ShapeRules::faceClear): with the shape rules, hair
   *  a stroke governs parts round the face too unless it follows a stroke over the face (hair
   *  at a centre part between two bang strokes hung across the eyes in the air, a veil in
   *  profile). On in every new session; off, sessions made before. */
  faceClear: { type: 'flag', hair: 'request' },
  /** Locks (solver-cpp/src/strand_detail.hpp applyDetail's locks), the rules locks 2.5 cm apart
   *  need: detail that bends strands (clumps, flyaways) keeps each within the length it grew, so
   *  the maximum length stays a maximum; a tie's tail takes its clumps without their tip spread
   *  (strands stay in their band). On in every new session and the presets with natural detail;
   *  off, sessions made before. */
  locks: { type: 'flag', hair: 'request' },
} as const satisfies Record<string, SettingSpec>;

export type SessionSettingName = keyof typeof SESSION_SETTINGS;
type SettingValue<S> = S extends { type: 'flag' } ? boolean : number;
type Settings = typeof SESSION_SETTINGS;

/** The settings as a session holds them (absent = the default). */
export type SessionSettings = {
  [K in SessionSettingName]?: SettingValue<Settings[K]>;
};

/** The settings every solve is given (hair: 'request'), defaults spelled out. */
export type SessionSettingValues = {
  [K in SessionSettingName as Settings[K]['hair'] extends 'request' ? K : never]: SettingValue<
    Settings[K]
  >;
};

export const SETTING_NAMES = Object.keys(SESSION_SETTINGS) as SessionSettingName[];

/** A setting's row, as the plain spec type. */
export const settingSpec = (k: SessionSettingName): SettingSpec => SESSION_SETTINGS[k];

/** Every field of a session, in the order the reader writes them (a file's key order). */
export const SESSION_FIELDS: Readonly<Record<string, FieldSpec>> = {
  version: { hair: false, link: 'layout' },
  head: { hair: 'setup', link: 'layout' },
  grid: { hair: 'setup', link: 'layout' },
  curves: { hair: 'request', link: 'layout' },
  growth: { hair: 'request', link: 'layout' },
  hairColor: { hair: false, link: 'layout' },
  /** The colour model (hairLook.ts); absent: hairColor is shown as it is. */
  hairLook: { hair: false, link: 'tail' },
  /** The colour of the ties' bands (tieBands.ts; absent: hairLook.ts DEFAULT_BAND_COLOR). */
  bandColor: { hair: false, link: 'tail' },
  ...Object.fromEntries(
    SETTING_NAMES.map((k) => [k, { hair: SESSION_SETTINGS[k].hair, link: 'tail' as const }]),
  ),
  detail: { hair: 'request', link: 'tail' },
  scalpPaint: { hair: 'setup', link: 'layout' },
  symmetry: { hair: false, link: 'layout' },
  /** Reference pictures (referenceImage.ts): drawn behind the head, never part of a solve. */
  references: { hair: false, link: 'tail' },
};

export const SESSION_FIELD_NAMES = Object.keys(SESSION_FIELDS);

/** The fields every solve is asked with. */
export const REQUEST_FIELDS = SESSION_FIELD_NAMES.filter(
  (k) => SESSION_FIELDS[k].hair === 'request',
);

/** Whether going from `prev` to `next` changes what the solver is asked (a change of colour or
 *  mirror plane alone does not; head and scalp changes are set up by the head controller). The
 *  editor replaces what it changes, so fields compare by identity. */
export function needsSolve(prev: object, next: object): boolean {
  const p = prev as Record<string, unknown>;
  const n = next as Record<string, unknown>;
  return REQUEST_FIELDS.some((k) => p[k] !== n[k]);
}

/** Whether going from `prev` to `next` changes anything the hair depends on (a 'request' or a
 *  'setup' field): after such a change new hair is on its way; after any other (colour, mirror
 *  plane, reference pictures) the hair shown stays the session's. */
export function changesHair(prev: object, next: object): boolean {
  const p = prev as Record<string, unknown>;
  const n = next as Record<string, unknown>;
  return SESSION_FIELD_NAMES.some((k) => SESSION_FIELDS[k].hair !== false && p[k] !== n[k]);
}

/** The settings a solve request carries, as the engine reads them (solver-cpp/src/
 *  engine_settings.hpp): one number per 'request' setting in table order, flags as 0 or 1. */
export function engineSettings(v: SessionSettingValues): Float64Array {
  const names = SETTING_NAMES.filter((k) => settingSpec(k).hair === 'request');
  const values = v as Record<string, boolean | number>;
  return Float64Array.from(names, (k) => Number(values[k]));
}

export function settingValues(s: SessionSettings): SessionSettingValues {
  const out: Record<string, boolean | number> = {};
  for (const k of SETTING_NAMES) {
    const spec = settingSpec(k);
    if (spec.hair !== 'request') continue;
    const v = s[k];
    out[k] = spec.type === 'flag' ? !!v : typeof v === 'number' ? v : spec.default;
  }
  return out as SessionSettingValues;
}
