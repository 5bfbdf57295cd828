#include "exact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "elapsed.hpp"

namespace hairsketch {
// Memory of the exact path (bytes; n points):
//   analysis   <= 1200 n   assembling M = D^T D (triplets, D, D^T, the product), the
//                          dissection and the supernodal rows (measured 680-1090 n)
//   held        = 304 n (M: 25 entries of 12 bytes + column pointers) + 12 n (perm, iperm,
//                 colSuper) + 4 rows + 48 supernodes   after the analysis
//   factor      = 8 (storedEntries + peakWorkEntries) + 4 n   the values, the update matrices
//                 alive at once during a factorisation (symbolic count), the row map
//   solve       = 160 n   rhs, field, permuted copy, refinement residual and M T (24 n each),
//                 the penalty vector (8 n) of a refactorisation, 8 n slack, the prior's
//                 beta^2 G (24 n)
// Before the analysis the factor is estimated from the dims: with a <= b <= c the box's sides,
// storedEntries ~ 22 n sqrt(a b) (measured 0.8-1.0x of the symbolic count on cubes 10^3-80^3,
// 2 x 2 x 2000, 4 x 4 x 3000, 12 x 30 x 40, 100 x 100 x 10) and peakWorkEntries ~ 0.6 of it.
namespace {
constexpr double kAnalysisBytesPerPoint = 1200, kSolveBytesPerPoint = 160;

double heldBytes(double n, double rows, double supernodes) {
  return 316 * n + 4 * rows + 48 * supernodes;
}
}  // namespace

double ExactSolver::estimateBytes(const Grid& grid) const {
  const double n = double(grid.nx) * grid.ny * grid.nz;
  if (hasGrid_ && grid.nx == grid_.nx && grid.ny == grid_.ny && grid.nz == grid_.nz)
    return analysedBytes();
  double d[3] = {double(grid.nx), double(grid.ny), double(grid.nz)};
  std::sort(d, d + 3);
  const double stored = 22 * n * std::sqrt(d[0] * d[1]);
  return kAnalysisBytesPerPoint * n + 8 * 1.6 * stored + kSolveBytesPerPoint * n + double(1 << 20);
}

double ExactSolver::analysedBytes() const {
  const SupernodalSymbolic& S = factor_.symbolic();
  const double n = S.n;
  return heldBytes(n, double(S.row.size()), S.supernodes()) + double(S.factorBytes()) + 4 * n +
         kSolveBytesPerPoint * n + double(1 << 20);
}

Status ExactSolver::setGrid(const Grid& grid, double omega) {
  if (hasGrid_) return Status::Error(StatusCode::InvalidInput, "exact: setGrid called twice");
  if (!grid.valid())
    return Status::Error(StatusCode::InvalidInput, "exact: grid must be at least 2x2x2");
  if (!std::isfinite(omega) || omega <= 0)
    return Status::Error(StatusCode::InvalidInput, "exact: omega must be finite and positive");
  Status fits = checkGridIndexable(grid);
  if (!fits.ok()) return fits;
  const int64_t cap = memoryCap();
  const double n = double(grid.nx) * grid.ny * grid.nz;
  // Before analysing: refuse when the analysis alone would not fit, or when the estimate from
  // the dims is over twice the cap (it errs by less than 1.3x), so that a large grid is refused
  // at once. Otherwise the symbolic count decides, before the factor is allocated.
  const double rough = estimateBytes(grid);
  if (kAnalysisBytesPerPoint * n > double(cap) || rough > 2 * double(cap))
    return checkMemory("exact solver", std::max(rough, double(cap) + 1), cap);
  const auto t0 = Clock::now();
  M_ = assembleBiLaplacian(grid);
  factor_.analyse(M_, boxNestedDissection(grid, opt_.dissection));
  const double bytes = analysedBytes();
  if (bytes > double(cap)) {
    factor_ = SupernodalFactor();
    M_ = SparseMatrix();
    return checkMemory("exact solver", bytes, cap);
  }
  grid_ = grid;
  omega_ = omega;
  hasGrid_ = true;
  stats_ = SolveStats();
  stats_.method = "analyse";
  stats_.setupMs = msSince(t0);
  return Status::Ok();
}

double ExactSolver::estimateUpdateFlops(const std::vector<int>& gridPoints) const {
  std::vector<int> pos;
  pos.reserve(gridPoints.size());
  for (int g : gridPoints) pos.push_back(factor_.symbolic().iperm[size_t(g)]);
  return estimateModifyFlops(factor_.symbolic(), pos);
}

Status ExactSolver::refactor() {
  // beta^2 = 0: exactly the penalties without a prior (0 + omega^2 = omega^2).
  Eigen::VectorXd penalty = Eigen::VectorXd::Constant(grid_.size(), beta2_);
  for (const Constraint& c : current_) penalty[c.index] += omega_ * omega_;
  Status st = factor_.factorize(M_, penalty);
  factored_.clear();
  modified_ = false;
  if (!st.ok()) return st;
  for (const Constraint& c : current_) factored_.push_back(c.index);
  return Status::Ok();
}

Status ExactSolver::setConstraints(const ConstraintSet& next) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "exact: no grid");
  Status v = validateConstraints(grid_, next);
  if (!v.ok()) return v;
  for (size_t i = 1; i < next.size(); ++i)
    if (next[i - 1].index >= next[i].index)
      return Status::Error(StatusCode::InvalidInput,
                           "exact: constraints must be sorted by index and unique");
  const auto t0 = Clock::now();
  const ConstraintDiff diff = diffConstraints(current_, next);
  stats_ = SolveStats();
  stats_.added = int(diff.added.size());
  stats_.removed = int(diff.removed.size());
  stats_.changed = int(diff.changed.size());
  current_ = next;

  if (current_.empty() && beta2_ == 0) {
    // Zero field by definition; D^T D alone is singular, so the factor keeps its last state.
    stats_.method = "zero";
    stats_.setupMs = msSince(t0);
    return Status::Ok();
  }

  // The factor's edit is relative to the set it holds, which may predate a "zero" step.
  std::vector<int> nextIdx;
  nextIdx.reserve(current_.size());
  for (const Constraint& c : current_) nextIdx.push_back(c.index);
  std::vector<int> add, remove;
  std::set_difference(nextIdx.begin(), nextIdx.end(), factored_.begin(), factored_.end(),
                      std::back_inserter(add));
  std::set_difference(factored_.begin(), factored_.end(), nextIdx.begin(), nextIdx.end(),
                      std::back_inserter(remove));

  Status st;
  if (!factor_.valid()) {
    stats_.method = "factor";
    st = refactor();
  } else if (add.empty() && remove.empty() && injectBad_ < 0) {
    stats_.method = "rhs";
  } else {
    std::vector<int> all = add;
    all.insert(all.end(), remove.begin(), remove.end());
    const double updateCost = estimateUpdateFlops(all) / opt_.updateRate;
    const double refactorCost = factorFlops() / opt_.factorRate;
    const bool update =
        opt_.policy == ExactSolverOptions::Policy::AlwaysUpdate ||
        (opt_.policy == ExactSolverOptions::Policy::Auto && updateCost < refactorCost);
    if (update) {
      // Updates first, then downdates: every intermediate matrix stays positive definite.
      std::vector<DiagonalTerm> terms;
      terms.reserve(all.size() + 1);
      const double w2 = omega_ * omega_;
      for (int g : add) terms.push_back({factor_.symbolic().iperm[size_t(g)], w2});
      for (int g : remove) terms.push_back({factor_.symbolic().iperm[size_t(g)], -w2});
      if (injectBad_ >= 0) {
        terms.push_back({factor_.symbolic().iperm[size_t(injectBad_)], -w2});
        injectBad_ = -1;
      }
      st = modifyDiagonal(factor_, terms, opt_.update);
      if (st.ok()) {
        modified_ = true;
        stats_.method = "update";
        factored_ = std::move(nextIdx);
      } else {
        // Never continue from the damaged factor: refactor from M.
        stats_.method = "recover";
        st = refactor();
      }
    } else {
      stats_.method = "refactor";
      st = refactor();
    }
  }
  stats_.setupMs = msSince(t0);
  return st;
}

