// Which reference pictures the view shows: the session's `references` (referenceImage.ts), each
// named by its file's SHA-256, with the file from the picture store (IndexedDB). The session is
// the truth; this follows it: a picture whose file is decoded is drawn (viewer/
// referencePlanes.ts); one whose file is not stored is reported as missing until the user opens
// that file. "Reference image" checks a file (pictureFile.ts, then decodes it), keeps it in the
// store and places it for the nearest named view of the camera: one undoable edit. Pictures
// change no hair: `references` is no 'request' field (sessionSchema.ts), so no edit of them
// solves or changes the cache key.
import type { Editor } from '../editor/editor';
import { sha256Hex } from '../model/bytes';
import {
  nearestView,
  newReference,
  REFERENCE_CENTRE,
  type ReferenceImage,
} from '../model/referenceImage';
import type { SessionState } from '../model/session';
import { SESSION_LIMITS as L } from '../model/sessionLimits';
import type { Vec3 } from '../model/vec3';
import { decodePicture } from '../reference/decodePicture';
import { checkPictureFile } from '../reference/pictureFile';
import type { PictureStore } from '../reference/pictureStore';
import type { ReferencePanelEvents, ReferencePanelState } from '../ui/referencePanel';
import type { ReferencePlanes } from '../viewer/referencePlanes';

export interface ReferenceControllerDeps {
  planes: ReferencePlanes;
  store: PictureStore;
  /** The camera's position and orbit target. */
  camera(): { position: Vec3; target: Vec3 };
  /** The view must be drawn again (the cached head layer included). */
  redraw(): void;
  error(message: string): void;
  /** A long task starts / ends on the status line (failed: said as an error). */
  task(message: string): void;
  taskDone(message: string, failed: boolean): void;
  /** The pictures or their state changed (the panel shows them). */
  changed(): void;
}

/** The sentence for a picture a session names that this browser has not stored. */
export function needsPictureMessage(r: { name: string }, what: 'link' | 'session'): string {
  return `This ${what} needs the picture “${r.name}”, which this browser has not stored. Reference image to load that file.`;
}

/** No pictures (one array, so that sessions without any compare equal). */
const NONE: readonly ReferenceImage[] = [];

export class ReferenceController {
  private readonly images = new Map<string, ImageBitmap>();
  private readonly loading = new Set<string>();
  private readonly missingHashes = new Set<string>();
  private refs: readonly ReferenceImage[] = NONE;
  /** The picture the panel edits (its hash), null: none. */
  selected: string | null = null;

  constructor(private readonly d: ReferenceControllerDeps) {}

  /** The session's pictures. */
  get pictures(): readonly ReferenceImage[] {
    return this.refs;
  }

  /** Pictures of the session whose files are not stored here. */
  get missing(): ReferenceImage[] {
    return this.refs.filter((r) => this.missingHashes.has(r.hash));
  }

  /** Files being read from the store or decoded. */
  get busy(): boolean {
    return this.loading.size > 0;
  }

  /** Planes drawn now (placed, shown and decoded). */
  get shown(): number {
    return this.d.planes.count;
  }

  /** The session changed: follow its pictures. */
  sessionChanged(s: SessionState): void {
    // NONE, not a fresh [], when there are none: every session edit (a stroke) comes here, and a
    // redraw drops the frame cache (a whole frame, ~70 ms on a software rasteriser, before the
    // stroke's hair can show)
    const refs = s.references ?? NONE;
    if (refs === this.refs) return;
    this.refs = refs;
    if (this.selected && !refs.some((r) => r.hash === this.selected)) this.selected = null;
    this.selected ??= refs.length > 0 ? refs[refs.length - 1].hash : null;
    for (const r of refs)
      if (!this.images.has(r.hash) && !this.loading.has(r.hash) && !this.missingHashes.has(r.hash))
        void this.fetch(r);
    this.show();
  }

  private async fetch(r: ReferenceImage): Promise<void> {
    this.loading.add(r.hash);
    this.d.changed();
    try {
      const stored = await this.d.store.get(r.hash).catch(() => null);
      if (!stored) {
        this.missingHashes.add(r.hash);
        this.d.error(needsPictureMessage(r, 'session'));
        return;
      }
      const check = checkPictureFile(new Uint8Array(stored.bytes));
      const decoded = check.ok ? await decodePicture(stored.bytes, check.value) : check;
      if (!decoded.ok) {
        this.missingHashes.add(r.hash);
        this.d.error(`The stored picture “${r.name}” could not be read: ${decoded.error}.`);
        return;
      }
      this.images.set(r.hash, decoded.image);
    } finally {
      this.loading.delete(r.hash);
      this.show();
    }
  }

  private show(): void {
    this.d.planes.show(this.refs, this.images);
    this.d.redraw();
    this.d.changed();
  }

