// Numeric supernodal LDL^T factorisation of M = D^T D + diag(penalty) (method S3.1) and the
// 3-right-hand-side solve. Multifrontal: each supernode's front is assembled from M and the
// children's update matrices, its own block is factored with dense kernels (Eigen LLT, TRSM,
// SYRK), and its update matrix is passed to the parent. The stored factor is LDL^T: the block
// of supernode s (nrows x width, column-major) holds D on its diagonal and the unit lower
// triangular L below it, so that factor_update can modify it in place.
#pragma once

#include <vector>

#include "field_system.hpp"
#include "status.hpp"
#include "supernodal_symbolic.hpp"

namespace hairsketch {

class SupernodalFactor {
 public:
  // Symbolic phase: keeps the analysis; the numeric factor is invalid until factorize.
  void analyse(const SparseMatrix& M, const DissectionTree& tree);
  // M: grid order, both triangles; penalty: grid order, n entries (omega^2 at constraints).
  // NotPositiveDefinite (and an invalid factor) when a pivot is not positive and finite.
  Status factorize(const SparseMatrix& M, const Eigen::VectorXd& penalty);
  // B (grid order, n x 3) <- A^{-1} B. Requires valid().
  void solveInPlace(Field& B) const;

  bool valid() const { return valid_; }
  void invalidate() { valid_ = false; }
  void release();  // frees the numeric values (keeps the analysis)
  const SupernodalSymbolic& symbolic() const { return sym_; }
  double* block(int s) { return values_.data() + sym_.valuePtr[size_t(s)]; }
  const double* block(int s) const { return values_.data() + sym_.valuePtr[size_t(s)]; }
  // D at elimination position k.
  double pivot(int k) const;

 private:
  SupernodalSymbolic sym_;
  std::vector<double> values_;
  bool valid_ = false;
};

}  // namespace hairsketch
