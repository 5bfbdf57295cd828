// FieldSolver "exact": the paper's §4.2 method (method S3). Nested-dissection ordering of the box,
// supernodal LDL^T of M = D^T D + omega^2 S, and on each edit either a multiple-rank
// update/downdate of the factor or a refactorisation, whichever the cost model says is cheaper
// (both are exact). stats().method records the choice:
//   "factor"   first factorisation,            "update"  factor modified on the diagonal,
//   "refactor" refactorised (cheaper),         "rhs"     only targets changed (no factor work),
//   "recover"  a downdate failed its pivot check (or refinement after updates did not settle)
//              and M was refactorised from scratch,
//   "zero"     no constraints and no prior: the field is zero (the factor is kept for the next
//              edit),
//   "prior"    setPrior refactorised M with the new beta^2.
// With a prior (setPrior) the base matrix is D^T D + beta^2 I: beta^2 joins the diagonal of every
// (re)factorisation and of the refinement's exact M; updates/downdates stay +-omega^2; with no
// constraints the factor of the base matrix gives the prior's field.
// After updates/downdates, solve() adds iterative refinement against the exact M (1-3 extra
// solves; stats().iterations counts them, stats().residual is the last relative correction), so
// the field equals that of a fresh factorisation to ~1e-12 however long the edit history.
#pragma once

#include <vector>

#include "factor_update.hpp"
#include "field_solver.hpp"
#include "grid_ordering.hpp"
#include "supernodal_factor.hpp"

namespace hairsketch {

// Per-target defaults, measured with bench/exact_bench (29^3 and 37^3, edits of 300 and 1000
// points): natively the blocked update kernel (Eigen GEMMs) wins; in wasm, where Eigen 3.4 has no
// SIMD path but the rank-1 strip sweeps auto-vectorise to simd128, the rank-1 kernel wins
// (0.57 s vs 0.74 s for 300 points at 29^3, 1.45 s vs 1.98 s at 37^3).
#if defined(__wasm__)
constexpr UpdateKernel kDefaultUpdateKernel = UpdateKernel::Rank1;
constexpr double kDefaultUpdateRate = 0.85;
#else
constexpr UpdateKernel kDefaultUpdateKernel = UpdateKernel::Blocked;
constexpr double kDefaultUpdateRate = 0.6;
#endif

struct ExactSolverOptions {
  DissectionOptions dissection;
  UpdateOptions update = [] {
    UpdateOptions u;
    u.kernel = kDefaultUpdateKernel;
    return u;
  }();
  // Cost model: seconds ~ flops / rate, with flops from the symbolic analysis (factorisation)
  // and the merged path lengths (estimateModifyFlops). Only the ratio matters; it was measured
  // per target (see above).
  double factorRate = 1.0;                 // relative speed of factorisation flops
  double updateRate = kDefaultUpdateRate;  // relative speed of update/downdate flops
  enum class Policy { Auto, AlwaysUpdate, AlwaysRefactor } policy = Policy::Auto;
  // The memory cap is FieldSolver::setMemoryCap (default: what the module has left).
};

class ExactSolver : public FieldSolver {
 public:
  explicit ExactSolver(ExactSolverOptions options = {}) : opt_(options) {}
  Status setGrid(const Grid& grid, double omega) override;
  // From the dims before setGrid; from the symbolic count (analysedBytes) after it.
  double estimateBytes(const Grid& grid) const override;
  // Refactors when beta2 changes (and a factor is needed); a new G alone changes only the
  // right-hand side.
  Status setPrior(double beta2, const Field& G) override;
  Status setConstraints(const ConstraintSet& next) override;
  Status solve(Field& T) override;
  const SolveStats& stats() const override { return stats_; }
  std::string name() const override { return "exact"; }
  // The estimate from the symbolic count of the analysed grid (see exact_solver.cpp).
  double analysedBytes() const;

  const SupernodalFactor& factor() const { return factor_; }
  // Cost-model estimates for an edit of the factored constraint set (flops).
  double estimateUpdateFlops(const std::vector<int>& gridPoints) const;
  double factorFlops() const { return factor_.symbolic().factorFlops; }
  // Test hook: the next update/downdate pass also removes omega^2 at this grid point (which is
  // not constrained), making the factor indefinite, to exercise detection and recovery.
  void injectBadDowndateForTest(int gridPoint) { injectBad_ = gridPoint; }

 private:
  Status refactor();

  ExactSolverOptions opt_;
  Grid grid_;
  double omega_ = kDefaultOmega;
  bool hasGrid_ = false;
  SparseMatrix M_;  // D^T D (the prior's beta^2 I is added to the diagonal where M is used)
  double beta2_ = 0;
  Field priorRhs_;  // beta^2 G (empty: none)
  SupernodalFactor factor_;
  ConstraintSet current_;      // the constraint set of the next solve
  std::vector<int> factored_;  // grid points whose penalty is in the factor (sorted)
  SolveStats stats_;
  int injectBad_ = -1;
  bool modified_ = false;  // the factor was updated/downdated since its factorisation
};

}  // namespace hairsketch
