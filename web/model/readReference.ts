// The reader of session.references (referenceImage.ts): at most maxReferences pictures, each
// named by its file's SHA-256, a known format, a size within maxPicturePixels, a named view and
// opacity, scale and offset within their ranges. A hash appears once (one file, one picture).
import { fail } from './readFailure';
import { array, bool, fileName, int, num, record, sha256Of } from './readValues';
import {
  PICTURE_FORMATS,
  type PictureFormat,
  REFERENCE_RANGES as R,
  REFERENCE_VIEWS,
  type ReferenceImage,
  type ReferenceView,
} from './referenceImage';
import { SESSION_LIMITS as L } from './sessionLimits';
import type { Plain } from './sessionMigrations';

const FIELDS = [
  'name',
  'hash',
  'format',
  'width',
  'height',
  'view',
  'opacity',
  'scale',
  'offset',
  'hidden',
];

const oneOf = (xs: readonly string[]) => xs.map((x) => `"${x}"`).join(', ');

function reference(v: Plain | undefined, at: string): ReferenceImage {
  const o = record(v, at, FIELDS);
  const name = fileName(o.name, `${at}.name`);
  const hash = sha256Of(o.hash, `${at}.hash`);
  if (typeof o.format !== 'string' || !(PICTURE_FORMATS as readonly string[]).includes(o.format))
    fail(`${at}.format`, `must be one of ${oneOf(PICTURE_FORMATS)}`);
  const width = int(o.width, `${at}.width`, 1, L.maxPicturePixels);
  const height = int(o.height, `${at}.height`, 1, L.maxPicturePixels);
  if (width * height > L.maxPicturePixels)
    fail(
      `${at}.height`,
      `${width} × ${height} is more than ${L.maxPicturePixels / 1e6} megapixels (the cap)`,
    );
  if (typeof o.view !== 'string' || !(REFERENCE_VIEWS as readonly string[]).includes(o.view))
    fail(`${at}.view`, `must be one of ${oneOf(REFERENCE_VIEWS)}`);
  const opacity = num(o.opacity, `${at}.opacity`, R.opacity.min, R.opacity.max);
  const scale = num(o.scale, `${at}.scale`, R.scale.min, R.scale.max);
  const off = o.offset;
  if (!Array.isArray(off) || off.length !== 2) fail(`${at}.offset`, 'must be [right, up]');
  const offset: [number, number] = [
    num(off[0], `${at}.offset[0]`, R.offset.min, R.offset.max),
    num(off[1], `${at}.offset[1]`, R.offset.min, R.offset.max),
  ];
  const hidden = o.hidden === undefined ? false : bool(o.hidden, `${at}.hidden`);
  return {
    name,
    hash,
    format: o.format as PictureFormat,
    width,
    height,
    view: o.view as ReferenceView,
    opacity,
    scale,
    offset,
    ...(hidden ? { hidden: true as const } : {}),
  };
}

/** session.references: the placed pictures in order (absent or empty = none). */
export function references(v: Plain | undefined, path: string): { references?: ReferenceImage[] } {
  if (v === undefined) return {};
  const a = array(v, path, 'pictures');
  if (a.length > L.maxReferences) fail(path, `has more than ${L.maxReferences} pictures (the cap)`);
  const out: ReferenceImage[] = [];
  const seen = new Set<string>();
  for (let i = 0; i < a.length; i++) {
    const r = reference(a[i], `${path}[${i}]`);
    if (seen.has(r.hash))
      fail(`${path}[${i}].hash`, 'names the same picture file as an earlier picture');
    seen.add(r.hash);
    out.push(r);
  }
  return out.length > 0 ? { references: out } : {};
}
