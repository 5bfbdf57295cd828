// The embeddable viewer (embed.html): the head and the hair of the session a link carries, with
// orbit and zoom and nothing to edit, and a link that opens the session in the editor. It uses
// the app's viewer, hair view and solver worker, and none of its editor, tools or panels. The
// worker runs single-threaded unless the page is cross-origin isolated (a framing page usually
// is not).

import { visibleStrands } from '../app/hairPresenter';
import { activeQuality, type QualitySetting } from '../app/quality';
import { Head } from '../head/head';
import { sessionScalpMask } from '../head/scalpPaint';
import { sessionHairline } from '../head/scalpRegion';
import { FIELD_OMEGA } from '../model/grid';
import { DEFAULT_BAND_COLOR, type HairLook } from '../model/hairLook';
import type { SessionState } from '../model/session';
import { sessionGrid } from '../model/session';
import { decodeSessionLink } from '../model/sessionLink';
import { tieBands } from '../model/tieBands';
import { jobOf } from '../solver/hairRequest';
import { SolverClient } from '../solver/solverClient';
import { createBodyMesh } from '../viewer/bodyMaterial';
import { setCameraButtons } from '../viewer/cameraButtons';
import { HairView } from '../viewer/hairView';
import { createHeadMesh, recolorHeadScalp, setHeadGeometry } from '../viewer/headMaterial';
import {
  BUST_VIEW_FLOOR,
  highestPoint,
  lowestPoint,
  namedView,
  type ViewName,
} from '../viewer/namedViews';
import { TieBandView } from '../viewer/tieBandView';
import { Viewer } from '../viewer/viewer';
import { editorUrlFor, parseEmbedOptions } from './embedOptions';

/** Strands the first look grows before the full hair (as the editor's first look). */
const FIRST_LOOK_STRANDS = 6000;

declare global {
  interface Window {
    /** For `hairsketch render` and tests: the view (or the still view `view` of the hair shown)
     *  as a PNG (base64), drawn as Export → PNG draws it, at the canvas's size times `scale`. */
    hairsketchEmbed?: {
      capture(scale?: number, view?: ViewName): Promise<string>;
      /** For `hairsketch render`: keeps a head file (base64) in this page's head store, where
       *  a link naming it finds it. */
      storeHead(name: string, hash: string, base64: string): Promise<void>;
      /** For `hairsketch render`'s looks: the hair shown with another colour look. */
      setLook(look: HairLook | null): void;
      /** For `hairsketch render`'s qualities: the hair drawn in another quality. */
      setQuality(quality: QualitySetting): void;
    };
  }
}

