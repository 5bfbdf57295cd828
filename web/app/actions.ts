// Every command a user can give, once: id, label (the button's accessible name), what it does,
// its keyboard shortcut and when it is enabled or pressed. The toolbar, the keyboard and the
// help overlay ("?") all read this table (in the manner of tldraw's actions).
import type { ToolName } from '../editor/editor';
import type { CurveType } from '../model/session';
import type { Action } from '../ui/action';
import { DISPLAY_TOGGLES, type DisplayKey } from '../ui/displayToggles';
import type { AppViewName } from '../viewer/namedViews';
import { TIE_TOOL_KINDS, TIE_TOOLS } from './tieTools';

/** What the actions act on (the composition root provides it). */
export interface ActionTarget {
  tool(): ToolName;
  setTool(name: ToolName): void;
  canUndo(): boolean;
  canRedo(): boolean;
  undo(): void;
  redo(): void;
  hasSelection(): boolean;
  selectedKind(): CurveType | null;
  surfaceMode(): 'ruled' | 'strip' | null;
  deleteSelected(): void;
  setViewpoint(): void;
  toggleSurfaceMode(): void;
  mirror(): boolean;
  setMirror(on: boolean): void;
  toggleAvoidScalp(): void;
  avoidScalpOn(): boolean;
  toggleBust(): void;
  bustOn(): boolean;
  share(): void;
  /** "Copy embed code": an <iframe> snippet showing this session (embed.html). */
  copyEmbed(): void;
  save(): void;
  open(): void;
  /** "New": an empty head, as a new session starts (one undoable edit). */
  newSession(): void;
  /** "Styles": the style library's dialog (app/styleGallery.ts). */
  openStyles(): void;
  exportMenu(): void;
  resetView(): void;
  /** Eases the camera to a named view (viewer/namedViews.ts). */
  showView(name: AppViewName): void;
  orbitSpeed(): number;
  setOrbitSpeed(factor: number): void;
  cancel(): void;
  toggleHelp(): void;
  /** The hair's Quality setting (app/quality.ts): its button label, and the next setting.
   *  Optional: without them there is no Quality action. */
  qualityLabel?(): string;
  cycleQuality?(): void;
  toggleDetailPanel(): void;
  detailPanelOpen(): boolean;
  /** "Open head": the head file dialog. */
  openHead(): void;
  toggleHeadPanel(): void;
  headPanelOpen(): boolean;
  /** "Reference image": the picture file dialog. */
  openReference(): void;
  display(key: DisplayKey): boolean;
  setDisplay(key: DisplayKey, on: boolean): void;
  /** Plays the motion chosen beside Play, or stops the one playing (app/motionPlayer.ts). */
  toggleMotion?(): void;
}

const ORBIT_SPEEDS = [0.25, 0.5, 0.75, 1, 1.5, 2];

