#include "cg_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "elapsed.hpp"

namespace hairsketch {

// Per grid point: 9 n x 3 double fields alive in solve() (previous_, work_, B, X, R, Z, P, Q
// and the caller's T: 216 bytes), 5 double vectors (invCount_, biDiag_, penalty_, diag, invDiag:
// 40 bytes), 8 bytes of penaltyDiagonal's temporary, 24 of slack (a warm start copy) and 24 of
// the prior's beta^2 G: 312 bytes per point, plus 1 MB (Lanczos tridiagonals, constraint set).
double CgSolver::estimateBytes(const Grid& grid) const {
  return bytesOf(double(grid.nx) * double(grid.ny) * double(grid.nz), 312) + double(1 << 20);
}

Status CgSolver::setGrid(const Grid& grid, double omega) {
  if (!grid.valid() || !std::isfinite(grid.step) || !grid.origin.allFinite())
    return Status::Error(StatusCode::InvalidInput,
                         "grid must have at least 2 points per axis and a finite step > 0");
  if (!std::isfinite(omega) || omega <= 0)
    return Status::Error(StatusCode::InvalidInput, "omega must be finite and > 0");
  Status fits = checkGridIndexable(grid);
  if (!fits.ok()) return fits;
  fits = checkMemory("cg solver", estimateBytes(grid), memoryCap());
  if (!fits.ok()) return fits;
  grid_ = grid;
  omega_ = omega;
  const int n = int(grid.size());
  invCount_.resize(n);
  for (int k = 0; k < grid.nz; ++k)
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const int c =
            (i > 0) + (i + 1 < grid.nx) + (j > 0) + (j + 1 < grid.ny) + (k > 0) + (k + 1 < grid.nz);
        invCount_[grid.index(i, j, k)] = 1.0 / c;
      }
  // (D^T D)_pp = sum_q D_qp^2 = 1 (the -1 of row p) + sum_{q in N(p)} (1 / |N(q)|)^2.
  biDiag_.resize(n);
  const int sx = 1, sy = grid.nx, sz = grid.nx * grid.ny;
  for (int k = 0; k < grid.nz; ++k)
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const int p = grid.index(i, j, k);
        double s = 1.0;
        if (i > 0) s += invCount_[p - sx] * invCount_[p - sx];
        if (i + 1 < grid.nx) s += invCount_[p + sx] * invCount_[p + sx];
        if (j > 0) s += invCount_[p - sy] * invCount_[p - sy];
        if (j + 1 < grid.ny) s += invCount_[p + sy] * invCount_[p + sy];
        if (k > 0) s += invCount_[p - sz] * invCount_[p - sz];
        if (k + 1 < grid.nz) s += invCount_[p + sz] * invCount_[p + sz];
        biDiag_[p] = s;
      }
  penalty_ = Eigen::VectorXd::Zero(n);
  beta2_ = 0;
  priorRhs_.resize(0, 3);
  set_.clear();
  previous_.resize(0, 3);
  hasGrid_ = true;
  stats_ = SolveStats{};
  stats_.method = "cg";
  return Status::Ok();
}

Status CgSolver::setConstraints(const ConstraintSet& next) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "setConstraints before setGrid");
  Status s = validateConstraints(grid_, next);
  if (!s.ok()) return s;
  for (size_t c = 1; c < next.size(); ++c)
    if (next[c].index <= next[c - 1].index)
      return Status::Error(StatusCode::InvalidInput, "constraints must be sorted and unique");
  const ConstraintDiff d = diffConstraints(set_, next);
  stats_.added = int(d.added.size());
  stats_.removed = int(d.removed.size());
  stats_.changed = int(d.changed.size());
  const auto t0 = Clock::now();
  set_ = next;
  rebuildPenalty();
  stats_.setupMs = msSince(t0);
  return Status::Ok();
}

void CgSolver::rebuildPenalty() {
  penalty_ = penaltyDiagonal(grid_, set_, omega_);
  if (beta2_ != 0) penalty_.array() += beta2_;
}

Status CgSolver::setPrior(double beta2, const Field& G) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "setPrior before setGrid");
  Status s = validatePrior(grid_, beta2, G);
  if (!s.ok()) return s;
  beta2_ = beta2;
  if (beta2 != 0 && G.rows() > 0)
    priorRhs_ = beta2 * G;
  else
    priorRhs_.resize(0, 3);
  rebuildPenalty();
  return Status::Ok();
}

