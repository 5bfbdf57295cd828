// One interface for every way of solving the field system (method S2.3), with the optional weak
// prior of a natural fall (hair_fall.hpp):
//   (D^T D + omega^2 S + beta^2 I) T = omega^2 S C + beta^2 G,
// the minimiser of E(T) = ||D T||^2 + omega^2 sum_{p in C} ||t_p - c_p||^2
//                        + beta^2 sum_p ||t_p - g_p||^2   (fieldEnergy with the prior).
// A solver is stateful: it caches whatever it has built (factor, hierarchy, previous field) and
// is told the whole new constraint set on each edit; it works out the difference itself (S3.2).
// Phases: setGrid (analyse) -> setPrior (optional, rare: may rebuild / refactor) ->
// setConstraints (factorise / update / downdate) -> solve.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "constraints.hpp"
#include "field_system.hpp"
#include "grid.hpp"
#include "memory_budget.hpp"
#include "status.hpp"

namespace hairsketch {

struct SolveStats {
  std::string method;   // what the last setConstraints/solve did, e.g. "cg", "update", "refactor"
  int iterations = 0;   // iterative solvers: iterations of the last solve
  double residual = 0;  // relative residual of the last solve (if the solver tracks it)
  int added = 0, removed = 0, changed = 0;  // size of the last edit
  double setupMs = 0, solveMs = 0;
};

struct IterateProgress {
  int iterations = 0;        // since the last setConstraints
  double errorEstimate = 0;  // estimated relative error of the current iterate
  bool converged = false;
  double relResidual = 0;  // ||B - M T|| / ||B|| of the current iterate (if tracked)
};

class FieldSolver {
 public:
  virtual ~FieldSolver() = default;
  // Analyse the grid (no constraints yet). Called once; a new grid needs a new solver.
  // Refuses with OverMemoryCap, before allocating, when estimateBytes(grid) > memoryCap().
  virtual Status setGrid(const Grid& grid, double omega) = 0;
  // An upper estimate of the bytes this solver allocates at its peak over setGrid,
  // setConstraints and solve on this grid (its arrays, the temporaries of building them, and
  // the n x 3 field solve() writes), from the dims alone: no allocation. Each solver documents
  // its formula; tests/native/memory_estimate_probe.cpp checks it against measured peaks.
  virtual double estimateBytes(const Grid& grid) const = 0;
  // The cap setGrid checks against; by default (negative) availableMemoryBytes() at the call.
  void setMemoryCap(int64_t bytes) { memoryCap_ = bytes; }
  int64_t memoryCap() const { return memoryCap_ >= 0 ? memoryCap_ : availableMemoryBytes(); }
  // Iterative solvers call the hook about once per iteration of solve()/iterate() (the caller
  // throttles); returning false stops the solve with StatusCode::Cancelled. Direct solvers never
  // call it.
  using ProgressHook = std::function<bool(const IterateProgress&)>;
  virtual void setProgressHook(ProgressHook hook) { hook_ = std::move(hook); }
  // The prior: beta2 >= 0 and finite, G n x 3 and finite, or empty meaning zero; otherwise
  // InvalidInput and nothing changes (NotReady before setGrid). beta2 = 0 (the default, and what
  // setGrid restores) gives bit-identical fields to a solver that never had a prior. May be
  // called again at any time (the head changed); the solver then rebuilds what depends on it
  // (the direct solver refactors, the multigrid one rebuilds its coarse operators and starts its
  // next solve cold). Constraints set before it are kept. This default accepts beta2 = 0 only.
  virtual Status setPrior(double beta2, const Field& G) {
    (void)G;
    if (beta2 == 0) return Status::Ok();
    return Status::Error(StatusCode::InvalidInput, name() + ": no prior term");
  }
  // Replace the constraint set (normalised: sorted, unique, validated by the caller or here).
  virtual Status setConstraints(const ConstraintSet& next) = 0;
  // Solve for the field of the current constraints. T is resized to n x 3.
  // With no constraints and no prior (beta2 = 0 or G = 0) the field is zero by definition; with
  // a prior it is the prior's smooth fit (D^T D + beta^2 I) T = beta^2 G.
  virtual Status solve(Field& T) = 0;
  // Progressive solving: at most maxIterations more iterations, stopping once the estimated
  // relative field error is <= tolerance; T receives the current iterate. Direct solvers (and
  // this default) solve fully: converged, error 0 (rounding).
  virtual Status iterate(int maxIterations, double tolerance, Field& T, IterateProgress& progress) {
    (void)maxIterations;
    (void)tolerance;
    Status s = solve(T);
    progress.iterations = stats().iterations;
    progress.errorEstimate = 0;
    progress.converged = s.ok();
    return s;
  }
  virtual const SolveStats& stats() const = 0;
  virtual std::string name() const = 0;
  // Iterative solvers start the next solve()/iterate() from zero instead of the previous field,
  // so the converged field depends on the constraints alone, not on the edits before them (a
  // share link then reopens bit-identical hair). Returns whether there was a warm start to
  // forget (direct solvers: false, their result never depends on history).
  virtual bool forgetWarmStart() { return false; }
  // The next setConstraints may leave the solver's costliest incremental update to its
  // preconditioner undone (MgPcgSolver: the coarsest factor), for a few iterations that
  // forgetWarmStart follows (a first look): a weaker preconditioner for those, no update whose
  // result the reset would throw away. A later setConstraints or forgetWarmStart catches up.
  // The iterates stay a PCG run with a symmetric positive definite preconditioner.
  virtual void deferPreconditionerUpdate() {}

 protected:
  bool keepGoing(const IterateProgress& p) const { return !hook_ || hook_(p); }
  int64_t memoryCap_ = -1;
  ProgressHook hook_;
};

// Factory by name: "cg" (plain conjugate gradients, the reference path), "fast" (multigrid-
// preconditioned CG, mg_pcg_solver.hpp), "exact" (supernodal LDL^T with updates,
// exact_solver.hpp), "auto" (exact on small grids, fast above, auto_solver.hpp); nullptr for an
// unknown name.
std::unique_ptr<FieldSolver> makeFieldSolver(const std::string& name);

}  // namespace hairsketch
