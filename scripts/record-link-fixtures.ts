// Share links of every link format hairsketch has written, with the hair each reopens to, for
// tests/e2e/oldLinks.spec.ts and tests/unit/linkFixtures.test.ts.
//   npx tsx scripts/record-link-fixtures.ts links <version>   adds links of that format (1, 2, 3)
//                                                             to tests/fixtures/links.json
//   RECORD_DIST=<dir> npx tsx scripts/record-link-fixtures.ts hashes
//                                                             records each link's hairHash
// Links are made once, by the encoder of the build that wrote that format, and never again: the
// fixture is what people hold. `links 1` and `links 2` were run on the build before link
// version 3 (version 2 written, version 1's encoder kept); `links 3` on the build that writes
// version 3. RECORD_DIST (an absolute path: vite's root is web/) is a `vite build --outDir <dir>` of a build from before the links'
// format changed, so the hash is the hair the link opened to then. Every link is opened at
// `?strands=2000`, as the e2e scenes are; the link's own growth settings (no strand cap in these
// sessions) decide how many strands grow.
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { presetSession } from '../web/cli/presetSession';
import { Head } from '../web/head/head';
import { DEFAULT_HAIR_LOOK } from '../web/model/hairLook';
import { CURLY_DETAIL } from '../web/model/presetDetail';
import { quantizeSession } from '../web/model/quantize';
import type { SessionState, StyleCurve } from '../web/model/session';
import * as link from '../web/model/sessionLink';
import { openWhenHairReady, previewAndBrowser, waitServer } from './previewServer';

const FILE = 'tests/fixtures/links.json';
const STRANDS = 2000;
const PORT = Number(process.env.RECORD_PORT ?? 4198);

export interface LinkFixture {
  /** Which session (sessions below) in which link format. */
  name: string;
  format: 1 | 2 | 3;
  /** What the session exercises. */
  covers: string;
  link: string;
  strands: number;
  hairHash?: string;
}

const head = Head.builtin();

/** The paper's method with every curve kind and every setting off its default: dividing and
 *  ponytail parameters, both surface modes, extend on and off, a curve's own detail, the
 *  session's detail, avoid scalp, growth settings, colour. */
function paperEverything(): SessionState {
  const s = presetSession('fig1', head);
  let streams = 0;
  const curves = s.curves.map((c): StyleCurve => {
    if (c.type === 'dividing') return { ...c, sigma: 1.5, h: 0.75, alpha0: 0.3, alpha1: -0.2 };
    if (c.type === 'ponytail') return { ...c, tightness: 0.8 };
    if (c.type !== 'stream') return c;
    streams++;
    if (streams === 1) return { ...c, surfaceMode: 'strip' };
    if (streams === 2) return { ...c, surfaceMode: 'ruled', extend: !c.extend };
    if (streams === 3) return { ...c, detail: { frizz: { distance: 0.02, shape: 0.3 } } };
    return c;
  });
  return quantizeSession({
    ...s,
    curves,
    growth: { ...s.growth, jitter: 0.5, seed: 7, maxLength: 2.5, thetaStepDeg: 1.5 },
    hairColor: '#a0b1c2',
    avoidScalp: true,
    detail: { clump: { factor: 0.4, shape: 0.5, tipSpread: 0.01, guideDistance: 0.1 } },
  });
}

/** Natural fall with the parts of session version 3: scalp brush strokes, a mirror plane,
 *  mirrored twins, and the curly detail. */
function fallEverything(): SessionState {
  const s = presetSession('long', head);
  const streams = s.curves.filter((c) => c.type === 'stream');
  const [a, b] = [streams[0].id, streams[1].id];
  const curves = s.curves.map((c) =>
    c.id === a ? { ...c, mirror: b } : c.id === b ? { ...c, mirror: a } : c,
  );
  return quantizeSession({
    ...s,
    curves,
    detail: CURLY_DETAIL,
    scalpPaint: [
      { erase: true, radius: 0.3, points: [[0, 1.05, -0.6]] },
      {
        erase: false,
        radius: 0.15,
        points: [
          [0.6, 0.2, 0.1],
          [0.62, 0.1, 0.12],
        ],
      },
    ],
    symmetry: { normal: [1, 0, 0], offset: 0.01 },
  });
}

/** A version 1 session, as the first links held it: stored scalp-avoidance constraints. */
function versionOne(): SessionState {
  const s = presetSession('fig7', head);
  const { fall: _f, ...rest } = s;
  return {
    ...rest,
    version: 1,
    avoid: { index: [5000, 5001, 5100], target: [0, 0.3, 0, 0.3, 0, 0, 0, 0, 0.3] },
  } as unknown as SessionState;
}

/** Braids and buns (link version 3 with five curve kinds): mirrored braids behind the ears and a
 *  top bun, natural fall. */
