// MultigridHierarchy: Gauss-Seidel smoothing and residuals, matrix-free on the fine level and
// on CSR operators on the coarse levels, in plane-multicolour order.
#include <algorithm>
#include <cmath>

#include "multigrid_hierarchy.hpp"

namespace hairsketch {

// ---- fine level, matrix-free -------------------------------------------------------------

void MultigridHierarchy::computeL(const double* x, double* L) const {
  const Fine& f = fine_;
  const int64_t sy = f.layout.sy, sz = f.layout.sz;
  const double* inv = f.inv.data();
  forPlanes(grid_.nz, 3 * int64_t(grid_.nx) * grid_.ny, [&](int64_t k0, int64_t k1) {
    for (int64_t k = k0; k < k1; ++k)
      for (int j = 0; j < grid_.ny; ++j) {
        const int64_t base = f.layout.offset + sy * j + sz * k;
        for (int i = 0; i < grid_.nx; ++i) {
          const int64_t p = base + i;
          const double* xp = x + 3 * p;
          for (int c = 0; c < 3; ++c) {
            const double s = xp[c - 3] + xp[c + 3] + xp[c - 3 * sy] + xp[c + 3 * sy] +
                             xp[c - 3 * sz] + xp[c + 3 * sz];
            L[3 * p + c] = inv[p] * s - xp[c];
          }
        }
      }
  });
}

namespace {

// The 25-point product written once: calls out(r, (D^T L)_r + w_r x_r) for every row
// r = 3 p + axis of every grid point p of the padded layout, with L = D x already computed,
// in parallel over z planes (out must only write row r).
// (D^T L)_p = sum over the 6 neighbours q of inv_q L_q, minus L_p (ghost rows have inv = 0).
template <class Out>
inline void forEachFineProduct(const BoxLayout& lay, const double* inv, const double* w,
                               const double* L, const double* x, Out&& out) {
  const int64_t sy = lay.sy, sz = lay.sz;
  forPlanes(lay.nz, 3 * int64_t(lay.nx) * lay.ny, [&](int64_t k0, int64_t k1) {
    for (int64_t k = k0; k < k1; ++k)
      for (int j = 0; j < lay.ny; ++j) {
        const int64_t base = lay.offset + sy * j + sz * k;
        for (int i = 0; i < lay.nx; ++i) {
          const int64_t p = base + i;
          const double i0 = inv[p - 1], i1 = inv[p + 1], i2 = inv[p - sy], i3 = inv[p + sy],
                       i4 = inv[p - sz], i5 = inv[p + sz];
          const double* Lp = L + 3 * p;
          for (int c = 0; c < 3; ++c) {
            const double dtl = i0 * Lp[c - 3] + i1 * Lp[c + 3] + i2 * Lp[c - 3 * sy] +
                               i3 * Lp[c + 3 * sy] + i4 * Lp[c - 3 * sz] + i5 * Lp[c + 3 * sz] -
                               Lp[c];
            out(3 * p + c, dtl + w[p] * x[3 * p + c]);
          }
        }
      }
  });
}

}  // namespace

// res = b - (D^T L + w x), with L = D x already computed.
void MultigridHierarchy::fineResidual(const double* x, const double* b, double* res) const {
  const Fine& f = fine_;
  forEachFineProduct(f.layout, f.inv.data(), f.w.data(), f.L.data(), x,
                     [&](int64_t r, double v) { res[r] = b[r] - v; });
}

void MultigridHierarchy::applyFine(const double* x, double* y) {
  computeL(x, fine_.L.data());
  const Fine& f = fine_;
  forEachFineProduct(f.layout, f.inv.data(), f.w.data(), f.L.data(), x,
                     [&](int64_t r, double v) { y[r] = v; });
}

// Gauss-Seidel on M x = b in plane-multicolour order: a point's update reads x and L = D x
// within two planes of its own, so planes k and k + C are independent for C >= 3
// (kFineColours); colour c holds the planes k = c mod C (C = fineColours_), swept one colour after
// the other, the planes of a colour in parallel, each plane in lexicographic order (forward) or
// its reverse (backward). The order is fixed, so every thread count gives the same bits, and a
// backward sweep is the exact reverse of a forward one (the V-cycle stays symmetric).
// fineSweepPlane keeps fine_.L = D x exact: the update delta at p changes L_p by -delta and L_q
// by inv_q * delta for the 6 neighbours q (in planes k - 1 .. k + 1: not touched by any other
// plane of the colour).
// Along a line, L at the previous and the current point stay in registers (carried from one
// point to the next), so the only serial dependency is delta_{p-1} -> delta_p through a few
// flops instead of a store and reload; everything read from the other lines is off that path.
void MultigridHierarchy::fineSweepPlane(int k, bool forward, double* x, const double* b) {
  Fine& f = fine_;
  const int64_t sy = f.layout.sy, sz = f.layout.sz;
  const double* inv = f.inv.data();
  const double* w = f.w.data();
  const double* invDiag = f.invDiag.data();
  double* L = f.L.data();
  const int nx = grid_.nx, ny = grid_.ny;
  const int64_t step = forward ? 1 : -1;  // along x
  for (int jj = 0; jj < ny; ++jj) {
    const int j = forward ? jj : ny - 1 - jj;
    const int64_t first = f.layout.offset + sy * j + sz * k + (forward ? 0 : nx - 1);
    // prev = the point before `first` in sweep order (a ghost), cur = first.
    double Lprev[3], Lcur[3];
    for (int c = 0; c < 3; ++c) {
      Lprev[c] = L[3 * (first - step) + c];
      Lcur[c] = L[3 * first + c];
    }
    for (int ii = 0; ii < nx; ++ii) {
      const int64_t p = first + step * ii;
      const int64_t pb = p - step, pn = p + step;  // previous / next in sweep order
      const double ib = inv[pb], in = inv[pn], i2 = inv[p - sy], i3 = inv[p + sy], i4 = inv[p - sz],
                   i5 = inv[p + sz];
      double* xp = x + 3 * p;
      const double* bp = b + 3 * p;
      double* Ln = L + 3 * pn;
      const double wp = w[p], dp = invDiag[p];
      for (int c = 0; c < 3; ++c) {
        const double Lnext = Ln[c];
        // Off the serial path: everything but the previous and current point's L.
        const double rest =
            bp[c] - wp * xp[c] -
            ((in * Lnext + i2 * L[3 * (p - sy) + c]) +
             (i3 * L[3 * (p + sy) + c] + i4 * L[3 * (p - sz) + c]) + i5 * L[3 * (p + sz) + c]);
        const double d = (rest + Lcur[c] - ib * Lprev[c]) * dp;
        xp[c] += d;
        L[3 * pb + c] = Lprev[c] + ib * d;  // the previous point's L is final now
        Lprev[c] = Lcur[c] - d;
        Lcur[c] = Lnext + in * d;
        L[3 * (p - sy) + c] += i2 * d;
        L[3 * (p + sy) + c] += i3 * d;
        L[3 * (p - sz) + c] += i4 * d;
        L[3 * (p + sz) + c] += i5 * d;
      }
    }
    const int64_t last = first + step * (nx - 1);
    for (int c = 0; c < 3; ++c) {
      L[3 * last + c] = Lprev[c];
      L[3 * (last + step) + c] = Lcur[c];  // ghost: inv there is 0, stays 0
    }
  }
}

void MultigridHierarchy::fineColourPass(int colour, bool forward, double* x, const double* b) {
  const int nz = grid_.nz;
  const int C = fineColours_;
  const int64_t planes = colour < nz ? (nz - colour + C - 1) / C : 0;
  forPlanes(planes, 6 * int64_t(grid_.nx) * grid_.ny, [&](int64_t t0, int64_t t1) {
    for (int64_t t = t0; t < t1; ++t) fineSweepPlane(colour + int(t) * C, forward, x, b);
  });
}

// ---- smoothing schedule --------------------------------------------------------------------

// Appends a sweep's colour passes: forward = colours ascending, each plane forward; backward =
// the exact reverse.
void MultigridHierarchy::appendSweep(std::vector<ColourPass>& plan, int colours, bool forward) {
  for (int a = 0; a < colours; ++a) plan.push_back({forward ? a : colours - 1 - a, forward});
}

std::vector<MultigridHierarchy::ColourPass> MultigridHierarchy::smoothingPlan(int colours,
                                                                              int sweeps,
                                                                              bool symmetric,
                                                                              bool pre) {
  // pre: forward (then backward when symmetric); post: its adjoint, (forward then) backward.
  std::vector<ColourPass> plan;
  for (int s = 0; s < sweeps; ++s) {
    if (pre || symmetric) appendSweep(plan, colours, true);
    if (!pre || symmetric) appendSweep(plan, colours, false);
  }
  return plan;
}

// ---- coarse levels, CSR --------------------------------------------------------------------

namespace {

// Row r of A (CSR) times x (rows of 3): two accumulator sets halve the add-latency chain.
inline void rowDot3(const int64_t* ptr, const int* col, const double* val, const double* x, int r,
                    double& o0, double& o1, double& o2) {
  double a0 = 0, a1 = 0, a2 = 0, b0 = 0, b1 = 0, b2 = 0;
  int64_t e = ptr[r];
  const int64_t end = ptr[r + 1];
  for (; e + 1 < end; e += 2) {
    const double va = val[e], vb = val[e + 1];
    const double* xa = x + 3 * int64_t(col[e]);
    const double* xb = x + 3 * int64_t(col[e + 1]);
    a0 += va * xa[0];
    a1 += va * xa[1];
    a2 += va * xa[2];
    b0 += vb * xb[0];
    b1 += vb * xb[1];
    b2 += vb * xb[2];
  }
  if (e < end) {
    const double va = val[e];
    const double* xa = x + 3 * int64_t(col[e]);
    a0 += va * xa[0];
    a1 += va * xa[1];
    a2 += va * xa[2];
  }
  o0 = a0 + b0;
  o1 = a1 + b1;
  o2 = a2 + b2;
}

}  // namespace

// One colour of a Gauss-Seidel sweep on level l: the planes k = colour mod lv.colours, each in
// row order (forward) or its reverse; rows of one colour's planes never couple (lv.colours is
// one more than the largest plane distance in the operator's pattern), so they run in parallel.
void MultigridHierarchy::coarseColourPass(int l, int colour, bool forward) {
  Level& lv = levels_[l];
  const int64_t planeRows = int64_t(lv.nx) * lv.ny;
  const int C = lv.colours;
  const int64_t planes = colour < lv.nz ? (lv.nz - colour + C - 1) / C : 0;
  const int64_t* ptr = lv.A.ptr.data();
  const int* col = lv.A.col.data();
  const double* val = lv.A.val.data();
  double* x = lv.x.data();
  const double* b = lv.b.data();
  const double* invDiag = lv.invDiag.data();
  const int64_t perPlane = 3 * lv.A.nnz() / std::max(lv.nz, 1);
  forPlanes(planes, perPlane, [&](int64_t t0, int64_t t1) {
    for (int64_t t = t0; t < t1; ++t) {
      const int64_t first = (colour + t * C) * planeRows;
      for (int64_t rr = 0; rr < planeRows; ++rr) {
        const int r = int(forward ? first + rr : first + planeRows - 1 - rr);
        double s0, s1, s2;
        rowDot3(ptr, col, val, x, r, s0, s1, s2);
        const double d = invDiag[r];
        x[3 * r] += (b[3 * r] - s0) * d;
        x[3 * r + 1] += (b[3 * r + 1] - s1) * d;
        x[3 * r + 2] += (b[3 * r + 2] - s2) * d;
      }
    }
  });
}

void MultigridHierarchy::coarseResidual(int l) {
  Level& lv = levels_[l];
  const int n = lv.A.rows;
  const int64_t* ptr = lv.A.ptr.data();
  const int* col = lv.A.col.data();
  const double* val = lv.A.val.data();
  const double* x = lv.x.data();
  const double* b = lv.b.data();
  double* res = lv.res.data();
  forPlanes(n, 3 * lv.A.nnz() / std::max(n, 1), [&](int64_t r0, int64_t r1) {
    for (int64_t r = r0; r < r1; ++r) {
      double s0, s1, s2;
      rowDot3(ptr, col, val, x, int(r), s0, s1, s2);
      res[3 * r] = b[3 * r] - s0;
      res[3 * r + 1] = b[3 * r + 1] - s1;
      res[3 * r + 2] = b[3 * r + 2] - s2;
    }
  });
}

}  // namespace hairsketch
