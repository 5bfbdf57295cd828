// Lighter polylines for hair that is only glanced at (a stroke's previews): every other point of
// each strand, and always its last, so a strand keeps its root, tip and shape with about half
// the segments. The strands are grown at the paper's step all the same (S4); only what is drawn
// and lit is thinner.
import type { StrandArrays } from '../solver/protocol';

/** Points 0, 2, 4, … and the last of every strand (strands of 1 or 2 points unchanged). */
export function everyOtherPoint(s: StrandArrays): StrandArrays {
  const strands = Math.max(0, s.strandStart.length - 1);
  let kept = 0;
  for (let k = 0; k < strands; k++) kept += keptPoints(s.strandStart[k + 1] - s.strandStart[k]);
  const points = new Float32Array(3 * kept);
  const strandStart = new Uint32Array(strands + 1);
  let w = 0;
  for (let k = 0; k < strands; k++) {
    const a = s.strandStart[k];
    const n = s.strandStart[k + 1] - a;
    strandStart[k] = w;
    for (let i = 0; i < n; i++) {
      if (i % 2 === 1 && i !== n - 1) continue;
      points.set(s.points.subarray(3 * (a + i), 3 * (a + i) + 3), 3 * w);
      w++;
    }
  }
  strandStart[strands] = w;
  return { points, strandStart };
}

/** Points everyOtherPoint keeps of a strand of n points. */
function keptPoints(n: number): number {
  return n <= 2 ? Math.max(n, 0) : Math.ceil(n / 2) + (n % 2 === 0 ? 1 : 0);
}
