// The built-in bust (issue 37): one closed surface of adult proportions under the head, which
// the head's neck enters; sessions made before it keep the head alone; exports append it to the
// head's triangles.
import { describe, expect, it } from 'vitest';
import { exportHeadWithBody } from '../../web/export/exportHead';
import { buildBody } from '../../web/head/buildBody';
import { buildHead, isClosedSphere } from '../../web/head/buildHead';
import { emptySession } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionRead';

const body = buildBody();
const head = buildHead();

describe('the built-in bust', () => {
  it('is one closed surface', () => {
    expect(isClosedSphere(body)).toBe(true);
  });

  it('has shoulders about 40 cm across and reaches 25 cm below the chin', () => {
    // the chin: the lowest head vertex in front of the neck (z > 0.45, above the neck's top)
    let chin = Infinity;
    for (let v = 0; v < head.positions.length; v += 3)
      if (head.positions[v + 2] > 0.45 && head.positions[v + 1] > -1.8)
        chin = Math.min(chin, head.positions[v + 1]);
    expect(chin).toBeGreaterThan(-1.45);
    expect(chin).toBeLessThan(-1.2);
    const width = body.bounds.max[0] - body.bounds.min[0];
    expect(width).toBeGreaterThan(3.8); // world units: 10 cm
    expect(width).toBeLessThan(4.2);
    expect(chin - body.bounds.min[1]).toBeGreaterThan(2.4);
    expect(chin - body.bounds.min[1]).toBeLessThan(2.6);
  });

  it("rises inside the head's neck, so the head and its scalp are the head alone", () => {
    // its flat top (y > -1.7) lies within the head's neck, an elliptic cylinder of half-widths
    // 0.52 × 0.54 round (0, -0.22) there (headSdf.ts); the trapezius meets the neck below it
    let above = 0;
    for (let v = 0; v < body.positions.length; v += 3) {
      const [x, y, z] = [body.positions[v], body.positions[v + 1], body.positions[v + 2]];
      if (y < -1.7) continue;
      above++;
      expect(Math.hypot(x / 0.52, (z + 0.22) / 0.54)).toBeLessThan(1);
    }
    expect(above).toBeGreaterThan(0);
  });
});

describe('sessions and the bust', () => {
  it('a new session has it; one saved before it (no `bust`) reads as the head alone', () => {
    const s = emptySession('25k');
    expect(s.bust).toBe(true);
    const { bust: _, ...old } = s;
    const r = parseSession(JSON.parse(JSON.stringify(old)));
    expect(r.ok).toBe(true);
    expect(r.ok && r.value.bust).toBeFalsy();
    const back = parseSession(JSON.parse(JSON.stringify(s)));
    expect(back.ok && back.value.bust).toBe(true);
  });
});

describe('exports carry the bust after the head', () => {
  it('appends its vertices and renumbers its triangles', () => {
    const h = {
      positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]),
      indices: new Uint32Array([0, 1, 2]),
      normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1]),
    };
    const b = {
      positions: new Float32Array([5, 5, 5, 6, 5, 5, 5, 6, 5, 5, 5, 6]),
      indices: new Uint32Array([0, 2, 1, 0, 1, 3]),
      normals: new Float32Array(12).fill(1),
    };
    const m = exportHeadWithBody(h, b);
    expect([...m.indices]).toEqual([0, 1, 2, 3, 5, 4, 3, 4, 6]);
    expect([...m.positions.slice(9, 12)]).toEqual([5, 5, 5]);
    expect(m.positions.length).toBe(21);
    expect(m.normals?.length).toBe(21);
    expect(exportHeadWithBody(h, null)).toBe(h);
  });
});
