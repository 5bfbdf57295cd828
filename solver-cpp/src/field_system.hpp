// The linear system of method S2 on a grid:
//   D: n x n discrete Laplacian, (D t)_i = sum_{j in N(i)} (t_j - t_i) / |N(i)|, N(i) the face
//      neighbours that exist in the grid (S2.2);
//   M = D^T D + omega^2 S, S = diag(1 on constrained points), right-hand side
//   B = omega^2 S C (n x 3, one column per component; S2.3).
// With the optional prior (FieldSolver::setPrior): M + beta^2 I and B + beta^2 G.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "constraints.hpp"
#include "grid.hpp"
#include "status.hpp"

namespace hairsketch {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Field = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;  // T: n x 3, row = t_p

// Paper's constant omega (S2.3).
constexpr double kDefaultOmega = 100.0;

// D (n x n), assembled row by row from S2.2.
SparseMatrix assembleLaplacian(const Grid& grid);

// D^T D (n x n, symmetric, up to 25 entries per row), full (both triangles) storage.
SparseMatrix assembleBiLaplacian(const Grid& grid);

// omega^2 S C: n x 3.
Field assembleRhs(const Grid& grid, const ConstraintSet& set, double omega);

// omega^2 S C + beta2 G (G empty: zero; beta2 = 0: exactly assembleRhs(grid, set, omega)).
Field assembleRhs(const Grid& grid, const ConstraintSet& set, double omega, double beta2,
                  const Field& G);

// OK when beta2 is finite and >= 0 and G is empty or n x 3 and finite; InvalidInput otherwise.
Status validatePrior(const Grid& grid, double beta2, const Field& G);

// Diagonal of omega^2 S: n entries (omega^2 at constrained points, 0 elsewhere).
Eigen::VectorXd penaltyDiagonal(const Grid& grid, const ConstraintSet& set, double omega);

// E(T) = ||D T||^2 + omega^2 sum_{p in C} ||t_p - c_p||^2 (S2.3).
double fieldEnergy(const Grid& grid, const ConstraintSet& set, double omega, const Field& T);
// The same plus the prior's beta2 sum_p ||t_p - g_p||^2 (G empty: zero).
double fieldEnergy(const Grid& grid, const ConstraintSet& set, double omega, const Field& T,
                   double beta2, const Field& G);

// Matrix-free Y = D^T D X for X: n x 3 (same result as assembleBiLaplacian(grid) * X).
void applyBiLaplacian(const Grid& grid, const Field& X, Field& Y);

}  // namespace hairsketch
