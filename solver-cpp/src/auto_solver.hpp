// FieldSolver "auto": picks the path per grid from a cost model and records the choice.
// The exact factorisation (paper §4.2) pays a factorisation up front, ~23-33 N^6 flops for an
// N^3 box with nested dissection (SOLVER-NOTES), and then updates whose cost is dominated by the
// dense root separator; multigrid-PCG costs ~25 iterations of O(n) work per edit. With the
// measured rates on this machine kind (wasm: ~8 GFLOP/s dense, ~7 ms per MG iteration at 37^3),
// the exact path answers an edit faster only on small grids, where its factor is cheap:
// below kExactMaxPoints grid points "auto" runs "exact", above it "fast".
// stats().method is "auto:" + the chosen solver's method, e.g. "auto:update", "auto:mg-pcg".
#pragma once

#include <memory>

#include "field_solver.hpp"

namespace hairsketch {

class AutoSolver : public FieldSolver {
 public:
  static constexpr int64_t kExactMaxPoints = 12000;

  Status setGrid(const Grid& grid, double omega) override;
  // The estimate of the solver this grid gets.
  double estimateBytes(const Grid& grid) const override;
  void setProgressHook(ProgressHook hook) override;
  Status setPrior(double beta2, const Field& G) override;
  Status setConstraints(const ConstraintSet& next) override;
  bool forgetWarmStart() override { return inner_ ? inner_->forgetWarmStart() : false; }
  void deferPreconditionerUpdate() override {
    if (inner_) inner_->deferPreconditionerUpdate();
  }
  Status solve(Field& T) override;
  Status iterate(int maxIterations, double tolerance, Field& T, IterateProgress& progress) override;
  const SolveStats& stats() const override;
  std::string name() const override { return "auto"; }
  // The solver chosen for the grid ("exact" or "fast"); empty before setGrid.
  std::string chosen() const { return inner_ ? inner_->name() : std::string(); }

 private:
  static std::unique_ptr<FieldSolver> pick(const Grid& grid);
  std::unique_ptr<FieldSolver> inner_;
  mutable SolveStats stats_;
};

}  // namespace hairsketch
