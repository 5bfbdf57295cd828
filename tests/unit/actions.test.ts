// The actions table: one entry per command with unique ids and shortcuts, keys map to the right
// action (display toggles 1–6, Ctrl+Shift+Z, "?"), and running an action calls its target.
import { describe, expect, it } from 'vitest';
import {
  type ActionTarget,
  actionForShortcut,
  buildActions,
  shortcutOf,
} from '../../web/app/actions';
import { displayShortcut } from '../../web/ui/action';
import type { DisplayKey } from '../../web/ui/displayToggles';

function target() {
  const calls: string[] = [];
  const display: Record<DisplayKey, boolean> = {
    curves: true,
    constraints: false,
    surface: false,
    field: false,
    box: false,
    cards: false,
  };
  let speed = 1;
  let avoidOn = false;
  let detailOpen = false;
  let mirrorOn = false;
  const t: ActionTarget = {
    tool: () => 'select',
    setTool: (n) => calls.push(`tool:${n}`),
    canUndo: () => true,
    canRedo: () => false,
    undo: () => calls.push('undo'),
    redo: () => calls.push('redo'),
    hasSelection: () => false,
    selectedKind: () => null,
    surfaceMode: () => null,
    deleteSelected: () => calls.push('delete'),
    setViewpoint: () => calls.push('viewpoint'),
    toggleSurfaceMode: () => calls.push('surface'),
    toggleAvoidScalp: () => {
      calls.push('avoid');
      avoidOn = !avoidOn;
    },
    avoidScalpOn: () => avoidOn,
    toggleBust: () => calls.push('toggleBust'),
    bustOn: () => false,
    mirror: () => mirrorOn,
    setMirror: (on) => {
      calls.push(`mirror:${on}`);
      mirrorOn = on;
    },
    share: () => calls.push('share'),
    copyEmbed: () => calls.push('copyEmbed'),
    save: () => calls.push('save'),
    open: () => calls.push('open'),
    newSession: () => calls.push('new'),
    openStyles: () => calls.push('styles'),
    exportMenu: () => calls.push('export'),
    resetView: () => calls.push('reset'),
    showView: (name) => calls.push(`view:${name}`),
    orbitSpeed: () => speed,
    setOrbitSpeed: (f) => {
      speed = f;
    },
    cancel: () => calls.push('cancel'),
    toggleHelp: () => calls.push('help'),
    openHead: () => calls.push('openHead'),
    openReference: () => calls.push('openReference'),
    toggleHeadPanel: () => calls.push('headPanel'),
    headPanelOpen: () => false,
    toggleDetailPanel: () => {
      calls.push('detail');
      detailOpen = !detailOpen;
    },
    detailPanelOpen: () => detailOpen,
    display: (k) => display[k],
    setDisplay: (k, on) => {
      display[k] = on;
    },
  };
  return { t, calls, display, speed: () => speed };
}

const key = (k: string, mods: Partial<Record<'ctrl' | 'shift' | 'meta' | 'alt', boolean>> = {}) =>
  shortcutOf({
    key: k,
    ctrlKey: !!mods.ctrl,
    metaKey: !!mods.meta,
    shiftKey: !!mods.shift,
    altKey: !!mods.alt,
  });

