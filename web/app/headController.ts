// Which head the app shows, sketches on and grows hair from: the session's `head` (the built-in
// mannequin or a loaded mesh named by its file's SHA-256) with the session's scalp painting over
// that head's default scalp. The session is the truth; this follows it:
//  - a new head ref: the file's bytes come from the head store (IndexedDB), are loaded and
//    turned as the ref says (loadHead.ts), and the new head goes to the viewer (same THREE.Mesh,
//    new geometry), the tools (they read `head` on every stroke) and the solver (a worker
//    restart with the new mesh). A ref whose bytes are not stored leaves the current head on
//    screen and is reported as missing until the user opens that file;
//  - new scalp strokes: the mask is recomputed (scalpPaint.ts), the head recoloured and the
//    solver sent only the mask (roots redistribute; the head's distance field is kept).
// Opening a file adds it to the store and runs one undoable `setHead` edit with the head's
// fitted symmetry plane; Rotate does the same with one more quarter turn.
// Every head shown sets the view Reset view returns to: the head framed as the built-in head is
// in the default view (viewMath.ts frameBounds); Open head, Rotate and Built-in head also ease
// the camera there once the head is on screen.

import type * as THREE from 'three';
import type { Editor } from '../editor/editor';
import type { Head } from '../head/head';
import { headFromPicked } from '../head/headFiles';
import type { HeadStore } from '../head/headStore';
import { hashHeadBytes, headRefOf, loadHeadRef } from '../head/headStore';
import { type LoadedHead, loadHeadFile } from '../head/loadHead';
import { forEachCovered, type ScalpPaintStroke, sessionScalpMask } from '../head/scalpPaint';
import { type Hairline, sessionHairline } from '../head/scalpRegion';
import { fitSymmetryPlane } from '../head/symmetryPlane';
import type { ScalpMesh } from '../model/hairArrays';
import { type MirrorPlane, reflectPoint } from '../model/mirror';
import type { Axis, HeadRef, ScalpStroke, SessionState } from '../model/session';
import { DEFAULT_CAMERA } from '../viewer/defaultCamera';
import { paintHeadTriangles, recolorHeadScalp, setHeadGeometry } from '../viewer/headMaterial';
import type { Viewer } from '../viewer/viewer';
import { frameBounds } from '../viewer/viewMath';

export interface HeadControllerDeps {
  viewer: Viewer;
  /** The displayed head (its geometry is replaced when the head changes). */
  headMesh: THREE.Mesh;
  /** The built-in bust, shown with the built-in head in sessions with `bust`. */
  bodyMesh?: THREE.Mesh;
  store: HeadStore;
  /** The solver gets a new head (worker restart) or only a new scalp mask. */
  setSolverHead(scalp: ScalpMesh): void;
  setSolverScalpMask(mask: Uint8Array): void;
  note(message: string): void;
  error(message: string): void;
  /** Long work under way (a stored head being read), and its end. */
  task(text: string): void;
  taskDone(message: string, failed?: boolean): void;
  /** The session's head is not stored: offer Open head (the Head panel). */
  offerOpenHead?(): void;
  /** After the head changed (grid fitting, overlays). */
  headChanged?(head: Head): void;
}

interface Prepared {
  head: Head;
  defaultScalp: Uint8Array;
}

const refKey = (h: SessionState['head']): string =>
  h === 'builtin'
    ? 'builtin'
    : `${h.hash}/${h.up}/${h.turns.map((t) => `${t.axis}${t.quarterTurns}`).join('')}`;

/** Turns in their shortest form: consecutive turns about one axis add up (mod 4), zero turns
 *  are dropped. */
export function addTurn(turns: readonly HeadRef['turns'][number][], axis: Axis): HeadRef['turns'] {
  const out = turns.map((t) => ({ ...t }));
  const last = out[out.length - 1];
  if (last && last.axis === axis) {
    last.quarterTurns = (last.quarterTurns + 1) % 4;
    if (last.quarterTurns === 0) out.pop();
  } else out.push({ axis, quarterTurns: 1 });
  return out;
}

