// The editor: the one owner of what the user is making. It holds the session history, the
// selection, the current tool and the stroke being drawn, and changes them only through
// `run(command)`, `undo`, `redo`, `select`, `setTool` and `setStroke`. Each change goes one way:
// history, then one notification to every subscriber (solver bridge, hair and overlay
// presenters, link writer, status line, UI). No DOM, no three.js: it runs as is in unit tests.
import type { PlainTieKind } from '../model/curveParams';
import { History } from '../model/history';
import type { StrokeKindName } from '../model/kinds';
import type { SessionState, StyleCurve, Viewpoint } from '../model/session';
import { findCurve } from '../model/session';
import type { Vec3 } from '../model/vec3';
import { applyCommand, type Command } from './commands';

export type ToolName = 'stream' | 'select' | 'dividing' | 'ponytail' | PlainTieKind | 'scalp';

export type ChangeCause = 'command' | 'undo' | 'redo' | 'select' | 'tool' | 'stroke';

/** The stream curve being drawn, as the hair previews it: transient instance state (as tldraw
 *  keeps its instance state), never in the undo history, the session or its links. Any change of
 *  the session ends it: the stroke was committed (or the work under it changed), and the tool
 *  sets it again with its next samples if it is still drawing. */
export interface StrokeInProgress {
  /** The stroke so far, lifted and resampled at the grid step. */
  readonly points: readonly Vec3[];
  /** The camera it is drawn from (its curve's viewpoint). */
  readonly viewpoint: Viewpoint;
  /** The curve it will make (default: a stream curve); previews solve it as that kind. */
  readonly kind?: StrokeKindName;
  /** Whether its hair grows on past its end ("Extend past the end"; default: as the session
   *  says for a new curve). */
  readonly extend?: boolean;
}

/** One change, as subscribers see it. */
export interface EditorChange {
  cause: ChangeCause;
  /** The command that caused it (cause 'command'). */
  command?: Command;
  session: SessionState;
  previous: SessionState;
  /** The session object changed (compare by identity: sessions are immutable). */
  sessionChanged: boolean;
  selectedId: string | null;
  selectionChanged: boolean;
  tool: ToolName;
  /** The stroke being drawn (null: none). */
  stroke: StrokeInProgress | null;
  strokeChanged: boolean;
  /** A sentence for the status line. */
  message: string;
  /** A loaded session's saved view, for the camera to take. */
  camera?: Viewpoint;
}

export type EditorListener = (change: EditorChange) => void;

/** Commands of the same kind on the same target within this many ms replace each other in the
 *  history (dragging the colour picker or a slider is one edit). */
const COALESCE_MS = 1500;
const COALESCING = new Set<Command['kind']>(['setHairColor', 'patchCurve']);

export class Editor {
  private readonly history: History<SessionState>;
  private selected: string | null = null;
  private currentTool: ToolName;
  private currentStroke: StrokeInProgress | null = null;
  private readonly listeners = new Set<EditorListener>();
  private lastCoalesce: { key: string; time: number } | null = null;

  constructor(
    initial: SessionState,
    tool: ToolName = 'select',
    private readonly now: () => number = () => Date.now(),
  ) {
    this.history = new History(initial);
    this.currentTool = tool;
  }

  get session(): SessionState {
    return this.history.current;
  }
  get selectedId(): string | null {
    return this.selected;
  }
  get selectedCurve(): StyleCurve | null {
    return findCurve(this.history.current, this.selected);
  }
  get tool(): ToolName {
    return this.currentTool;
  }
  get stroke(): StrokeInProgress | null {
    return this.currentStroke;
  }
  get canUndo(): boolean {
    return this.history.canUndo;
  }
  get canRedo(): boolean {
    return this.history.canRedo;
  }

