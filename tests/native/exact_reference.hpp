// Independent references for the exact solver's tests: Eigen's SimplicialLDLT (AMD ordering,
// up-looking, no supernodes) on the assembled matrix, and small random problems.
#pragma once

#include <Eigen/SparseCholesky>
#include <random>

#include "field_system.hpp"

namespace hairsketch {
namespace testref {

inline Grid box(int nx, int ny, int nz) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  return g;
}

// M + diag(penalty), grid order.
inline SparseMatrix withPenalty(const SparseMatrix& M, const Eigen::VectorXd& penalty) {
  SparseMatrix D(M.rows(), M.cols());
  D.reserve(Eigen::VectorXi::Constant(M.cols(), 1));
  for (int i = 0; i < M.rows(); ++i) D.insert(i, i) = penalty[i];
  SparseMatrix A = M + D;
  A.makeCompressed();
  return A;
}

// Fresh Eigen SimplicialLDLT solves for many constraint sets on one grid (pattern analysed once:
// the diagonal is always stored, so the pattern does not depend on the set).
class ReferenceSolver {
 public:
  ReferenceSolver(const Grid& g, double omega) : g_(g), omega_(omega), M_(assembleBiLaplacian(g)) {
    ldlt_.analyzePattern(withPenalty(M_, Eigen::VectorXd::Zero(g.size())));
  }
  Field field(const ConstraintSet& set) {
    if (set.empty()) return Field::Zero(g_.size(), 3);
    ldlt_.factorize(withPenalty(M_, penaltyDiagonal(g_, set, omega_)));
    const Field B = assembleRhs(g_, set, omega_);
    return Field(Eigen::MatrixXd(ldlt_.solve(Eigen::MatrixXd(B))));
  }

 private:
  Grid g_;
  double omega_;
  SparseMatrix M_;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt_;
};

// Field of the constraint set by a fresh Eigen SimplicialLDLT solve.
inline Field referenceField(const Grid& g, const ConstraintSet& set, double omega) {
  if (set.empty()) return Field::Zero(g.size(), 3);
  const SparseMatrix A = withPenalty(assembleBiLaplacian(g), penaltyDiagonal(g, set, omega));
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(A);
  const Field B = assembleRhs(g, set, omega);
  Eigen::MatrixXd X = ldlt.solve(Eigen::MatrixXd(B));
  return Field(X);
}

inline double relError(const Field& a, const Field& ref) {
  const double r = ref.norm();
  return r == 0 ? a.norm() : (a - ref).norm() / r;
}

}  // namespace testref
}  // namespace hairsketch