Status ExactSolver::setPrior(double beta2, const Field& G) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "exact: no grid");
  Status v = validatePrior(grid_, beta2, G);
  if (!v.ok()) return v;
  const auto t0 = Clock::now();
  if (beta2 != 0 && G.rows() > 0)
    priorRhs_ = beta2 * G;
  else
    priorRhs_.resize(0, 3);
  if (beta2 == beta2_) return Status::Ok();  // the matrix is unchanged
  beta2_ = beta2;
  stats_ = SolveStats();
  // The factor holds the old beta^2: refactor now when a solve needs one (constraints, or a
  // prior alone), else drop it so that the next constraints factor afresh.
  Status st;
  if (!current_.empty() || beta2_ != 0) {
    stats_.method = "prior";
    st = refactor();
  } else {
    factor_.invalidate();
    factored_.clear();
    modified_ = false;
    stats_.method = "zero";
  }
  stats_.setupMs = msSince(t0);
  return st;
}

Status ExactSolver::solve(Field& T) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "exact: no grid");
  const auto t0 = Clock::now();
  if (current_.empty() && priorRhs_.rows() == 0) {  // no right-hand side: the field is zero
    T = Field::Zero(grid_.size(), 3);
    stats_.solveMs = msSince(t0);
    return Status::Ok();
  }
  if (!factor_.valid())
    return Status::Error(StatusCode::NotPositiveDefinite, "exact: no valid factorisation");
  Field B = assembleRhs(grid_, current_, omega_);
  if (priorRhs_.rows() > 0) B += priorRhs_;
  T = B;
  factor_.solveInPlace(T);
  stats_.iterations = 0;
  if (modified_) {
    // The modified factor carries the rounding of every update/downdate since the last fresh
    // factorisation (downdates of omega^2 lose digits to cancellation), which the solution
    // amplifies by the condition number. Iterative refinement against the exact matrix removes
    // it: R = B - M T, T += A^-1 R. The size of the correction is the error estimate.
    const double w2 = omega_ * omega_;
    for (int it = 0; it < 3; ++it) {  // usually one step
      Field R = B - M_ * T;
      for (const Constraint& c : current_) R.row(c.index) -= w2 * T.row(c.index);
      if (beta2_ != 0) R -= beta2_ * T;
      factor_.solveInPlace(R);
      T += R;
      stats_.iterations = it + 1;
      const double rel = R.norm() / std::max(T.norm(), 1e-300);
      stats_.residual = rel;
      if (rel < 1e-8) break;  // the next correction would be ~rel^2: negligible
    }
    // Refinement did not settle: the modified factor is too far off. Refactor from M and solve
    // again (never return a field that is not exact).
    if (!(stats_.residual <= 1e-8)) {
      stats_.method = "recover";
      Status st = refactor();
      if (!st.ok()) return st;
      T = B;
      factor_.solveInPlace(T);
    }
  }
  stats_.solveMs = msSince(t0);
  if (!T.allFinite())
    return Status::Error(StatusCode::NotPositiveDefinite,
                         "exact: solve produced non-finite values");
  return Status::Ok();
}

}  // namespace hairsketch