export function buildActions(t: ActionTarget): Action[] {
  const tool = (id: ToolName, label: string, key: string, title: string): Action => ({
    id: `tool.${id}`,
    label,
    title,
    shortcuts: [key],
    group: 'tools',
    toolbar: 'main',
    run: () => t.setTool(id),
    pressed: () => t.tool() === id,
  });
  const orbitStep = (dir: 1 | -1) => {
    const i = ORBIT_SPEEDS.findIndex((s) => s >= t.orbitSpeed() - 1e-9);
    const next = ORBIT_SPEEDS[Math.min(ORBIT_SPEEDS.length - 1, Math.max(0, i + dir))];
    t.setOrbitSpeed(next);
  };
  return [
    tool(
      'stream',
      'Stream curve',
      's',
      'Draw a stream curve starting on the scalp; on the selected curve’s supporting surface, a hint stroke edits it',
    ),
    tool(
      'dividing',
      'Dividing curve',
      'd',
      'Draw a parting on the scalp; a stroke beside the selected dividing curve tilts that side',
    ),
    tool(
      'ponytail',
      'Ponytail',
      'p',
      'Four strokes: spine from the scalp, then cross-section and two profiles',
    ),
    ...TIE_TOOL_KINDS.map((kind) => {
      const spec = TIE_TOOLS[kind];
      return tool(kind, spec.label, spec.key, spec.title);
    }),
    tool('select', 'Select', 'v', 'Select a curve; drag to orbit'),
    tool(
      'scalp',
      'Scalp brush',
      'b',
      'Paint the scalp (where hair grows) by dragging on the head; Shift+drag erases; the wheel sets the radius',
    ),
    {
      id: 'edit.undo',
      label: 'Undo',
      title: 'Undo the last edit',
      shortcuts: ['mod+z'],
      group: 'edit',
      toolbar: 'main',
      run: () => t.undo(),
      enabled: () => t.canUndo(),
    },
    {
      id: 'edit.redo',
      label: 'Redo',
      title: 'Redo what was undone',
      shortcuts: ['mod+shift+z', 'mod+y'],
      group: 'edit',
      toolbar: 'main',
      run: () => t.redo(),
      enabled: () => t.canRedo(),
    },
    {
      id: 'edit.delete',
      label: 'Delete',
      title: 'Delete the selected curve',
      shortcuts: ['delete', 'backspace'],
      group: 'edit',
      toolbar: 'main',
      // always enabled: with nothing selected it says what to do first
      run: () => t.deleteSelected(),
    },
    {
      id: 'curve.viewpoint',
      label: 'Set viewpoint',
      title:
        'Store the current camera as the selected curve’s viewpoint (its supporting surface is rebuilt)',
      group: 'curve',
      toolbar: 'more',
      run: () => t.setViewpoint(),
      enabled: () => t.hasSelection(),
    },
    {
      id: 'curve.surfaceMode',
      label: 'Surface mode',
      title:
        'Switch the selected stream curve’s supporting surface: ruled (towards its viewpoint) or strip (facing it)',
      shortcuts: ['m'],
      group: 'curve',
      toolbar: 'more',
      run: () => t.toggleSurfaceMode(),
      enabled: () => t.selectedKind() === 'stream',
      pressed: () => t.surfaceMode() === 'strip',
      stateLabel: () => {
        const m = t.surfaceMode();
        return m ? `Surface mode: ${m}` : 'Surface mode';
      },
      widestLabel: 'Surface mode: strip',
    },
    {
      id: 'curve.avoidScalp',
      label: 'Avoid scalp',
      title:
        'Turn the hair near the scalp along it (the field is solved again with scalp constraints each time the curves change); on or off',
      group: 'curve',
      toolbar: 'more',
      run: () => t.toggleAvoidScalp(),
      pressed: () => t.avoidScalpOn(),
    },
    {
      id: 'head.bust',
      label: 'Bust',
      title:
        'Show the head on a bust (neck, shoulders, the top of the chest and back): long hair rests on the shoulders and slides off them; off: the head alone',
      group: 'curve',
      toolbar: 'more',
      run: () => t.toggleBust(),
      pressed: () => t.bustOn(),
    },
    {
      id: 'file.share',
      label: 'Share link',
      title: 'Copy a link that opens this session (the address bar always holds it too)',
      group: 'file',
      toolbar: 'more',
      run: () => t.share(),
    },
    {
      id: 'file.embed',
      label: 'Copy embed code',
      title:
        'Copy an <iframe> snippet that shows this hairstyle in another page (orbit and zoom, no editing)',
      group: 'file',
      toolbar: 'more',
      run: () => t.copyEmbed(),
    },
    {
      id: 'file.save',
      label: 'Save',
      title: 'Save the session as a JSON file',
      shortcuts: ['mod+s'],
      group: 'file',
      toolbar: 'more',
      run: () => t.save(),
    },
    {
      id: 'file.open',
      label: 'Open',
      title: 'Open a session JSON file',
      shortcuts: ['mod+o'],
      group: 'file',
      toolbar: 'more',
      run: () => t.open(),
    },
    {
      id: 'file.openHead',
      label: 'Open head',
      title: 'Load your own head mesh (OBJ, glTF/GLB, PLY or STL); hair grows on its scalp',
      shortcuts: ['mod+shift+o'],
      group: 'file',
      toolbar: 'more',
      run: () => t.openHead(),
    },
    {
      id: 'file.reference',
      label: 'Reference image',
      title:
        'Open a picture (PNG, JPEG or WebP) to sketch over: shown behind the head for the current view; it stays in this browser',
      group: 'file',
      toolbar: 'more',
      run: () => t.openReference(),
    },
    {
      id: 'file.export',
      label: 'Export',
      title: 'Export the hair: USD, Cem Yuksel .hair, OBJ, glTF, or a PNG image',
      shortcuts: ['mod+e'],
      group: 'file',
      toolbar: 'more',
      run: () => t.exportMenu(),
    },
    {
      id: 'view.reset',
      label: 'Reset view',
      title: 'Bring the camera back to the starting view of the head',
      shortcuts: ['r'],
      group: 'view',
      toolbar: 'more',
      run: () => t.resetView(),
    },
    ...NAMED_VIEWS.map(
      (v): Action => ({
        id: `view.${v.name}`,
        label: v.label,
        title: v.title,
        shortcuts: [v.key],
        group: 'view',
        run: () => t.showView(v.name),
      }),
    ),
    ...(t.cycleQuality && t.qualityLabel
      ? [
          {
            id: 'view.quality',
            label: 'Quality',
            title:
              'Hair drawing quality: Auto (High on a GPU, Fast on a software renderer), Fast (lines, precomputed lighting) or High (tapered strips, deep opacity shadow maps)',
            shortcuts: ['q'],
            group: 'view',
            toolbar: 'more',
            run: () => t.cycleQuality?.(),
            stateLabel: () => t.qualityLabel?.() ?? 'Quality',
            widestLabel: 'Quality: Auto (High)',
          } satisfies Action,
        ]
      : []),
    {
      id: 'view.orbitSlower',
      label: 'Slower orbit',
      title: 'Orbit the camera more slowly per pixel dragged',
      shortcuts: ['['],
      group: 'view',
      run: () => orbitStep(-1),
    },
    {
      id: 'view.orbitFaster',
      label: 'Faster orbit',
      title: 'Orbit the camera faster per pixel dragged',
      shortcuts: [']'],
      group: 'view',
      run: () => orbitStep(1),
    },
    {
      id: 'view.motion',
      label: 'Play motion',
      title: 'Play the motion chosen beside Play, or stop it (the groom comes back)',
      shortcuts: ['shift+p'],
      group: 'view',
      run: () => t.toggleMotion?.(),
    },
    {
      id: 'view.help',
      label: 'Shortcuts',
      title: 'Show every keyboard shortcut',
      shortcuts: ['?'],
      group: 'view',
      toolbar: 'more',
      run: () => t.toggleHelp(),
    },
    {
      id: 'edit.mirror',
      label: 'Mirror',
      title:
        'Mirror editing: every new curve gets a twin across the head, and editing or deleting one does the same to the other',
      shortcuts: ['x'],
      group: 'edit',
      toolbar: 'main',
      run: () => t.setMirror(!t.mirror()),
      pressed: () => t.mirror(),
    },
    {
      id: 'view.detail',
      label: 'Detail',
      title:
        'Show or hide the Hair panel: strand count, maximum length, curl, clump, frizz, flyaways',
      shortcuts: ['h'],
      group: 'view',
      toolbar: 'more',
      run: () => t.toggleDetailPanel(),
      pressed: () => t.detailPanelOpen(),
    },
    {
      id: 'view.head',
      label: 'Head',
      title:
        'Show or hide the Head panel: open a head, rotate it, the scalp brush radius, the mirror plane',
      shortcuts: ['g'],
      group: 'view',
      toolbar: 'more',
      run: () => t.toggleHeadPanel(),
      pressed: () => t.headPanelOpen(),
    },
    {
      id: 'edit.cancel',
      label: 'Cancel',
      title: 'Abandon the stroke being drawn (and a ponytail in progress) and deselect',
      shortcuts: ['escape'],
      group: 'edit',
      run: () => t.cancel(),
    },
    ...DISPLAY_TOGGLES.map(
      ({ key, label, title }, i): Action => ({
        id: `display.${key}`,
        label,
        title,
        shortcuts: [String(i + 1)],
        group: 'display',
        run: () => t.setDisplay(key, !t.display(key)),
        pressed: () => t.display(key),
      }),
    ),
    // last in the toolbar's second row: it fits on its last line without moving the rest
    {
      id: 'file.new',
      label: 'New',
      title: 'Start again from an empty head (Undo brings the work back)',
      group: 'file',
      toolbar: 'more',
      run: () => t.newSession(),
    },
    // "Styles" sits on the toolbar's first row, where there is room (beside New it wrapped the
    // toolbar a row deeper in a 1000 px window and moved the 3D view down 30 px); on a phone,
    // whose first row is full, it is in More instead (style.css shows one of the two)
    ...(['main', 'more'] as const).map(
      (row): Action => ({
        id: row === 'main' ? 'file.styles' : 'file.styles.more',
        label: 'Styles',
        title:
          'Start from a style in the library: every stroke of it can be edited (Undo brings the work back)',
        group: 'file',
        toolbar: row,
        run: () => t.openStyles(),
      }),
    ),
  ];
}

