// Pieces of the composition root (app.ts) that stand on their own: how the solver's news, the
// overlay keys, the starting link and the curve and Hair panels are wired.
import type { Editor } from '../editor/editor';
import type { indexedDbHeadStore } from '../head/headStore';
import { buildCurvePanel } from '../ui/curvePanel';
import { buildDetailPanel, type DetailPanel } from '../ui/detailPanel';
import type { HelpOverlay } from '../ui/helpOverlay';
import type { ActiveTool } from './activeTool';
import type { ExportWiring } from './exportActions';
import type { HairPresenter } from './hairPresenter';
import type { OverlayPresenter } from './overlayPresenter';
import type { SectionTintPresenter } from './sectionTintPresenter';
import { type LinkWriter, openSessionLinkOutcome } from './sessionIO';
import type { SolverBridge } from './solverBridge';
import type { StatusPresenter } from './statusPresenter';
import type { TieAndPartingReporter } from './tieAndPartingReporter';
import type { TieBandPresenter } from './tieBandPresenter';

/** The solver's news on screen: progress and errors in the status line, results to the hair,
 *  the section tint and the overlays, "Ready" once the converged hair is shown. */
export function showSolverResults(p: {
  bridge: SolverBridge;
  hair: HairPresenter;
  sectionTint: SectionTintPresenter;
  bands: TieBandPresenter;
  overlays: OverlayPresenter;
  status: StatusPresenter;
  active: ActiveTool;
  reports: TieAndPartingReporter;
}): void {
  const { bridge, hair, sectionTint, bands, overlays, status, active, reports } = p;
  bridge.subscribe({
    busy: (phase, fraction, previewing) => status.busy(phase, fraction, previewing),
    result: (r, final) => {
      hair.result(r, final);
      if (final) reports.hairShown(hair.strands);
      sectionTint.update();
      bands.hairShown(hair.strands);
      overlays.result(r);
      status.result(r, final);
      active.previewAnswered();
    },
    error: (m, kind, restarting) => status.solverError(m, kind, restarting),
    gridChanged: (g) => overlays.setGrid(g),
    idle: () => {
      hair.idle();
      // "Ready" once the converged hair is on screen (cached or unchanged hair: at once)
      if (!hair.awaitingFrame) status.ready();
    },
  });
  hair.onFinalShown = () => status.ready();
}

/** Escape closes the open Export menu, Escape or ? the open help overlay; whether a key did. */
export function closeOverlay(
  key: string,
  exporting: ExportWiring | null,
  help: HelpOverlay | null,
): boolean {
  if (key === 'escape' && exporting?.menu.open) {
    exporting.menu.close();
    return true;
  }
  if (!help?.open || (key !== 'escape' && key !== '?')) return false;
  help.close();
  return true;
}

/** A session link in the address bar (#s=…) opens, at the start and whenever one is pasted
 *  there; without one the address bar carries the session from the start. */
export function openStartingLink(p: {
  editor: Editor;
  status: StatusPresenter;
  links: LinkWriter;
  headStore: ReturnType<typeof indexedDbHeadStore>;
}): void {
  const { editor, status, links, headStore } = p;
  const open = (pasted: boolean) =>
    void openSessionLinkOutcome(editor, window.location.hash, headStore, pasted).then((o) => {
      // a bad link pasted over the work changes nothing: a note, not an error state
      if (o.kind === 'failed') pasted ? status.note(o.message) : status.error(o.message);
      else links.markLinked(editor.session);
    });
  if (window.location.hash.startsWith('#s=')) open(false);
  else links.schedule();
  // a link pasted into the address bar of a tab that shows the app opens too (the app writes its
  // own link with replaceState, which fires no hashchange): one undoable edit, as Open is
  window.addEventListener('hashchange', () => {
    if (window.location.hash.startsWith('#s=')) open(true);
  });
}

/** The selected curve's panel: its parameters, "Extend past the end", "Braid the tail". */
export function buildSelectedCurvePanel(
  stage: HTMLElement,
  editor: Editor,
  status: StatusPresenter,
) {
  return buildCurvePanel(
    stage,
    (id, patch) => editor.run({ kind: 'patchCurve', id, patch }),
    (m) => status.note(m),
    (id) => editor.run({ kind: 'braidTail', id }),
    (id, width) => editor.run({ kind: 'setPonytailWidth', id, width }),
  );
}

/** The Hair panel: strands, length, the whole head's and the selected curve's detail. */
export function buildHairPanel(
  stage: HTMLElement,
  editor: Editor,
  status: StatusPresenter,
): DetailPanel {
  return buildDetailPanel(stage, {
    setGrowth: (patch) => editor.run({ kind: 'setGrowth', patch }),
    setVolume: (volume) => editor.run({ kind: 'setVolume', volume }),
    lengthen: (by) => editor.run({ kind: 'lengthen', by }),
    setDetail: (curveId, detail) => editor.run({ kind: 'setDetail', curveId, detail }),
    setCurlType: (curveId, type) => editor.run({ kind: 'setCurlType', curveId, type }),
    setHairLook: (look) => editor.run({ kind: 'setHairLook', look }),
    setBandColor: (color) => editor.run({ kind: 'setBandColor', color }),
    say: (m) => status.note(m),
  });
}
