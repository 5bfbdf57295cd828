// The view control: a small row over the 3D view (bottom left) naming the view the camera is in
// ("three-quarter front" at the start, "free" after an orbit) and a button per named view
// (Front, Left, Right, Back, Top), each running its action (app/actions.ts NAMED_VIEWS, also at
// a key each).
import type { Action } from './action';

export interface ViewControl {
  readonly element: HTMLElement;
  /** Shows the current view's name (null: a free view). */
  setLabel(name: string | null): void;
}

/** `views`: the named views' actions, in the order their buttons go. */
export function buildViewControl(stage: HTMLElement, views: readonly Action[]): ViewControl {
  const nav = document.createElement('nav');
  nav.id = 'view-control';
  nav.setAttribute('aria-label', 'Views');
  const label = document.createElement('span');
  label.className = 'view-label';
  label.dataset.testid = 'view-label';
  nav.append(label);
  for (const a of views) {
    const b = document.createElement('button');
    b.type = 'button';
    b.className = 'view-button';
    b.textContent = a.label.replace(/ view$/, '');
    b.setAttribute('aria-label', a.label);
    const key = a.shortcuts?.[0];
    b.title = key ? `${a.title} (${key.replace('shift+', 'Shift+').toUpperCase()})` : a.title;
    b.addEventListener('click', () => a.run());
    nav.append(b);
  }
  stage.append(nav);
  let shown: string | null | undefined;
  return {
    element: nav,
    setLabel(name) {
      if (name === shown) return;
      shown = name;
      label.textContent = `View: ${name ?? 'free'}`;
      nav.dataset.view = name ?? 'free';
    },
  };
}