export async function startEmbed(): Promise<void> {
  const opts = parseEmbedOptions(window.location.search);
  const byId = (id: string) => document.getElementById(id) as HTMLElement;
  const status = byId('status');
  const say = (state: 'loading' | 'ready' | 'error', text: string) => {
    status.dataset.state = state;
    status.textContent = text;
  };
  const open = byId('open-editor') as HTMLAnchorElement;
  open.href = editorUrlFor(window.location.href);
  if (opts.still) document.body.classList.add('still');

  const api: NonNullable<Window['hairsketchEmbed']> = {
    capture: () => Promise.reject(new Error('no hair on screen yet')),
    storeHead: async (name, hash, base64) => {
      const { storeHeadFile } = await import('./embedHead');
      await storeHeadFile(
        name,
        hash,
        Uint8Array.from(atob(base64), (c) => c.charCodeAt(0)),
      );
    },
    setLook: () => {
      throw new Error('no hair on screen yet');
    },
    setQuality: () => {
      throw new Error('no hair on screen yet');
    },
  };
  window.hairsketchEmbed = api;
  const decoded = window.location.hash.startsWith('#s=')
    ? await decodeSessionLink(window.location.hash)
    : null;
  if (!decoded) {
    say('error', 'This page shows a hairstyle from a hairsketch link (#s=…); this one has none.');
    return;
  }
  if (!decoded.ok) {
    say('error', `Could not open the link: ${decoded.error}.`);
    return;
  }
  const s: SessionState = decoded.value;

  const viewer = new Viewer(byId('viewport') as HTMLCanvasElement);
  setCameraButtons(viewer.controls, false); // nothing to draw: the primary button orbits
  let head = Head.builtin();
  const headMesh = createHeadMesh(head.mesh);
  viewer.addHead(headMesh);
  // the bust goes with the built-in head in a session with it (a loaded head is its own body)
  const showsBody = !!s.bust && s.head === 'builtin' && head.body !== null;
  if (showsBody && head.body) {
    const body = createBodyMesh(head.body);
    body.visible = true;
    viewer.addHead(body);
  }
  let note = '';
  status.dataset.head = 'builtin'; // the head drawn: 'builtin' or the loaded head's file name
  if (s.head !== 'builtin') {
    const { storedHead } = await import('./embedHead');
    const loaded = await storedHead(s.head);
    if (typeof loaded === 'string') note = loaded;
    else {
      head = loaded.head;
      setHeadGeometry(headMesh, head.mesh);
      status.dataset.head = s.head.name;
    }
  }
  if (s.scalpPaint?.length || s.finish) {
    head.mesh.scalp.set(
      sessionScalpMask(head.mesh, head.mesh.scalp.slice(), s.scalpPaint ?? [], sessionHairline(s)),
    );
    recolorHeadScalp(headMesh, head.mesh);
  }
  const hair = new HairView(viewer, headMesh);
  hair.setQuality(activeQuality(opts.quality, viewer.software));
  hair.setLook(s.hairLook ?? null, s.hairColor);
  const bands = new TieBandView(viewer);

  let moved = false;
  viewer.controls.addEventListener('start', () => {
    moved = true;
  });
  let framed = false;
  let highest = Number.NEGATIVE_INFINITY;
  let lowest = Math.min(head.mesh.bounds.min[1], showsBody ? BUST_VIEW_FLOOR : Infinity);
  const bounds = s.head === 'builtin' ? undefined : head.mesh.bounds;
  const grid = sessionGrid(s, bounds);
  say('loading', 'Growing the hair…');
  const client = new SolverClient(
    () => new Worker(new URL('../worker/worker.ts', import.meta.url), { type: 'module' }),
    { type: 'init', grid, omega: FIELD_OMEGA, solver: 'fast', scalp: head.scalpMesh() },
    {
      onBusy: () => {},
      onResult: (r, final) => {
        if (final) {
          // the views frame the hair's top, and the shoulders too when the bust is shown
          highest = highestPoint(r.strands.points);
          lowest = Math.min(
            lowestPoint(r.strands.points, head.mesh.bounds.min[1]),
            showsBody ? BUST_VIEW_FLOOR : Infinity,
          );
        }
        if (final && !framed && !moved) {
          framed = true;
          const v = namedView(opts.view ?? 'front', lowest, highest);
          viewer.setCamera(v.position, v.target);
          viewer.setHomeView(v.position, v.target);
        }
        hair.show(
          r.strands,
          r.lighting,
          () => {
            status.dataset.strands = String(visibleStrands(r.strands));
            if (final) say('ready', note);
          },
          final,
          r.attributes ?? null,
        );
        bands.show(tieBands(s, r.strands), s.bandColor ?? DEFAULT_BAND_COLOR);
      },
      onError: (message, restarting) => {
        if (!restarting) say('error', `The hair could not be grown: ${message}.`);
      },
      onIdle: () => {},
    },
  );
  client.request(
    jobOf(s),
    'full',
    s.growth.maxStrands > 0
      ? Math.min(s.growth.maxStrands, FIRST_LOOK_STRANDS)
      : FIRST_LOOK_STRANDS,
  );

  api.setLook = (look) => hair.setLook(look, s.hairColor);
  api.setQuality = (quality) => hair.setQuality(activeQuality(quality, viewer.software));
  api.capture = async (scale = 1, view) => {
    if (view) {
      const v = namedView(view, lowest, highest);
      viewer.setCamera(v.position, v.target);
    }
    const blob = await viewer.captureImage({ scale });
    const bytes = new Uint8Array(await blob.arrayBuffer());
    let bin = '';
    for (let i = 0; i < bytes.length; i += 0x8000)
      bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
    return btoa(bin);
  };
}

/** The lowest height the hair reaches (the head's bottom when there is no hair). */
