// MultigridHierarchy: the coarsest level's banded Cholesky factor, kept up to date by rank-1
// updates or refactorisation, and its solve.
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "multigrid_hierarchy.hpp"

namespace hairsketch {

Status MultigridHierarchy::prepare() {
  if (!coarsestDirty_) return Status::Ok();
  // Within the band (lower bandwidth w): a rank-1 term costs ~2 w (m - first), m w on average,
  // a refactorisation m w^2 / 2.
  const bool update = factorValid_ && 2 * pending_.size() < size_t(std::max(coarsestBand_, 1));
  lastRefactored_ = !(update && updateCoarsest());
  pending_.clear();
  if (lastRefactored_) {
    Status s = refactorCoarsest();
    if (!s.ok()) return s;
  }
  coarsestDirty_ = false;
  return Status::Ok();
}

// The coarsest operator is banded in its lexicographic order (a Galerkin stencil reaches at
// most 2 points along each axis): its Cholesky factor has no entry outside that band, so every
// loop on the factor stays inside it (lower bandwidth w: m w^2 / 2 flops instead of m^3 / 3;
// 25K's 9 x 10 x 9 level: w = 200 of m = 810). Right-looking, column by column, in a fixed order.
Status MultigridHierarchy::refactorCoarsest() {
  factorValid_ = false;
  const Level& c = levels_.back();
  const int n = c.A.rows;
  coarsestL_.setZero(n, n);
  int band = 0;
  for (int r = 0; r < n; ++r)
    for (int64_t e = c.A.ptr[r]; e < c.A.ptr[r + 1]; ++e)
      if (c.A.col[e] <= r) {
        coarsestL_(r, c.A.col[e]) = c.A.val[e];
        band = std::max(band, r - c.A.col[e]);
      }
  coarsestBand_ = band;
  double* L = coarsestL_.data();
  const int64_t ld = coarsestL_.outerStride();
  for (int j = 0; j < n; ++j) {
    double* __restrict cj = L + ld * j;
    const int end = std::min(n, j + band + 1);
    if (!(cj[j] > 0) || !std::isfinite(cj[j]))
      return Status::Error(StatusCode::NotPositiveDefinite,
                           "coarsest level is not positive definite");
    const double ljj = std::sqrt(cj[j]);
    cj[j] = ljj;
    for (int i = j + 1; i < end; ++i) cj[i] /= ljj;
    for (int k = j + 1; k < end; ++k) {
      double* __restrict ck = L + ld * k;
      const double lkj = cj[k];
      for (int i = k; i < end; ++i) ck[i] -= cj[i] * lkj;
    }
  }
  factorValid_ = true;
  return Status::Ok();
}

// L L^T + delta v v^T for each pending term, updates (delta > 0) before downdates so that every
// intermediate matrix stays positive definite; columns before the term's first entry do not
// change. false (factor invalid) when a pivot is not finite or drops below 1e-10 of its old
// value: the caller refactors from the operator.
bool MultigridHierarchy::updateCoarsest() {
  const int n = int(coarsestL_.rows());
  Eigen::VectorXd u(n);
  for (int pass = 0; pass < 2; ++pass)
    for (const CoarseTerm& t : pending_) {
      if ((pass == 0) != (t.delta > 0)) continue;
      const double sigma = t.delta > 0 ? 1.0 : -1.0;
      const double scale = std::sqrt(std::abs(t.delta));
      int first = n;
      for (int a = 0; a < t.count; ++a) first = std::min(first, t.idx[a]);
      u.segment(first, n - first).setZero();
      for (int a = 0; a < t.count; ++a) u[t.idx[a]] += scale * t.v[a];
      double beta = 1.0;
      for (int j = first; j < n; ++j) {
        const double uj = u[j];
        if (uj == 0.0) continue;  // column j unchanged
        const double ljj = coarsestL_(j, j), dj = ljj * ljj;
        const double su2 = sigma * uj * uj;
        const double x = dj + su2 / beta;
        if (!(x > 1e-10 * dj) || !std::isfinite(x)) {
          factorValid_ = false;
          return false;
        }
        const double nljj = std::sqrt(x);
        const double gamma = dj * beta + su2;
        beta += su2 / dj;
        coarsestL_(j, j) = nljj;
        // u's support stays within [j, j + band] (the term's 8 entries span less than the band)
        const int rs = std::min(n - j - 1, coarsestBand_);
        if (rs == 0) continue;
        auto col = coarsestL_.col(j).segment(j + 1, rs);
        auto ut = u.segment(j + 1, rs);
        ut -= (uj / ljj) * col;
        col = (nljj / ljj) * col + (nljj * sigma * uj / gamma) * ut;
      }
    }
  return true;
}

// x = (L L^T)^-1 b for the 3 columns of b by column-oriented substitution on the column-major
// factor, the columns of b apart (coarseWork_: 3 contiguous vectors, so the inner loops
// vectorise): each pass reads every column of L once, contiguously, for all 3 right-hand sides.
// (Eigen's blocked triangular solve repacked L into GEMM panels on every call: 18 % of the fast
// solver's time at 37^3 natively, for a 1000-point coarsest level.)
void MultigridHierarchy::solveCoarsest() {
  Level& c = levels_.back();
  const int n = c.A.rows;
  const double* L = coarsestL_.data();
  const int64_t ld = coarsestL_.outerStride();
  const int band = coarsestBand_;
  coarseWork_.resize(3 * size_t(n));
  double* __restrict y0 = coarseWork_.data();
  double* __restrict y1 = y0 + n;
  double* __restrict y2 = y1 + n;
  for (int i = 0; i < n; ++i) {
    y0[i] = c.b[3 * i];
    y1[i] = c.b[3 * i + 1];
    y2[i] = c.b[3 * i + 2];
  }
  for (int j = 0; j < n; ++j) {  // L y = b
    const double* __restrict col = L + ld * j;
    const double a = y0[j] / col[j], b = y1[j] / col[j], d = y2[j] / col[j];
    y0[j] = a;
    y1[j] = b;
    y2[j] = d;
    const int end = std::min(n, j + band + 1);
    for (int i = j + 1; i < end; ++i) {
      const double l = col[i];
      y0[i] -= l * a;
      y1[i] -= l * b;
      y2[i] -= l * d;
    }
  }
  for (int j = n - 1; j >= 0; --j) {  // L^T x = y: dot products, 4 partial sums each
    const double* __restrict col = L + ld * j;
    double s[3][4] = {};
    int i = j + 1;
    const int end = std::min(n, j + band + 1);
    for (; i + 3 < end; i += 4)
      for (int u = 0; u < 4; ++u) {
        const double l = col[i + u];
        s[0][u] += l * y0[i + u];
        s[1][u] += l * y1[i + u];
        s[2][u] += l * y2[i + u];
      }
    for (; i < end; ++i) {
      s[0][0] += col[i] * y0[i];
      s[1][0] += col[i] * y1[i];
      s[2][0] += col[i] * y2[i];
    }
    y0[j] = (y0[j] - ((s[0][0] + s[0][1]) + (s[0][2] + s[0][3]))) / col[j];
    y1[j] = (y1[j] - ((s[1][0] + s[1][1]) + (s[1][2] + s[1][3]))) / col[j];
    y2[j] = (y2[j] - ((s[2][0] + s[2][1]) + (s[2][2] + s[2][3]))) / col[j];
  }
  for (int i = 0; i < n; ++i) {
    c.x[3 * i] = y0[i];
    c.x[3 * i + 1] = y1[i];
    c.x[3 * i + 2] = y2[i];
  }
}

}  // namespace hairsketch
