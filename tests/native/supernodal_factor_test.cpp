#include "supernodal_factor.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "exact_reference.hpp"

namespace supernodal_factor_test {
using namespace hairsketch;
namespace {

using testref::box;

// Random penalty: omega^2 at about a fraction of the points (at least one).
Eigen::VectorXd randomPenalty(int n, double fraction, std::mt19937& rng) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < n; ++i)
    if (u(rng) < fraction) p[i] = 1e4;
  p[int(rng() % unsigned(n))] = 1e4;
  return p;
}

TEST(SupernodalFactor, SmallGridMatchesDenseCholesky) {
  std::mt19937 rng(7);
  const Grid g = box(5, 4, 6);
  const SparseMatrix M = assembleBiLaplacian(g);
  const Eigen::VectorXd pen = randomPenalty(int(g.size()), 0.1, rng);
  SupernodalFactor F;
  DissectionOptions o;
  o.leafMax = 6;
  F.analyse(M, boxNestedDissection(g, o));
  ASSERT_TRUE(F.factorize(M, pen).ok());

  const Eigen::MatrixXd A = Eigen::MatrixXd(M) + Eigen::MatrixXd(pen.asDiagonal());
  Field B = Field::Random(g.size(), 3);
  const Eigen::MatrixXd ref = A.llt().solve(Eigen::MatrixXd(B));
  Field X = B;
  F.solveInPlace(X);
  EXPECT_LT((Eigen::MatrixXd(X) - ref).norm() / ref.norm(), 1e-10);

  // The pivots are those of a dense Cholesky in the same elimination order (L is unique).
  const auto& S = F.symbolic();
  Eigen::MatrixXd P(A.rows(), A.cols());
  for (int a = 0; a < S.n; ++a)
    for (int b = 0; b < S.n; ++b) P(a, b) = A(S.perm[size_t(a)], S.perm[size_t(b)]);
  Eigen::LLT<Eigen::MatrixXd> llt(P);
  for (int k = 0; k < S.n; ++k) {
    const double dk = llt.matrixLLT()(k, k) * llt.matrixLLT()(k, k);
    EXPECT_NEAR(F.pivot(k), dk, 1e-9 * dk);
  }
}

TEST(SupernodalFactor, MediumGridResidualAndEigenReference) {
  std::mt19937 rng(11);
  const Grid g = box(17, 14, 15);
  const SparseMatrix M = assembleBiLaplacian(g);
  const Eigen::VectorXd pen = randomPenalty(int(g.size()), 0.02, rng);
  SupernodalFactor F;
  F.analyse(M, boxNestedDissection(g));
  ASSERT_TRUE(F.factorize(M, pen).ok());
  const SparseMatrix A = testref::withPenalty(M, pen);
  Field B = Field::Random(g.size(), 3);
  Field X = B;
  F.solveInPlace(X);
  const Field R = B - A * X;
  EXPECT_LT(R.norm() / B.norm(), 1e-11);
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(A);
  const Field ref = Field(Eigen::MatrixXd(ldlt.solve(Eigen::MatrixXd(B))));
  EXPECT_LT(testref::relError(X, ref), 1e-9);
}

TEST(SupernodalFactor, IndefiniteMatrixIsRejected) {
  const Grid g = box(6, 6, 6);
  const SparseMatrix M = assembleBiLaplacian(g);
  Eigen::VectorXd pen = Eigen::VectorXd::Zero(g.size());
  pen[3] = 1e4;
  pen[100] = -1e4;  // a negative diagonal entry makes M indefinite
  SupernodalFactor F;
  F.analyse(M, boxNestedDissection(g));
  const Status st = F.factorize(M, pen);
  EXPECT_EQ(st.code, StatusCode::NotPositiveDefinite);
  EXPECT_FALSE(F.valid());
}

}  // namespace
}  // namespace supernodal_factor_test
