#include "mg_pcg_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "elapsed.hpp"
#include "multigrid_transfer.hpp"
#include "parallel.hpp"

namespace hairsketch {
namespace {

constexpr double kEstimateSafety = 2.0;
constexpr double kRhoMin = 0.3, kRhoMax = 0.95, kRhoFirst = 0.9;

// Vector operations on padded n x 3 arrays, in parallel. Sums are ordered reductions over
// fixed blocks of kBlockRows rows (parallel::sumBlocks), so every thread count gives the same
// bits: the threaded and the single-threaded wasm modules give the same field.
constexpr size_t kBlockRows = 2048;
constexpr size_t kGrainBlocks = 4;  // blocks per thread at least (~100K values)

// Column-wise dot products of two padded n x 3 arrays.
void dots3(const std::vector<double>& a, const std::vector<double>& b, double out[3]) {
  const double* pa = a.data();
  const double* pb = b.data();
  const auto s =
      parallel::sumBlocks<3>(a.size() / 3, kBlockRows, kGrainBlocks, [&](size_t i0, size_t i1) {
        double s0 = 0, s1 = 0, s2 = 0;
        for (size_t i = i0; i < i1; ++i) {
          s0 += pa[3 * i] * pb[3 * i];
          s1 += pa[3 * i + 1] * pb[3 * i + 1];
          s2 += pa[3 * i + 2] * pb[3 * i + 2];
        }
        return std::array<double, 3>{s0, s1, s2};
      });
  for (int c = 0; c < 3; ++c) out[c] = s[c];
}

// fn(i0, i1) over row ranges in parallel chunks (no reduction).
template <class F>
void forRows(size_t rows, F&& fn) {
  parallel::forRange(0, rows, kBlockRows * kGrainBlocks, fn);
}

}  // namespace

// The peak is the larger of building the hierarchy and solving (n points, R = (nx+2)(ny+2)(nz+2)
// padded fine rows, m_l points and s_l = prod_axis min(5, dim) stencil entries per row on coarse
// level l, all in bytes):
//   steady = 248 R   fine arrays (inv, diagK, w, invDiag, L, res: 80 R) + CG vectors (144 R)
//                    + the prior's right-hand side beta^2 G (24 R)
//          + sum_l (96 + 20 s_l) m_l   Galerkin CSR (12 per entry, 8 per row), its W = 0 copy
//                                       (8 per entry) + diagPos, invDiag,
//                                       x, b, res (96 per row)
//          + 16 m_c^2                  dense coarsest matrix and its Cholesky factor
//          + 24 (c_x n_y n_z + c_x c_y n_z)   transfer scratch at the fine level
//          + 24 n                      the field solve() writes
//   build  = 80 R + levels + max(assembling D: 288 n (triplets 112 n, two Eigen copies 176 n),
//              D (92 n) + P_0 (12 p n + 8 n) + G = D P_0 (12 g n + 8 n) + 12 m_1,
//              D + G + G^T (12 g n + 8 m_1) + A_1 (12 s_1 m_1 + 8 m_1) + 12 n)
//     with per-row bounds p = prod (2 on a coarsened axis, else 1) and g = the union of the
//     coarse supports of D's 7-point row (3 x 2 x 2 per axis line, inclusion-exclusion: 20 in a
//     full box); multiplyCsr and interpolationMatrix allocate exactly.
//   + 96 (nx + ny + nz) per level: composite interpolation tables, 1D transfers and the
//     prior's 1D Gram bands (40).
// Coarser Galerkin products (at most 1/8 of the fine rows) stay below the level-1 ones.
double MgPcgSolver::estimateBytes(const Grid& grid) const {
  const double n = double(grid.nx) * grid.ny * grid.nz;
  const double R = double(grid.nx + 2) * double(grid.ny + 2) * double(grid.nz + 2);
  double levels = 0, m1 = 0, s1 = 0, coarsest = n, count = 1;
  int ax = grid.nx, ay = grid.ny, az = grid.nz;
  for (;;) {
    const double size = double(ax) * ay * az;
    if (size <= mgOptions_.coarsestMaxPoints) break;
    const int cx = coarsenedSize(ax), cy = coarsenedSize(ay), cz = coarsenedSize(az);
    const double m = double(cx) * cy * cz;
    if (m == size) break;
    const double s = double(std::min(5, cx)) * std::min(5, cy) * std::min(5, cz);
    levels += (96 + 20 * s) * m;
    if (m1 == 0) m1 = m, s1 = s;
    coarsest = m;
    count += 1;
    ax = cx, ay = cy, az = cz;
  }
  if (m1 == 0) levels = (96 + 20 * 25) * n;  // one level: its assembled matrix
  auto axisP = [](int d) { return coarsenedSize(d) < d ? 2.0 : 1.0; };
  // Coarse support of one fine index (S1) and of three consecutive ones (S3), per axis.
  auto s1Of = [](int d) { return coarsenedSize(d) < d ? 2.0 : 1.0; };
  auto s3Of = [](int d) { return coarsenedSize(d) < d ? 3.0 : double(std::min(d, 3)); };
  const double p = axisP(grid.nx) * axisP(grid.ny) * axisP(grid.nz);
  const double ux = s1Of(grid.nx), uy = s1Of(grid.ny), uz = s1Of(grid.nz);
  const double g = s3Of(grid.nx) * uy * uz + ux * s3Of(grid.ny) * uz + ux * uy * s3Of(grid.nz) -
                   2 * ux * uy * uz;
  // Composite interpolation tables (32 bytes per fine index per axis and level) and 1D transfers.
  const double tables = (32 + 24 + 40) * double(grid.nx + grid.ny + grid.nz) * count;
  const double c0x = coarsenedSize(grid.nx), c0y = coarsenedSize(grid.ny);
  const double scratch = 24 * (c0x * grid.ny * grid.nz + c0x * c0y * grid.nz);
  const double steady = 248 * R + levels + tables + 16 * coarsest * coarsest + scratch + 24 * n;
  const double t1 = 288 * n;
  const double t2 = 92 * n + (12 * p + 8) * n + (12 * g + 8) * n + 12 * m1;
  const double t3 = 92 * n + 2 * (12 * g + 8) * n + (12 * s1 + 8) * m1 + 12 * n;
  const double build = 80 * R + levels + tables + std::max({t1, t2, t3});
  return std::max(steady, build) + double(1 << 20);
}

Status MgPcgSolver::setGrid(const Grid& grid, double omega) {
  if (!grid.valid()) return Status::Error(StatusCode::InvalidInput, "grid must be at least 2^3");
  if (!std::isfinite(omega) || omega <= 0)
    return Status::Error(StatusCode::InvalidInput, "omega must be finite and positive");
  Status fits = checkGridIndexable(grid);
  if (!fits.ok()) return fits;
  fits = checkMemory("fast solver", estimateBytes(grid), memoryCap());
  if (!fits.ok()) return fits;
  const auto t0 = Clock::now();
  beta2_ = 0;  // a new grid has no prior (its G has the old grid's size)
  prior_.clear();
  prior_.shrink_to_fit();
  Status s = mg_.build(grid, mgOptions_);
  if (!s.ok()) return s;
  grid_ = grid;
  omega_ = omega;
  hasGrid_ = true;
  set_.clear();
  const size_t m = 3 * size_t(mg_.paddedRows());
  for (auto* v : {&x_, &b_, &r_, &z_, &p_, &q_}) v->assign(m, 0.0);
  runActive_ = false;
  coldStart_ = true;
  operatorsFresh_ = true;
  progress_ = MgProgress();
  progress_.errorEstimate = 0;
  progress_.converged = true;
  stats_ = SolveStats();
  stats_.method = "mg-pcg";
  stats_.setupMs = msSince(t0);
  return Status::Ok();
}

Status MgPcgSolver::setConstraints(const ConstraintSet& input) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "setGrid first");
  const bool deferAsked = deferFactor_;  // for this call only, whatever its outcome
  deferFactor_ = false;
  const auto t0 = Clock::now();
  Status s = validateConstraints(grid_, input);
  if (!s.ok()) return s;
  bool normal = true;
  for (size_t i = 1; i < input.size(); ++i) normal = normal && input[i - 1].index < input[i].index;
  const ConstraintSet next = normal ? input : normalizeConstraints(input);

  const ConstraintDiff d = diffConstraints(set_, next);
  // penalties added to fresh operators of an empty set before their first factorisation, in
  // ascending order, are what resetPenalties adds: the operators stay fresh; any other penalty
  // change makes them not (an empty set with a prior has a factor: additions update it)
  if (!d.removed.empty() || (!d.added.empty() && (!set_.empty() || mg_.hasFactor())))
    operatorsFresh_ = false;
  const double w = constrainedPenalty();
  for (int p : d.removed)
    if (!(s = mg_.setPenalty(p, beta2_)).ok()) return s;
  for (int p : d.added)
    if (!(s = mg_.setPenalty(p, w)).ok()) return s;
  set_ = next;
  const bool defer = deferAsked && mg_.hasFactor() && !coldStart_;
  assembleRhs();
  factorDeferred_ = false;
  if (!hasRhs()) {
    std::fill(x_.begin(), x_.end(), 0.0);
    coldStart_ = true;
  } else if (defer) {
    factorDeferred_ = true;  // the next setConstraints' or forgetWarmStart's prepare() catches up
    operatorsFresh_ = false;
  } else if (!(s = mg_.prepare()).ok()) {
    return s;
  }
  runActive_ = false;
  progress_ = MgProgress();
  stats_.method = "mg-pcg";
  stats_.added = int(d.added.size());
  stats_.removed = int(d.removed.size());
  stats_.changed = int(d.changed.size());
  stats_.iterations = 0;
  stats_.setupMs = msSince(t0);
  return Status::Ok();
}

