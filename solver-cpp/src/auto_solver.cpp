#include "auto_solver.hpp"

#include "exact_solver.hpp"
#include "mg_pcg_solver.hpp"

namespace hairsketch {

Status AutoSolver::setGrid(const Grid& grid, double omega) {
  if (grid.size() <= kExactMaxPoints)
    inner_ = std::make_unique<ExactSolver>();
  else
    inner_ = std::make_unique<MgPcgSolver>();
  return inner_->setGrid(grid, omega);
}

Status AutoSolver::setConstraints(const ConstraintSet& next) {
  if (!inner_) return Status::Error(StatusCode::NotReady, "setConstraints before setGrid");
  return inner_->setConstraints(next);
}

Status AutoSolver::solve(Field& T) {
  if (!inner_) return Status::Error(StatusCode::NotReady, "solve before setGrid");
  return inner_->solve(T);
}

Status AutoSolver::iterate(int maxIterations, double tolerance, Field& T,
                           IterateProgress& progress) {
  if (!inner_) return Status::Error(StatusCode::NotReady, "iterate before setGrid");
  return inner_->iterate(maxIterations, tolerance, T, progress);
}

const SolveStats& AutoSolver::stats() const {
  if (!inner_) return stats_;
  stats_ = inner_->stats();
  stats_.method = "auto:" + stats_.method;
  return stats_;
}

}  // namespace hairsketch
