// FieldSolver "fast": conjugate gradients on (D^T D + omega^2 S) T = omega^2 S C (method S2.3;
// with a prior (D^T D + omega^2 S + beta^2 I) T = omega^2 S C + beta^2 G, beta^2 a base penalty
// of the hierarchy at every point: MultigridHierarchy::setBasePenalty),
// preconditioned by one symmetric geometric multigrid V-cycle per iteration
// (multigrid_hierarchy.hpp), three right-hand sides (x, y, z) run together, warm-started from
// the previous field. Every loop runs in parallel on parallel.hpp's threads (the V-cycle's, and
// the CG vector operations with their dot products as ordered sums over fixed blocks), so any
// thread count gives the same bits.
//
// Stopping. The relative residual is useless here (field error ~ 2e4 x it at 37^3, and the factor
// grows like N^4 with the grid). Instead each column tracks the CG step lengths
// u_k = |alpha_k| ||p_k|| (= ||T_{k+1} - T_k||); with the observed contraction rate rho (geometric
// mean of the last 3 step ratios, clamped to [0.3, 0.95]) the remaining error is estimated by
// the tail of a geometric series u_k rho / (1 - rho), times a safety factor of 2:
//   errorEstimate = 2 sqrt(sum_c est_c^2) / ||T_k||_F   ~>=  ||T_k - T*||_F / ||T*||_F.
// tests/native/multigrid_test.cpp checks that this bounds the true error on random constraint
// sets, edit sequences and irregular grids.
//
// Scheduler use (the solve state survives between calls; an edit restarts CG warm):
//   setConstraints(next);                  // O(#changed points) hierarchy update + tiny refactor
//   iterate(3, 0);  field(T);              // quick preview after a few iterations
//   iterate(50, 1e-3);  field(T);          // "good enough to show"
//   iterate(200, 1e-6); field(T);          // converged (equals the exact solve to ~1e-6)
//   iterate(k, 1e-10);                     // keep refining while idle, k per time slice
#pragma once

#include <limits>
#include <vector>

#include "field_solver.hpp"
#include "multigrid_hierarchy.hpp"

namespace hairsketch {

struct MgProgress {
  int iterations = 0;  // CG iterations since the last edit
  double errorEstimate = std::numeric_limits<double>::infinity();  // ~ ||T-T*||_F / ||T*||_F
  double relResidual = 0;  // ||B - M T||_F / ||B||_F (recursive residual; for reference only)
  bool converged = false;  // errorEstimate <= the tolerance of the last iterate() call
};

class MgPcgSolver : public FieldSolver {
 public:
  explicit MgPcgSolver(const MultigridOptions& mg = {}) : mgOptions_(mg) {}

  Status setGrid(const Grid& grid, double omega) override;
  double estimateBytes(const Grid& grid) const override;
  // Rebuilds the coarse operators for the new beta^2 (the constraints' penalties added again in
  // ascending order, as a fresh solver adds them), the right-hand side, and starts the next
  // solve cold from a history-free state (as after forgetWarmStart); the coarsest factor is
  // refactored when the next run starts. The same beta^2 and G again change nothing.
  Status setPrior(double beta2, const Field& G) override;
  // Validates (InvalidInput on bad index / non-finite target, nothing changed then), normalises
  // an unsorted set, updates penalties on all levels for the added/removed points.
  Status setConstraints(const ConstraintSet& next) override;
  // iterate(maxIterations(), tolerance()) then field(T). NotConverged (T still written) when the
  // budget ran out first.
  Status solve(Field& T) override;
  const SolveStats& stats() const override { return stats_; }
  std::string name() const override { return "fast"; }