void MgPcgSolver::assembleRhs() {
  const double w2 = omega_ * omega_;
  if (prior_.empty()) {
    std::fill(b_.begin(), b_.end(), 0.0);
    for (const Constraint& c : set_) {
      const int64_t r = mg_.paddedRow(c.index);
      for (int k = 0; k < 3; ++k) b_[3 * r + k] = w2 * c.target[k];
    }
    return;
  }
  std::copy(prior_.begin(), prior_.end(), b_.begin());
  for (const Constraint& c : set_) {
    const int64_t r = mg_.paddedRow(c.index);
    for (int k = 0; k < 3; ++k) b_[3 * r + k] = w2 * c.target[k] + prior_[3 * r + k];
  }
}

bool MgPcgSolver::samePrior(double beta2, const Field& G) const {
  if (beta2 == 0 || G.rows() == 0) return prior_.empty();
  if (prior_.empty()) return false;
  for (int p = 0; p < int(grid_.size()); ++p) {
    const int64_t r = mg_.paddedRow(p);
    for (int k = 0; k < 3; ++k)
      if (!(prior_[3 * r + k] == G(p, k) * beta2)) return false;
  }
  return true;
}

Status MgPcgSolver::setPrior(double beta2, const Field& G) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "setGrid first");
  Status s = validatePrior(grid_, beta2, G);
  if (!s.ok()) return s;
  if (beta2 == beta2_ && samePrior(beta2, G)) return Status::Ok();  // nothing to rebuild
  const auto t0 = Clock::now();
  // the operators of a fresh hierarchy with this base penalty, then the constraints' penalties
  // in ascending order: what setGrid, setPrior and setConstraints(set_) build
  if (!(s = mg_.setBasePenalty(beta2)).ok()) return s;
  beta2_ = beta2;
  if (beta2 != 0 && G.rows() > 0) {
    prior_.assign(3 * size_t(mg_.paddedRows()), 0.0);
    mg_.toPadded(G, prior_.data());
    for (double& v : prior_) v *= beta2;  // as G(p, k) * beta2 (samePrior)
  } else {
    prior_.clear();
    prior_.shrink_to_fit();
  }
  const double w = constrainedPenalty();
  for (const Constraint& c : set_)
    if (!(s = mg_.setPenalty(c.index, w)).ok()) return s;
  assembleRhs();
  // a history-free cold start; the coarsest factor is refactored when the run starts
  deferFactor_ = false;
  startFromZero();
  if (!hasRhs()) {
    progress_.errorEstimate = 0;
    progress_.converged = true;
  }
  stats_.method = "mg-pcg";
  stats_.iterations = 0;
  stats_.setupMs = msSince(t0);
  return Status::Ok();
}

