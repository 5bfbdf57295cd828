// What the toolbar's and keyboard's actions do to the editor, the camera and the session's
// files: the ActionTarget of actions.ts, minus the view toggles the composition root adds.
import type { Editor } from '../editor/editor';
import type { HeadStore } from '../head/headStore';
import type { SessionState } from '../model/session';
import type { PictureStore } from '../reference/pictureStore';
import type { Viewer } from '../viewer/viewer';
import type { ActionTarget } from './actions';
import { downloadSession, type LinkWriter } from './sessionIO';
import type { StatusPresenter } from './statusPresenter';
import type { ViewStore } from './viewState';

export interface EditActionDeps {
  editor: Editor;
  viewer: Viewer;
  status: StatusPresenter;
  links: LinkWriter;
  /** Where loaded heads are kept ("Save" embeds the session's head file from here). */
  heads: HeadStore;
  /** Where reference pictures are kept ("Save" embeds the session's picture files). */
  pictures?: PictureStore;
  view: ViewStore;
  /** The lowest point (world y) the hairstyle's views must show: its hair's, or the head's
   *  bottom. */
  hairstyleLowest(): number;
  /** The hairstyle's highest point (world y), at least the head's top. */
  hairstyleHighest(): number;
  /** Abandons what the active tool is doing. */
  cancelTool(): void;
  openDialog(): void;
  /** What "New" starts from: an empty head with a new session's settings. */
  emptySession(): SessionState;
  /** The toolbar reflects a state change (e.g. "Avoid scalp" busy). */
  refresh(): void;
}

export type EditActions = Omit<
  ActionTarget,
  | 'toggleHelp'
  | 'display'
  | 'setDisplay'
  | 'exportMenu'
  | 'toggleDetailPanel'
  | 'detailPanelOpen'
  | 'openHead'
  | 'toggleHeadPanel'
  | 'headPanelOpen'
  | 'openReference'
  | 'openStyles'
>;

export function editActions(d: EditActionDeps): EditActions {
  const { editor, viewer, status } = d;
  return {
    tool: () => editor.tool,
    setTool: (name) => editor.setTool(name),
    canUndo: () => editor.canUndo,
    canRedo: () => editor.canRedo,
    undo: () => editor.undo(),
    redo: () => editor.redo(),
    hasSelection: () => editor.selectedId !== null,
    selectedKind: () => editor.selectedCurve?.type ?? null,
    surfaceMode: () => {
      const c = editor.selectedCurve;
      return c?.type === 'stream' ? (c.surfaceMode ?? 'ruled') : null;
    },
    deleteSelected: () => {
      if (editor.selectedId) editor.run({ kind: 'deleteCurve', id: editor.selectedId });
      else status.note('Select a curve first: Delete removes the selected curve.');
    },
    setViewpoint: () => {
      if (editor.selectedId)
        editor.run({
          kind: 'setViewpoint',
          id: editor.selectedId,
          viewpoint: viewer.cameraState(),
        });
    },
    toggleSurfaceMode: () => {
      const c = editor.selectedCurve;
      if (c?.type === 'stream')
        editor.run({
          kind: 'setSurfaceMode',
          id: c.id,
          mode: (c.surfaceMode ?? 'ruled') === 'ruled' ? 'strip' : 'ruled',
        });
    },
    mirror: () => d.view.state.mirror,
    setMirror: (on) => d.view.update({ mirror: on }),
    /** S4.7 as a setting of the session, an undoable edit. */
    toggleAvoidScalp: () => editor.run({ kind: 'setAvoidScalp', on: !editor.session.avoidScalp }),
    avoidScalpOn: () => !!editor.session.avoidScalp,
    toggleBust: () => editor.run({ kind: 'setBust', on: !editor.session.bust }),
    bustOn: () => !!editor.session.bust,
    share: () => void d.links.share().then((m) => status.note(m)),
    copyEmbed: () => void d.links.copyEmbed().then((m) => status.note(m)),
    save: () => {
      const n = editor.session.curves.length;
      void downloadSession(editor.session, viewer.cameraState(), d.heads, d.pictures).then((m) =>
        status.note(m ?? `Saved the session (${n} curves).`),
      );
    },
    open: () => d.openDialog(),
    newSession: () => {
      const n = editor.session.curves.length;
      // Mirror is a view setting and stays as it was: say so while it is on (fresh eyes drew a
      // bun after pigtails and got two)
      const mirror = d.view.state.mirror ? '; Mirror is on (X turns it off)' : '';
      editor.run({
        kind: 'loadSession',
        session: d.emptySession(),
        what:
          n === 0
            ? `New session: an empty head${mirror}`
            : `New session: an empty head${mirror} (Undo brings back the ${n === 1 ? 'curve' : `${n} curves`} before)`,
        resetHistory: false,
      });
    },
    resetView: () => viewer.resetView(),
    showView: (name) => viewer.showView(name, d.hairstyleLowest(), d.hairstyleHighest()),
    orbitSpeed: () => viewer.orbitSpeed,
    setOrbitSpeed: (f) => {
      viewer.setOrbitSpeed(f);
      status.note(`Orbit speed ×${f}.`);
    },
    cancel: () => {
      d.cancelTool();
      editor.select(null);
    },
  };
}
