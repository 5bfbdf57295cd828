// What the toolbar, the help overlay and the view control show of a command: its label, tooltip,
// shortcuts and state. The app's table of commands (app/actions.ts) is made of these.

export type ActionGroup = 'tools' | 'curve' | 'edit' | 'file' | 'view' | 'display';

export interface Action {
  id: string;
  /** Button label and accessible name. */
  label: string;
  /** What it does (tooltip and help overlay). */
  title: string;
  /** Shortcuts: 's', 'mod+z', 'mod+shift+z', 'delete', '?', '1'… ('mod' is Ctrl or ⌘). */
  shortcuts?: readonly string[];
  group: ActionGroup;
  /** Where the toolbar shows it: 'main' (always), 'more' (in the overflow menu on narrow
   *  screens), or not at all (keyboard only, or drawn by its own control). */
  toolbar?: 'main' | 'more';
  run(): void;
  enabled?(): boolean;
  /** For toggles and tools: whether it is on now. */
  pressed?(): boolean;
  /** A label that shows state (e.g. which surface mode is on); the accessible name still
   *  starts with `label`. */
  stateLabel?(): string;
  /** Its widest state label: the toolbar keeps the button that wide, so a state change (a curve
   *  selected) never reflows the toolbar and moves the 3D view under the pointer. */
  widestLabel?: string;
}

/** How a shortcut reads in the help overlay and tooltips ('Ctrl+Shift+Z'). */
export function displayShortcut(s: string): string {
  return s
    .split('+')
    .map((p) =>
      p === 'mod' ? 'Ctrl' : p.length === 1 ? p.toUpperCase() : p[0].toUpperCase() + p.slice(1),
    )
    .join('+');
}