// Fresh operators and a zero start: the next run starts cold (setPrior, forgetWarmStart).
void MgPcgSolver::startFromZero() {
  factorDeferred_ = false;
  operatorsFresh_ = true;
  std::fill(x_.begin(), x_.end(), 0.0);
  coldStart_ = true;
  runActive_ = false;
  progress_ = MgProgress();
}

bool MgPcgSolver::forgetWarmStart() {
  deferFactor_ = false;
  // a run that started cold on fresh operators (the first solve on a new grid) is already the
  // solve a reset would start: it goes on (CG's iterates do not depend on how they are sliced)
  // (a deferred factor update leaves the operators not fresh)
  lastForgetKept_ = operatorsFresh_ && (runActive_ ? runCold_ : coldStart_);
  if (lastForgetKept_) return true;
  // the operators as a fresh solver builds them (no rounding of earlier edits), and a zero start
  if (!mg_.resetPenalties().ok() || !mg_.prepare().ok()) return false;
  startFromZero();
  stats_.iterations = 0;
  return true;
}

// A cold start begins at the full-multigrid solution (a function of the constraints and the
// operators alone, which forgetWarmStart has rebuilt history-free), then fmgFineCycles V-cycle
// corrections on the fine level; a warm one at the previous field.
void MgPcgSolver::coldStartField() {
  mg_.fullMultigrid(b_.data(), x_.data(), mgOptions_.fmgCycles);
  const size_t rows = x_.size() / 3;
  for (int c = 0; c < mgOptions_.fmgFineCycles; ++c) {
    mg_.applyFine(x_.data(), q_.data());
    forRows(rows, [&](size_t i0, size_t i1) {
      for (size_t i = 3 * i0; i < 3 * i1; ++i) r_[i] = b_[i] - q_[i];
    });
    mg_.vcycle(r_.data(), z_.data());
    forRows(rows, [&](size_t i0, size_t i1) {
      for (size_t i = 3 * i0; i < 3 * i1; ++i) x_[i] += z_[i];
    });
  }
}