void CgSolver::applyOperator(const Field& X, Field& Y) const {
  const Grid& g = grid_;
  const int n = int(g.size());
  const int sx = 3, sy = 3 * g.nx, sz = 3 * g.nx * g.ny;  // strides in doubles
  Field& L = const_cast<Field&>(work_);
  L.resize(n, 3);
  Y.resize(n, 3);
  const double* x = X.data();
  double* l = L.data();
  const double* inv = invCount_.data();
  // Pass 1: L = D X, (D x)_p = inv_p * sum_{q in N(p)} x_q - x_p.
  for (int k = 0, p = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i, ++p) {
        const double* xp = x + 3 * p;
        double s0 = 0, s1 = 0, s2 = 0;
        auto add = [&](int off) {
          s0 += xp[off];
          s1 += xp[off + 1];
          s2 += xp[off + 2];
        };
        if (i > 0) add(-sx);
        if (i + 1 < g.nx) add(sx);
        if (j > 0) add(-sy);
        if (j + 1 < g.ny) add(sy);
        if (k > 0) add(-sz);
        if (k + 1 < g.nz) add(sz);
        const double w = inv[p];
        l[3 * p] = w * s0 - xp[0];
        l[3 * p + 1] = w * s1 - xp[1];
        l[3 * p + 2] = w * s2 - xp[2];
      }
  // Pass 2: Y = D^T L + penalty * X, (D^T l)_p = -l_p + sum_{q in N(p)} inv_q l_q.
  double* y = Y.data();
  const double* pen = penalty_.data();
  for (int k = 0, p = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i, ++p) {
        const double* lp = l + 3 * p;
        double s0 = 0, s1 = 0, s2 = 0;
        auto add = [&](int off, int q) {
          const double w = inv[q];
          s0 += w * lp[off];
          s1 += w * lp[off + 1];
          s2 += w * lp[off + 2];
        };
        if (i > 0) add(-sx, p - 1);
        if (i + 1 < g.nx) add(sx, p + 1);
        if (j > 0) add(-sy, p - g.nx);
        if (j + 1 < g.ny) add(sy, p + g.nx);
        if (k > 0) add(-sz, p - g.nx * g.ny);
        if (k + 1 < g.nz) add(sz, p + g.nx * g.ny);
        const double w = pen[p];
        y[3 * p] = s0 - lp[0] + w * x[3 * p];
        y[3 * p + 1] = s1 - lp[1] + w * x[3 * p + 1];
        y[3 * p + 2] = s2 - lp[2] + w * x[3 * p + 2];
      }
}

double smallestTridiagonalEigenvalue(const std::vector<double>& d, const std::vector<double>& e) {
  const size_t k = d.size();
  if (k == 0) return 0;
  // Gershgorin interval.
  double lo = d[0], hi = d[0];
  for (size_t i = 0; i < k; ++i) {
    const double r = (i > 0 ? std::abs(e[i - 1]) : 0) + (i + 1 < k ? std::abs(e[i]) : 0);
    lo = std::min(lo, d[i] - r);
    hi = std::max(hi, d[i] + r);
  }
  // Number of eigenvalues < x (LDL^T inertia).
  auto countBelow = [&](double x) {
    int neg = 0;
    double q = d[0] - x;
    for (size_t i = 0;; ++i) {
      if (q == 0) q = -1e-300;
      if (q < 0) ++neg;
      if (i + 1 == k) break;
      q = d[i + 1] - x - e[i] * e[i] / q;
    }
    return neg;
  };
  for (int it = 0; it < 100 && hi - lo > 1e-14 * std::max(std::abs(lo), std::abs(hi)); ++it) {
    const double mid = 0.5 * (lo + hi);
    if (countBelow(mid) >= 1)
      hi = mid;
    else
      lo = mid;
  }
  return lo;  // the lower end: errs on the small side, which makes the error bound larger
}

