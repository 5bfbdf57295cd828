// The hair's optical depth towards the light, for any point, from one pass over the hair's box
// (hairLightingContext.ts): the grid's σ·h is resampled onto columns parallel to the light (a
// lattice sheared along it: plane by plane across the axis m where the light is longest, each
// plane's samples shifted by the light's slope), and each column is summed from the light's
// side. The depth from a point is then one trilinear look-up of those sums, at the column through
// the point and the plane where the counted part of its ray begins. Like a march of one sample
// per plane along every ray, interpolated once across columns (not once per step, as a sweep
// from node to node would be, which blurs the shadow more with every step).
import type { Dims, NodeBox } from './lightingKernels';

export class ShearedDepth {
  /** Column sums: sums[i + ni·(j + nj·k)], plane k counted from the plane farthest from the
   *  light; each holds Σ of σ·h over planes k … nk − 1 of its column. */
  private sums = new Float32Array(0);
  private ni = 0;
  private nj = 0;
  private nk = 0;
  // axes: m (the light's longest component), a, b (the others); strides in the node grid
  private m = 1;
  private a = 0;
  private b = 2;
  private dm = 1;
  /** Column slope: a − cu·m and b − cv·m are constant along the light. */
  private cu = 0;
  private cv = 0;
  /** Ray length per plane, in cells. */
  private step = 1;
  private lm = 1;
  /** Plane index of k = 0, and the sheared lattice's first column (α, β). */
  private mRef = 0;
  private alpha0 = 0;
  private beta0 = 0;

  /** Resamples `tau` (σ·h per node, 0 outside `box`) into light-parallel columns and sums them.
   *  L: unit direction towards the light. */
  build(tau: Float32Array, dims: Dims, L: readonly [number, number, number], box: NodeBox): void {
    const abs = L.map(Math.abs);
    const m = abs[0] >= abs[1] && abs[0] >= abs[2] ? 0 : abs[1] >= abs[2] ? 1 : 2;
    this.m = m;
    this.a = m === 0 ? 1 : 0;
    this.b = m === 2 ? 1 : 2;
    this.dm = L[m] > 0 ? 1 : -1;
    this.lm = abs[m];
    this.step = 1 / abs[m];
    this.cu = (L[this.a] / abs[m]) * this.dm;
    this.cv = (L[this.b] / abs[m]) * this.dm;
    if (box.lo[0] > box.hi[0] || box.lo[1] > box.hi[1] || box.lo[2] > box.hi[2]) {
      this.nk = 0;
      return;
    }
    const [m0, m1] = [box.lo[m], box.hi[m]];
    this.mRef = this.dm > 0 ? m0 : m1;
    const span = (lo: number, hi: number, c: number): [number, number] => {
      const shifts = [c * m0, c * m1];
      const first = Math.floor(lo - Math.max(...shifts)) - 1;
      return [first, Math.ceil(hi - Math.min(...shifts)) - first + 2];
    };
    [this.alpha0, this.ni] = span(box.lo[this.a], box.hi[this.a], this.cu);
    [this.beta0, this.nj] = span(box.lo[this.b], box.hi[this.b], this.cv);
    this.nk = m1 - m0 + 1;
    const size = this.ni * this.nj * this.nk;
    if (this.sums.length < size) this.sums = new Float32Array(Math.ceil(size * 1.25));
    this.sums.fill(0, 0, size);
    for (let k = 0; k < this.nk; k++) this.resamplePlane(tau, dims, box, k);
    this.sumColumns();
  }

