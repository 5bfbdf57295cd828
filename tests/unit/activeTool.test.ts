// The active tool: the one place a tool's update() runs (each frame, and at once when a preview
// is answered while a stroke is drawn), and a tool change cancels the tool left.
import { describe, expect, it } from 'vitest';
import { ActiveTool } from '../../web/app/activeTool';
import { Editor, type ToolName } from '../../web/editor/editor';
import { emptySession } from '../../web/model/session';
import type { Tool } from '../../web/tools/tool';

function fakeTool(name: string) {
  const calls: string[] = [];
  const tool: Tool = {
    name,
    state: 'idle',
    onPointerDown: () => true,
    onPointerMove: () => {},
    onPointerUp: () => {},
    onCancel: () => calls.push('cancel'),
    update: () => calls.push('update'),
  };
  return { tool, calls };
}

function setup() {
  const editor = new Editor(emptySession('25k'), 'stream');
  const fakes = {
    stream: fakeTool('stream'),
    select: fakeTool('select'),
    dividing: fakeTool('dividing'),
    ponytail: fakeTool('ponytail'),
    scalp: fakeTool('scalp'),
  };
  const tools = Object.fromEntries(Object.entries(fakes).map(([k, v]) => [k, v.tool])) as Record<
    ToolName,
    Tool
  >;
  const frames: Array<() => void> = [];
  const active = new ActiveTool({ editor, tools, onFrame: (h) => frames.push(h) });
  const frame = () => {
    for (const h of frames) h();
  };
  return { editor, fakes, active, frame };
}

describe('ActiveTool', () => {
  it("runs the tool's update once per frame", () => {
    const { fakes, frame } = setup();
    frame();
    frame();
    expect(fakes.stream.calls).toEqual(['update', 'update']);
  });

  it('runs it at once when a preview is answered while a stroke is drawn, only then', async () => {
    const { editor, fakes, active } = setup();
    active.previewAnswered(); // no stroke: waits for the frame
    await Promise.resolve();
    expect(fakes.stream.calls).toEqual([]);
    editor.setStroke({ points: [], viewpoint: { position: [0, 0, 5], target: [0, 0, 0] } });
    active.previewAnswered();
    active.previewAnswered(); // coalesced
    await Promise.resolve();
    expect(fakes.stream.calls).toEqual(['update']);
  });

  it('cancels the tool left when the editor changes tool', () => {
    const { editor, fakes, active } = setup();
    editor.setTool('select');
    expect(fakes.stream.calls).toEqual(['cancel']);
    expect(active.current).toBe(fakes.select.tool);
  });
});
