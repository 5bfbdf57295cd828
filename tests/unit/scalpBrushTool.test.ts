import { describe, expect, it } from 'vitest';
import type { ScalpPaintStroke } from '../../web/head/scalpPaint';
import type { Vec3 } from '../../web/model/vec3';
import { ScalpBrushTool } from '../../web/tools/scalpBrushTool';

/** A head that is the screen's right half (x >= 100), one unit a pixel. */
function tool() {
  const commits: ScalpPaintStroke[] = [];
  const said: string[] = [];
  const t = new ScalpBrushTool({
    hit: (x, y) => (x >= 100 ? ([x / 100, y / 100, 0] as Vec3) : null),
    preview: () => {},
    commit: (s) => commits.push(s),
    notify: (m) => said.push(m),
  });
  return { t, commits, said };
}

describe('the scalp brush', () => {
  it('a drag that starts off the head paints from where it comes onto the head', () => {
    const { t, commits } = tool();
    expect(t.onPointerDown({ x: 50, y: 0, button: 0, shiftKey: true })).toBe(true);
    for (let x = 60; x <= 200; x += 10) t.onPointerMove({ x, y: 0, button: 0 });
    t.onPointerUp({ x: 200, y: 0, button: 0 });
    expect(commits.length).toBe(1);
    expect(commits[0].erase).toBe(true);
    // the first point is the first one on the head (x = 100), spaced by radius / 3 from there on
    expect(commits[0].points[0]).toEqual([1, 0, 0]);
    expect(commits[0].points.at(-1)?.[0]).toBeGreaterThan(1.9);
  });

  it('a drag that never comes onto the head paints nothing and says so', () => {
    const { t, commits, said } = tool();
    t.onPointerDown({ x: 10, y: 0, button: 0 });
    t.onPointerMove({ x: 60, y: 0, button: 0 });
    t.onPointerUp({ x: 90, y: 0, button: 0 });
    expect(commits.length).toBe(0);
    expect(said.join(' ')).toContain('never came onto the head');
  });
});
