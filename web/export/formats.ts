// The hair export formats, one row each: everything the Export menu, the app's exporter,
// writeExport and `hairsketch grow` know of a format lives here and nowhere else, but its writer:
// that is in formatWriters.ts, keyed by the same names (a compile error when one is missing), so
// the page that shows the menu does not load the writers, which run in the export worker. The
// rows' order is the menu's and the `--format` list's.

export interface ExportFormatSpec {
  /** The file name's extension, without the dot. */
  readonly extension: string;
  /** A file name with this extension means this format (`hairsketch grow --out x.glb`); false
   *  where another format has the extension first. */
  readonly byExtension: boolean;
  /** The download's name without the extension (hairstyle.usda, hairstyle-cards.glb). */
  readonly fileStem: string;
  /** The Export menu item reads `${menuName} (.${extension})` (exact accessible names: the test
   *  contract relies on them); menuTitle is its tooltip. */
  readonly menuName: string;
  readonly menuTitle: string;
  /** The format in status lines ("Export USD failed: …"). */
  readonly statusName: string;
  /** The download's MIME type. */
  readonly mime: string;
  /** Includes the head when the user has not said (the menu's checkbox indeterminate, `grow`
   *  without --with-head or --no-head). */
  readonly headByDefault: boolean;
  /** Embeds the session, so that Open and `hairsketch grow` read the export back. */
  readonly carriesSession: boolean;
  /** Reads a loaded head's own UVs (the USD groom's root UVs). */
  readonly readsHeadUv: boolean;
  /** Is cut into a chosen number of hair cards (the menu's "Card count", `grow --cards N`). */
  readonly takesCardCount: boolean;
}

const HAIRSTYLE = 'hairstyle';

export const EXPORT_FORMATS = {
  usda: {
    extension: 'usda',
    byExtension: true,
    fileStem: HAIRSTYLE,
    menuName: 'USD',
    menuTitle: 'Blender, Houdini, Unreal (via Blender → Alembic)',
    statusName: 'USD',
    mime: 'text/plain',
    headByDefault: true,
    carriesSession: true,
    readsHeadUv: true,
    takesCardCount: false,
  },
  hair: {
    extension: 'hair',
    byExtension: true,
    fileStem: HAIRSTYLE,
    menuName: 'Cem Yuksel',
    menuTitle: 'Research and offline hair renderers',
    statusName: '.hair',
    mime: 'application/octet-stream',
    headByDefault: false, // a .hair file has no meshes
    carriesSession: false,
    readsHeadUv: false,
    takesCardCount: false,
  },
  obj: {
    extension: 'obj',
    byExtension: true,
    fileStem: HAIRSTYLE,
    menuName: 'OBJ',
    menuTitle: 'Lines, one per strand: opens almost anywhere',
    statusName: 'OBJ',
    mime: 'text/plain',
    headByDefault: false,
    carriesSession: false,
    readsHeadUv: false,
    takesCardCount: false,
  },
  glb: {
    extension: 'glb',
    byExtension: true,
    fileStem: HAIRSTYLE,
    menuName: 'glTF',
    menuTitle: 'Lines with colour and width: web viewers, Blender',
    statusName: 'glTF',
    mime: 'model/gltf-binary',
    headByDefault: true,
    carriesSession: true,
    readsHeadUv: false,
    takesCardCount: false,
  },
  cards: {
    extension: 'glb',
    byExtension: false, // a .glb is the strands (glb) unless --format cards
    fileStem: `${HAIRSTYLE}-cards`,
    menuName: 'Hair cards',
    menuTitle: 'Textured cards for game engines: the count is set below',
    statusName: 'hair cards',
    mime: 'model/gltf-binary',
    headByDefault: true,
    carriesSession: true,
    readsHeadUv: false,
    takesCardCount: true,
  },
} as const satisfies Record<string, ExportFormatSpec>;

export type ExportFormat = keyof typeof EXPORT_FORMATS;

/** The motion export: the USD format's writer with the hair's points and the head's transform
 *  as time samples (export/motionExport.ts), from the Export menu (the motion chosen beside
 *  Play, 48 frames) and `hairsketch grow --motion`. Its menu item reads `Motion (USD)`. */
export const MOTION_EXPORT = {
  format: 'usda',
  fileStem: `${HAIRSTYLE}-motion`,
  menuName: 'Motion (USD)',
  menuTitle: 'The chosen motion, 2 s at 24 fps: animated hair and head for Blender, Houdini',
  statusName: 'motion USD',
} as const satisfies {
  format: ExportFormat;
  fileStem: string;
  menuName: string;
  menuTitle: string;
  statusName: string;
};

/** Every format, in the table's order. */
export const EXPORT_FORMAT_IDS = Object.keys(EXPORT_FORMATS) as readonly ExportFormat[];

/** The format's row; undefined for a name that is none (input from outside the type system). */
export function exportFormat(name: string): ExportFormatSpec | undefined {
  return Object.hasOwn(EXPORT_FORMATS, name) ? EXPORT_FORMATS[name as ExportFormat] : undefined;
}

export function isExportFormat(name: string): name is ExportFormat {
  return exportFormat(name) !== undefined;
}

/** The download's file name: `hairstyle.usda`, …, `hairstyle-cards.glb`. */
export function exportFileName(format: ExportFormat): string {
  const f = EXPORT_FORMATS[format];
  return `${f.fileStem}.${f.extension}`;
}

/** The Export menu item's label: `USD (.usda)`, …. */
export function exportMenuLabel(format: ExportFormat): string {
  const f = EXPORT_FORMATS[format];
  return `${f.menuName} (.${f.extension})`;
}

/** The formats with `flag` set, in the table's order. */
export function exportFormatsWith(
  flag: 'byExtension' | 'carriesSession' | 'takesCardCount',
): ExportFormat[] {
  return EXPORT_FORMAT_IDS.filter((f) => EXPORT_FORMATS[f][flag]);
}

/** The format of a file name by its extension (case-insensitive): .usda, .hair, .obj, .glb (the
 *  formats told by their extension); null for anything else (.usd, .usdc and .gltf included). */
export function formatFromFileName(name: string): ExportFormat | null {
  const m = /\.([A-Za-z]+)$/.exec(name.trim());
  if (!m) return null;
  const ext = m[1].toLowerCase();
  return exportFormatsWith('byExtension').find((f) => EXPORT_FORMATS[f].extension === ext) ?? null;
}

/** The distinct extensions of `formats` in words: ".usda, .hair, .obj or .glb". */
export function extensionsInWords(formats: readonly ExportFormat[]): string {
  const exts = [...new Set(formats.map((f) => `.${EXPORT_FORMATS[f].extension}`))];
  return exts.length < 2 ? exts.join('') : `${exts.slice(0, -1).join(', ')} or ${exts.at(-1)}`;
}
