import { describe, expect, it } from 'vitest';
import { History } from '../../web/model/history';
import {
  addCurve,
  deleteCurve,
  emptySession,
  nextCurveId,
  type StyleCurve,
} from '../../web/model/session';

const curve = (id: string): StyleCurve => ({
  id,
  type: 'stream',
  points: [
    [0, 0, 0],
    [0.1, 0, 0],
  ],
  extend: true,
  viewpoint: { position: [0, 0, 5], target: [0, 0, 0] },
});

describe('History and session edits', () => {
  it('undoes and redoes adds and deletes in order', () => {
    const s0 = emptySession('25k');
    const h = new History(s0);
    h.push(addCurve(h.current, curve(nextCurveId(h.current))));
    h.push(addCurve(h.current, curve(nextCurveId(h.current))));
    expect(h.current.curves.map((c) => c.id)).toEqual(['c1', 'c2']);
    h.push(deleteCurve(h.current, 'c1'));
    expect(h.current.curves.map((c) => c.id)).toEqual(['c2']);
    expect(h.undo()).toBe(true);
    expect(h.current.curves.map((c) => c.id)).toEqual(['c1', 'c2']);
    expect(h.undo()).toBe(true);
    expect(h.undo()).toBe(true);
    expect(h.current).toBe(s0);
    expect(h.undo()).toBe(false);
    expect(h.redo()).toBe(true);
    expect(h.current.curves.map((c) => c.id)).toEqual(['c1']);
    // A new edit clears the redo stack.
    h.push(addCurve(h.current, curve('c9')));
    expect(h.canRedo).toBe(false);
    expect(h.redo()).toBe(false);
  });

  it('records nothing for a no-op edit and keeps ids unique', () => {
    const h = new History(emptySession('25k'));
    h.push(deleteCurve(h.current, 'nope'));
    expect(h.canUndo).toBe(false);
    const s = addCurve(addCurve(h.current, curve('c1')), curve('c7'));
    expect(nextCurveId(s)).toBe('c8');
  });

  it('drops the oldest states past its limit', () => {
    const h = new History(0, 3);
    for (let i = 1; i <= 5; i++) h.push(i);
    let undos = 0;
    while (h.undo()) undos++;
    expect(undos).toBe(3);
    expect(h.current).toBe(2);
  });
});
