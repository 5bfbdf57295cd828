// Wires "Export": the menu, file exports in their own worker (Exporter) and the PNG from the
// viewer, each after the running solve (if any) has finished, with progress on the status line.
import type { Editor } from '../editor/editor';
import { exportHeadWithBody } from '../export/exportHead';
import { MOTION_EXPORT } from '../export/formats';
import type { Head } from '../head/head';
import type { gridForSession } from '../model/grid';
import { MOTION_DEFAULT_FRAMES, type MotionName } from '../model/motion';
import type { SolverName } from '../solver/protocol';
import { buildExportMenu, type ExportMenu } from '../ui/exportMenu';
import type { Viewer } from '../viewer/viewer';
import { download, Exporter, formatBytes } from './exporter';
import type { SolverBridge } from './solverBridge';
import type { StatusPresenter } from './statusPresenter';

export interface ExportWiring {
  menu: ExportMenu;
  exporter: Exporter;
  /** An export or a PNG is being made. */
  busy(): boolean;
}

export function wireExport(d: {
  editor: Editor;
  viewer: Viewer;
  bridge: SolverBridge;
  status: StatusPresenter;
  /** The head shown (it changes with Open head). */
  head(): Head;
  /** A loaded head's bounds for the grid (undefined: the built-in head). */
  headBounds(): Parameters<typeof gridForSession>[2];
  solver: SolverName;
  anchor: HTMLElement;
  /** The hair cards' count (view state: the Cards view shows the same cards). */
  cardCount(): number;
  setCardCount(n: number): void;
  /** The motion chosen beside Play (the menu's motion export plays it). */
  motion?(): MotionName;
}): ExportWiring {
  const { status, bridge } = d;
  let png = false;
  const exporter = new Exporter({
    editor: d.editor,
    solver: d.solver,
    scalp: () => d.head().scalpMesh(),
    headBounds: () => d.headBounds(),
    head: () => {
      const h = d.head();
      const m = h.mesh;
      const s = d.editor.session;
      return exportHeadWithBody(
        { positions: m.positions, indices: m.indices, normals: m.normals },
        s.bust && s.head === 'builtin' ? h.body : null,
      );
    },
    headUv: () => {
      const m = d.head().mesh;
      return m.cornerUvs
        ? { positions: m.positions, indices: m.indices, cornerUvs: m.cornerUvs }
        : null;
    },
    solveSettled: () => bridge.whenIdle(),
    solving: () => bridge.pending,
    progress: (text) => status.task(text),
    done: (m) => status.taskDone(m),
    failed: (m) => status.taskDone(m, true),
  });
  const menu = buildExportMenu(d.anchor, {
    exportFile: (format, withHead) => void exporter.export(format, withHead, d.cardCount()),
    ...(d.motion
      ? {
          exportMotion: (withHead: boolean) =>
            void exporter.export(MOTION_EXPORT.format, withHead, undefined, {
              name: d.motion?.() ?? 'head-turn',
              frames: MOTION_DEFAULT_FRAMES,
            }),
        }
      : {}),
    cardCount: () => d.cardCount(),
    setCardCount: (n) => d.setCardCount(n),
    say: (m) => status.note(m),
    exportPng: async (transparent) => {
      if (png) return;
      png = true;
      try {
        if (bridge.pending) {
          status.task('PNG image: waiting for the solve to finish…');
          await bridge.whenIdle();
        }
        status.task('PNG image: drawing every strand…');
        const blob = await d.viewer.captureImage({ scale: 2, transparent });
        download(blob, 'hairstyle.png');
        status.taskDone(`Exported hairstyle.png (${formatBytes(blob.size)}).`);
      } catch (e) {
        status.taskDone(`PNG image failed: ${e instanceof Error ? e.message : String(e)}.`, true);
      } finally {
        png = false;
      }
    },
  });
  return { menu, exporter, busy: () => png || exporter.busy };
}