  // Runs at most maxIterations more CG iterations of the current solve, stopping early once
  // errorEstimate <= tolerance (tolerance 0: run exactly maxIterations).
  Status iterate(int maxIterations, double tolerance, MgProgress* progress = nullptr);
  bool forgetWarmStart() override;
  // The next setConstraints changes the operators and their penalties but leaves the coarsest
  // factor's rank-1 updates (or refactorisation) pending, when a factor exists: the run until
  // the next prepare solves the coarsest level with the factor of the previous penalties.
  void deferPreconditionerUpdate() override { deferFactor_ = true; }
  // Whether the coarsest factor lags the constraints (tests).
  bool factorDeferred() const { return factorDeferred_; }
  // Whether the last forgetWarmStart found the run already history-free and kept it (tests).
  bool lastForgetKeptRun() const { return lastForgetKept_; }
  // FieldSolver's progressive interface: the call above, then field(T).
  Status iterate(int maxIterations, double tolerance, Field& T,
                 IterateProgress& progress) override {
    MgProgress p;
    Status s = iterate(maxIterations, tolerance, &p);
    field(T);
    progress.iterations = p.iterations;
    progress.errorEstimate = p.errorEstimate;
    progress.converged = p.converged;
    return s;
  }
  // Current iterate (n x 3); after an edit and before any iteration: the previous field.
  void field(Field& T) const;
  const MgProgress& progress() const { return progress_; }

  void setTolerance(double t) { tolerance_ = t; }
  double tolerance() const { return tolerance_; }
  void setMaxIterations(int m) { maxIterations_ = m; }
  int maxIterations() const { return maxIterations_; }

  const MultigridHierarchy& hierarchy() const { return mg_; }
  size_t memoryBytes() const;

 private:
  Status startRun();
  void assembleRhs();  // b_ from set_ and prior_
  // prior_ is beta2 G (for the current beta2_): setPrior has nothing to do.
  bool samePrior(double beta2, const Field& G) const;
  // A field is to be solved for: constraints, or a prior with a right-hand side.
  bool hasRhs() const { return !set_.empty() || !prior_.empty(); }
  // Fine penalty of a constrained point (beta^2 = 0: omega^2 exactly).
  double constrainedPenalty() const { return omega_ * omega_ + beta2_; }
  void coldStartField();
  void startFromZero();
  void updateEstimate();
  void nextDirection();

  MultigridOptions mgOptions_;
  MultigridHierarchy mg_;
  Grid grid_;
  double omega_ = kDefaultOmega;
  bool hasGrid_ = false;
  ConstraintSet set_;
  double beta2_ = 0;           // the prior's weight (the hierarchy's base penalty)
  std::vector<double> prior_;  // beta^2 G, padded n x 3 (empty: no prior right-hand side)
  double tolerance_ = 1e-6;
  int maxIterations_ = 500;

  // Padded n x 3 vectors (see MultigridHierarchy): field, rhs, CG residual, preconditioned
  // residual, direction, M * direction.
  std::vector<double> x_, b_, r_, z_, p_, q_;
  bool runActive_ = false;
  // The next run starts cold (after setGrid, forgetWarmStart, or an empty set zeroed the field):
  // from the full-multigrid solution instead of the previous field (MultigridOptions::fmgStart).
  bool coldStart_ = true;
  // deferPreconditionerUpdate was called / the last setConstraints left the factor behind.
  bool deferFactor_ = false;
  bool factorDeferred_ = false;
  // The operators and the coarsest factor are those a fresh hierarchy builds for the current
  // penalties (setGrid, or forgetWarmStart, then at most the first constraints added to an
  // empty set: the same additions in the same order), and the current run started cold with
  // them: it is then already the history-free solve forgetWarmStart would start.
  bool operatorsFresh_ = false;
  bool runCold_ = false;
  bool lastForgetKept_ = false;
  double gamma_[3] = {0, 0, 0};
  // The last iteration's step lengths; its direction update is still to do (nextDirection).
  double alpha_[3] = {0, 0, 0};
  bool directionPending_ = false;
  double bnorm2_ = 0;
  double xx_[3] = {0, 0, 0}, rr_[3] = {0, 0, 0};  // column norms^2 of x and r (after an update)
  std::vector<double> steps_[3];                  // u_k per column
  MgProgress progress_;
  SolveStats stats_;
};

}  // namespace hairsketch