export class HeadController {
  private current: Prepared;
  private key = 'builtin';
  private paint: readonly ScalpStroke[] | undefined = undefined;
  private hairline: Hairline = 'classic';
  private readonly cache = new Map<string, Prepared>();
  private generation = 0;
  private latest: SessionState | null = null;
  private switching: Promise<void> | null = null;
  private missingRef: HeadRef | null = null;
  /** The stroke being painted (its triangles shown painted before the edit is made). */
  private previewMask: Uint8Array | null = null;
  private previewPoints = 0;
  /** The head (refKey) whose arrival eases the camera to frame it (Open head, Rotate, Built-in
   *  head); null: a head that comes otherwise (undo, a file, a link) leaves the camera alone. */
  private frameOnArrival: string | null = null;

  constructor(
    builtin: Head,
    private readonly d: HeadControllerDeps,
  ) {
    this.current = { head: builtin, defaultScalp: builtin.mesh.scalp.slice() };
    this.cache.set('builtin', this.current);
  }

  /** The head strokes are drawn on and hair grows from. */
  get head(): Head {
    return this.current.head;
  }

  /** What the bounding volume must hold besides the curves: a loaded head's bounds (the
   *  built-in head: none, the default box holds it). */
  get gridBounds(): { min: [number, number, number]; max: [number, number, number] } | undefined {
    return this.key === 'builtin' ? undefined : this.current.head.mesh.bounds;
  }

  /** A head is being loaded (the test API waits for it). */
  get busy(): boolean {
    return this.switching !== null;
  }

  /** The session's head when its file is not stored (the current head stays on screen). */
  get missing(): HeadRef | null {
    return this.missingRef;
  }

  /** The built-in head's scalp for the first session (before the solver is told of any): its
   *  finished edges and strokes, on the head drawn and in the head the solver starts from. */
  startWith(s: SessionState): void {
    this.showBody(s);
    if (s.head !== 'builtin') return; // a loaded head arrives through sessionChanged
    this.paint = s.scalpPaint;
    this.hairline = sessionHairline(s);
    const { head, defaultScalp } = this.current;
    head.mesh.scalp.set(
      sessionScalpMask(head.mesh, defaultScalp, s.scalpPaint ?? [], this.hairline),
    );
    recolorHeadScalp(this.d.headMesh, head.mesh);
  }

  /** The bust goes with the built-in head in a session with `bust` (a loaded head is its own
   *  body). */
  private showBody(s: SessionState): void {
    const b = this.d.bodyMesh;
    const on = !!s.bust && s.head === 'builtin';
    if (!b || b.visible === on) return;
    b.visible = on;
    this.d.viewer.invalidateFrameCache();
  }

  /** The session changed (any edit, undo, a file, a link): follow its head and scalp. */
  sessionChanged(s: SessionState): void {
    this.latest = s;
    this.showBody(s);
    if (this.switching) return; // the switch picks up the newest session when it ends
    const key = refKey(s.head);
    if (key !== this.key) {
      const gen = ++this.generation;
      this.switching = this.switchTo(s, key, gen).finally(() => {
        this.switching = null;
        if (this.latest && this.latest !== s) this.sessionChanged(this.latest);
      });
      return;
    }
    if (s.scalpPaint !== this.paint || sessionHairline(s) !== this.hairline)
      this.applyPaint(s.scalpPaint, sessionHairline(s));
  }

  /** "Open head" from the files the user picked (a head file, or a .gltf with its .bin and
   *  textures): openFile, with its progress and outcome on the status line. */
  openHeadFiles(editor: Editor, files: readonly File[]): void {
    const first = files.find((f) => /\.(obj|gltf|glb|ply|stl)$/i.test(f.name)) ?? files[0];
    if (!first) return;
    this.d.task(`Opening the head ${first.name}…`);
    void Promise.all(files.map(async (f) => ({ name: f.name, bytes: await f.arrayBuffer() })))
      .then((picked) => {
        const h = headFromPicked(picked);
        return h.ok
          ? this.openFile(editor, h.head.name, h.head.bytes)
          : `Could not open the head: ${h.error}. The head and the session are unchanged.`;
      })
      .then(
        (m) => this.d.taskDone(m, m.startsWith('Could not')),
        (e) => this.d.taskDone(`Could not open the head: ${String(e)}.`, true),
      );
  }

