// The stroke being drawn as transient editor state, and the solver bridge's one input: previews
// follow the stroke, a commit ends the stroke in the same change (one full solve), a stroke
// that ends without an edit brings the session's hair back, and none of it enters the undo
// history. Against a fake worker, without a browser.
import { describe, expect, it } from 'vitest';
import { SolverBridge } from '../../web/app/solverBridge';
import { ViewStore } from '../../web/app/viewState';
import type { Command } from '../../web/editor/commands';
import { Editor, type EditorChange } from '../../web/editor/editor';
import { emptySession, type Viewpoint } from '../../web/model/session';
import type { Vec3 } from '../../web/model/vec3';
import type { FromWorker, ToWorker } from '../../web/solver/protocol';

class FakeWorker {
  sent: ToWorker[] = [];
  onmessage: ((ev: MessageEvent<FromWorker>) => void) | null = null;
  onerror: ((ev: ErrorEvent) => void) | null = null;
  postMessage(m: ToWorker) {
    this.sent.push(m);
  }
  terminate() {}
  reply(m: FromWorker) {
    this.onmessage?.({ data: m } as MessageEvent<FromWorker>);
  }
  modes() {
    return this.sent.flatMap((m) => (m.type === 'solve' ? [m.mode] : []));
  }
}

const vp: Viewpoint = { position: [0, 0, 5], target: [0, 0, 0] };
const stroke = (n: number): Vec3[] =>
  Array.from({ length: n }, (_, i): Vec3 => [0.1 * i, 0.9, 0.2]);
const add = (points: Vec3[]): Command => ({
  kind: 'addCurve',
  curve: { type: 'stream', points, extend: true, viewpoint: vp },
  what: 'stream curve {id}',
});

function setup() {
  const editor = new Editor(emptySession('25k'), 'stream');
  const log: EditorChange[] = [];
  editor.listen((c) => log.push(c));
  const worker = new FakeWorker();
  const bridge = new SolverBridge(editor, {
    grid: { dims: [4, 4, 4], origin: [-1, -1, -1], step: 0.5 },
    solver: 'cg',
    scalp: {
      positions: new Float32Array(),
      indices: new Uint32Array(),
      scalp: new Uint8Array(),
      center: [0, 0, 0],
    },
    interactiveDetail: () => 1,
    shownStrands: () => 0,
    makeWorker: () => worker as unknown as Worker,
  });
  worker.reply({ type: 'ready', gridPoints: 64, roots: 0 });
  return { editor, log, worker, bridge };
}

describe('the stroke in progress', () => {
  it('is instance state: not in the session or its history', () => {
    const { editor, log } = setup();
    const before = editor.session;
    editor.setStroke({ points: stroke(4), viewpoint: vp });
    expect(editor.session).toBe(before);
    expect(editor.canUndo).toBe(false);
    expect(log.at(-1)).toMatchObject({
      cause: 'stroke',
      strokeChanged: true,
      sessionChanged: false,
    });
    editor.setStroke(null);
    expect(editor.stroke).toBeNull();
    expect(editor.canUndo).toBe(false);
  });

  it('ends with the commit that makes its curve, in the same change', () => {
    const { editor, log } = setup();
    editor.setStroke({ points: stroke(4), viewpoint: vp });
    editor.run(add(stroke(4)));
    expect(editor.stroke).toBeNull();
    expect(log.at(-1)).toMatchObject({
      cause: 'command',
      sessionChanged: true,
      strokeChanged: true,
    });
    const n = log.length;
    editor.setStroke(null); // the tool ends its stroke after the edit: nothing more to hear
    expect(log).toHaveLength(n);
  });
});

describe('the solver bridge, fed by the editor alone', () => {
  it('asks for a preview of each new stroke state, then one full solve for the commit', () => {
    const { editor, worker, bridge } = setup();
    const sent = worker.modes().length;
    editor.setStroke({ points: stroke(2), viewpoint: vp }); // not a stroke yet: nothing asked
    expect(bridge.previewing).toBe(true);
    expect(worker.modes().slice(sent)).toEqual([]);
    editor.setStroke({ points: stroke(4), viewpoint: vp });
    expect(worker.modes().slice(sent)).toEqual(['preview']);
    editor.run(add(stroke(4)));
    editor.setStroke(null);
    expect(bridge.previewing).toBe(false);
    // the preview in flight is superseded by the commit's full solve, asked for once
    expect(
      worker
        .modes()
        .slice(sent)
        .filter((m) => m === 'full'),
    ).toHaveLength(1);
  });

  it("brings the session's hair back when a previewed stroke ends without an edit", () => {
    const { editor, worker } = setup();
    const sent = worker.modes().length;
    editor.setStroke({ points: stroke(5), viewpoint: vp });
    editor.setStroke(null);
    expect(worker.modes().slice(sent)).toEqual(['preview', 'full']);
  });

  it('asks nothing when a stroke that was never previewed ends', () => {
    const { editor, worker } = setup();
    const sent = worker.modes().length;
    editor.setStroke({ points: stroke(2), viewpoint: vp });
    editor.setStroke(null);
    expect(worker.modes().slice(sent)).toEqual([]);
  });
});

describe('the view store', () => {
  it('notifies once per change, and not at all when nothing changed', () => {
    const view = new ViewStore();
    const seen: boolean[] = [];
    view.listen((c) => seen.push(c.state.mirror));
    view.update({ mirror: true });
    view.update({ mirror: true });
    view.setDisplay('field', true);
    view.setDisplay('field', true);
    expect(seen).toEqual([true, true]);
    expect(view.state.display.field).toBe(true);
  });
});
