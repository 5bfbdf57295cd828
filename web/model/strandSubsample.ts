// Lighter polylines for hair that is only glanced at (a stroke's previews): every other point of
// each strand, and always its last, so a strand keeps its root, tip and shape with about half
// the segments. The strands are grown at the paper's step all the same (S4); only what is drawn
// and lit is thinner.
import { type StrandArrays, strandCount } from './hairArrays';

/** Whether everyOtherPoint keeps point i of a strand of n points. */
const kept = (i: number, n: number): boolean => i % 2 === 0 || i === n - 1;

/** Points 0, 2, 4, … and the last of every strand (strands of 1 or 2 points unchanged). */
export function everyOtherPoint(s: StrandArrays): StrandArrays {
  const strands = strandCount(s);
  const strandStart = new Uint32Array(strands + 1);
  for (let k = 0; k < strands; k++) {
    const n = s.strandStart[k + 1] - s.strandStart[k];
    let m = 0;
    for (let i = 0; i < n; i++) if (kept(i, n)) m++;
    strandStart[k + 1] = strandStart[k] + m;
  }
  const points = new Float32Array(3 * strandStart[strands]);
  for (let k = 0; k < strands; k++) {
    const a = s.strandStart[k];
    const n = s.strandStart[k + 1] - a;
    let w = strandStart[k];
    for (let i = 0; i < n; i++)
      if (kept(i, n)) points.set(s.points.subarray(3 * (a + i), 3 * (a + i) + 3), 3 * w++);
  }
  return { points, strandStart };
}