Status CgSolver::solve(Field& T) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "solve before setGrid");
  const auto t0 = Clock::now();
  const int n = int(grid_.size());
  stats_.method = "cg";
  stats_.iterations = 0;
  stats_.residual = 0;
  errorEstimate_ = 0;
  if (set_.empty() && priorRhs_.rows() == 0) {
    // No right-hand side: the field is zero (by definition without a prior: D^T D alone is
    // singular).
    T = Field::Zero(n, 3);
    previous_ = T;
    stats_.solveMs = msSince(t0);
    return Status::Ok();
  }
  Field B = assembleRhs(grid_, set_, omega_);
  if (priorRhs_.rows() > 0) B += priorRhs_;
  const Eigen::RowVector3d bNorm = B.colwise().norm();
  const Eigen::VectorXd diag = biDiag_ + penalty_;
  const Eigen::VectorXd invDiag = diag.cwiseInverse();
  const double minDiag = diag.minCoeff();

  Field X = (options_.warmStart && previous_.rows() == n) ? previous_ : Field::Zero(n, 3);
  Field R(n, 3), Z(n, 3), P(n, 3), Q(n, 3);
  applyOperator(X, Q);
  R = B - Q;
  // A warm start worse than zero (e.g. after a big edit) is dropped, column by column.
  for (int c = 0; c < 3; ++c)
    if (R.col(c).norm() > bNorm[c]) {
      X.col(c).setZero();
      R.col(c) = B.col(c);
    }
  Z = R.array().colwise() * invDiag.array();
  P = Z;
  double rz[3], rr[3], xx[3];
  for (int c = 0; c < 3; ++c) {
    rz[c] = R.col(c).dot(Z.col(c));
    rr[c] = R.col(c).squaredNorm();
    xx[c] = X.col(c).squaredNorm();
  }

  // Lanczos tridiagonal per component, from the PCG coefficients.
  std::vector<double> tDiag[3], tOff[3];
  double lastAlpha[3] = {0, 0, 0}, lastBeta[3] = {0, 0, 0};
  double theta[3] = {0, 0, 0};
  int thetaAt[3] = {-1, -1, -1};
  double bound[3] = {0, 0, 0};
  bool active[3];
  // Two bounds on ||x - x*||_2, both from lambda_min(A') ~ theta (see the header):
  //   ||r||_2 / (min P * theta)   and   sqrt(r^T P^-1 r) / (sqrt(min P) * theta);
  // the second is much tighter when the residual sits on the heavy (constrained) rows.
  auto boundWith = [&](int c, double th) {
    const double b1 = std::sqrt(rr[c]) / (minDiag * th);
    const double b2 = std::sqrt(std::max(rz[c], 0.0)) / (std::sqrt(minDiag) * th);
    return std::min(b1, b2);
  };
  auto converged = [&](int c, int it) {
    if (rr[c] == 0) return true;
    if (rr[c] > options_.residualGate * options_.residualGate * bNorm[c] * bNorm[c] ||
        tDiag[c].empty())
      return false;
    // The Ritz value only decreases with k: a stale one is optimistic, so it is refreshed
    // every 32 iterations and always before declaring convergence.
    if (thetaAt[c] < 0 || it - thetaAt[c] >= 32) {
      theta[c] = smallestTridiagonalEigenvalue(tDiag[c], tOff[c]);
      thetaAt[c] = it;
    }
    if (!(theta[c] > 0)) return false;
    const double tol2 = options_.errorTolerance * options_.errorTolerance * xx[c];
    bound[c] = boundWith(c, theta[c]);
    if (bound[c] * bound[c] > tol2) return false;
    if (thetaAt[c] != it) {
      theta[c] = smallestTridiagonalEigenvalue(tDiag[c], tOff[c]);
      thetaAt[c] = it;
      bound[c] = boundWith(c, theta[c]);
    }
    return bound[c] * bound[c] <= tol2;
  };
  for (int c = 0; c < 3; ++c) active[c] = rr[c] > 0;

  const double* id = invDiag.data();
  int it = 0;
  while ((active[0] || active[1] || active[2]) && it < options_.maxIterations) {
    applyOperator(P, Q);
    ++it;
    double pq[3] = {0, 0, 0};
    {
      const double* p = P.data();
      const double* q = Q.data();
      for (int i = 0; i < 3 * n; i += 3) {
        pq[0] += p[i] * q[i];
        pq[1] += p[i + 1] * q[i + 1];
        pq[2] += p[i + 2] * q[i + 2];
      }
    }
    double alpha[3] = {0, 0, 0};
    for (int c = 0; c < 3; ++c) {
      if (!active[c]) continue;
      if (!(pq[c] > 0) || !std::isfinite(pq[c]))
        return Status::Error(
            StatusCode::NotPositiveDefinite,
            "cg: non-positive curvature (p^T M p = " + std::to_string(pq[c]) + ")");
      alpha[c] = rz[c] / pq[c];
    }
    // x += alpha p, r -= alpha q, z = P^-1 r, and the new dot products, in one pass.
    double rzNew[3] = {0, 0, 0}, rrNew[3] = {0, 0, 0}, xxNew[3] = {0, 0, 0};
    {
      double* x = X.data();
      double* r = R.data();
      double* z = Z.data();
      const double* p = P.data();
      const double* q = Q.data();
      for (int i = 0; i < n; ++i) {
        const double w = id[i];
        for (int c = 0; c < 3; ++c) {
          const int k = 3 * i + c;
          x[k] += alpha[c] * p[k];
          r[k] -= alpha[c] * q[k];
          z[k] = w * r[k];
          rzNew[c] += r[k] * z[k];
          rrNew[c] += r[k] * r[k];
          xxNew[c] += x[k] * x[k];
        }
      }
    }
    double beta[3] = {0, 0, 0};
    for (int c = 0; c < 3; ++c) {
      if (!active[c]) continue;
      beta[c] = rzNew[c] / rz[c];
      // T_k: delta_j = 1/alpha_j + beta_{j-1}/alpha_{j-1}, eta_j = sqrt(beta_j)/alpha_j.
      tDiag[c].push_back(1.0 / alpha[c] + (tDiag[c].empty() ? 0.0 : lastBeta[c] / lastAlpha[c]));
      tOff[c].push_back(std::sqrt(beta[c]) / alpha[c]);
      lastAlpha[c] = alpha[c];
      lastBeta[c] = beta[c];
      rz[c] = rzNew[c];
      rr[c] = rrNew[c];
      xx[c] = xxNew[c];
      tOff[c].pop_back();  // eta_k couples to a row not built yet
      if (converged(c, it)) {
        active[c] = false;
        beta[c] = 0;
      } else {
        tOff[c].push_back(std::sqrt(beta[c]) / alpha[c]);
      }
    }
    {
      double* p = P.data();
      const double* z = Z.data();
      for (int i = 0; i < 3 * n; i += 3)
        for (int c = 0; c < 3; ++c)
          if (active[c]) p[i + c] = z[i + c] + beta[c] * p[i + c];
    }
    if (hook_) {
      IterateProgress pr;
      pr.iterations = it;
      pr.errorEstimate = 0;
      for (int c = 0; c < 3; ++c) {
        if (bNorm[c] > 0) pr.relResidual = std::max(pr.relResidual, std::sqrt(rr[c]) / bNorm[c]);
        // The error bound exists once a component passed the residual gate; before, unknown.
        const double xn = std::sqrt(xx[c]);
        const double e = bound[c] > 0 && xn > 0 ? bound[c] / xn
                         : active[c]            ? std::numeric_limits<double>::infinity()
                                                : 0.0;
        pr.errorEstimate = std::max(pr.errorEstimate, e);
      }
      if (!keepGoing(pr)) {
        stats_.iterations = it;
        stats_.residual = pr.relResidual;
        stats_.solveMs = msSince(t0);
        errorEstimate_ = pr.errorEstimate;
        T = X;
        previous_ = X;
        return Status::Error(StatusCode::Cancelled, "cg: stopped after " + std::to_string(it) +
                                                        " iterations (relative residual " +
                                                        std::to_string(pr.relResidual) + ")");
      }
    }
  }
  stats_.iterations = it;
  double rel = 0;
  for (int c = 0; c < 3; ++c) {
    if (bNorm[c] > 0) rel = std::max(rel, R.col(c).norm() / bNorm[c]);
    const double xn = X.col(c).norm();
    if (xn > 0) errorEstimate_ = std::max(errorEstimate_, bound[c] / xn);
  }
  stats_.residual = rel;
  stats_.solveMs = msSince(t0);
  if (!X.allFinite()) return Status::Error(StatusCode::NotConverged, "cg: field is not finite");
  T = X;
  previous_ = X;
  if (active[0] || active[1] || active[2])
    return Status::Error(StatusCode::NotConverged,
                         "cg: no convergence after " + std::to_string(it) +
                             " iterations (relative residual " + std::to_string(rel) + ")");
  return Status::Ok();
}

}  // namespace hairsketch