  /** What the panel shows. */
  panelState(): ReferencePanelState {
    return {
      pictures: this.pictures,
      selected: this.selected,
      missing: this.missing.map((r) => r.hash),
      shown: this.shown,
      busy: this.busy,
    };
  }

  /** The panel's buttons and fields, acting on `editor`'s session. */
  panelEvents(
    editor: Editor,
    ui: Pick<ReferencePanelEvents, 'open' | 'say'>,
  ): ReferencePanelEvents {
    return {
      ...ui,
      select: (hash) => {
        this.selected = hash;
        this.d.changed();
      },
      placeForView: () => this.placeForView(editor),
      setHidden: (hidden) =>
        this.update(
          editor,
          { hidden: hidden || undefined },
          hidden ? 'Hid the picture' : 'Showed the picture',
        ),
      remove: () => this.remove(editor),
      patch: (patch, what) => this.update(editor, patch, what),
    };
  }

  /** The file picked with "Reference image", opened (openFile) with its progress and outcome on
   *  the status line. */
  openPickedFile(editor: Editor, file: File): void {
    this.d.task(`Opening the picture ${file.name}…`);
    void file
      .arrayBuffer()
      .then((bytes) => this.openFile(editor, file.name, bytes))
      .then(
        (m) => this.d.taskDone(m, m.startsWith('Could not')),
        (e) => this.d.taskDone(`Could not open the picture: ${String(e)}.`, true),
      );
  }

  /** "Reference image": checks the file, keeps it and places it for the camera's nearest view
   *  (one undoable edit); a file a missing picture needs fills it in. A bad file changes
   *  nothing. Returns the status line's sentence. */
  async openFile(editor: Editor, name: string, bytes: ArrayBuffer): Promise<string> {
    const refuse = (why: string) =>
      `Could not open the picture “${name}”: ${why}. Nothing changed.`;
    const check = checkPictureFile(new Uint8Array(bytes));
    if (!check.ok) return refuse(check.error);
    const decoded = await decodePicture(bytes, check.value);
    if (!decoded.ok) return refuse(decoded.error);
    const hash = await sha256Hex(bytes);
    const placed = editor.session.references ?? [];
    const had = placed.find((r) => r.hash === hash);
    if (!had && placed.length >= L.maxReferences) {
      decoded.image.close();
      return refuse(`a session holds at most ${L.maxReferences} pictures`);
    }
    await this.d.store.put({ hash, name, bytes });
    const wasMissing = this.missingHashes.delete(hash);
    this.images.get(hash)?.close();
    this.images.set(hash, decoded.image);
    this.selected = hash;
    if (had) {
      this.show();
      return wasMissing
        ? `“${had.name}” is the picture this session needs; it is shown.`
        : `“${had.name}” is placed already (for the ${had.view} view).`;
    }
    const { width, height } = decoded.image;
    const r = newReference(
      { name, hash, format: check.value.format, width, height },
      this.cameraView(),
    );
    editor.run({
      kind: 'setReferences',
      references: [...placed, r],
      what: `Placed the picture ${name} for the ${r.view} view`,
    });
    return `Placed the picture “${name}” (${width} × ${height}) for the ${r.view} view.`;
  }

  private cameraView(): ReferenceImage['view'] {
    const { position } = this.d.camera();
    const c = REFERENCE_CENTRE;
    return nearestView([position[0] - c[0], position[1] - c[1], position[2] - c[2]]);
  }

  /** Changes the selected picture (one undoable edit). */
  update(editor: Editor, patch: Partial<ReferenceImage>, what: string): void {
    const hash = this.selected;
    const refs = editor.session.references ?? [];
    if (!hash || !refs.some((r) => r.hash === hash)) return;
    editor.run({
      kind: 'setReferences',
      references: refs.map((r) => (r.hash === hash ? withPatch(r, patch) : r)),
      what,
    });
  }

  /** "Place for this view": the selected picture faces the camera's nearest view. */
  placeForView(editor: Editor): void {
    const view = this.cameraView();
    this.update(editor, { view }, `Placed the picture for the ${view} view`);
  }

  /** "Remove": the selected picture leaves the session (its file stays stored). */
  remove(editor: Editor): void {
    const hash = this.selected;
    const refs = editor.session.references ?? [];
    const r = refs.find((x) => x.hash === hash);
    if (!r) return;
    editor.run({
      kind: 'setReferences',
      references: refs.filter((x) => x !== r),
      what: `Removed the picture ${r.name}`,
    });
  }
}

function withPatch(r: ReferenceImage, patch: Partial<ReferenceImage>): ReferenceImage {
  const { hidden: _, ...rest } = { ...r, ...patch };
  const hidden = 'hidden' in patch ? patch.hidden : r.hidden;
  return hidden ? { ...rest, hidden: true } : rest;
}
