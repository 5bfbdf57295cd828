// The fixtures the fuzz targets' arbitraries start from (preset sessions, their links, small CLI
// problems, exports, session files), made once per run, and the arbitraries targets share.
import { createHash } from 'node:crypto';
import fc from 'fast-check';
import { presetSession } from '../../web/cli/presetSession';
import { writeExport } from '../../web/export/writeExport';
import { Head } from '../../web/head/head';
import type { StrandArrays } from '../../web/model/hairArrays';
import { PRESET_NAMES } from '../../web/model/presets';
import { quantizeSession } from '../../web/model/quantize';
import type { SessionState } from '../../web/model/session';
import { writeSessionFile } from '../../web/model/sessionFile';
import { encodeSessionLink } from '../../web/model/sessionLink';
import { pngFile } from '../support/pictureFiles';
import { type Places, placesOf } from './mutate';

// ---- the fixtures the arbitraries start from -------------------------------------------------

export interface FuzzContext {
  /** Preset sessions as the app builds them (plus one on the 100k grid with avoid scalp on, a
   *  session-wide detail and a curve's own detail), as plain JSON. */
  sessions: { name: string; json: unknown; places: Places }[];
  /** Their share links. */
  links: string[];
  /** Small valid problems for `hairsketch solve`, as JSON. */
  problems: { json: unknown; places: Places }[];
  /** A .usda and a .glb export of a small hair with each preset session. */
  exports: Uint8Array[];
  /** Saved session files (JSON) that embed reference picture files. */
  sessionFiles: { name: string; json: unknown; places: Places }[];
}

export function concat(chunks: Uint8Array[]): Uint8Array {
  let n = 0;
  for (const c of chunks) n += c.length;
  const out = new Uint8Array(n);
  let at = 0;
  for (const c of chunks) {
    out.set(c, at);
    at += c.length;
  }
  return out;
}

export async function makeContext(): Promise<FuzzContext> {
  const head = Head.builtin();
  const built: { name: string; session: SessionState }[] = PRESET_NAMES.map((name) => ({
    name,
    session: presetSession(name, head),
  }));
  const withAvoid = presetSession('fig7', head, '100k', 5000);
  built.push({
    name: 'fig7+avoidScalp+detail@100k',
    session: {
      ...withAvoid,
      hairColor: '#C0FFEE',
      avoidScalp: true,
      detail: {
        curl: { radius: 0.05, frequency: 3, start: 0.15, randomOffset: 1 },
        clump: { factor: 0.5, shape: -0.3, tipSpread: 0.02, guideDistance: 0.12 },
        frizz: { distance: 0.006, shape: 0.5 },
        lengthJitter: 0.15,
      },
      curves: withAvoid.curves.map((c, i) =>
        i === 1 ? { ...c, detail: { frizz: { distance: 0.01, shape: -1 } } } : c,
      ),
    },
  });
  // a loaded head (its reference), scalp brush strokes and a tilted mirror plane (version 3)
  const def = presetSession('default', head);
  built.push({
    name: 'default+loaded head+scalp strokes+mirror plane',
    session: quantizeSession({
      ...def,
      head: {
        kind: 'mesh',
        name: 'my head.glb',
        hash: '9f86d081884c7d659a2feaa0c55ad015a3bf4f1b2b0b822cd15d6c15b0f00a08',
        format: 'glb',
        up: 'z',
        turns: [
          { axis: 'y', quarterTurns: 1 },
          { axis: 'x', quarterTurns: 3 },
        ],
      },
      scalpPaint: [
        { erase: false, radius: 0.15, points: def.curves[0].points.slice(0, 12) },
        { erase: true, radius: 0.04, points: [def.curves[1].points[0]] },
      ],
      symmetry: { normal: [0.9986295347545738, 0.05233595624294383, 0], offset: 0.012 },
    }),
  });
  // reference pictures (one hidden, one moved) on the empty preset, so that most of the places a
  // mutation picks are theirs
  const pictures = [pngFile(4, 6, () => [255, 0, 255]), pngFile(3, 3, (x) => [x * 80, 200, 0])];
  const sha = (b: Uint8Array) => createHash('sha256').update(b).digest('hex');
  const withPictures = quantizeSession({
    ...presetSession('empty', head),
    references: [
      {
        name: 'front photo.jpg',
        hash: sha(pictures[0]),
        format: 'png',
        width: 4,
        height: 6,
        view: 'front',
        opacity: 0.6,
        scale: 3.2,
        offset: [0, 0.15],
      },
      {
        name: 'side.webp',
        hash: sha(pictures[1]),
        format: 'png',
        width: 3,
        height: 3,
        view: 'side',
        opacity: 1,
        scale: 2.5,
        offset: [-0.4, 0],
        hidden: true,
      },
    ],
  });
  built.push({ name: 'empty+reference pictures', session: withPictures });
  const fileText = await writeSessionFile(withPictures, {
    pictureBytes: new Map(
      pictures.map((b) => [sha(b), new Uint8Array(b).slice().buffer as ArrayBuffer]),
    ),
  });
  const fileJson = JSON.parse(fileText);
  const sessionFiles = [
    { name: 'session file with pictures', json: fileJson, places: placesOf(fileJson) },
  ];
  const sessions = built.map(({ name, session }) => {
    const json = JSON.parse(JSON.stringify(session));
    return { name, json, places: placesOf(json) };
  });
  const links = await Promise.all(built.map(({ session }) => encodeSessionLink(session)));
  const problems = [
    { grid: [4, 3, 2], omega: 100, steps: [{ set: [[1, 2, 1, 0, 1, 0]], unset: [] }] },
    {
      grid: [5, 5, 5],
      steps: [
        {
          set: [
            [0, 0, 0, 1, 0, 0],
            [4, 4, 4, 0, 0.5, -0.5],
          ],
        },
        { unset: [[0, 0, 0]], set: [[2, 3, 4, 1e-3, 2, 3]] },
        {},
      ],
    },
  ].map((json) => ({ json, places: placesOf(json) }));
  const strands = packStrands(
    [2, 5, 0, 1, 300].map((n, s) => Array.from({ length: 3 * n }, (_, i) => (s + 1) * 0.01 * i)),
  );
  const exports: Uint8Array[] = [];
  for (const { session } of built)
    for (const format of ['usda', 'glb'] as const)
      exports.push(concat([...writeExport(format, { strands, session, head: null })]));
  return { sessions, links, problems, exports, sessionFiles };
}

export function packStrands(strands: number[][]): StrandArrays {
  const strandStart = new Uint32Array(strands.length + 1);
  let p = 0;
  strands.forEach((s, i) => {
    p += s.length / 3;
    strandStart[i + 1] = p;
  });
  return { points: new Float32Array(strands.flat()), strandStart };
}

/** Any code points, lone surrogates included (made once: building it takes a second). */
let binaryTextArb: fc.Arbitrary<string> | null = null;
export const binaryText: fc.Arbitrary<string> = fc.constant(null).chain(() => {
  binaryTextArb ??= fc.string({ unit: 'binary', maxLength: 40 });
  return binaryTextArb;
});
