// The "Export" menu: one item per file format (export/formats.ts: label, tooltip, whether it
// includes the head by default) and the PNG image, "Include head" (indeterminate = each format's
// default), "Transparent background" for the PNG and "Card count" for the hair cards.
import {
  CARD_COUNT_MAX,
  CARD_COUNT_MIN,
  cardCountProblem,
  DEFAULT_CARD_COUNT,
} from '../export/cardCount';
import {
  EXPORT_FORMAT_IDS,
  EXPORT_FORMATS,
  type ExportFormat,
  exportMenuLabel,
  MOTION_EXPORT,
} from '../export/formats';

export interface ExportMenuActions {
  exportFile(format: ExportFormat, withHead: boolean): void;
  /** The hair cards' count, and a change of it (a whole number in range; the Cards view uses it
   *  too). */
  cardCount(): number;
  setCardCount(n: number): void;
  /** One sentence for the status line (a card count out of range). */
  say(message: string): void;
  exportPng(transparent: boolean): void;
  /** The motion export (formats.ts MOTION_EXPORT) of the motion chosen beside Play. */
  exportMotion?(withHead: boolean): void;
}

export interface ExportMenu {
  readonly open: boolean;
  toggle(): void;
  close(): void;
}

export function buildExportMenu(anchor: HTMLElement, actions: ExportMenuActions): ExportMenu {
  const menu = document.createElement('div');
  menu.className = 'export-menu';
  menu.id = 'export-menu';
  menu.setAttribute('role', 'menu');
  menu.setAttribute('aria-label', 'Export');
  menu.hidden = true;

  const head = checkbox('Include head', 'Default: with USD and glTF, without OBJ (.hair has none)');
  head.input.indeterminate = true;
  const transparent = checkbox('Transparent background', 'For the PNG image');

  const close = () => {
    menu.hidden = true;
  };
  const item = (label: string, title: string, onClick: () => void) => {
    const b = document.createElement('button');
    b.type = 'button';
    b.setAttribute('role', 'menuitem');
    b.textContent = label;
    b.title = title;
    b.addEventListener('click', () => {
      close();
      onClick();
    });
    menu.append(b);
  };
  for (const format of EXPORT_FORMAT_IDS) {
    const f = EXPORT_FORMATS[format];
    item(exportMenuLabel(format), f.menuTitle, () =>
      actions.exportFile(format, head.input.indeterminate ? f.headByDefault : head.input.checked),
    );
  }
  const motion = actions.exportMotion;
  if (motion)
    item(MOTION_EXPORT.menuName, MOTION_EXPORT.menuTitle, () =>
      motion(head.input.indeterminate ? EXPORT_FORMATS.usda.headByDefault : head.input.checked),
    );
  // the PNG is drawn by the viewer: not an export format
  item('PNG image', 'The current view at twice the canvas resolution', () =>
    actions.exportPng(transparent.input.checked),
  );
  menu.append(
    head.label,
    transparent.label,
    cardCountField(actions.cardCount(), actions.setCardCount, actions.say),
  );
  anchor.append(menu);
  document.addEventListener('pointerdown', (e) => {
    const t = e.target as HTMLElement | null;
    if (!menu.hidden && !menu.contains(t) && !t?.closest('[data-action="file.export"]')) close();
  });
  return {
    get open() {
      return !menu.hidden;
    },
    toggle() {
      menu.hidden = !menu.hidden;
      if (!menu.hidden) (menu.querySelector('[role="menuitem"]') as HTMLElement | null)?.focus();
    },
    close,
  };
}

function checkbox(text: string, title: string) {
  const label = document.createElement('label');
  label.title = title;
  const input = document.createElement('input');
  input.type = 'checkbox';
  label.append(input, text);
  return { label, input };
}

/** "Card count": the hair cards' count; out-of-range input is put back to the last good value
 *  and said so. */
function cardCountField(
  initial: number,
  set: (n: number) => void,
  say: (message: string) => void,
): HTMLElement {
  const label = document.createElement('label');
  label.title = `Hair cards: ${CARD_COUNT_MIN}–${CARD_COUNT_MAX.toLocaleString('en-US')} (default ${DEFAULT_CARD_COUNT.toLocaleString('en-US')}); the Cards view shows the same`;
  const input = document.createElement('input');
  input.type = 'number';
  input.min = String(CARD_COUNT_MIN);
  input.max = String(CARD_COUNT_MAX);
  input.step = '100';
  input.value = String(initial);
  input.dataset.testid = 'card-count';
  let good = initial;
  input.addEventListener('change', () => {
    const n = input.value.trim() === '' ? Number.NaN : Number(input.value);
    const problem = cardCountProblem(n);
    if (problem === null) {
      good = n;
      set(n);
    } else {
      input.value = String(good);
      say(
        `The card count must be a whole number from ${CARD_COUNT_MIN} to ${CARD_COUNT_MAX.toLocaleString('en-US')}; it stays ${good.toLocaleString('en-US')}.`,
      );
    }
  });
  label.append('Card count ', input);
  return label;
}