function tailsEverything(): SessionState {
  const s = presetSession('pigtail-braids', head);
  const bun = presetSession('bun', head).curves.find((c) => c.type === 'bun');
  if (!bun) throw new Error('the bun preset has no bun');
  return quantizeSession({ ...s, curves: [...s.curves, { ...bun, id: 'bun1', height: 0.4 }] });
}

/** Sections, the bust and hair colour (link version 3): a new user's half-up (an ear-to-ear
 *  parting and a bun on the top section, ties on) over the long preset's strokes, the bust on,
 *  and every hair-colour setting off its default; without the shape rules, which are still
 *  changing, so the hair it grows stays what it was. */
function sectionsBustColour(): SessionState {
  const s = presetSession('long', head);
  const halfUp = JSON.parse(
    readFileSync('tests/fixtures/shape/half-up-into-bun.json', 'utf8'),
  ) as SessionState;
  const ties = halfUp.curves
    .filter((c) => c.type === 'dividing' || c.type === 'bun')
    .map((c, i) => ({ ...c, id: `t${i + 1}` }) as StyleCurve);
  return quantizeSession({
    ...s,
    curves: [...s.curves, ...ties],
    sections: true,
    ties: true,
    bust: true,
    hairLook: {
      ...(s.hairLook ?? DEFAULT_HAIR_LOOK),
      melanin: 0.32,
      redness: 0.8,
      grey: 20,
      tipMelanin: 0.1,
      tipLength: 1.5,
    },
  });
}

const SESSIONS: Record<string, { make: () => SessionState; covers: string; formats: number[] }> = {
  'sections-bust-colour': {
    make: sectionsBustColour,
    covers:
      'sections (an ear-to-ear parting, a bun gathering the top section, ties on), the bust, hair colour settings; natural fall, no shape rules',
    formats: [3],
  },
  'paper-everything': {
    make: paperEverything,
    covers:
      'stream (both surface modes, extend on and off, own detail), dividing and ponytail parameters, detail, avoidScalp, growth, colour; no fall',
    formats: [1, 2, 3],
  },
  'fall-everything': {
    make: fallEverything,
    covers:
      'natural fall, dividing and stream curves, mirrored twins, scalpPaint, symmetry, curly detail',
    formats: [1, 2, 3],
  },
  'tails-everything': {
    make: tailsEverything,
    covers: 'braids (mirrored twins) and a bun with its own height, natural fall',
    formats: [3],
  },
  'version-one': {
    make: versionOne,
    covers: 'a version 1 session: stored avoid constraints (opens with avoidScalp on)',
    formats: [1],
  },
};

async function encode(s: SessionState, format: number): Promise<string> {
  const api = link as unknown as Record<string, (s: SessionState) => Promise<string>>;
  if (format === 1) return api.encodeSessionLinkV1(s);
  const l = await api.encodeSessionLink(s);
  if (!l.startsWith(`s=${format}.`))
    throw new Error(`this build writes ${l.slice(0, 4)}, not version ${format}`);
  return l;
}

function load(): LinkFixture[] {
  return existsSync(FILE) ? (JSON.parse(readFileSync(FILE, 'utf8')) as LinkFixture[]) : [];
}

function save(list: LinkFixture[]) {
  writeFileSync(FILE, `${JSON.stringify(list, null, 1)}\n`);
}

async function addLinks(format: 1 | 2 | 3) {
  const list = load();
  for (const [name, def] of Object.entries(SESSIONS)) {
    if (!def.formats.includes(format)) continue;
    if (list.some((f) => f.name === name && f.format === format)) continue;
    const l = await encode(def.make(), format);
    list.push({ name, format, covers: def.covers, link: `#${l}`, strands: STRANDS });
    console.log(`${name} v${format}: ${l.length} characters`);
  }
  save(list);
}

async function recordHashes() {
  const dist = process.env.RECORD_DIST;
  if (!dist) throw new Error('RECORD_DIST=<dir> is needed');
  const list = load();
  const { server, browser } = await previewAndBrowser(dist, PORT);
  try {
    await waitServer(`http://127.0.0.1:${PORT}`);
    for (const f of list) {
      if (f.hairHash) continue;
      const page = await openWhenHairReady(
        browser,
        `http://127.0.0.1:${PORT}/?strands=${f.strands}${f.link}`,
      );
      const hash = await page.evaluate(() => window.hairsketch.hairHash());
      if (!hash) throw new Error(`${f.name} v${f.format}: no hair`);
      f.hairHash = hash;
      console.log(`${f.name} v${f.format}: hair ${hash}`);
      save(list);
      await page.close();
    }
  } finally {
    await browser.close();
    server.kill();
  }
}

const [mode, arg] = process.argv.slice(2);
if (mode === 'links' && (arg === '1' || arg === '2' || arg === '3'))
  await addLinks(Number(arg) as 1 | 2 | 3);
else if (mode === 'hashes') await recordHashes();
else {
  console.error('usage: record-link-fixtures.ts links 1|2|3, or RECORD_DIST=<dir> … hashes');
  process.exit(2);
}
