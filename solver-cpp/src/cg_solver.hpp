// Jacobi-preconditioned conjugate gradient on M = D^T D + omega^2 S (+ beta^2 I with a prior;
// method S2.3, FieldSolver::setPrior), matrix-free,
// the three components (x, y, z) solved together with one operator pass per iteration.
//
// Stopping (SOLVER-NOTES "CG stopping trap"): the omega^2 rows dominate ||b||, so a small
// relative residual can still leave a large error in the field (measured: error ~ 1e4 x
// relative residual). We bound the error instead. With P = diag(M) and A' = P^-1/2 M P^-1/2,
//   ||x - x*||_2 = ||P^-1/2 A'^-1 P^-1/2 r||_2 <= ||r||_2 / (min(P) * lambda_min(A')),
// and lambda_min(A') is estimated by the smallest Ritz value of the Lanczos tridiagonal that
// PCG builds from its own alpha/beta coefficients (Golub & Van Loan 10.2.6); the Ritz value
// approaches lambda_min from above and has converged long before the residual is small. A
// component stops when that bound is <= errorTolerance * ||x_c||. The tests check the
// result against a dense direct solve.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "field_solver.hpp"

namespace hairsketch {

struct CgOptions {
  // Bound on the relative error ||x - x*|| / ||x|| per component. The bound is pessimistic: on a
  // 28x36x28 stroke, 1e-5 gave a measured error of 4e-8 (bench/cg_stroke_bench.cpp).
  double errorTolerance = 1e-5;
  double residualGate = 1e-7;  // the bound is evaluated once ||r|| / ||b|| is below this
  int maxIterations = 50000;
  bool warmStart = true;  // start from the previous solution of the same grid
};

class CgSolver : public FieldSolver {
 public:
  CgSolver() = default;
  explicit CgSolver(const CgOptions& options) : options_(options) {}

  Status setGrid(const Grid& grid, double omega) override;
  double estimateBytes(const Grid& grid) const override;
  // beta^2 joins the penalty diagonal (and the Jacobi preconditioner), beta^2 G the right-hand
  // side; the warm start is kept (it is dropped column by column when worse than zero).
  Status setPrior(double beta2, const Field& G) override;
  Status setConstraints(const ConstraintSet& next) override;
  Status solve(Field& T) override;
  const SolveStats& stats() const override { return stats_; }
  std::string name() const override { return "cg"; }
  bool forgetWarmStart() override {
    previous_.resize(0, 3);
    return true;
  }
  // Estimated relative error bound of the last solve (max over components).
  double errorEstimate() const { return errorEstimate_; }

  // Y = (D^T D + omega^2 S + beta^2 I) X for X: n x 3. Same result as applyBiLaplacian(X) +
  // penalty * X, with the neighbour weights precomputed (the hot loop of the solver).
  void applyOperator(const Field& X, Field& Y) const;

 private:
  void rebuildPenalty();  // penalty_ from set_ and beta2_

  CgOptions options_;
  Grid grid_;
  double omega_ = kDefaultOmega;
  bool hasGrid_ = false;
  ConstraintSet set_;
  Eigen::VectorXd invCount_;  // 1 / |N(p)|
  Eigen::VectorXd biDiag_;    // diagonal of D^T D
  Eigen::VectorXd penalty_;   // omega^2 on constrained points, + beta^2 everywhere
  double beta2_ = 0;          // the prior's weight
  Field priorRhs_;            // beta^2 G (empty: no prior right-hand side)
  Field previous_;            // last solution (warm start)
  Field work_;                // L = D X in applyOperator
  SolveStats stats_;
  double errorEstimate_ = 0;
};

// Smallest eigenvalue of the symmetric tridiagonal matrix with diagonal diag and
// off-diagonal off (off[i] couples i and i+1), by Sturm-sequence bisection.
double smallestTridiagonalEigenvalue(const std::vector<double>& diag,
                                     const std::vector<double>& off);

}  // namespace hairsketch