describe('actions', () => {
  it('ids and shortcuts are unique; every toolbar action has a label', () => {
    const actions = buildActions(target().t);
    expect(new Set(actions.map((a) => a.id)).size).toBe(actions.length);
    const keys = actions.flatMap((a) => a.shortcuts ?? []);
    expect(new Set(keys).size).toBe(keys.length);
    for (const a of actions) if (a.toolbar) expect(a.label.length).toBeGreaterThan(0);
  });

  it('key events spell shortcuts', () => {
    expect(key('z', { ctrl: true })).toBe('mod+z');
    expect(key('Z', { ctrl: true, shift: true })).toBe('mod+shift+z');
    expect(key('z', { meta: true })).toBe('mod+z');
    expect(key('?', { shift: true })).toBe('?');
    expect(key('Delete')).toBe('delete');
    expect(key('s', { alt: true })).toBeNull();
    expect(key('Shift', { shift: true })).toBeNull();
    expect(displayShortcut('mod+shift+z')).toBe('Ctrl+Shift+Z');
  });

  it('shortcuts run their actions: tools, undo/redo, display toggles 1–6, help', () => {
    const { t, calls, display } = target();
    const actions = buildActions(t);
    const run = (s: string | null) => {
      const a = s ? actionForShortcut(actions, s) : null;
      if (!a) throw new Error(`no action for ${s}`);
      a.run();
    };
    run(key('s'));
    run(key('z', { ctrl: true }));
    run(key('Z', { ctrl: true, shift: true }));
    run(key('y', { ctrl: true }));
    run(key('?', { shift: true }));
    run(key('Escape'));
    expect(calls).toEqual(['tool:stream', 'undo', 'redo', 'redo', 'help', 'cancel']);
    for (const k of ['1', '2', '3', '4', '5', '6']) run(key(k));
    expect(display).toEqual({
      curves: false,
      constraints: true,
      surface: true,
      field: true,
      box: true,
      cards: true,
    });
    for (const k of ['0', '7', '9', 'F1'])
      expect(actionForShortcut(actions, key(k) ?? '')).toBeNull();
  });

  it('enabled and pressed follow the target; orbit speed steps within its range', () => {
    const { t, speed } = target();
    const actions = buildActions(t);
    const byId = (id: string) => actions.find((a) => a.id === id);
    expect(byId('edit.undo')?.enabled?.()).toBe(true);
    expect(byId('edit.redo')?.enabled?.()).toBe(false);
    expect(byId('tool.select')?.pressed?.()).toBe(true);
    expect(byId('curve.surfaceMode')?.stateLabel?.()).toBe('Surface mode');
    for (let i = 0; i < 10; i++) byId('view.orbitFaster')?.run();
    expect(speed()).toBe(2);
    for (let i = 0; i < 10; i++) byId('view.orbitSlower')?.run();
    expect(speed()).toBe(0.25);
  });

  it('"Avoid scalp" is a toggle: always enabled, pressed while on', () => {
    const { t, calls } = target();
    const avoid = buildActions(t).find((a) => a.label === 'Avoid scalp');
    if (!avoid) throw new Error('no Avoid scalp action');
    expect(avoid.enabled?.() ?? true).toBe(true);
    expect(avoid.pressed?.()).toBe(false);
    avoid.run();
    expect(avoid.pressed?.()).toBe(true);
    expect(avoid.enabled?.() ?? true).toBe(true); // it can be turned off again
    avoid.run();
    expect(avoid.pressed?.()).toBe(false);
    expect(calls).toEqual(['avoid', 'avoid']);
  });

  it('"h" shows and hides the Detail panel; its button is pressed while open', () => {
    const { t, calls } = target();
    const actions = buildActions(t);
    const a = actionForShortcut(actions, key('h') ?? '');
    expect(a?.label).toBe('Detail');
    a?.run();
    expect(a?.pressed?.()).toBe(true);
    a?.run();
    expect(a?.pressed?.()).toBe(false);
    expect(calls).toEqual(['detail', 'detail']);
  });

  it('named views at a key each: F front, Shift+F back, L left, Shift+L right, T top', () => {
    const { t, calls } = target();
    const actions = buildActions(t);
    for (const [k, shift] of [
      ['f', false],
      ['f', true],
      ['l', false],
      ['l', true],
      ['t', false],
    ] as const) {
      const s = key(k, { shift });
      const a = s ? actionForShortcut(actions, s) : null;
      a?.run();
    }
    expect(calls).toEqual(['view:front', 'view:back', 'view:left', 'view:right', 'view:top']);
  });

  it('"x" toggles Mirror; its button is pressed while on', () => {
    const { t, calls } = target();
    const a = actionForShortcut(buildActions(t), key('x') ?? '');
    expect(a?.label).toBe('Mirror');
    expect(a?.pressed?.()).toBe(false);
    a?.run();
    expect(a?.pressed?.()).toBe(true);
    a?.run();
    expect(calls).toEqual(['mirror:true', 'mirror:false']);
  });
});