  /** "Open head": reads the file, keeps it in the store and makes it the session's head (one
   *  undoable edit). A bad file changes nothing. Returns the status line's sentence. */
  async openFile(editor: Editor, name: string, bytes: ArrayBuffer): Promise<string> {
    const t0 = performance.now();
    const r = await loadHeadFile(name, bytes);
    if (!r.ok)
      return `Could not open the head: ${r.error}. The head and the session are unchanged.`;
    const hash = await hashHeadBytes(bytes);
    await this.d.store.put({ hash, name, bytes });
    const ref = headRefOf(name, hash, r.head);
    const prepared = this.prepare(r.head);
    this.remember(refKey(ref), prepared);
    const symmetry = fitSymmetryPlane(prepared.head).plane;
    const ms = Math.round(performance.now() - t0);
    // a link waiting for this very head: the session already names it
    if (this.missingRef && this.missingRef.hash === hash && this.latest) {
      const waited = refKey(this.missingRef);
      this.missingRef = null;
      this.key = '';
      this.frameWhenShown(waited);
      this.sessionChanged(this.latest);
      return `${r.head.message} — the head this session needs (${ms} ms).`;
    }
    this.frameWhenShown(refKey(ref));
    editor.run({ kind: 'setHead', head: ref, symmetry, what: `Opened head ${r.head.message}` });
    return `${r.head.message} (${ms} ms).`;
  }

  /** "Rotate": the loaded head a quarter turn about `axis` (one undoable edit). */
  rotate(editor: Editor, axis: Axis): string | null {
    const ref = editor.session.head;
    if (ref === 'builtin') return 'Rotate turns a loaded head; the built-in head is upright.';
    const next: HeadRef = { ...ref, turns: addTurn(ref.turns, axis) };
    this.frameWhenShown(refKey(next));
    editor.run({ kind: 'setHead', head: next, what: `Turned the head 90° about ${axis}` });
    return null;
  }

  /** "Fit": the loaded head's best symmetry plane again (x = 0 for the built-in head). */
  fitPlane(editor: Editor): void {
    const builtin = editor.session.head === 'builtin';
    editor.run({
      kind: 'setSymmetry',
      plane: builtin ? undefined : fitSymmetryPlane(this.current.head).plane,
    });
  }

  /** One line about the head shown, for the Head panel. */
  label(s: SessionState): string {
    if (s.head === 'builtin') return 'Built-in mannequin';
    const triangles = this.current.head.mesh.indices.length / 3;
    return `${s.head.name} · ${triangles.toLocaleString('en-US')} triangles`;
  }

  /** "Built-in head": back to the mannequin (one undoable edit). */
  useBuiltin(editor: Editor): void {
    this.frameWhenShown('builtin');
    editor.run({ kind: 'setHead', head: 'builtin', what: 'Built-in head' });
  }

  /** Shows `stroke` painted over the current scalp while it is drawn (no edit, no solve). */
  previewStroke(stroke: ScalpPaintStroke | null, mirror: MirrorPlane | null = null): void {
    const mesh = this.current.head.mesh;
    if (stroke === null) {
      // undo what the preview painted (the edit, if any, follows as a new mask)
      if (this.previewMask) {
        const back: number[] = [];
        for (let t = 0; t < mesh.scalp.length; t++)
          if (mesh.scalp[t] !== this.previewMask[t]) back.push(t);
        for (const value of [0, 1] as const)
          paintHeadTriangles(
            this.d.headMesh,
            mesh,
            back.filter((t) => this.previewMask?.[t] === value),
            value,
          );
      }
      this.previewMask = null;
      this.previewPoints = 0;
      this.d.viewer.invalidateFrameCache();
      return;
    }
    this.previewMask ??= mesh.scalp.slice();
    // points are only appended while a stroke is drawn: paint the segments not painted yet
    const from = Math.max(0, this.previewPoints - 1);
    this.previewPoints = stroke.points.length;
    const covered: number[] = [];
    const fresh = stroke.points.slice(from);
    // with Mirror, the reflected stroke too (paintScalp's mirror)
    for (const points of mirror ? [fresh, fresh.map((p) => reflectPoint(p, mirror))] : [fresh])
      forEachCovered(mesh, { ...stroke, points }, (t) => {
        covered.push(t);
      });
    if (paintHeadTriangles(this.d.headMesh, mesh, covered, stroke.erase ? 0 : 1) > 0)
      this.d.viewer.invalidateFrameCache();
  }