/** The named views (the view control's buttons, ui/viewControl.ts), and their keys: Shift turns
 *  a view round to its opposite. */
export const NAMED_VIEWS: ReadonlyArray<{
  name: AppViewName;
  label: string;
  key: string;
  title: string;
}> = [
  { name: 'front', label: 'Front view', key: 'f', title: 'Look at the face, straight on' },
  { name: 'back', label: 'Back view', key: 'shift+f', title: 'Look at the back of the head' },
  { name: 'left', label: 'Left view', key: 'l', title: "The head's left side (its left ear)" },
  { name: 'right', label: 'Right view', key: 'shift+l', title: "The head's right side" },
  { name: 'top', label: 'Top view', key: 't', title: 'Look down on the crown' },
];

/** The shortcut a key event spells ('mod+shift+z', 'delete', '?', 's'…). */
export function shortcutOf(e: {
  key: string;
  ctrlKey: boolean;
  metaKey: boolean;
  shiftKey: boolean;
  altKey: boolean;
}): string | null {
  if (e.altKey) return null;
  const key = e.key.length === 1 ? e.key.toLowerCase() : e.key.toLowerCase();
  if (key === 'control' || key === 'shift' || key === 'meta' || key === 'alt') return null;
  const mod = e.ctrlKey || e.metaKey;
  // a shifted symbol ('?', '{') is its own key; Shift counts only with letters and mod
  const letter = /^[a-z]$/.test(key);
  const shift = e.shiftKey && (letter || mod) ? 'shift+' : '';
  return `${mod ? 'mod+' : ''}${shift}${key}`;
}

/** The action a shortcut runs, if any. */
export function actionForShortcut(actions: readonly Action[], shortcut: string): Action | null {
  return actions.find((a) => a.shortcuts?.includes(shortcut)) ?? null;
}