  /** Plane k of the lattice: σ·h bilinear in grid plane mRef + dm·k, at the columns' points. */
  private resamplePlane(tau: Float32Array, dims: Dims, box: NodeBox, k: number): void {
    const stride = [1, dims[0], dims[0] * dims[1]];
    const sa = stride[this.a];
    const sb = stride[this.b];
    const plane = this.mRef + this.dm * k;
    const base = plane * stride[this.m];
    // column (i, j) meets the plane at a = alpha0 + i + cu·plane, b = beta0 + j + cv·plane
    const aShift = this.alpha0 + this.cu * plane;
    const bShift = this.beta0 + this.cv * plane;
    const ia = Math.floor(aShift);
    const ib = Math.floor(bShift);
    const fa = aShift - ia;
    const fb = bShift - ib;
    const w00 = (1 - fa) * (1 - fb);
    const w10 = fa * (1 - fb);
    const w01 = (1 - fa) * fb;
    const w11 = fa * fb;
    // σ is 0 outside the box: only columns whose 4 nodes can touch it are resampled, and those
    // nodes stay in the grid (the box does)
    const [aLo, aHi] = [box.lo[this.a], box.hi[this.a]];
    const [bLo, bHi] = [box.lo[this.b], box.hi[this.b]];
    const i0 = Math.max(0, aLo - 1 - ia);
    const i1 = Math.min(this.ni - 1, aHi - ia);
    const j0 = Math.max(0, bLo - 1 - ib);
    const j1 = Math.min(this.nj - 1, bHi - ib);
    const sums = this.sums;
    const row0 = this.ni * this.nj * k;
    for (let j = j0; j <= j1; j++) {
      const B = ib + j;
      const bOk0 = B >= bLo && B <= bHi;
      const bOk1 = B + 1 >= bLo && B + 1 <= bHi;
      for (let i = i0; i <= i1; i++) {
        const A = ia + i;
        const c = base + A * sa + B * sb;
        let v = 0;
        if (A >= aLo && A <= aHi) {
          if (bOk0) v += w00 * tau[c];
          if (bOk1) v += w01 * tau[c + sb];
        }
        if (A + 1 >= aLo && A + 1 <= aHi) {
          if (bOk0) v += w10 * tau[c + sa];
          if (bOk1) v += w11 * tau[c + sa + sb];
        }
        sums[row0 + i + this.ni * j] = v;
      }
    }
  }

  /** Each column summed from the light's side: plane k holds Σ over planes k … nk − 1. */
  private sumColumns(): void {
    const n = this.ni * this.nj;
    const sums = this.sums;
    for (let k = this.nk - 2; k >= 0; k--) {
      const here = n * k;
      const up = here + n;
      for (let c = 0; c < n; c++) sums[here + c] += sums[up + c];
    }
  }

  /** ∫ σ ds along the ray from grid point p towards the light, from ray length s0 (cells) on:
   *  each plane's sample stands for the ray between the half-planes either side of it. */
  depth(px: number, py: number, pz: number, s0: number): number {
    if (this.nk === 0) return 0;
    const m = this.m;
    const pm = m === 0 ? px : m === 1 ? py : pz;
    const pa = m === 0 ? py : px; // a: the first axis that is not m
    const pb = m === 2 ? py : pz; // b: the last
    const k = this.dm * (pm - this.mRef) + s0 * this.lm + 0.5;
    const i = pa - this.cu * pm - this.alpha0;
    const j = pb - this.cv * pm - this.beta0;
    return this.step * this.sample(i, j, k);
  }

  /** Trilinear in the lattice: 0 past the light's end of the columns and outside them, the
   *  column's total before its first plane. */
  private sample(i: number, j: number, k: number): number {
    if (!(k < this.nk && i > -1 && j > -1 && i < this.ni && j < this.nj)) return 0;
    let kk = Math.floor(k);
    let fk = k - kk;
    if (kk < 0) {
      kk = 0;
      fk = 0;
    }
    const i0 = Math.floor(i);
    const j0 = Math.floor(j);
    const fi = i - i0;
    const fj = j - j0;
    const n = this.ni * this.nj;
    let sum = 0;
    for (let dk = 0; dk < 2; dk++) {
      const K = kk + dk;
      const wk = dk ? fk : 1 - fk;
      if (K >= this.nk || wk === 0) continue;
      for (let dj = 0; dj < 2; dj++) {
        const J = j0 + dj;
        if (J < 0 || J >= this.nj) continue;
        const wjk = wk * (dj ? fj : 1 - fj);
        const row = n * K + this.ni * J;
        if (i0 >= 0) sum += wjk * (1 - fi) * this.sums[row + i0];
        if (i0 + 1 < this.ni) sum += wjk * fi * this.sums[row + i0 + 1];
      }
    }
    return sum;
  }
}