Status MgPcgSolver::startRun() {
  // no factor yet (setPrior, or a failed prepare): the first run brings it up to date
  if (!mg_.hasFactor()) {
    Status s = mg_.prepare();
    if (!s.ok()) return s;
  }
  if (coldStart_ && mgOptions_.fmgStart) coldStartField();
  runCold_ = coldStart_;
  coldStart_ = false;
  mg_.applyFine(x_.data(), q_.data());
  forRows(r_.size() / 3, [&](size_t i0, size_t i1) {
    for (size_t i = 3 * i0; i < 3 * i1; ++i) r_[i] = b_[i] - q_[i];
  });
  mg_.vcycle(r_.data(), z_.data());
  forRows(p_.size() / 3, [&](size_t i0, size_t i1) {
    std::copy(z_.begin() + 3 * i0, z_.begin() + 3 * i1, p_.begin() + 3 * i0);
  });
  dots3(r_, z_, gamma_);
  double bb[3];
  dots3(b_, b_, bb);
  bnorm2_ = bb[0] + bb[1] + bb[2];
  for (auto& h : steps_) h.clear();
  progress_ = MgProgress();
  directionPending_ = false;
  runActive_ = true;
  return Status::Ok();
}

// The direction after an update: z = M^-1 r (a V-cycle), p = z + beta p. Deferred to the start
// of the next iteration, so a run that ends (converged, superseded by new constraints, or a
// preview's last iteration) does not pay for a V-cycle whose direction is never used; the
// iterates are the same as computing it at the end of each iteration.
void MgPcgSolver::nextDirection() {
  mg_.vcycle(r_.data(), z_.data());
  double g[3], beta[3];
  dots3(r_, z_, g);
  for (int c = 0; c < 3; ++c) {
    beta[c] = (gamma_[c] > 0 && alpha_[c] != 0) ? g[c] / gamma_[c] : 0.0;
    gamma_[c] = alpha_[c] != 0 ? g[c] : 0.0;
  }
  const double* zv = z_.data();
  double* pw = p_.data();
  forRows(p_.size() / 3, [&](size_t i0, size_t i1) {
    for (size_t i = i0; i < i1; ++i)
      for (int c = 0; c < 3; ++c) pw[3 * i + c] = zv[3 * i + c] + beta[c] * pw[3 * i + c];
  });
  directionPending_ = false;
}

