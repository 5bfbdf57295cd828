// D^T D against a brute-force build from method S2.2 on irregular boxes, boundary included.
#include "field_system.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "auto_solver.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace field_system_test {

using namespace hairsketch;

namespace {

// Dense D built straight from the definition, independently of the assembler's loops.
Eigen::MatrixXd bruteLaplacian(const Grid& g) {
  const int n = int(g.size());
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  for (int p = 0; p < n; ++p) {
    const int i = p % g.nx, j = (p / g.nx) % g.ny, k = p / (g.nx * g.ny);
    std::vector<int> nb;
    for (int q = 0; q < n; ++q) {
      const int a = q % g.nx, b = (q / g.nx) % g.ny, c = q / (g.nx * g.ny);
      if (std::abs(a - i) + std::abs(b - j) + std::abs(c - k) == 1) nb.push_back(q);
    }
    D(p, p) = -1.0;
    for (int q : nb) D(p, q) = 1.0 / double(nb.size());
  }
  return D;
}

}  // namespace

TEST(FieldSystem, BiLaplacianMatchesBruteForceOnIrregularBoxes) {
  for (auto dims :
       {std::array<int, 3>{4, 5, 6}, std::array<int, 3>{2, 3, 2}, std::array<int, 3>{7, 2, 3}}) {
    Grid g;
    g.nx = dims[0];
    g.ny = dims[1];
    g.nz = dims[2];
    const Eigen::MatrixXd Db = bruteLaplacian(g);
    const Eigen::MatrixXd Mb = Db.transpose() * Db;
    const Eigen::MatrixXd M = Eigen::MatrixXd(assembleBiLaplacian(g));
    EXPECT_LT((M - Mb).cwiseAbs().maxCoeff(), 1e-14);
    // A corner point has 3 neighbours, so its D row holds 1/3.
    EXPECT_DOUBLE_EQ(Eigen::MatrixXd(assembleLaplacian(g))(0, 1), 1.0 / 3.0);
    // Matrix-free apply equals the assembled product.
    Field X = Field::Random(g.size(), 3), Y;
    applyBiLaplacian(g, X, Y);
    const Field Yb = Mb * X;
    EXPECT_LT((Y - Yb).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(FieldSystem, ConstraintDiffSeparatesAddedRemovedChanged) {
  ConstraintSet a =
      normalizeConstraints({{5, {1, 0, 0}}, {2, {0, 1, 0}}, {9, {0, 0, 1}}, {2, {0, 0, 1}}});
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0].index, 2);
  EXPECT_DOUBLE_EQ(a[0].target.y(), 0.5);  // duplicates averaged
  ConstraintSet b = normalizeConstraints({{5, {1, 0, 0}}, {9, {0, 1, 0}}, {11, {1, 1, 1}}});
  ConstraintDiff d = diffConstraints(a, b);
  EXPECT_EQ(d.added, std::vector<int>{11});
  EXPECT_EQ(d.removed, std::vector<int>{2});
  EXPECT_EQ(d.changed, std::vector<int>{9});
}

TEST(AutoSolver, PicksExactOnSmallGridsAndFastOnLargeOnesAndRecordsIt) {
  Grid small;
  small.nx = small.ny = small.nz = 10;
  AutoSolver a;
  ASSERT_TRUE(a.setGrid(small, kDefaultOmega).ok());
  EXPECT_EQ(a.chosen(), "exact");
  ASSERT_TRUE(a.setConstraints(normalizeConstraints({{5, {1, 0, 0}}})).ok());
  Field T;
  ASSERT_TRUE(a.solve(T).ok());
  EXPECT_EQ(a.stats().method.rfind("auto:", 0), 0u);
  Grid large;
  large.nx = large.ny = large.nz = 30;
  AutoSolver b;
  ASSERT_TRUE(b.setGrid(large, kDefaultOmega).ok());
  EXPECT_EQ(b.chosen(), "fast");
}

}  // namespace field_system_test