  /** Subscribes to every change; returns the unsubscribe function. */
  listen(listener: EditorListener): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Runs one command: the session it makes is recorded in the history (undoable), the
   *  selection follows, and subscribers hear of it once. Returns whether the session changed. */
  run(command: Command): boolean {
    const previous = this.history.current;
    const r = applyCommand(previous, command);
    const changed = r.session !== previous;
    if (changed) {
      if (command.kind === 'loadSession' && command.resetHistory) {
        this.history.reset(r.session);
        this.lastCoalesce = null;
      } else {
        const key = coalesceKey(command);
        const t = this.now();
        if (
          key !== null &&
          this.lastCoalesce?.key === key &&
          t - this.lastCoalesce.time < COALESCE_MS &&
          this.history.canUndo
        )
          this.history.replace(r.session);
        else this.history.push(r.session);
        this.lastCoalesce = key === null ? null : { key, time: t };
      }
    }
    const before = this.selected;
    if (r.selectedId !== undefined) this.selected = r.selectedId;
    this.dropMissingSelection();
    this.emit({
      cause: 'command',
      command,
      previous,
      message: r.message,
      selectionChanged: before !== this.selected,
      camera: command.kind === 'loadSession' ? command.camera : undefined,
    });
    return changed;
  }

  undo(): boolean {
    return this.move('undo');
  }
  redo(): boolean {
    return this.move('redo');
  }

  /** Selects a curve (null: none). An id not in the session selects nothing. */
  select(id: string | null): void {
    const next = findCurve(this.history.current, id) ? id : null;
    if (next === this.selected) return;
    this.selected = next;
    const s = this.history.current;
    this.emit({
      cause: 'select',
      previous: s,
      message: next ? `Selected ${next}.` : 'Nothing selected.',
      selectionChanged: true,
    });
  }

  /** The stroke being drawn changed (null: it ended). Not an edit: nothing is recorded. */
  setStroke(stroke: StrokeInProgress | null): void {
    if (stroke === this.currentStroke) return;
    this.currentStroke = stroke;
    this.emit({
      cause: 'stroke',
      previous: this.history.current,
      message: '',
      selectionChanged: false,
      strokeChanged: true,
    });
  }

  setTool(tool: ToolName): void {
    if (tool === this.currentTool) return;
    this.currentTool = tool;
    this.emit({
      cause: 'tool',
      previous: this.history.current,
      message: '',
      selectionChanged: false,
    });
  }

  private move(cause: 'undo' | 'redo'): boolean {
    const previous = this.history.current;
    const moved = cause === 'undo' ? this.history.undo() : this.history.redo();
    if (!moved) return false;
    this.lastCoalesce = null;
    const before = this.selected;
    this.dropMissingSelection();
    this.emit({
      cause,
      previous,
      message: cause === 'undo' ? 'Undone.' : 'Redone.',
      selectionChanged: before !== this.selected,
    });
    return true;
  }

  private dropMissingSelection(): void {
    if (this.selected !== null && !findCurve(this.history.current, this.selected))
      this.selected = null;
  }

  private emit(
    c: Pick<EditorChange, 'cause' | 'command' | 'previous' | 'message' | 'selectionChanged'> & {
      camera?: Viewpoint;
      strokeChanged?: boolean;
    },
  ): void {
    const session = this.history.current;
    const sessionChanged = session !== c.previous;
    // a commit and the end of its stroke are one change (the solver hears of them once)
    const ended = sessionChanged && this.currentStroke !== null;
    if (ended) this.currentStroke = null;
    const change: EditorChange = {
      ...c,
      session,
      sessionChanged,
      selectedId: this.selected,
      tool: this.currentTool,
      stroke: this.currentStroke,
      strokeChanged: ended || !!c.strokeChanged,
    };
    for (const l of [...this.listeners]) l(change);
  }
}

function coalesceKey(c: Command): string | null {
  if (!COALESCING.has(c.kind)) return null;
  if (c.kind === 'patchCurve') return `patch:${c.id}:${Object.keys(c.patch).sort().join(',')}`;
  return c.kind;
}
