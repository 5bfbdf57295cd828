// The status line's sentence about a parting (web/model/partingReport.ts), on hand-built hair:
// roots on a unit sphere whose sections are set by which side of a plane they lie, so the
// shares are counted here independently of the code.
import { describe, expect, it } from 'vitest';
import { partingReport } from '../../web/model/partingReport';
import type { Vec3 } from '../../web/model/vec3';

function hairOn(section: (r: Vec3) => number) {
  const points: number[] = [];
  const strandStart: number[] = [0];
  const sections: number[] = [];
  for (let t = 2; t < 100; t += 3)
    for (let p = 0; p < 360; p += 3) {
      const a = (t * Math.PI) / 180;
      const b = (p * Math.PI) / 180;
      const r: Vec3 = [Math.sin(a) * Math.sin(b), Math.cos(a), Math.sin(a) * Math.cos(b)];
      points.push(...r, r[0] * 1.1, r[1] * 1.1, r[2] * 1.1);
      strandStart.push(points.length / 3);
      sections.push(section(r));
    }
  return {
    points: new Float32Array(points),
    strandStart: new Uint32Array(strandStart),
    rootSections: new Uint8Array(sections),
  };
}

/** The circle of the sphere in the plane z = d, over the top from one side to the other. */
function arc(d: number): Vec3[] {
  const r = Math.sqrt(1 - d * d);
  return Array.from({ length: 41 }, (_, i) => {
    const a = -Math.PI / 2 + (Math.PI * i) / 40;
    return [r * Math.sin(a), r * Math.cos(a), d] as Vec3;
  });
}

describe('partingReport', () => {
  it('names the two sections of an ear-to-ear parting with their shares of the hair', () => {
    const h = hairOn((r) => (r[2] > -0.3 ? 0 : 1));
    const front = h.rootSections.filter((s) => s === 0).length / h.rootSections.length;
    const m = partingReport('c1', arc(-0.3), h);
    expect(m).toBe(
      `c1 splits the scalp: front ${Math.round(100 * front)} %, back ${Math.round(100 * (1 - front))} %`,
    );
  });

  it('names a centre parting left and right', () => {
    const h = hairOn((r) => (r[0] > 0 ? 0 : 1));
    const left = h.rootSections.filter((s) => s === 0).length / h.rootSections.length;
    const line: Vec3[] = Array.from({ length: 41 }, (_, i) => {
      const a = -Math.PI / 2 + (Math.PI * i) / 40;
      return [0, Math.cos(a), Math.sin(a)] as Vec3;
    });
    expect(partingReport('c2', line, h)).toBe(
      `c2 splits the scalp: left ${Math.round(100 * left)} %, right ${Math.round(100 * (1 - left))} %`,
    );
  });

  it('says a parting that bounds nothing is a parting, and nothing without sections', () => {
    const h = hairOn(() => 0);
    expect(partingReport('c1', arc(-0.3), h)).toMatch(
      /^c1 parts the hair: a parting \(for sections to tie/,
    );
    expect(partingReport('c1', arc(-0.3), { ...h, rootSections: undefined })).toBeNull();
    expect(partingReport('c1', arc(-0.3), null)).toBeNull();
  });
});
