// The tool the pointer goes to, and the one place its work runs. Pointer handlers only record
// input; update() samples it, shows the draft and sets the stroke being drawn (the solver
// previews it). That work runs once per animation frame, and also as soon as the solver
// answers a preview while a stroke is drawn, so the pointer's newest samples go out as the next
// preview at once instead of at the next frame (frames are slow on a software rasteriser; the
// worker would wait).
import type { Editor, ToolName } from '../editor/editor';
import type { Tool } from '../tools/tool';

export interface ActiveToolDeps {
  editor: Editor;
  tools: Readonly<Record<ToolName, Tool>>;
  /** Runs a hook once per animation frame (the viewer). */
  onFrame(hook: () => void): void;
  /** The tool changed (camera buttons, hint line). */
  switched?(name: ToolName): void;
}

export class ActiveTool {
  private tool: Tool;
  private queued = false;

  constructor(private readonly d: ActiveToolDeps) {
    this.tool = d.tools[d.editor.tool];
    d.onFrame(() => this.update());
    d.editor.listen((c) => {
      if (c.cause === 'tool' && this.tool !== d.tools[c.tool]) this.switchTo(c.tool);
    });
  }

  get current(): Tool {
    return this.tool;
  }

  /** A stroke is in progress (the app is not idle). */
  get busy(): boolean {
    return this.tool.state !== 'idle' && this.tool.state !== 'pressed';
  }

  /** The solver answered a preview: the stroke's newest samples may go out now. */
  previewAnswered(): void {
    if (this.queued || this.d.editor.stroke === null) return;
    this.queued = true;
    queueMicrotask(() => {
      this.queued = false;
      this.update();
    });
  }

  /** Abandons what the tool is doing (Escape). */
  cancel(): void {
    this.tool.onCancel();
  }

  private update(): void {
    this.tool.update();
  }

  private switchTo(name: ToolName): void {
    this.tool.onCancel();
    this.tool = this.d.tools[name];
    this.d.switched?.(name);
  }
}
