#include "factor_update.hpp"

#include <gtest/gtest.h>

#include <random>

#include "exact_reference.hpp"

namespace factor_update_test {
using namespace hairsketch;
namespace {

using testref::box;

constexpr double kW2 = 1e4;

// Applies random updates/downdates to a factor and compares it with a fresh factorisation of
// the same matrix: pivots and a 3-RHS solve.
void randomModifications(const Grid& g, int leafMax, int rounds, unsigned seed, UpdateOptions uo) {
  std::mt19937 rng(seed);
  const int n = int(g.size());
  const SparseMatrix M = assembleBiLaplacian(g);
  DissectionOptions o;
  o.leafMax = leafMax;
  const DissectionTree tree = boxNestedDissection(g, o);
  SupernodalFactor F, fresh;
  F.analyse(M, tree);
  fresh.analyse(M, tree);
  Eigen::VectorXd pen = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < 3; ++i) pen[int(rng() % unsigned(n))] = kW2;
  ASSERT_TRUE(F.factorize(M, pen).ok());

  for (int r = 0; r < rounds; ++r) {
    // Add a few points (clustered or scattered), remove a few constrained ones; keep >= 1.
    std::vector<DiagonalTerm> up, down;
    const int adds = int(rng() % 12), removes = int(rng() % 10);
    int p = int(rng() % unsigned(n));
    for (int a = 0; a < adds; ++a) {
      p = (rng() % 3 == 0) ? int(rng() % unsigned(n)) : (p + 1 + int(rng() % 3)) % n;
      if (pen[p] == 0) {
        pen[p] = kW2;
        up.push_back({F.symbolic().iperm[size_t(p)], kW2});
      }
    }
    std::vector<int> on;
    for (int i = 0; i < n; ++i)
      if (pen[i] != 0) on.push_back(i);
    std::shuffle(on.begin(), on.end(), rng);
    for (int d = 0; d < removes && d + 1 < int(on.size()); ++d) {
      if (std::find_if(up.begin(), up.end(), [&](const DiagonalTerm& t) {
            return t.position == F.symbolic().iperm[size_t(on[size_t(d)])];
          }) != up.end())
        continue;
      pen[on[size_t(d)]] = 0;
      down.push_back({F.symbolic().iperm[size_t(on[size_t(d)])], -kW2});
    }
    std::vector<DiagonalTerm> terms = up;
    terms.insert(terms.end(), down.begin(), down.end());
    UpdateStats st;
    const Status s = modifyDiagonal(F, terms, uo, &st);
    ASSERT_TRUE(s.ok()) << s.message << " at round " << r;
  }
  ASSERT_TRUE(fresh.factorize(M, pen).ok());
  for (int k = 0; k < n; ++k)
    ASSERT_NEAR(F.pivot(k), fresh.pivot(k), 1e-9 * fresh.pivot(k)) << "pivot " << k;
  for (int s = 0; s < F.symbolic().supernodes(); ++s) {
    const auto& S = F.symbolic();
    const Eigen::Map<const Eigen::MatrixXd> a(F.block(s), S.nrows(s), S.width(s));
    const Eigen::Map<const Eigen::MatrixXd> b(fresh.block(s), S.nrows(s), S.width(s));
    ASSERT_LT((a - b).norm(), 1e-9 * (1.0 + b.norm())) << "supernode " << s;
  }
  Field B = Field::Random(n, 3), X = B, Y = B;
  F.solveInPlace(X);
  fresh.solveInPlace(Y);
  EXPECT_LT(testref::relError(X, Y), 1e-10);
  // And against an independent solver.
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(testref::withPenalty(M, pen));
  const Field ref = Field(Eigen::MatrixXd(ldlt.solve(Eigen::MatrixXd(B))));
  EXPECT_LT(testref::relError(X, ref), 1e-9);
}

UpdateOptions opts(UpdateKernel kernel, int panel, int chunk) {
  UpdateOptions o;
  o.kernel = kernel;
  o.panel = panel;
  o.chunk = chunk;
  return o;
}

TEST(FactorUpdate, RandomSequenceSmallGridRank1) {
  randomModifications(box(6, 5, 7), 8, 200, 1, opts(UpdateKernel::Rank1, 4, 0));
}
TEST(FactorUpdate, RandomSequenceSmallGridBlocked) {
  // Tiny panels and chunks: many panels per supernode, several chunks per edit.
  randomModifications(box(6, 5, 7), 8, 200, 1, opts(UpdateKernel::Blocked, 3, 4));
}
TEST(FactorUpdate, RandomSequenceMediumGridRank1) {
  randomModifications(box(14, 12, 13), 64, 200, 2, opts(UpdateKernel::Rank1, 32, 0));
}
TEST(FactorUpdate, RandomSequenceMediumGridBlocked) {
  randomModifications(box(14, 12, 13), 64, 200, 2, opts(UpdateKernel::Blocked, 48, 128));
  randomModifications(box(13, 11, 12), 27, 100, 3, opts(UpdateKernel::Blocked, 16, 7));
}

TEST(FactorUpdate, ManyVectorsInOnePassMatchFreshFactor) {
  // A curve of 150 points added in one pass, then 100 of them removed in one pass.
  const Grid g = box(16, 15, 14);
  const int n = int(g.size());
  const SparseMatrix M = assembleBiLaplacian(g);
  SupernodalFactor F, fresh;
  F.analyse(M, boxNestedDissection(g));
  fresh.analyse(M, boxNestedDissection(g));
  Eigen::VectorXd pen = Eigen::VectorXd::Zero(n);
  pen[g.index(8, 8, 8)] = kW2;
  ASSERT_TRUE(F.factorize(M, pen).ok());
  std::vector<DiagonalTerm> up, down;
  int i = 1, j = 2, k = 3;
  std::mt19937 rng(3);
  while (up.size() < 150) {
    const int axis = int(rng() % 3);
    (axis == 0 ? i : axis == 1 ? j : k) += 1;
    i %= g.nx;
    j %= g.ny;
    k %= g.nz;
    const int p = g.index(i, j, k);
    if (pen[p] != 0) continue;
    pen[p] = kW2;
    up.push_back({F.symbolic().iperm[size_t(p)], kW2});
  }
  UpdateStats st;
  ASSERT_TRUE(modifyDiagonal(F, up, opts(UpdateKernel::Rank1, 32, 0), &st).ok());
  EXPECT_EQ(st.maxRank, 150);
  for (int t = 0; t < 100; ++t) {
    down.push_back({up[size_t(t)].position, -kW2});
    pen[F.symbolic().perm[size_t(up[size_t(t)].position)]] = 0;
  }
  ASSERT_TRUE(modifyDiagonal(F, down).ok());  // blocked, two chunks of up to 128
  ASSERT_TRUE(fresh.factorize(M, pen).ok());
  for (int q = 0; q < n; ++q) ASSERT_NEAR(F.pivot(q), fresh.pivot(q), 1e-9 * fresh.pivot(q));
}

class IndefiniteDowndate : public ::testing::TestWithParam<UpdateKernel> {};

TEST_P(IndefiniteDowndate, IsDetected) {
  UpdateOptions uo;
  uo.kernel = GetParam();
  const Grid g = box(8, 8, 8);
  const SparseMatrix M = assembleBiLaplacian(g);
  SupernodalFactor F;
  F.analyse(M, boxNestedDissection(g));
  Eigen::VectorXd pen = Eigen::VectorXd::Zero(g.size());
  pen[10] = kW2;
  ASSERT_TRUE(F.factorize(M, pen).ok());
  // Removing omega^2 where there is no constraint: M - omega^2 e e^T is indefinite.
  const Status st = modifyDiagonal(F, {{F.symbolic().iperm[200], -kW2}}, uo);
  EXPECT_EQ(st.code, StatusCode::NotPositiveDefinite);
  EXPECT_FALSE(F.valid());
  // A damaged factor refuses further modification.
  EXPECT_FALSE(modifyDiagonal(F, {{F.symbolic().iperm[10], kW2}}, uo).ok());
}
INSTANTIATE_TEST_SUITE_P(Kernels, IndefiniteDowndate,
                         ::testing::Values(UpdateKernel::Blocked, UpdateKernel::Rank1));

TEST(FactorUpdate, CostEstimateCountsPathFlops) {
  const Grid g = box(12, 12, 12);
  const SparseMatrix M = assembleBiLaplacian(g);
  SupernodalFactor F;
  F.analyse(M, boxNestedDissection(g));
  Eigen::VectorXd pen = Eigen::VectorXd::Zero(g.size());
  pen[0] = kW2;
  ASSERT_TRUE(F.factorize(M, pen).ok());
  const int pos = F.symbolic().iperm[size_t(g.index(3, 4, 5))];
  UpdateStats st;
  ASSERT_TRUE(modifyDiagonal(F, {{pos, kW2}}, opts(UpdateKernel::Rank1, 32, 0), &st).ok());
  // One vector: the estimate is exact up to the zero entries the kernel skips.
  const double est = estimateModifyFlops(F.symbolic(), {pos});
  EXPECT_GT(st.flops, 0.3 * est);
  EXPECT_LE(st.flops, est * 1.0000001);
}

}  // namespace
}  // namespace factor_update_test
