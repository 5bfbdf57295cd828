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
  const from = s.points;
  // copied a coordinate at a time: a subarray per point cost ~5 ms a 6,000-strand preview
  for (let k = 0; k < strands; k++) {
    const a = s.strandStart[k];
    const n = s.strandStart[k + 1] - a;
    let w = 3 * strandStart[k];
    for (let i = 0; i < n; i++)
      if (kept(i, n)) {
        const r = 3 * (a + i);
        points[w++] = from[r];
        points[w++] = from[r + 1];
        points[w++] = from[r + 2];
      }
  }
  return { points, strandStart };
}

/** Every `stride`-th point of each strand and its tip (a playing motion's strands on a slow
 *  renderer): the points kept, in order, and where each strand's start in them (and the end). */
export function everyNthPoint(
  strandStart: Uint32Array,
  stride: number,
): { points: Uint32Array; start: Uint32Array } {
  const k = Math.max(1, Math.floor(stride));
  const strands = Math.max(0, strandStart.length - 1);
  const start = new Uint32Array(strands + 1);
  let n = 0;
  for (let s = 0; s < strands; s++) {
    const len = strandStart[s + 1] - strandStart[s];
    n += len > 0 ? Math.ceil((len - 1) / k) + 1 : 0;
    start[s + 1] = n;
  }
  const points = new Uint32Array(n);
  let w = 0;
  for (let s = 0; s < strands; s++) {
    const last = strandStart[s + 1] - 1;
    if (last < strandStart[s]) continue;
    for (let i = strandStart[s]; i < last; i += k) points[w++] = i;
    points[w++] = last;
  }
  return { points, start };
}
