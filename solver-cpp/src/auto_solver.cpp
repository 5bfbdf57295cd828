#include "auto_solver.hpp"

#include "exact_solver.hpp"
#include "mg_pcg_solver.hpp"

namespace hairsketch {

std::unique_ptr<FieldSolver> AutoSolver::pick(const Grid& grid) {
  if (grid.size() <= kExactMaxPoints) return std::make_unique<ExactSolver>();
  return std::make_unique<MgPcgSolver>();
}

double AutoSolver::estimateBytes(const Grid& grid) const { return pick(grid)->estimateBytes(grid); }

void AutoSolver::setProgressHook(ProgressHook hook) {
  hook_ = hook;
  if (inner_) inner_->setProgressHook(std::move(hook));
}

Status AutoSolver::setGrid(const Grid& grid, double omega) {
  inner_ = pick(grid);
  inner_->setMemoryCap(memoryCap());
  inner_->setProgressHook(hook_);
  return inner_->setGrid(grid, omega);
}

Status AutoSolver::setPrior(double beta2, const Field& G) {
  if (!inner_) return Status::Error(StatusCode::NotReady, "setPrior before setGrid");
  return inner_->setPrior(beta2, G);
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