void MgPcgSolver::updateEstimate() {
  double est2 = 0;
  for (int c = 0; c < 3; ++c) {
    const std::vector<double>& h = steps_[c];
    if (h.empty() || h.back() == 0.0) continue;
    const size_t k = h.size();
    double rho = kRhoFirst;
    if (k >= 2) {
      const size_t m = std::min<size_t>(3, k - 1);
      const double prev = h[k - 1 - m];
      rho = prev > 0 ? std::pow(h.back() / prev, 1.0 / double(m)) : kRhoMax;
      rho = std::clamp(rho, kRhoMin, kRhoMax);
    }
    const double e = h.back() * rho / (1.0 - rho);
    est2 += e * e;
  }
  const double xn = std::sqrt(xx_[0] + xx_[1] + xx_[2]);
  const double est = kEstimateSafety * std::sqrt(est2);
  progress_.errorEstimate =
      est == 0 ? 0 : (xn > 0 ? est / xn : std::numeric_limits<double>::infinity());
  progress_.relResidual = bnorm2_ > 0 ? std::sqrt((rr_[0] + rr_[1] + rr_[2]) / bnorm2_) : 0;
}

Status MgPcgSolver::iterate(int maxIterations, double tolerance, MgProgress* out) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "setGrid first");
  const auto t0 = Clock::now();
  if (!hasRhs()) {  // no constraints and no prior: the field is zero by definition
    progress_ = MgProgress();
    progress_.errorEstimate = 0;
    progress_.converged = true;
    if (out) *out = progress_;
    return Status::Ok();
  }
  if (!runActive_) {
    Status s = startRun();
    if (!s.ok()) return s;
  }
  const size_t rows = r_.size() / 3;
  int done = 0;
  auto isConverged = [&] {
    // At least two iterations, so that the rate estimate has seen one ratio (unless exact).
    return progress_.errorEstimate <= tolerance &&
           (progress_.iterations >= 2 || progress_.errorEstimate == 0);
  };
  while (done < maxIterations && !(tolerance > 0 && isConverged())) {
    if (directionPending_) nextDirection();
    mg_.applyFine(p_.data(), q_.data());
    // p.q and p.p in one pass
    const double* pv = p_.data();
    const double* qv = q_.data();
    const auto pqpp =
        parallel::sumBlocks<6>(rows, kBlockRows, kGrainBlocks, [&](size_t i0, size_t i1) {
          std::array<double, 6> s{};
          for (size_t i = i0; i < i1; ++i)
            for (int c = 0; c < 3; ++c) {
              const double pc = pv[3 * i + c];
              s[c] += pc * qv[3 * i + c];
              s[3 + c] += pc * pc;
            }
          return s;
        });
    double pq[3], pp[3], alpha[3];
    for (int c = 0; c < 3; ++c) pq[c] = pqpp[c], pp[c] = pqpp[3 + c];
    for (int c = 0; c < 3; ++c) {
      alpha[c] = (gamma_[c] > 0 && pq[c] > 0 && std::isfinite(gamma_[c] / pq[c]))
                     ? gamma_[c] / pq[c]
                     : 0.0;
      steps_[c].push_back(std::abs(alpha[c]) * std::sqrt(pp[c]));
    }
    // x += alpha p, r -= alpha q, and x.x, r.r of the results (for the estimate)
    double* xv = x_.data();
    double* rv = r_.data();
    const auto xxrr =
        parallel::sumBlocks<6>(rows, kBlockRows, kGrainBlocks, [&](size_t i0, size_t i1) {
          std::array<double, 6> s{};
          for (size_t i = i0; i < i1; ++i)
            for (int c = 0; c < 3; ++c) {
              const double xc = xv[3 * i + c] + alpha[c] * pv[3 * i + c];
              const double rc = rv[3 * i + c] - alpha[c] * qv[3 * i + c];
              xv[3 * i + c] = xc;
              rv[3 * i + c] = rc;
              s[c] += xc * xc;
              s[3 + c] += rc * rc;
            }
          return s;
        });
    for (int c = 0; c < 3; ++c) xx_[c] = xxrr[c], rr_[c] = xxrr[3 + c], alpha_[c] = alpha[c];
    directionPending_ = true;
    ++done;
    ++progress_.iterations;
    updateEstimate();
    if (hook_) {
      IterateProgress pr;
      pr.iterations = progress_.iterations;
      pr.errorEstimate = progress_.errorEstimate;
      pr.relResidual = progress_.relResidual;
      if (!keepGoing(pr)) {
        stats_.iterations = progress_.iterations;
        stats_.residual = progress_.relResidual;
        stats_.solveMs = msSince(t0);
        if (out) *out = progress_;
        return Status::Error(StatusCode::Cancelled,
                             "fast: stopped after " + std::to_string(progress_.iterations) +
                                 " iterations (error estimate " +
                                 std::to_string(progress_.errorEstimate) + ")");
      }
    }
  }
  progress_.converged = isConverged();
  if (!std::isfinite(progress_.relResidual))
    return Status::Error(StatusCode::NotConverged, "non-finite residual");
  stats_.iterations = progress_.iterations;
  stats_.residual = progress_.relResidual;
  stats_.solveMs = msSince(t0);
  if (out) *out = progress_;
  return Status::Ok();
}

void MgPcgSolver::field(Field& T) const {
  if (!hasGrid_) {
    T.resize(0, 3);
    return;
  }
  mg_.fromPadded(x_.data(), T);
}

Status MgPcgSolver::solve(Field& T) {
  Status s = iterate(maxIterations_, tolerance_);
  if (!s.ok()) return s;
  field(T);
  if (!progress_.converged)
    return Status::Error(StatusCode::NotConverged,
                         "error estimate " + std::to_string(progress_.errorEstimate) + " after " +
                             std::to_string(progress_.iterations) + " iterations");
  return Status::Ok();
}

size_t MgPcgSolver::memoryBytes() const {
  return mg_.memoryBytes() +
         (x_.size() + b_.size() + r_.size() + z_.size() + p_.size() + q_.size() + prior_.size()) *
             sizeof(double) +
         set_.size() * sizeof(Constraint);
}

}  // namespace hairsketch