  private applyPaint(strokes: readonly ScalpStroke[] | undefined, hairline: Hairline): void {
    this.paint = strokes;
    this.hairline = hairline;
    this.previewMask = null;
    const { head, defaultScalp } = this.current;
    const mask = sessionScalpMask(head.mesh, defaultScalp, strokes ?? [], hairline);
    head.mesh.scalp.set(mask);
    recolorHeadScalp(this.d.headMesh, head.mesh);
    this.d.viewer.invalidateFrameCache();
    this.d.setSolverScalpMask(mask.slice());
  }

  private async switchTo(s: SessionState, key: string, gen: number): Promise<void> {
    let prepared = this.cache.get(key) ?? null;
    if (!prepared && s.head !== 'builtin') {
      const ref = s.head;
      const stored = await this.d.store.get(ref.hash);
      if (gen !== this.generation) return;
      if (!stored) {
        this.missingRef = ref;
        this.key = key; // wait for the file (openFile) rather than retry on every edit
        this.d.error(
          `This session needs the head “${ref.name}”, which this browser has not stored. Open head to load that file; until then the hair grows on the head shown.`,
        );
        this.d.offerOpenHead?.();
        return;
      }
      this.d.task(`Loading the head “${ref.name}”…`);
      const t0 = performance.now();
      const r = await loadHeadRef(ref, stored.bytes);
      if (gen !== this.generation) return;
      if (!r.ok) {
        this.key = key;
        this.d.taskDone(`The stored head “${ref.name}” could not be read: ${r.error}.`, true);
        return;
      }
      const loaded: LoadedHead = r.head;
      this.d.taskDone(`Head “${ref.name}” loaded (${Math.round(performance.now() - t0)} ms).`);
      prepared = this.prepare(loaded);
      this.remember(key, prepared);
    }
    if (!prepared) return;
    this.missingRef = null;
    this.key = key;
    this.current = prepared;
    this.previewMask = null;
    this.paint = s.scalpPaint;
    this.hairline = sessionHairline(s);
    const mask = sessionScalpMask(
      prepared.head.mesh,
      prepared.defaultScalp,
      s.scalpPaint ?? [],
      this.hairline,
    );
    prepared.head.mesh.scalp.set(mask);
    setHeadGeometry(this.d.headMesh, prepared.head.mesh);
    this.d.viewer.invalidateFrameCache();
    this.d.setSolverHead(prepared.head.scalpMesh());
    this.d.headChanged?.(prepared.head);
    this.frameHead(key);
  }

  /** The camera frames the head `key` once it is on screen (at once when it already is). */
  private frameWhenShown(key: string): void {
    this.frameOnArrival = key;
    if (key === this.key && !this.switching) this.frameHead(key);
  }

  /** Reset view's framing follows the head shown; the camera eases there when asked for. */
  private frameHead(key: string): void {
    const builtin = this.cache.get('builtin')?.head.mesh.bounds;
    const bounds = this.current.head.mesh.bounds;
    const home = builtin
      ? frameBounds(bounds, builtin, DEFAULT_CAMERA, this.d.viewer.camera.aspect)
      : DEFAULT_CAMERA;
    this.d.viewer.setHomeView(home.position, home.target);
    if (this.frameOnArrival !== key) return;
    this.frameOnArrival = null;
    this.d.viewer.resetView();
  }

  private prepare(loaded: LoadedHead): Prepared {
    return { head: loaded.head, defaultScalp: loaded.mesh.scalp.slice() };
  }

  /** Keeps the built-in head and the two most recent loaded heads (undo between them is quick). */
  private remember(key: string, p: Prepared): void {
    this.cache.delete(key);
    this.cache.set(key, p);
    for (const k of this.cache.keys()) {
      if (this.cache.size <= 3) break;
      if (k !== 'builtin' && k !== key && this.cache.get(k) !== this.current) this.cache.delete(k);
    }
  }
}
