// The "?" overlay: every action with its keyboard shortcuts, read from the actions table, plus
// the pointer gestures. Closed by "?", Escape, its button or a click outside the panel.
import { type Action, type ActionGroup, displayShortcut } from './action';

const GROUP_TITLES: Record<ActionGroup, string> = {
  tools: 'Tools',
  edit: 'Edit',
  curve: 'Selected curve',
  file: 'Session',
  view: 'View',
  display: 'Display',
};

const GESTURES: ReadonlyArray<[string, string]> = [
  ['Drag from the scalp', 'draw with the active tool'],
  ['Right-drag (drawing tools) / drag (Select)', 'orbit'],
  ['Wheel', 'zoom'],
  ['Middle-drag (drawing tools) / right-drag (Select)', 'pan'],
];

export interface HelpOverlay {
  readonly open: boolean;
  toggle(): void;
  close(): void;
}

export function buildHelpOverlay(parent: HTMLElement, actions: readonly Action[]): HelpOverlay {
  const backdrop = document.createElement('div');
  backdrop.className = 'help-backdrop';
  backdrop.hidden = true;
  const panel = document.createElement('div');
  panel.className = 'help-panel';
  panel.setAttribute('role', 'dialog');
  panel.setAttribute('aria-label', 'Keyboard shortcuts');
  const h = document.createElement('h2');
  h.className = 'help-title';
  h.textContent = 'Keyboard shortcuts';
  const close = document.createElement('button');
  close.type = 'button';
  close.textContent = 'Close';
  close.className = 'help-close';
  panel.append(h, close);

  const groups = new Map<ActionGroup, Action[]>();
  for (const a of actions) {
    if (!a.shortcuts?.length) continue;
    const list = groups.get(a.group) ?? [];
    list.push(a);
    groups.set(a.group, list);
  }
  const table = document.createElement('table');
  for (const [g, list] of groups) {
    const head = table.insertRow();
    const th = document.createElement('th');
    th.colSpan = 2;
    th.textContent = GROUP_TITLES[g];
    head.append(th);
    for (const a of list) {
      const row = table.insertRow();
      const keys = row.insertCell();
      for (const s of a.shortcuts ?? []) {
        const k = document.createElement('kbd');
        k.textContent = displayShortcut(s);
        keys.append(k, ' ');
      }
      row.insertCell().textContent = `${a.label} — ${a.title}`;
    }
  }
  const gh = table.insertRow();
  const gth = document.createElement('th');
  gth.colSpan = 2;
  gth.textContent = 'Pointer';
  gh.append(gth);
  for (const [g, what] of GESTURES) {
    const row = table.insertRow();
    row.insertCell().textContent = g;
    row.insertCell().textContent = what;
  }
  panel.append(table);
  backdrop.append(panel);
  parent.append(backdrop);

  const overlay: HelpOverlay = {
    get open() {
      return !backdrop.hidden;
    },
    toggle() {
      backdrop.hidden = !backdrop.hidden;
      if (!backdrop.hidden) close.focus();
    },
    close() {
      backdrop.hidden = true;
    },
  };
  close.addEventListener('click', () => overlay.close());
  backdrop.addEventListener('pointerdown', (e) => {
    if (e.target === backdrop) overlay.close();
  });
  return overlay;
}
